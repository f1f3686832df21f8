//! "The first two attempts are the correct ones, differing only by the sign in the formula
//! for calculating b" (§5.2): in the example, in seeded scenes under the program's own depth
//! conventions, and its cause.

use super::blocks::Block;
use super::{ClaimResult, Power, ResultBuilder, Tolerance, ToleranceSource, Value, Verdict};
use crate::claims::identity_example::author_program::convention::{census, ConventionCensus};
use crate::claims::identity_example::author_program::Example;
use crate::claims::identity_example::ranking::{rank_example, ExampleRanking};
use crate::claims::identity_example::IdentityExampleCase;
use crate::studies::identity::distance_level;

pub(super) fn results(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    ex: &Example,
    truth: &[usize; 4],
    blocks: &[Block],
) -> Vec<ClaimResult> {
    let r = rank_example(ex, truth, case.census_c_factor);
    let factors = [case.census_c_factor];
    let generic = census(case.census_trials, case.seed, &factors, false);
    let planar = census(case.census_trials, case.seed, &factors, true);
    let cause = cause_result(b, case, truth, blocks, &generic, &planar);
    let planar_body = planar_result(b, case, cause.verdict, &generic, &planar);
    vec![
        first_result(b, case, truth, blocks, &r, &generic),
        ranking_result(b, case, truth, &r),
        generic_result(b, case, &generic, &planar),
        cause,
        planar_body,
    ]
}

fn tolerance(r: &ExampleRanking) -> Tolerance {
    Tolerance::bound(
        r.true_bound,
        ToleranceSource::Propagated,
        "first-order effect of the frames' rounding on the distance, plus 3√(64ε) × the image size",
    )
}

/// The best wrong assignment's distance; `None` when no wrong assignment has a line, so
/// none can pass the distance test.
fn runner_up(r: &ExampleRanking, truth: &[usize; 4]) -> Option<f64> {
    r.by_paper
        .iter()
        .filter(|x| x.0 != *truth)
        .find_map(|x| x.1)
}

/// Is the best wrong assignment rejected by the true assignment's bound?
fn rejected(runner: Option<f64>, bound: f64) -> bool {
    runner.is_none_or(|d| d > bound)
}

/// The runner-up as a detail: its distance, or that no wrong assignment has a line.
fn runner_value(runner: Option<f64>) -> Value {
    runner.map_or_else(
        || Value::label("no wrong assignment has a real line"),
        Value::real,
    )
}

fn first_result(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    truth: &[usize; 4],
    blocks: &[Block],
    r: &ExampleRanking,
    generic: &ConventionCensus,
) -> ClaimResult {
    let first_two = blocks.len() >= 2
        && blocks[0].assignment() == Some(*truth)
        && blocks[1].assignment() == Some(*truth)
        && blocks[0].attempt.version != blocks[1].attempt.version;
    let on_line =
        !r.true_distances.is_empty() && r.true_distances.iter().all(|d| *d <= r.true_bound);
    let runner = runner_up(r, truth);
    b.claim(&case.correct)
        .printed("attempts called correct", Value::count(2))
        .computed_cell("first two blocks", "the true assignment, opposite signs of b", Value::flag(first_two))
        .computed("distances of T₂ from its line, true assignment", Value::reals(&r.true_distances))
        .computed("generic scenes where both signs of b pass under the program's conventions (see identity-procedure/two-values-of-b)", Value::count_of(generic.both, generic.scenes))
        .tolerance(tolerance(r))
        .power(Power::mutant(rejected(runner, r.true_bound), "the best wrong assignment, through the same distance test, is rejected"))
        .method("the procedure at c = census_c_factor × the smallest admissible c for the true assignment, both signs of b; true of the example, which owes it to its planar body (ex5-correct/cause, ex5-correct/planar-body): in generic scenes exactly one sign passes (identity-procedure/two-values-of-b)")
        .detail("best wrong assignment's distance", runner_value(runner))
        .verdict(Verdict::holds(first_two && on_line))
}

fn ranking_result(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    truth: &[usize; 4],
    r: &ExampleRanking,
) -> ClaimResult {
    let runner = runner_up(r, truth);
    let within: Vec<[usize; 4]> = r
        .by_paper
        .iter()
        .filter(|x| x.1.is_some_and(|d| d <= r.true_bound))
        .map(|x| x.0)
        .collect();
    let epi_first = r.by_epipolar.first().map(|x| x.0);
    let distances: Vec<f64> = r.by_paper.iter().filter_map(|x| x.1).collect();
    let no_line = r.by_paper.len() - distances.len();
    b.claim(&case.correct)
        .suffix("ranking")
        .printed("the assignment that puts T₂ on its line", Value::label(format!("{truth:?}")))
        .computed("assignments within the bound by the paper's distance", Value::label(format!("{within:?}")))
        .computed("first by the equal-scale epipolar residual", Value::label(format!("{:?}", epi_first.unwrap_or([0; 4]))))
        .tolerance(tolerance(r))
        .power(Power::mutant(rejected(runner, r.true_bound), "every wrong assignment is rejected by the same bound"))
        .method("every assignment of frame 2 (re-centred at its R) through the paper's procedure at census_c_factor × its smallest admissible c, and through the affine epipolar constraint with the coordinates' rounding (the body is planar: equal scale is met inside a two-dimensional null space)")
        .detail("by the paper's distance", Value::reals(&distances))
        .cell("assignments with no real line (no admissible c", "the paper's distance does not exist)", Value::count_of(no_line, r.by_paper.len()))
        .detail("by the epipolar residual", Value::reals(&r.by_epipolar.iter().map(|x| x.1).collect::<Vec<_>>()))
        .verdict(if within == [*truth] && epi_first == Some(*truth) { Verdict::Reproduced } else { Verdict::Contradicted })
}

/// A property of the method over seeded scenes (docs/verdicts.md, §5.2): the proportion of
/// scenes that show it, against 1/2 with two binomial standard errors 2√(¼ / n): above →
/// holds, below → fails, within → inconclusive.
pub(super) fn judge_share(shown: usize, n: usize) -> Verdict {
    if n == 0 {
        return Verdict::Inconclusive;
    }
    let p = shown as f64 / n as f64;
    let band = 2.0 * (0.25 / n as f64).sqrt();
    if p > 0.5 + band {
        Verdict::StatisticalHolds
    } else if p < 0.5 - band {
        Verdict::StatisticalFails
    } else {
        Verdict::Inconclusive
    }
}

/// "b can in fact take one of two distinct values … the lower value of the distance … shall be
/// taken": read from its words, the two values give two distances of which the lower is the
/// body's (the sentence presupposes they differ); judged over seeded scenes as the share where
/// exactly one version passes. That both pass, the example's situation, is shown beside it.
fn generic_result(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    g: &ConventionCensus,
    p: &ConventionCensus,
) -> ClaimResult {
    let control = judge_share(p.exactly_one, p.scenes);
    b.claim(&case.two_values_of_b)
        .suffix("two-values-of-b")
        .printed("two values of b, the lower distance taken", Value::flag(true))
        .computed_cell("generic scenes", "exactly one version puts P₂ on its line", Value::count_of(g.exactly_one, g.scenes))
        .computed("… both versions", Value::count_of(g.both, g.scenes))
        .computed("… neither", Value::count_of(g.neither, g.scenes))
        .computed("the passing version is the true root of b² when T's depth has the same sign in both frames, the other root otherwise", Value::count_of(g.predicted, g.exactly_one))
        .computed("the outcome is the same at every d tried", Value::count_of(g.c_independent, g.scenes))
        .computed_cell("planar scenes (P in the plane RTQ)", "exactly one version passes", Value::count_of(p.exactly_one, p.scenes))
        .computed_cell("the reading that also tries both frame-2 mirror images", "both signs pass in generic scenes", Value::count_of(g.mirrors_both, g.scenes))
        .detail("reading", Value::label("\"the lower value of the distance … shall be taken\" presupposes that the two values of b give different distances, one of them the body's: judged as the share of scenes where exactly one version passes; that both pass (the example's situation, ex5-correct) is what the sentence rules out, shown as \"both versions\""))
        .tolerance(Tolerance::bound(distance_level(), ToleranceSource::ErrorBound, "a version passes when the distance of P₂ from its line is within 3√(64ε) of the image size"))
        .power(Power::mutant(control != Verdict::StatisticalHolds, "the same judge on the planar scenes (where both versions pass) does not say the claim holds"))
        .method("seeded random bodies of four points in two frames (program order P, Q, R, T), the program's conventions (T's depth positive in both frames, Q's flag closing the triangle, one frame-2 orientation), d at its true value and at census_c_factor × the smallest admissible d; rule: docs/verdicts.md (§5.2). A sign of b and a frame-2 mirror trade places: with both mirrors allowed both signs pass")
        .detail("seed", Value::exact(case.seed))
        .detail("verdict of the same judge on the planar scenes", Value::label(control.name()))
        .verdict(judge_share(g.exactly_one, g.scenes))
}

/// The example owes its two passing versions to its body: P₁ = α T₁ + β Q₁ with P in the
/// plane R, T, Q puts Pa on P₂ whatever d and b.
fn cause_result(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    truth: &[usize; 4],
    blocks: &[Block],
    g: &ConventionCensus,
    p: &ConventionCensus,
) -> ClaimResult {
    let true_blocks: Vec<_> = blocks
        .iter()
        .filter(|bl| bl.assignment() == Some(*truth))
        .filter_map(|bl| bl.program.as_ref())
        .collect();
    let on = true_blocks
        .iter()
        .filter(|r| r.block.pa_off <= r.pa_off_bound + r.float_bound)
        .count();
    let offs: Vec<f64> = true_blocks.iter().map(|r| r.block.pa_off).collect();
    let level = distance_level();
    let rejected = g.pa_off_min > level && p.pa_off_max <= level;
    b.claim(&case.correct)
        .suffix("cause")
        .printed("attempts called correct", Value::count(2))
        .computed("true-assignment blocks with Pa.xy = P2 within the propagated bound (both versions)", Value::count_of(on, true_blocks.len()))
        .computed("|Pa.xy − P2| in those blocks", Value::reals(&offs))
        .computed_cell("generic scenes", "smallest |Pa.xy − P₂| / image size", Value::real(g.pa_off_min))
        .computed_cell("planar scenes", "largest |Pa.xy − P₂| / image size", Value::real(p.pa_off_max))
        .tolerance(Tolerance::bound(0.0, ToleranceSource::Propagated, "the first-order effect of the frames' and d0's rounding on |Pa.xy − P2| + 64ε × the block's largest number"))
        .power(Power::mutant(rejected, "the same test in the generic scenes finds Pa off P₂ in every one (and on it in every planar one)"))
        .method("the tested point lies in the plane of R, T, Q (the hidden table's Gram matrix has exact rank 2, ex5-hidden-table): then T_a is the tested point itself, its image is P₂ for either sign of b and any d, and the line through it passes P₂ trivially; this, not the method, makes both attempts correct")
        .verdict(if on == true_blocks.len() && on > 0 { Verdict::ReproducedWithinRounding } else { Verdict::Contradicted })
}

/// The example's body is planar, so both signs of b pass there whatever d: the example cannot
/// show what the test tells apart. An erratum of the example when its true-assignment blocks
/// put Pa on P₂ (the cause), every planar scene passes both versions and generic scenes
/// almost never do.
fn planar_result(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    cause: Verdict,
    g: &ConventionCensus,
    p: &ConventionCensus,
) -> ClaimResult {
    let planar_both = judge_share(p.both, p.scenes) == Verdict::StatisticalHolds;
    let generic_one = judge_share(g.exactly_one, g.scenes) == Verdict::StatisticalHolds;
    let shown = cause == Verdict::ReproducedWithinRounding && planar_both && generic_one;
    b.claim(&case.correct)
        .suffix("planar-body")
        .printed("attempts called correct", Value::count(2))
        .computed("the example's body is planar and both versions pass there (ex5-correct/cause)", Value::flag(cause == Verdict::ReproducedWithinRounding))
        .computed_cell("planar scenes", "both versions pass", Value::count_of(p.both, p.scenes))
        .computed_cell("generic scenes", "exactly one version passes", Value::count_of(g.exactly_one, g.scenes))
        .detail_as("defect", Value::label("the example's body is planar (P lies in the plane of R, T, Q: the hidden table's Gram matrix has rank 2), so both signs of b put the tested point on its line whatever d: the example presents as the procedure's behaviour what only a planar body does, and cannot show what the test tells apart; in generic bodies exactly one version passes"), crate::check::Role::Defect)
        .correction("an example with a body that is not planar, in which exactly one of the two attempts (one sign of b) passes the test")
        .tolerance(Tolerance::exact("counts of scenes against 1/2 ± two binomial standard errors"))
        .power(Power::mutant(judge_share(g.both, g.scenes) != Verdict::StatisticalHolds, "the same judge of 'both versions pass' over generic scenes does not hold: the census tells planar from generic bodies"))
        .method("ex5-correct/cause (the example's blocks) with the census of planar and generic scenes of identity-procedure/two-values-of-b")
        .verdict(if shown { Verdict::Erratum } else { Verdict::Inconclusive })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_share_judge_on_both_sides() {
        assert_eq!(judge_share(200, 200), Verdict::StatisticalHolds);
        assert_eq!(judge_share(0, 200), Verdict::StatisticalFails);
        assert_eq!(judge_share(100, 200), Verdict::Inconclusive);
        // the band at n = 100 is ±0.1
        assert_eq!(judge_share(61, 100), Verdict::StatisticalHolds);
        assert_eq!(judge_share(59, 100), Verdict::Inconclusive);
        assert_eq!(judge_share(0, 0), Verdict::Inconclusive);
    }
}
