//! The judge of §4's uniqueness over seeded scenes: unique for generic bodies, a planar body
//! rank-deficient.

use crate::check::{ClaimResult, Power, ResultBuilder, Tolerance, Value, Verdict};
use crate::claims::shared::CensusDesign;
use crate::error::Result;
use crate::studies::census;

/// §4's uniqueness: unique and exact in every generic scene.
fn generic_holds(c: &census::P4f3CensusCase) -> bool {
    c.unique == c.trials && c.truth_found == c.trials
}

/// The exception: every planar body leaves the six equations rank-deficient.
fn planar_degenerate(c: &census::P4f3CensusCase) -> bool {
    !c.planar_ranks.is_empty() && c.planar_ranks.iter().all(|r| *r < 6)
}

pub(super) fn results(b: &ResultBuilder, case: &CensusDesign) -> Result<Vec<ClaimResult>> {
    let c = census::p4f3(case.trials, case.seed);
    let generic = generic_holds(&c);
    let planar = planar_degenerate(&c);
    let mut out = Vec::new();
    for claim in &case.claims {
        let exception = case
            .exception
            .as_ref()
            .filter(|e| e.qualifies == claim.claim);
        let mut r = match case.suffixes.get(&claim.claim) {
            Some(s) => b.claim(claim).suffix(s),
            None => b.claim(claim),
        };
        r = census_numbers(r, &c).power(Power::mutant(
            c.viewing_axis_rank < 6,
            "the same rank test reports a rank below 6 for motions about the viewing axis",
        ));
        let verdict = match (generic, exception.is_some() && planar) {
            (false, _) => Verdict::Contradicted,
            (true, true) => Verdict::HoldsGenerically,
            (true, false) => Verdict::Reproduced,
        };
        if exception.is_some() {
            r = r.detail(
                "exception (never named by the paper)",
                Value::label("a planar body: the six equations lose rank whatever the motion"),
            );
        }
        out.push(r.verdict(verdict));
        if let Some(e) = exception {
            out.push(planar_result(b, claim, &e.suffix, &c, generic && planar));
        }
    }
    Ok(out)
}

fn census_numbers<'b>(
    r: crate::check::ClaimBuilder<'b>,
    c: &census::P4f3CensusCase,
) -> crate::check::ClaimBuilder<'b> {
    r.printed("solutions", Value::label("at most one, of a linear system (unless the motion is degenerate)"))
        .computed("unique feasible, realizable solutions", Value::count_of(c.unique, c.trials))
        .computed("equal to the truth within the rounding bound", Value::count_of(c.truth_found, c.trials))
        .computed("rank of all eight equations, motions about the viewing axis only", c.viewing_axis_rank)
        .tolerance(Tolerance::exact("numerical rank above the derived rounding floor of the entries"))
        .method("the paper's six equations on seeded random scenes of four points in three frames; then planar bodies (z an affine function of x and y) and motions about the viewing axis")
        .detail("seed", c.seed)
        .detail("largest relative error", Value::below(c.max_truth_error))
        .detail("median condition number", c.median_condition)
}

fn planar_result(
    b: &ResultBuilder,
    claim: &crate::cases::ClaimRef,
    suffix: &str,
    c: &census::P4f3CensusCase,
    holds: bool,
) -> ClaimResult {
    let ranks: Vec<f64> = c.planar_ranks.iter().map(|r| *r as f64).collect();
    let all: Vec<f64> = c
        .planar_ranks_all_triangles
        .iter()
        .map(|r| *r as f64)
        .collect();
    let mut r = b
        .claim(claim)
        .suffix(suffix)
        .printed("solutions", Value::label("at most one; only a degenerate motion is excepted"))
        .computed("ranks of the six equations, planar bodies", Value::reals(&ranks))
        .computed("ranks of all eight equations, planar bodies", Value::reals(&all))
        .computed("planar bodies tried", c.planar_trials)
        .tolerance(Tolerance::exact("numerical rank above the derived rounding floor of the entries"))
        .power(Power::mutant(c.unique > 0, "the same rank test gives rank 6 for the generic (non-planar) bodies of the census"))
        .method("the claim holds for every generic scene and fails exactly on planar bodies, whatever the motion: a degenerate set the paper never names");
    if let Some(d) = &c.planar_outcome {
        r = r.cell(
            "planar body",
            "the solver says",
            Value::label(d.to_string()),
        );
    }
    r.verdict(if holds {
        Verdict::HoldsGenerically
    } else {
        Verdict::Contradicted
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_planar_exception_needs_every_planar_rank_deficient() {
        let mut c = census::P4f3CensusCase {
            trials: 1,
            seed: 0,
            unique: 1,
            truth_found: 1,
            max_truth_error: 0.0,
            median_condition: 1.0,
            planar_trials: 2,
            planar_ranks: vec![5],
            planar_ranks_all_triangles: vec![5],
            planar_outcome: None,
            viewing_axis_rank: 4,
        };
        assert!(generic_holds(&c) && planar_degenerate(&c));
        c.planar_ranks = vec![5, 6];
        assert!(!planar_degenerate(&c));
        c.truth_found = 0;
        assert!(!generic_holds(&c));
    }
}
