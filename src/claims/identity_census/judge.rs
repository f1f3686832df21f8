//! Claims of §5.2 and §5.3 over seeded random scenes: the paper's four-point test, its
//! independence of the arbitrary c, the assignment ranking, five points. The census is
//! [`crate::studies::identity`]; here it is judged, with its controls (wrong assignments and a
//! point moved off the rigid body) as the power.

use crate::check::{ClaimResult, Power, ResultBuilder, Tolerance, ToleranceSource, Value, Verdict};
use crate::claims::identity_census::IdentityCensusCase;
use crate::error::Result;
use crate::studies::identity::{census, distance_level, IdentityCensus};

/// A line test holds when the true assignment stays within `level` while every control (the
/// best wrong assignment, the moved point) lies beyond it.
pub(super) fn judge_line(
    true_max: f64,
    wrong_min: f64,
    accepted_controls: usize,
    level: f64,
) -> Verdict {
    Verdict::holds(true_max <= level && wrong_min > level && accepted_controls == 0)
}

fn level_tolerance() -> Tolerance {
    Tolerance::bound(
        distance_level(),
        ToleranceSource::ErrorBound,
        "three depths √(e² − eᵢ²), each with the error √(64ε)·e, relative to the image size",
    )
}

pub(super) fn results(b: &ResultBuilder, case: &IdentityCensusCase) -> Result<Vec<ClaimResult>> {
    let c = census(case.trials, case.seed, &case.c_factors, case.control_shift);
    let level = distance_level();
    Ok(vec![
        line_result(b, case, &c, level),
        procedure_result(b, case, &c, level),
        tracing_result(b, case, &c, level),
        five_result(b, case, &c, level),
    ])
}

fn line_result(
    b: &ResultBuilder,
    case: &IdentityCensusCase,
    c: &IdentityCensus,
    level: f64,
) -> ClaimResult {
    b.claim(&case.line)
        .printed("scenes", Value::count(case.trials))
        .computed("largest distance of T₂ from its line, true assignment, every c (relative)", Value::below(c.true_max))
        .computed("smallest distance of the best wrong assignment", Value::real(c.wrong_min))
        .computed("scenes tested", Value::count(c.tested))
        .tolerance(level_tolerance())
        .power(Power::mutant(c.wrong_min > level && c.nonrigid_accepted == 0, "the best wrong assignment of every scene, and T₂ moved off the body by the control shift, are rejected by the same level"))
        .method("seeded random bodies of five points in two frames; the paper's test for P, Q, R, T at c = each factor × the smallest admissible c, both signs of b and of frame 2's depths, the smaller distance kept")
        .detail("controls accepted (moved T₂ on its line)", Value::count_of(c.nonrigid_accepted, c.tested))
        .detail("c factors", Value::reals(&case.c_factors))
        .detail("seed", Value::exact(case.seed))
        .verdict(judge_line(c.true_max, c.wrong_min, c.nonrigid_accepted, level))
}

fn procedure_result(
    b: &ResultBuilder,
    case: &IdentityCensusCase,
    c: &IdentityCensus,
    level: f64,
) -> ClaimResult {
    let first = c.paper_first == c.tested;
    b.claim(&case.procedure)
        .suffix("dependence-on-c")
        .printed("c chosen above its lower bounds, smaller distance over the two values of b", Value::count(case.c_factors.len()))
        .computed("largest distance of T₂ from its line, true assignment, every c", Value::below(c.true_max))
        .computed("wrong lines at larger c found again at the smallest c", Value::count_of(c.lines_found_again.0, c.lines_found_again.1))
        .computed("wrong assignments whose smallest distance changed with c", Value::count_of(c.min_changed.0, c.min_changed.1))
        .computed("true assignment first by the paper's distance", Value::count_of(c.paper_first, c.tested))
        .computed("… by the epipolar check", Value::count_of(c.epi_first, c.tested))
        .computed("both tests name the same first assignment", Value::count_of(c.same_first, c.tested))
        .tolerance(level_tolerance())
        .power(Power::mutant(c.wrong_min > level && c.nonrigid_accepted == 0, "wrong assignments and a point moved off the body are rejected at every c by the same level"))
        .method("the line does not depend on c: c only picks a member of the two-view family (two solutions, the two values of b); the line is fixed by the three points and the equal scale of the views")
        .detail("seed", Value::exact(case.seed))
        .verdict(Verdict::holds(judge_line(c.true_max, c.wrong_min, c.nonrigid_accepted, level) == Verdict::Reproduced && first))
}

fn tracing_result(
    b: &ResultBuilder,
    case: &IdentityCensusCase,
    c: &IdentityCensus,
    level: f64,
) -> ClaimResult {
    let median = c
        .runner_up
        .get(c.runner_up.len() / 2)
        .copied()
        .unwrap_or(0.0);
    let smallest = c.runner_up.first().copied().unwrap_or(0.0);
    b.claim(&case.tracing)
        .suffix("four-points")
        .printed("four points over two frames identify the points", Value::count(24))
        .computed("true correspondence first of 24 by the epipolar residual", Value::count_of(c.epi_first, c.tested))
        .computed("… by the paper's distance", Value::count_of(c.paper_first, c.tested))
        .computed("median residual of the runner-up", Value::real(median))
        .tolerance(Tolerance::exact("ranking"))
        .power(Power::mutant(smallest > level, "the runner-up (a wrong correspondence) has a residual above the rounding level in every scene"))
        .method("every ordered choice of four frame-2 points ranked by the equal-scale epipolar residual and by the paper's distance")
        .detail("smallest runner-up residual", Value::real(smallest))
        .verdict(Verdict::holds(c.epi_first == c.tested && c.paper_first == c.tested))
}

fn five_result(
    b: &ResultBuilder,
    case: &IdentityCensusCase,
    c: &IdentityCensus,
    level: f64,
) -> ClaimResult {
    b.claim(&case.five_points)
        .printed("assignments of five points", Value::count(120))
        .computed("largest distance of S₂ from S₂ₐS₂_b, true assignment", Value::below(c.five_true_max))
        .computed("true assignment first of 120", Value::count_of(c.five_first, c.tested))
        .computed("smallest distance of the best wrong assignment", Value::real(c.five_wrong_min))
        .tolerance(level_tolerance())
        .power(Power::mutant(c.five_wrong_min > level && c.five_nonrigid_accepted == 0, "wrong assignments and S₂ moved off the body by the control shift are rejected by the same level"))
        .method("affine coordinates of S₁ in (T₁; T₁P₁, T₁Q₁) and (R₁; R₁P₁, R₁Q₁) carried to frame 2: linear, no quadratic")
        .detail("controls accepted", Value::count_of(c.five_nonrigid_accepted, c.tested))
        .detail("seed", Value::exact(case.seed))
        .verdict(Verdict::holds(judge_line(c.five_true_max, c.five_wrong_min, c.five_nonrigid_accepted, level) == Verdict::Reproduced && c.five_first == c.tested))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_judge_both_sides() {
        let l = distance_level();
        assert_eq!(judge_line(l / 10.0, 0.1, 0, l), Verdict::Reproduced);
        assert_eq!(judge_line(l * 2.0, 0.1, 0, l), Verdict::Contradicted);
        assert_eq!(judge_line(l / 10.0, l / 2.0, 0, l), Verdict::Contradicted);
        assert_eq!(judge_line(l / 10.0, 0.1, 1, l), Verdict::Contradicted);
    }
}
