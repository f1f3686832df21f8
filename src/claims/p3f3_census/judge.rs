//! The judge of §2.2's count over seeded scenes: at most two feasible solutions, infinitely
//! many in the two named degenerate cases.

use crate::check::{ClaimResult, Power, ResultBuilder, Tolerance, Value, Verdict};
use crate::claims::shared::census::census_claim;
use crate::claims::shared::CensusDesign;
use crate::derivations::solver::Degenerate;
use crate::error::Result;
use crate::studies::census;

/// §2.2's count: never more than two feasible solutions, and the two named degenerate cases
/// give infinitely many.
fn count_holds(c: &census::P3f3CensusCase) -> bool {
    matches!(c.collinear, Some(Degenerate::Collinear))
        && matches!(c.identical_frames, Some(Degenerate::IdenticalFrames { .. }))
        && c.truth_found == c.trials
}

pub(super) fn results(b: &ResultBuilder, case: &CensusDesign) -> Result<Vec<ClaimResult>> {
    let c = census::p3f3(case.trials, case.seed);
    let ok = count_holds(&c);
    // the control: the same census rejects "at most one solution" whenever it sees two
    let two = c.feasible_counts[2];
    let motions = c
        .motions_per_edge_solution
        .iter()
        .copied()
        .max()
        .unwrap_or(0);
    Ok(case
        .claims
        .iter()
        .map(|claim| {
            census_claim(b, case, claim)
                .printed("solutions", Value::label("none, one or two; infinitely many if collinear or two frames identical up to rotation"))
                .computed("scenes with 0 feasible solutions", Value::count_of(c.feasible_counts[0], c.trials))
                .computed("scenes with 1", Value::count_of(c.feasible_counts[1], c.trials))
                .computed("scenes with 2", Value::count_of(two, c.trials))
                .computed_cell("collinear body", "infinitely many", Value::flag(matches!(c.collinear, Some(Degenerate::Collinear))))
                .computed_cell("identical frames", "infinitely many", Value::flag(matches!(c.identical_frames, Some(Degenerate::IdenticalFrames { .. }))))
                .tolerance(Tolerance::exact("counts of roots; degeneracy detected at the derived rounding level"))
                .power(Power::mutant(two > 0, "the census rejects the narrower claim \"at most one solution\": it finds scenes with two"))
                .method("p3f3 on seeded random scenes (uniform rotations, points in the unit cube), plus a collinear body and two frames related by an in-plane rotation")
                .detail("seed", c.seed)
                .detail("true squares among the feasible ones", Value::count_of(c.truth_found, c.trials))
                .detail("largest relative error of the true solution", Value::below(c.max_truth_error))
                .cell("independent routes", "largest relative disagreement with the solver", Value::below(c.max_route_disagreement))
                .detail("scenes validated by the independent routes", Value::count_of(c.routes_checked.1, c.routes_checked.0))
                .detail("structure-and-motion solutions per edge solution, up to the mirror", motions)
                .detail("with the mirror", 2 * motions)
                .detail("with two edge solutions, up to", 4 * motions)
                .verdict(Verdict::holds(ok))
        })
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_counts_need_both_degenerate_cases() {
        let mut c = census::P3f3CensusCase {
            trials: 2,
            seed: 0,
            feasible_counts: [0, 1, 1],
            truth_found: 2,
            max_truth_error: 0.0,
            motions_per_edge_solution: vec![2],
            max_route_disagreement: 0.0,
            routes_checked: (2, 2),
            collinear: Some(Degenerate::Collinear),
            identical_frames: Some(Degenerate::IdenticalFrames {
                first: 1,
                second: 2,
            }),
        };
        assert!(count_holds(&c));
        c.collinear = None;
        assert!(!count_holds(&c));
    }
}
