//! Claims of eq. p3f3sqr: the signed relations and their twofold squaring.

use num_traits::One;

use super::{ClaimResult, Evidence, OldTolerance, ResultBuilder, Verdict};
use crate::algebra::{agree_at_random_points, Poly};
use crate::cases::{parse_signs, TwofoldCase};
use crate::derivations::twofold::{relation_census, sign_class_product, twofold_squared};
use crate::error::{Error, Result};
use crate::numfmt::below;

/// Everything `orthocheck audit twofold-squared` and the report show.
#[derive(Clone, Debug, serde::Serialize)]
pub struct TwofoldAudit {
    /// The transcription, as in the case file.
    pub transcription: String,
    /// The transcription, expanded.
    pub printed: String,
    /// The polynomial derived by squaring twice.
    pub derived: String,
    /// derived = ratio · printed, per printed sign pattern (`None` when not a multiple).
    pub ratios: Vec<Option<String>>,
    /// The product over the four sign classes = ratio · printed.
    pub product_ratio: Option<String>,
    /// Whether every a, b, c exponent is even and the degree in (a², b², c²) is at most 2.
    pub quadratic_in_squares: bool,
    /// Random-point evaluation: points, seed, agreeing.
    pub evaluation: (usize, u64, usize),
    /// The verdict.
    pub verdict: Verdict,
}

/// Run the exact audit of eq. p3f3sqr.
pub fn audit(case: &TwofoldCase) -> Result<TwofoldAudit> {
    let printed = Poly::parse(&case.polynomial.printed).map_err(|source| Error::Formula {
        formula: case.polynomial.printed.clone(),
        source,
    })?;
    let patterns: Vec<[i64; 3]> = case
        .relations
        .patterns
        .iter()
        .filter_map(|p| parse_signs(p))
        .collect();
    let derived: Vec<Poly> = patterns.iter().map(|s| twofold_squared(*s)).collect();
    let ratios: Vec<_> = derived.iter().map(|d| d.ratio_to(&printed)).collect();
    let product_ratio = sign_class_product().ratio_to(&printed);
    let quadratic_in_squares = printed.terms().all(|(m, _)| {
        let e: Vec<u32> = ["a", "b", "c"].iter().map(|v| m.exponent(v)).collect();
        e.iter().all(|x| x % 2 == 0) && e.iter().sum::<u32>() <= 4
    });
    let first = derived.first().cloned().unwrap_or_default();
    let ratio = ratios.first().cloned().flatten();
    let evaluation = agree_at_random_points(
        &first.clone().into(),
        &printed.clone().into(),
        &ratio.clone().unwrap_or_else(num_rational::BigRational::one),
        case.evaluation_points,
        case.seed,
    );
    let all_ratios = ratios.iter().all(Option::is_some);
    let verdict = if all_ratios && evaluation.agreeing == evaluation.points && quadratic_in_squares
    {
        Verdict::IdentityVerified
    } else {
        Verdict::Erratum
    };
    Ok(TwofoldAudit {
        transcription: case.polynomial.printed.clone(),
        printed: printed.to_string(),
        derived: first.to_string(),
        ratios: ratios
            .iter()
            .map(|r| r.as_ref().map(|x| x.to_string()))
            .collect(),
        product_ratio: product_ratio.map(|x| x.to_string()),
        quadratic_in_squares,
        evaluation: (evaluation.points, evaluation.seed, evaluation.agreeing),
        verdict,
    })
}

pub(super) fn check(b: &ResultBuilder, case: &TwofoldCase) -> Result<Vec<ClaimResult>> {
    let mut out = Vec::new();
    let patterns: Vec<[i64; 3]> = case
        .relations
        .patterns
        .iter()
        .filter_map(|p| parse_signs(p))
        .collect();
    let census = relation_census(&patterns, case.relations.trials, case.relations.seed);
    out.push(b.result(
        &case.relations.claim,
        None,
        Verdict::holds(census.none_held == 0),
        format!("one of {} holds in each frame", case.relations.patterns.join(" | ")),
        format!(
            "held in {} of {} random frames (per pattern: {:?}); none held: {}",
            census.trials - census.none_held,
            census.trials,
            census.held,
            census.none_held
        ),
        Some(OldTolerance::exact(
            "sign matching of depth differences (they sum to zero, so all-equal signs cannot occur)",
        )),
        Evidence::new("seeded random triangles under random rotations; signs of z_Q−z_P, z_R−z_Q, z_P−z_R compared with each pattern up to a global sign")
            .with("trials", census.trials)
            .with("seed", census.seed)
            .with("largest relative residual of the matching relation", below(census.max_residual)),
    ));

    let a = audit(case)?;
    out.push(b.result(
        &case.polynomial.claim,
        None,
        a.verdict,
        format!("{} = 0", a.transcription),
        format!("{} = 0", a.derived),
        Some(OldTolerance::exact("polynomial identity over ℚ")),
        Evidence::new("symbolic twofold squaring with √A, √B, √C as variables reduced by (√X)² = X; exact expansion over ℚ; Schwartz–Zippel evaluation as a second check")
            .with("derived / printed, per sign pattern", format!("{:?}", a.ratios.iter().map(|r| r.clone().unwrap_or_else(|| "not a multiple".into())).collect::<Vec<_>>()))
            .with("product over the four sign classes / printed", a.product_ratio.clone().unwrap_or_else(|| "not a multiple".into()))
            .with("quadratic in a², b², c²", a.quadratic_in_squares)
            .with("random rational points (agreeing/total, seed)", format!("{}/{}, seed {}", a.evaluation.2, a.evaluation.0, a.evaluation.1)),
    ));
    Ok(out)
}
