//! The judge of §3's uniqueness over seeded scenes: unique unless the motion is special.

use crate::check::{ClaimResult, Power, ResultBuilder, Tolerance, Value, Verdict};
use crate::claims::shared::census::census_claim;
use crate::claims::shared::CensusDesign;
use crate::error::Result;
use crate::studies::census;

/// §3's uniqueness: every generic scene rank 3 and exact; a special motion loses rank.
fn unique_holds(c: &census::P3f4CensusCase) -> bool {
    c.unique == c.trials && c.truth_found == c.trials && c.viewing_axis_rank < 3
}

pub(super) fn results(b: &ResultBuilder, case: &CensusDesign) -> Result<Vec<ClaimResult>> {
    let c = census::p3f4(case.trials, case.frames, case.seed);
    let ok = unique_holds(&c);
    Ok(case
        .claims
        .iter()
        .map(|claim| {
            census_claim(b, case, claim)
                .printed("solution", Value::label("linear in a², b², c², unique unless the motion is special"))
                .computed("unique (rank 3) and exact", Value::count_of(c.truth_found.min(c.unique), c.trials))
                .computed("rank, rotations about the viewing axis", c.viewing_axis_rank)
                .computed("rank, rotations about one fixed generic axis", c.fixed_axis_rank)
                .tolerance(Tolerance::exact("numerical rank above the derived rounding floor of the entries"))
                .power(Power::mutant(c.viewing_axis_rank < 3, "the same rank test reports a rank below 3 for rotations about the viewing axis (the special motion)"))
                .method("p3f4 (frame differences, linear in a², b², c²) on seeded random scenes, plus rotations about the viewing axis and about one fixed generic axis")
                .detail("frames", c.frames)
                .detail("seed", c.seed)
                .detail("largest relative error", Value::below(c.max_truth_error))
                .detail("median condition number", c.median_condition)
                .verdict(Verdict::holds(ok))
        })
        .collect())
}
