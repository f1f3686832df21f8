//! Eq. p3f3sqr as a study: the printed polynomial against the twofold squaring of every sign
//! pattern, and the census of which signed relation holds in random frames; each with the
//! mutant the same check must reject.

use num_rational::BigRational;
use num_traits::One;

use crate::algebra::{Monomial, Poly, RatFn};
use crate::derivations::twofold::{
    relation_census, sign_class_product, twofold_squared, RelationCensus,
};
use crate::error::{Error, Result};
use crate::studies::points::{agree_at_points, flip_one_term, PointCheck};

/// The printed polynomial against the derivation.
#[derive(Clone, Debug)]
pub struct TwofoldStudy {
    /// The printed polynomial, expanded.
    pub printed: Poly,
    /// The twofold squaring of each sign pattern.
    pub derived: Vec<Poly>,
    /// derived = ratio · printed, per pattern (`None`: not a multiple).
    pub ratios: Vec<Option<BigRational>>,
    /// The product over the four sign classes = ratio · printed.
    pub product_ratio: Option<BigRational>,
    /// Every a, b, c exponent even and the degree in (a², b², c²) at most 2.
    pub quadratic_in_squares: bool,
    /// The first pattern's derivation against the printed polynomial at random points.
    pub points: PointCheck,
    /// The printed polynomial with one term's sign flipped, through the same checks.
    pub mutant: Option<TwofoldMutant>,
}

/// The mutant of the printed polynomial.
#[derive(Clone, Debug)]
pub struct TwofoldMutant {
    /// The term whose sign was flipped.
    pub term: Monomial,
    /// Some pattern's derivation is a multiple of the mutant.
    pub some_ratio: bool,
    /// The random-point check of the mutant against the first derivation.
    pub points: PointCheck,
}

impl TwofoldMutant {
    /// The same check rejected it.
    pub fn rejected(&self) -> bool {
        !self.some_ratio && !self.points.all_agree()
    }
}

/// Whether every exponent of a, b, c is even and the degree in their squares at most 2.
fn quadratic(p: &Poly) -> bool {
    crate::derivations::formulas::quadratic_in_squares(p, &["a", "b", "c"])
}

/// Compare the printed polynomial (text) with the twofold squaring of each pattern.
pub fn twofold(
    printed_text: &str,
    patterns: &[[i64; 3]],
    points: usize,
    seed: u64,
) -> Result<TwofoldStudy> {
    let printed = Poly::parse(printed_text).map_err(|source| Error::Formula {
        formula: printed_text.to_string(),
        source,
    })?;
    let derived: Vec<Poly> = patterns.iter().map(|s| twofold_squared(*s)).collect();
    let ratios: Vec<_> = derived.iter().map(|d| d.ratio_to(&printed)).collect();
    let first: RatFn = derived.first().cloned().unwrap_or_default().into();
    let ratio = ratios
        .first()
        .cloned()
        .flatten()
        .unwrap_or_else(BigRational::one);
    let check = agree_at_points(&first, &printed.clone().into(), &ratio, points, seed);
    let mutant = flip_one_term(&printed.clone().into()).map(|(term, m)| TwofoldMutant {
        term,
        some_ratio: m
            .to_poly()
            .is_some_and(|mp| derived.iter().any(|d| d.ratio_to(&mp).is_some())),
        points: agree_at_points(&first, &m, &ratio, points, seed),
    });
    Ok(TwofoldStudy {
        quadratic_in_squares: quadratic(&printed),
        product_ratio: sign_class_product().ratio_to(&printed),
        points: check,
        mutant,
        printed,
        derived,
        ratios,
    })
}

/// The census of the signed relations, and of a mutant pattern set.
#[derive(Clone, Debug)]
pub struct CensusStudy {
    /// The printed patterns.
    pub census: RelationCensus,
    /// The mutant pattern set: the first sign of the last pattern flipped.
    pub mutant_patterns: Vec<[i64; 3]>,
    /// Its census (same trials, same seed).
    pub mutant: RelationCensus,
}

/// Run the census for `patterns` and for the mutant set.
pub fn census(patterns: &[[i64; 3]], trials: usize, seed: u64) -> CensusStudy {
    let mut mutant_patterns = patterns.to_vec();
    if let Some(last) = mutant_patterns.last_mut() {
        last[0] = -last[0];
    }
    CensusStudy {
        census: relation_census(patterns, trials, seed),
        mutant: relation_census(&mutant_patterns, trials, seed),
        mutant_patterns,
    }
}
