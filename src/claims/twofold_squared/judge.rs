//! Claims of eq. p3f3sqr: the signed relations and their twofold squaring.

use crate::check::Role;
use crate::check::{points_details, points_tolerance};
use crate::check::{ClaimResult, Power, ResultBuilder, Tolerance, Value, Verdict};
use crate::claims::twofold_squared::study::{census, twofold, TwofoldStudy};
use crate::claims::twofold_squared::{parse_signs, TwofoldSquaredCase};
use crate::error::Result;

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

fn patterns(case: &TwofoldSquaredCase) -> Vec<[i64; 3]> {
    case.relations
        .patterns
        .iter()
        .filter_map(|p| parse_signs(p))
        .collect()
}

fn study(case: &TwofoldSquaredCase) -> Result<TwofoldStudy> {
    twofold(
        &case.polynomial.printed,
        &patterns(case),
        case.evaluation_points,
        case.seed,
    )
}

/// The judge: every pattern's squaring is a multiple of the printed polynomial, every random
/// point agrees, and the polynomial is quadratic in the squares.
fn identity_verdict(s: &TwofoldStudy) -> Verdict {
    let ok = s.ratios.iter().all(Option::is_some) && s.points.all_agree() && s.quadratic_in_squares;
    if ok {
        Verdict::IdentityVerified
    } else {
        Verdict::Erratum
    }
}

/// Run the exact audit of eq. p3f3sqr.
pub fn audit(case: &TwofoldSquaredCase) -> Result<TwofoldAudit> {
    let s = study(case)?;
    Ok(TwofoldAudit {
        transcription: case.polynomial.printed.clone(),
        printed: s.printed.to_string(),
        derived: derived_text(&s),
        ratios: s
            .ratios
            .iter()
            .map(|r| r.as_ref().map(|x| x.to_string()))
            .collect(),
        product_ratio: s.product_ratio.as_ref().map(|x| x.to_string()),
        quadratic_in_squares: s.quadratic_in_squares,
        evaluation: (s.points.points, s.points.seed, s.points.agreeing),
        verdict: identity_verdict(&s),
    })
}

/// The polynomial derived by squaring twice, as text.
fn derived_text(s: &TwofoldStudy) -> String {
    s.derived.first().cloned().unwrap_or_default().to_string()
}

fn signs_text(p: &[i64; 3]) -> String {
    p.iter()
        .map(|s| if *s > 0 { "+" } else { "-" })
        .collect::<Vec<_>>()
        .join(" ")
}

fn relations(b: &ResultBuilder, case: &TwofoldSquaredCase) -> ClaimResult {
    let pats = patterns(case);
    let c = census(&pats, case.relations.trials, case.relations.seed);
    let mut r = b
        .claim(&case.relations.claim)
        .printed("patterns", Value::label(case.relations.patterns.join(" | ")))
        .computed(
            "frames where one pattern held",
            Value::count_of(c.census.trials - c.census.none_held, c.census.trials),
        )
        .computed("frames where none held", c.census.none_held)
        .tolerance(Tolerance::exact(
            "signs of the depth differences matched exactly (they sum to zero, so all-equal signs cannot occur)",
        ))
        .power(Power::mutant(
            c.mutant.none_held > 0,
            &format!(
                "the pattern set with the first sign of its last pattern flipped ({}): the same census finds frames where none holds",
                c.mutant_patterns.iter().map(signs_text).collect::<Vec<_>>().join(" | ")
            ),
        ))
        .method("seeded random triangles under random rotations; signs of z_Q−z_P, z_R−z_Q, z_P−z_R compared with each pattern up to a global sign")
        .detail_as("trials", c.census.trials, Role::Trials)
        .detail("seed", c.census.seed)
        .detail("largest relative residual of the matching relation", Value::below(c.census.max_residual))
        .cell("mutant", "frames where none held", c.mutant.none_held);
    for (p, n) in pats.iter().zip(&c.census.held) {
        r = r.detail(&format!("frames where {} held", signs_text(p)), *n);
    }
    r.verdict(Verdict::holds(c.census.none_held == 0))
}

/// The audit's item: the claim result of eq. p3f3sqr and the derived polynomial, from one
/// study.
pub(super) fn audit_item(
    b: &ResultBuilder,
    case: &TwofoldSquaredCase,
) -> Result<(ClaimResult, String)> {
    let s = study(case)?;
    Ok((polynomial(b, case, &s), derived_text(&s)))
}

/// The claim result of eq. p3f3sqr.
fn polynomial(b: &ResultBuilder, case: &TwofoldSquaredCase, s: &TwofoldStudy) -> ClaimResult {
    let (rejected, term, mutant_agree) = match &s.mutant {
        Some(m) => (m.rejected(), Power::term_text(&m.term), m.points.agreeing),
        None => (false, String::new(), 0),
    };
    let mut r = b
        .claim(&case.polynomial.claim)
        .printed("polynomial", Value::formula(format!("{} = 0", case.polynomial.printed)))
        .computed(
            "derived",
            Value::formula(format!("{} = 0", s.derived.first().cloned().unwrap_or_default())),
        )
        .tolerance(points_tolerance(&s.points))
        .power(Power::mutant(
            rejected,
            &format!("the printed polynomial with the sign of its term {term} flipped: no pattern's squaring is a multiple of it and the random points disagree"),
        ))
        .method("symbolic twofold squaring with √A, √B, √C as variables reduced by (√X)² = X; exact expansion over ℚ; Schwartz–Zippel evaluation as a second check");
    for (p, ratio) in patterns(case).iter().zip(&s.ratios) {
        let v = ratio
            .as_ref()
            .map_or(Value::label("not a multiple"), Value::exact);
        r = r.computed(&format!("derived / printed ({})", signs_text(p)), v);
    }
    let product = s
        .product_ratio
        .as_ref()
        .map_or(Value::label("not a multiple"), Value::exact);
    r = r
        .detail("product over the four sign classes / printed", product)
        .detail("quadratic in a², b², c²", s.quadratic_in_squares);
    r = points_details(
        r.computed(
            "random points agreeing",
            Value::count_of(s.points.agreeing, s.points.points),
        ),
        &s.points,
    )
    .cell(
        "mutant",
        "random points agreeing",
        Value::count_of(mutant_agree, s.points.points),
    );
    r.verdict(identity_verdict(s))
}

pub(super) fn results(b: &ResultBuilder, case: &TwofoldSquaredCase) -> Result<Vec<ClaimResult>> {
    Ok(vec![relations(b, case), polynomial(b, case, &study(case)?)])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::claims::twofold_squared::study::twofold;

    const PATTERNS: [[i64; 3]; 3] = [[1, 1, -1], [1, -1, 1], [-1, 1, 1]];

    #[test]
    fn the_judge_accepts_the_squaring_and_rejects_a_changed_term() {
        let right = crate::derivations::twofold::twofold_squared([1, 1, -1]).to_string();
        let s = twofold(&right, &PATTERNS, 8, 1).unwrap();
        assert_eq!(identity_verdict(&s), Verdict::IdentityVerified);
        assert!(s.mutant.as_ref().is_some_and(|m| m.rejected()));
        let wrong = format!("{right} + a^2");
        let s = twofold(&wrong, &PATTERNS, 8, 1).unwrap();
        assert_eq!(identity_verdict(&s), Verdict::Erratum);
    }
}
