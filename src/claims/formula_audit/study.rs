//! The formula audit as a study: every transcribed formula of the paper against this crate's
//! own derivation (exactly over ℚ, then at seeded random points), with a mutant of the accepted
//! formula run through the same two checks; printed arithmetic evaluated exactly; the dedicated
//! computations. Returns exact values and flags; the judgement is the judge's.

use std::collections::BTreeMap;

use num_rational::BigRational;
use num_traits::One;
use rayon::prelude::*;

use crate::algebra::{Monomial, Poly, RatFn};
use crate::claims::formula_audit::{
    ArithmeticItem, ComputedTest, FormulaAuditCase, FormulaItem, Relation,
};
use crate::derivations::appendix_a::quadratic_formula_solves;
use crate::derivations::formulas::{
    derived, ordered_choices, ordered_choices_enumerated, quadratic_in_squares,
};
use crate::derivations::two_frames::{fourth_relation, FourthRelation};
use crate::derivations::twofold::{frame_equation, relation_squared};
use crate::error::{Error, Result};
use crate::studies::points::{agree_at_points, flip_one_term, PointCheck};

mod expanded;
mod export;
mod reading;
pub use expanded::{expanded, ExpandedFinding, Screened};
pub use export::sympy_scripts;
use reading::{FormulaReading, Text};

/// Which form of a formula was accepted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    /// As printed (transcribed).
    Printed,
    /// The corrected form of the case file.
    Corrected,
}

/// A mutant of the accepted formula: the sign of one term of its expanded numerator flipped.
#[derive(Clone, Debug)]
pub struct Mutant {
    /// The term whose sign was flipped (its monomial).
    pub term: Monomial,
    /// The exact comparison rejected it (no rational multiple of the derivation).
    pub exact_rejected: bool,
    /// The random-point check of the mutant (with the accepted form's ratio).
    pub points: PointCheck,
}

impl Mutant {
    /// Both stages of the check rejected the mutant.
    pub fn rejected(&self) -> bool {
        self.exact_rejected && !self.points.all_agree()
    }
}

/// What the accepted form of a formula gave.
#[derive(Clone, Debug)]
pub struct Accepted {
    /// Printed or corrected.
    pub form: Form,
    /// accepted = ratio · derivation.
    pub ratio: BigRational,
    /// The random-point check.
    pub points: PointCheck,
    /// Per `quadratic_in` group: whether the formula is at most quadratic in its squares.
    pub quadratic: Vec<(Vec<String>, bool)>,
    /// The mutant run through the same checks; `None` when the formula is zero.
    pub mutant: Option<Mutant>,
}

/// One displayed formula against its derivation.
#[derive(Clone, Debug)]
pub struct FormulaFinding {
    /// The derivation it must equal.
    pub target: RatFn,
    /// The printed transcription matches (`None` when no formula was printed).
    pub printed_matches: Option<bool>,
    /// The corrected form matches (`None` when there is none).
    pub corrected_matches: Option<bool>,
    /// The first form that matched, with its evidence.
    pub accepted: Option<Accepted>,
}

/// Which formulas of a case a study computes (the others only lend later ones what they
/// define).
pub type Judged<'a> = &'a (dyn Fn(&FormulaItem) -> bool + Sync);

/// Every formula of the case that `judged` selects, in order, each with the names bound
/// before it substituted but its free symbols (read when a formula needs them, once). The
/// formulas are read and checked in parallel.
pub fn formulas(case: &FormulaAuditCase, judged: Judged) -> Result<Vec<FormulaFinding>> {
    let reading = FormulaReading::new(case, true);
    let (points, seed) = (case.evaluation_points, case.seed);
    // every formula computed, then the first error in case order (whichever finished first)
    let found: Vec<Result<FormulaFinding>> = case
        .formulas
        .par_iter()
        .enumerate()
        .filter(|(_, f)| judged(f))
        .map(|(i, f)| {
            let printed = reading.read(Text::Printed(i))?;
            let corrected = reading.read(Text::Corrected(i))?;
            formula(f, printed, corrected, points, seed)
        })
        .collect();
    found.into_iter().collect()
}

/// `e = k · target` under the item's relation: `Some(k)` when it holds.
fn relation_ratio(e: &RatFn, target: &RatFn, relation: Relation) -> Option<BigRational> {
    match relation {
        Relation::Equal => e.equals(target).then(BigRational::one),
        Relation::Proportional => e.ratio_to(target),
    }
}

fn formula(
    f: &FormulaItem,
    printed: Option<RatFn>,
    corrected: Option<RatFn>,
    points: usize,
    seed: u64,
) -> Result<FormulaFinding> {
    let target = derived(&f.derived)
        .ok_or_else(|| Error::InvalidInput(format!("no derivation `{}`", f.derived)))?;
    let ratio = |e: &Option<RatFn>| e.as_ref().map(|e| relation_ratio(e, &target, f.relation));
    let (pr, cr) = (ratio(&printed), ratio(&corrected));
    let accepted = match (&pr, &cr, &printed, &corrected) {
        (Some(Some(k)), _, Some(e), _) => Some((Form::Printed, k.clone(), e)),
        (_, Some(Some(k)), _, Some(e)) => Some((Form::Corrected, k.clone(), e)),
        _ => None,
    }
    .map(|(form, k, e)| accept(form, k, e, &target, f, points, seed));
    Ok(FormulaFinding {
        printed_matches: pr.map(|r| r.is_some()),
        corrected_matches: cr.map(|r| r.is_some()),
        accepted,
        target,
    })
}

fn accept(
    form: Form,
    ratio: BigRational,
    e: &RatFn,
    target: &RatFn,
    f: &FormulaItem,
    points: usize,
    seed: u64,
) -> Accepted {
    let check = agree_at_points(e, target, &ratio, points, seed);
    let quadratic = accepted_quadratic(e, f);
    let mutant = flip_one_term(e).map(|(term, m)| Mutant {
        term,
        exact_rejected: relation_ratio(&m, target, f.relation).is_none(),
        points: agree_at_points(&m, target, &ratio, points, seed),
    });
    Accepted {
        form,
        ratio,
        points: check,
        quadratic,
        mutant,
    }
}

/// Per `quadratic_in` group of the item: whether `e` is at most quadratic in those squares.
fn accepted_quadratic(e: &RatFn, f: &FormulaItem) -> Vec<(Vec<String>, bool)> {
    f.quadratic_in
        .iter()
        .map(|group| {
            let vars: Vec<&str> = group.iter().map(String::as_str).collect();
            // a polynomial, or a numerator over a denominator free of these variables
            let q = e.to_poly().is_some_and(|p| quadratic_in_squares(&p, &vars))
                || (e
                    .den
                    .variables()
                    .iter()
                    .all(|v| !vars.contains(&v.as_str()))
                    && quadratic_in_squares(&e.num, &vars));
            (group.clone(), q)
        })
        .collect()
}

/// Printed arithmetic, evaluated exactly.
#[derive(Clone, Debug)]
pub struct ArithmeticFinding {
    /// Each printed step's exact value (`None` when it does not parse or evaluate).
    pub steps: Vec<Option<BigRational>>,
}

/// Evaluate every printed step at the item's values.
pub fn arithmetic(a: &ArithmeticItem) -> ArithmeticFinding {
    let vals: BTreeMap<String, BigRational> = a
        .values
        .iter()
        .map(|(k, v)| (k.clone(), BigRational::from_integer((*v).into())))
        .collect();
    ArithmeticFinding {
        steps: a
            .steps
            .iter()
            .map(|s| Poly::parse(s).ok().and_then(|p| p.eval(&vals)))
            .collect(),
    }
}

/// A dedicated computation's outcome.
#[derive(Clone, Debug)]
pub enum ComputedFinding {
    /// The fourth relation of §5.
    FourthRelation(FourthRelation),
    /// The fourth relation of §5 in the twofold-squared system the section solves.
    FourthRelationSquared(FourthRelation),
    /// The quadratic formula for b² (Appendix A).
    BFormula {
        /// Both signs of the root solve the quadratic.
        solves: bool,
        /// The mutant (−B replaced by +B) was rejected by the same check.
        mutant_rejected: bool,
    },
    /// A signed relation of §4 squared twice.
    SignedRelation {
        /// Exactly three edges were given.
        three_edges: bool,
        /// Each of the four sign choices gives the triangle's polynomial.
        per_sign: Vec<bool>,
        /// The mutant (coefficient 2 on the last radical) was rejected by the same check.
        mutant_rejected: bool,
    },
    /// A list of constant symbols against those used.
    ConstantSymbols {
        /// Used but not listed.
        missing: Vec<String>,
        /// Listed but not used.
        extra: Vec<String>,
    },
    /// Ordered choices of four points.
    OrderedQuadruples {
        /// (n, formula, enumeration).
        rows: Vec<(usize, usize, usize)>,
        /// The printed value equals the formula's value for the first n.
        printed_matches: bool,
    },
}

/// The size of the choices an ordered quadruple makes.
const QUADRUPLE: usize = 4;

/// Run one dedicated computation.
pub fn computed(test: &ComputedTest) -> ComputedFinding {
    match test {
        ComputedTest::FourthRelation { seed } => {
            ComputedFinding::FourthRelation(fourth_relation(*seed))
        }
        ComputedTest::FourthRelationSquared { seed } => {
            ComputedFinding::FourthRelationSquared(fourth_relation(*seed))
        }
        ComputedTest::BFormula => ComputedFinding::BFormula {
            solves: quadratic_formula_solves(-1, 4),
            // the same check with the sign of B in the numerator flipped
            mutant_rejected: !quadratic_formula_solves(1, 4),
        },
        ComputedTest::SignedRelation { edges } => signed_relation(edges),
        ComputedTest::ConstantSymbols { listed, used, .. } => ComputedFinding::ConstantSymbols {
            missing: used
                .iter()
                .filter(|u| !listed.contains(u))
                .cloned()
                .collect(),
            extra: listed
                .iter()
                .filter(|l| !used.contains(l))
                .cloned()
                .collect(),
        },
        ComputedTest::OrderedQuadruples { n, printed } => {
            let rows: Vec<(usize, usize, usize)> = n
                .iter()
                .map(|&n| {
                    (
                        n,
                        ordered_choices(n, QUADRUPLE),
                        ordered_choices_enumerated(n, QUADRUPLE),
                    )
                })
                .collect();
            let printed_matches = rows
                .first()
                .is_some_and(|r| printed.to_integer() == Some(num_bigint::BigInt::from(r.1)));
            ComputedFinding::OrderedQuadruples {
                rows,
                printed_matches,
            }
        }
    }
}

/// The four sign choices of √X₀ = ±√X₁ ± √X₂ squared twice, against the triangle's
/// eq. p3f3sqr; the mutant gives the last radical the coefficient 2.
fn signed_relation(edges: &[String]) -> ComputedFinding {
    let e: Vec<&str> = edges.iter().map(String::as_str).collect();
    let [e0, e1, e2] = e[..] else {
        return ComputedFinding::SignedRelation {
            three_edges: false,
            per_sign: Vec::new(),
            mutant_rejected: false,
        };
    };
    let e3 = [e0, e1, e2];
    let target = frame_equation(e3, "i");
    // √X₀ = s₁√X₁ + s₂√X₂, i.e. √X₀ − s₁√X₁ − s₂√X₂ = 0
    let per_sign = [(1, 1), (1, -1), (-1, 1), (-1, -1)]
        .iter()
        .map(|&(s1, s2)| relation_squared(e3, [1, -s1, -s2]) == target)
        .collect();
    ComputedFinding::SignedRelation {
        three_edges: true,
        per_sign,
        mutant_rejected: relation_squared(e3, [1, -1, -2]) != target,
    }
}
