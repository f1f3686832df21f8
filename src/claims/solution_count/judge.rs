//! How many solutions, exactly: the paper's "at most two" (§2.2) and "at most a single
//! solution" (§4) against exact elimination over ℚ at seeded rational instances, and the
//! literature's 64:1 and 2:1 (Knill & Ramirez-Herran) against the same counts. Computation in
//! `study`; here the verdicts (rules in docs/verdicts.md).

use crate::cases::Printed;
use crate::check::ClaimBuilder;
use crate::check::{ClaimResult, Power, ResultBuilder, Tolerance, Value, Verdict};
use crate::claims::solution_count::study::{
    self as solution_count, LinesFirst, P3f3Count, P4f3Count,
};
use crate::claims::solution_count::LiteratureCount;
use crate::claims::solution_count::SolutionCountCase;
use crate::error::Result;

/// A printed whole number (the loader has checked it is one).
fn whole(p: &Printed) -> usize {
    p.to_integer()
        .and_then(|n| usize::try_from(n).ok())
        .unwrap_or(usize::MAX)
}

/// "At most `bound`" holds for the counts found.
fn at_most_holds(counts: &[usize], bound: usize) -> bool {
    counts.iter().all(|&c| c <= bound)
}

/// The single value every instance gave, or `None` when they differ (or there are none).
fn common(values: impl IntoIterator<Item = usize>) -> Option<usize> {
    let mut it = values.into_iter();
    let first = it.next()?;
    it.all(|v| v == first).then_some(first)
}

/// A literature ratio against the exact fibre count (the same at every instance):
/// reproduced when equal; otherwise not reproducible, not contradicted: what the publication
/// counts is known only from its abstract, so a different number may count something else.
fn ratio_verdict(printed: usize, computed: Option<usize>) -> Verdict {
    match computed {
        Some(c) if c == printed => Verdict::Reproduced,
        Some(_) => Verdict::NotReproducible,
        None => Verdict::Inconclusive,
    }
}

/// Run the case: the three-point and four-point counts, then the literature's ratios.
pub(super) fn results(b: &ResultBuilder, case: &SolutionCountCase) -> Result<Vec<ClaimResult>> {
    // three independent exact studies of the same seeds: at once
    let (n, seed) = (case.instances, case.seed);
    let ((three, four), lines) = rayon::join(
        || {
            rayon::join(
                || solution_count::p3f3_count(n, seed),
                || solution_count::p4f3_count(n, seed),
            )
        },
        || solution_count::lines_first_count(n, seed),
    );
    let mut out = vec![three_points(b, case, &three), four_points(b, case, &four)];
    out.extend(literature(b, case, (&three, &four), &lines));
    Ok(out)
}

fn three_points(b: &ResultBuilder, case: &SolutionCountCase, c: &P3f3Count) -> ClaimResult {
    let bound = whole(&case.three_points.at_most);
    let n = c.instances.len();
    let complex: Vec<usize> = c.instances.iter().map(|i| i.edge_complex).collect();
    let feasible: Vec<usize> = c.instances.iter().map(|i| i.edge_feasible).collect();
    let truth = c.instances.iter().filter(|i| i.truth_is_root).count();
    let ok = n == case.instances
        && truth == n
        && at_most_holds(&complex, bound)
        && at_most_holds(&feasible, bound);
    // the control: the same count rejects "at most one less" whenever it finds the bound
    let mutant_rejected = bound > 0 && !at_most_holds(&feasible, bound - 1);
    let two = feasible.iter().filter(|&&f| f == bound).count();
    let sm_real_consistent = c
        .instances
        .iter()
        .all(|i| i.sm_real == i.sm_complex / i.edge_complex.max(1) * i.edge_feasible);
    let per_edge = common(
        c.instances
            .iter()
            .map(|i| i.sm_up_to_reflection / i.edge_complex.max(1)),
    );
    b.claim(&case.three_points.claim)
        .printed("edge-length solutions", Value::label(case.three_points.words.clone()))
        .printed("at most", Value::printed(&case.three_points.at_most))
        .computed("complex edge-length solutions (square-free degree in c²)", distinct(&complex))
        .computed("largest number of real feasible ones", feasible.iter().copied().max().unwrap_or(0))
        .computed("instances with that many", Value::count_of(two, n))
        .computed("true squared edges a root", Value::count_of(truth, n))
        .computed_cell("two frames identical up to rotation", "zero-dimensional", Value::flag(c.identical_frames_edge_degree.is_some()))
        .tolerance(Tolerance::exact("exact elimination over ℚ, square-free degrees and Sturm counts"))
        .power(Power::mutant(mutant_rejected, "the same count rejects the narrower claim \"at most one\": it finds instances with two real feasible edge solutions"))
        .method("seeded rational scenes (rational body, Cayley rotations): F₁−F₃, F₂−F₃ solved for a², b² over ℚ, the quadratic in c²; then the polynomial in t = Σkᵢsᵢ over every depth-sign pattern (resultants with sᵢ² − wᵢ, then the norm over the quadratic's roots)")
        .detail("seed", case.seed)
        .detail("structure-and-motion solutions, complex (degree in t)", distinct(&c.instances.iter().map(|i| i.sm_complex).collect::<Vec<_>>()))
        .detail("up to the global reflection (degree in t²)", distinct(&c.instances.iter().map(|i| i.sm_up_to_reflection).collect::<Vec<_>>()))
        .detail("per edge solution, up to the reflection", per_edge.unwrap_or(0))
        .detail("real ones = per-edge count × feasible edge solutions (Sturm)", Value::flag(sm_real_consistent))
        .detail("even in t at every instance", Value::flag(c.instances.iter().all(|i| i.sm_even)))
        .verdict(Verdict::holds(ok && c.identical_frames_edge_degree.is_none()))
}

/// The count every instance gave, or the range of the counts when they differ.
fn distinct(values: &[usize]) -> Value {
    let (lo, hi) = values
        .iter()
        .fold((usize::MAX, 0), |(lo, hi), &v| (lo.min(v), hi.max(v)));
    match common(values.iter().copied()) {
        Some(v) => Value::count(v),
        None if values.is_empty() => Value::count(0),
        None => Value::interval(lo as f64, hi as f64),
    }
}

fn four_points(b: &ResultBuilder, case: &SolutionCountCase, c: &P4f3Count) -> ClaimResult {
    let bound = whole(&case.four_points.at_most);
    let n = c.instances.len();
    let full = c.instances.iter().filter(|i| i.edge_rank == 6).count();
    let truth = c.instances.iter().filter(|i| i.truth_is_solution).count();
    let planar_singular = c.planar.iter().all(|i| i.edge_rank < 6);
    // one edge solution where the system has full rank; the planar bodies (never named by
    // the paper) leave a line of solutions: the same count rejects them
    let ok = n == case.instances && full == n && truth == n && bound >= 1;
    let verdict = match (ok, planar_singular) {
        (true, true) => Verdict::HoldsGenerically,
        (true, false) => Verdict::Reproduced,
        (false, _) => Verdict::Contradicted,
    };
    b.claim(&case.four_points.claim)
        .printed("edge-length solutions", Value::label(case.four_points.words.clone()))
        .printed("at most", Value::printed(&case.four_points.at_most))
        .computed("instances with the 6×6 system of full rank (one solution)", Value::count_of(full, n))
        .computed("its solution the true squared edges", Value::count_of(truth, n))
        .computed("structure-and-motion solutions, complex", distinct(&c.instances.iter().map(|i| i.sm_complex).collect::<Vec<_>>()))
        .computed("real (Sturm)", distinct(&c.instances.iter().map(|i| i.sm_real).collect::<Vec<_>>()))
        .tolerance(Tolerance::exact("exact rank and solution over ℚ; square-free degree and Sturm count"))
        .power(Power::mutant(planar_singular, "the same count on planar bodies (T in the plane PQR) finds a singular system, a line of edge solutions"))
        .method("seeded rational scenes: the paper's system (frames 2, 3 × PQT, QRT, RPT) over ℚ; the depth-sign patterns of the three frames that a proper rotation realises (det Xᵢ = det X₁)")
        .detail("seed", case.seed)
        .detail("depth-sign patterns realised, of 2³", distinct(&c.instances.iter().map(|i| i.sm_patterns).collect::<Vec<_>>()))
        .cell("planar bodies", "ranks", distinct(&c.planar.iter().map(|i| i.edge_rank).collect::<Vec<_>>()))
        .cell("planar bodies", "depth-sign patterns realised", distinct(&c.planar.iter().map(|i| i.sm_patterns).collect::<Vec<_>>()))
        .detail("every frame's depths realise all six edges", Value::flag(c.instances.iter().all(|i| i.depths_consistent)))
        .verdict(verdict)
}

fn literature(
    b: &ResultBuilder,
    case: &SolutionCountCase,
    (three, four): (&P3f3Count, &P4f3Count),
    lines: &[LinesFirst],
) -> Vec<ClaimResult> {
    let lit = &case.literature;
    let fibre4 = common(four.instances.iter().map(|i| i.sm_complex));
    let planar4 = common(four.planar.iter().map(|i| i.sm_patterns));
    let printed4 = whole(&lit.four_points);
    let base = |suffix: &str| {
        b.claim(&lit.claim)
            .suffix(suffix)
            .printed("publication", Value::label(lit.publication.clone()))
            .tolerance(Tolerance::exact(
                "exact counts (square-free degrees over ℚ)",
            ))
            .detail("seed", case.seed)
    };
    let four_r = base("four-points")
        .printed("ratio for 3 cameras, 4 points", Value::printed(&lit.four_points))
        .computed("structure-and-motion solutions (rigid motions quotiented, the reflection counted)", fibre4.unwrap_or(0))
        .computed("edge-length solutions", 1usize)
        .power(Power::mutant(planar4.is_some_and(|p| p != printed4), "the same count on planar bodies gives another number (every depth-sign pattern is realised)"))
        .method("the four-point count of solution-count/p4f3: one edge solution × the depth-sign patterns realised by proper rotations")
        .cell("planar bodies", "depth-sign patterns realised", planar4.unwrap_or(0))
        .verdict(ratio_verdict(printed4, fibre4));
    let three_r = three_points_ratio(base("three-points"), lit, three, lines);
    vec![three_r, four_r]
}

/// Whether the lines-first construction checks out at every instance: its real choices'
/// edges solve the paper's system, the scene's own lines are among the choices, and each real
/// choice is a mirror pair of the reconstructions the Sturm count finds.
fn lines_verified(three: &P3f3Count, lines: &[LinesFirst]) -> bool {
    lines.len() == three.instances.len()
        && lines.iter().zip(&three.instances).all(|(l, i)| {
            l.seed == i.seed
                && l.edges_solve
                && l.truth_among
                && 2 * l.real_choices == i.sm_real
                && l.per_root.iter().filter(|&&n| n > 0).count() == i.edge_feasible
        })
}

/// Knill and Ramirez-Herran's 64 against the branches of the lines-first construction,
/// beside the reconstructions they come to.
fn three_points_ratio(
    c: ClaimBuilder,
    lit: &LiteratureCount,
    three: &P3f3Count,
    lines: &[LinesFirst],
) -> ClaimResult {
    let branches = common(lines.iter().map(|l| l.branches));
    let verified = lines_verified(three, lines);
    let both = three
        .instances
        .iter()
        .filter(|i| i.edge_feasible == 2)
        .count();
    let per_line = |f: fn(&LinesFirst) -> usize| distinct(&lines.iter().map(f).collect::<Vec<_>>());
    let per_root = common(
        lines
            .iter()
            .flat_map(|l| l.per_root.iter().copied().filter(|&n| n > 0)),
    );
    let verdict = match ratio_verdict(whole(&lit.three_points), branches) {
        Verdict::Reproduced if !verified => Verdict::Inconclusive,
        v => v,
    };
    c.printed("ratio for 3 cameras, 3 points", Value::printed(&lit.three_points))
        .computed("lines-first branches (a signed direction of each camera pair's intersection line)", branches.unwrap_or(0))
        .computed("real lines per camera pair", distinct(&lines.iter().flat_map(|l| l.lines.iter().map(|n| n.unwrap_or(0))).collect::<Vec<_>>()))
        .computed("choices of one line per pair", per_line(|l| l.choices))
        .computed("of them a real body (Gram matrix positive definite), up to the reflection", per_line(|l| l.real_choices))
        .computed("choices per feasible edge solution", per_root.unwrap_or(0))
        .computed("real reconstructions, the reflection counted (the Sturm count of solution-count/p3f3)", distinct(&three.instances.iter().map(|i| i.sm_real).collect::<Vec<_>>()))
        .computed("instances with both edge solutions feasible (16 reconstructions, 4 branches each)", Value::count_of(both, three.instances.len()))
        .computed("complex reconstructions, the reflection counted (the four-point ratio's convention)", common(three.instances.iter().map(|i| i.sm_complex)).unwrap_or(0))
        .detail("every real choice's squared edges solve the paper's system exactly", Value::flag(lines.iter().all(|l| l.edges_solve)))
        .detail("the scene's own lines among the choices", Value::count_of(lines.iter().filter(|l| l.truth_among).count(), lines.len()))
        .detail("2 × real choices = real reconstructions at every instance", Value::flag(verified))
        .undecided("the lines-first construction did not check out at every instance (the edges of its real choices, the scene's own lines among them, or two reconstructions per real choice)")
        .power(Power::exact_value("exact integer comparison of the branch count: it rejects 16 (the complex reconstructions, the count that reproduces the four-point ratio), 8 (the branches without the directions' signs) and every other number"))
        .method("Ullman's lines-first construction at the seeded rational scenes of solution-count/p3f3: per camera pair, the real null lines of vᵀ(NᵀN − I)v on the image circle (its discriminant exact over ℚ), two signed directions each; per choice of one line per pair, the Gram matrix G of the three lines and each squared edge sᵀG⁻¹s, exact in ℚ(√Δ₁₂, √Δ₁₃, √Δ₂₃). Each real choice is one reconstruction up to the reflection, and its 2³ sign patterns are the branches that reach its mirror pair")
        .verdict(verdict)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn at_most_holds_up_to_the_bound_only() {
        assert!(at_most_holds(&[1, 2, 0], 2));
        assert!(!at_most_holds(&[1, 2, 0], 1));
        assert!(at_most_holds(&[], 0));
    }

    #[test]
    fn a_ratio_is_reproduced_only_when_equal() {
        assert_eq!(ratio_verdict(2, Some(2)), Verdict::Reproduced);
        assert_eq!(ratio_verdict(64, Some(16)), Verdict::NotReproducible);
        assert_eq!(ratio_verdict(64, Some(65)), Verdict::NotReproducible);
        assert_eq!(ratio_verdict(2, None), Verdict::Inconclusive);
    }

    #[test]
    fn common_needs_one_value_everywhere() {
        assert_eq!(common([16, 16]), Some(16));
        assert_eq!(common([16, 8]), None);
        assert_eq!(common([]), None);
    }
}
