//! The debug printouts of §5.2's example judged number by number, the error lines, and the
//! two "correct" attempts.

use super::blocks::{judge_number, Block, NumberCheck};
use super::{
    printed_num, ClaimResult, Power, ResultBuilder, Tolerance, ToleranceSource, Value, Verdict,
};
use crate::cases::Printed;
use crate::claims::identity_example::author_program::{
    delta_at_bound, float_sign_at_bound, DeltaAtBound, Example,
};
use crate::claims::identity_example::{DebugAttempt, IdentityExampleCase};

fn printed_twelve(a: &DebugAttempt) -> [&Printed; 12] {
    [
        &a.b2, &a.pak[0], &a.pak[1], &a.pak[2], &a.pbk[0], &a.pbk[1], &a.pbk[2], &a.pa[0],
        &a.pa[1], &a.pb[0], &a.pb[1], &a.line[2],
    ]
}

/// Every printed number of every recomputed block judged against its recomputation:
/// (block index, quantity index, check).
fn block_checks(case: &IdentityExampleCase, blocks: &[Block]) -> Vec<(usize, usize, NumberCheck)> {
    let d = case.debug.significant_digits;
    let zero_half = 0.5 * 10f64.powi(1 - d as i32);
    let k = case.debug.mutant_half_units;
    let mut out = Vec::new();
    for (i, bl) in blocks.iter().enumerate() {
        let Some(r) = &bl.recomputed else { continue };
        for (q, p) in printed_twelve(bl.attempt).iter().enumerate() {
            let n = printed_num(p, d);
            let c = judge_number(
                n.value,
                n.half,
                r.values[q],
                r.bounds[q],
                r.float_bound,
                k,
                zero_half,
            );
            out.push((i, q, c));
        }
    }
    out
}

/// Per quantity: (agree, undetermined, mutants rejected, determined) and the widest width of
/// a determined number; a number is undetermined when it is at rounding level or its
/// acceptance is wider than the mutant (those go to `ex5-debug/undetermined`).
fn number_checks(
    case: &IdentityExampleCase,
    blocks: &[Block],
) -> (Vec<[usize; 4]>, Vec<f64>, usize) {
    let mut counts = vec![[0usize; 4]; 12];
    let mut widest = vec![0.0_f64; 12];
    let unmatched = blocks.iter().filter(|bl| bl.recomputed.is_none()).count();
    for (_, q, c) in block_checks(case, blocks) {
        counts[q][0] += usize::from(c.agree);
        if c.rounding_level || !c.mutant_rejected {
            counts[q][1] += 1;
        } else {
            counts[q][2] += 1;
            counts[q][3] += 1;
            widest[q] = widest[q].max(c.width);
        }
    }
    (counts, widest, unmatched)
}

/// The printed numbers: every block's, and the ones the rounding leaves undetermined.
pub(super) fn number_results(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    ex: &Example,
    frame1: &[usize; 4],
    blocks: &[Block],
) -> Vec<ClaimResult> {
    vec![
        debug_result(b, case, blocks),
        undetermined_result(b, case, ex, frame1, blocks),
    ]
}

/// The error lines and the sign of Δ_b behind them.
pub(super) fn error_results(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    ex: &Example,
    frame1: &[usize; 4],
    blocks: &[Block],
) -> Vec<ClaimResult> {
    let mut out = vec![errors_result(b, case, ex, frame1, blocks)];
    out.extend(deltab_results(b, case, ex, frame1, blocks));
    out
}

/// The debug numbers: reproduced within rounding when every number agrees and every mutant
/// of a number with determined digits is rejected.
pub(super) fn judge_debug(agree: usize, total: usize, unmatched: usize) -> Verdict {
    if agree == total && unmatched == 0 {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Contradicted
    }
}

fn debug_result(b: &ResultBuilder, case: &IdentityExampleCase, blocks: &[Block]) -> ClaimResult {
    let (counts, widest, unmatched) = number_checks(case, blocks);
    let total: usize = blocks.iter().filter(|x| x.recomputed.is_some()).count() * 12;
    let sum = |i: usize| counts.iter().map(|c| c[i]).sum::<usize>();
    let (agree, level, rejected, checked) = (sum(0), sum(1), sum(2), sum(3));
    let mut c = b
        .claim(&case.debug.claim)
        .printed("debug blocks", Value::count(case.debug.attempts.len()))
        .printed("numbers recomputed per block", Value::count(12))
        .computed("numbers reproduced", Value::count_of(agree, total))
        .computed("blocks without a unique assignment or a real b", Value::count(unmatched))
        .computed("numbers whose digits the rounded frames do not determine (see ex5-debug/undetermined)", Value::count(level))
        .tolerance(Tolerance::bound(0.0, ToleranceSource::Propagated, "per number: half a unit in the sixth significant digit (none for a printed 0) + the first-order effect of the frames' and d0's rounding + 64ε × the block's largest number"))
        .power(Power::mutant(checked > 0 && rejected == checked, "every number whose digits are determined, moved by the mutant's half units either way, is rejected by the same test"))
        .method("each block's assignment read off its printed T₂, Q₂, P₂ (unique); the paper's procedure at c = the printed d0 with the block's sign of b, the frame-2 depth sign whose Pb is nearer the printed one")
        .detail("mutants rejected", Value::count_of(rejected, checked));
    for (q, name) in case.debug.quantities.iter().enumerate() {
        c = c
            .cell(
                name,
                "reproduced",
                Value::count_of(counts[q][0], total / 12),
            )
            .cell(
                name,
                "widest acceptance (half units)",
                Value::real(widest[q]),
            );
    }
    c.verdict(judge_debug(agree, total, unmatched))
}

/// The assignments no block shows.
fn skipped(blocks: &[Block]) -> Vec<[usize; 4]> {
    let shown: Vec<[usize; 4]> = blocks.iter().filter_map(Block::assignment).collect();
    crate::algebra::permutations4()
        .into_iter()
        .filter(|a| !shown.contains(a))
        .collect()
}

/// Each printed ratio matched to the never-real assignments: Some(index) when exactly one
/// ratio agrees within half + bound.
pub(super) fn match_ratio(printed: f64, half: f64, candidates: &[(f64, f64)]) -> Option<usize> {
    let hits: Vec<usize> = (0..candidates.len())
        .filter(|&i| (candidates[i].0 - printed).abs() <= half + candidates[i].1)
        .collect();
    (hits.len() == 1).then(|| hits[0])
}

/// The error lines' ratios against the never-real assignments.
struct RatioChecks {
    all: Vec<DeltaAtBound>,
    skip: Vec<[usize; 4]>,
    /// (f_cb / f_b², its bound) of each never-real assignment, and the assignment.
    cand: Vec<(f64, f64, [usize; 4])>,
    /// Per printed ratio: its value, the assignment it matches, whether the mutant is
    /// rejected, and the acceptance width in half units.
    per: Vec<(f64, Option<usize>, bool, f64)>,
}

fn ratio_checks(
    case: &IdentityExampleCase,
    ex: &Example,
    frame1: &[usize; 4],
    blocks: &[Block],
) -> RatioChecks {
    let d = case.debug.significant_digits;
    let all = delta_at_bound(ex, frame1);
    let skip = skipped(blocks);
    // the bound: the frames' rounding propagated, plus 64ε of the ratio for its evaluation
    let cand: Vec<(f64, f64, [usize; 4])> = all
        .iter()
        .filter(|x| x.never_real)
        .map(|x| {
            let r = x.ratio.unwrap_or(f64::NAN);
            (
                r,
                x.ratio_bound + r.abs() * crate::algebra::NEGLIGIBLE_ULPS * f64::EPSILON,
                x.assignment,
            )
        })
        .collect();
    let pairs: Vec<(f64, f64)> = cand.iter().map(|c| (c.0, c.1)).collect();
    let k = case.debug.mutant_half_units;
    let per = case
        .debug
        .errors
        .iter()
        .flat_map(|e| e.ratios.iter())
        .map(|r| {
            let (v, h) = (r.to_f64(), printed_num(r, d).half);
            let m = match_ratio(v, h, &pairs);
            let rejected = match_ratio(v + k * h, h, &pairs).is_none()
                && match_ratio(v - k * h, h, &pairs).is_none();
            let width = m.map_or(f64::INFINITY, |i| (h + pairs[i].1) / h);
            (v, m, rejected, width)
        })
        .collect();
    RatioChecks {
        all,
        skip,
        cand,
        per,
    }
}

fn errors_result(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    ex: &Example,
    frame1: &[usize; 4],
    blocks: &[Block],
) -> ClaimResult {
    let r = ratio_checks(case, ex, frame1, blocks);
    let mut hit: Vec<usize> = r.per.iter().filter_map(|x| x.1).collect();
    hit.sort();
    hit.dedup();
    let determined: Vec<&(f64, Option<usize>, bool, f64)> = r.per.iter().filter(|x| x.2).collect();
    let never_skipped = r.cand.iter().all(|x| r.skip.contains(&x.2));
    let ok = r.per.iter().all(|x| x.1.is_some()) && hit.len() == r.cand.len() && never_skipped;
    let float_negative = r.all.iter().filter(|x| x.float_at_bound < 0.0).count();
    let kappa_negative: Vec<[usize; 4]> = r
        .all
        .iter()
        .filter(|x| x.kappa < 0.0)
        .map(|x| x.assignment)
        .collect();
    let never: Vec<[usize; 4]> = r
        .all
        .iter()
        .filter(|x| x.never_real)
        .map(|x| x.assignment)
        .collect();
    b.claim(&case.debug.claim)
        .suffix("errors")
        .printed("\"ERROR: Fdg_dg / Fdg_g2\" lines", Value::count(r.per.len()))
        .printed("ratios", Value::reals(&r.per.iter().map(|x| x.0).collect::<Vec<_>>()))
        .computed("assignments without a block", Value::count_of(r.skip.len(), r.all.len()))
        .computed("assignments with Δ_b < 0 for every c above its bound (exact over ℚ)", Value::count(r.cand.len()))
        .computed("all of them without a block", Value::flag(never_skipped))
        .computed("printed ratios equal to f_cb / f_b² of exactly one of them", Value::count_of(r.per.iter().filter(|x| x.1.is_some()).count(), r.per.len()))
        .computed("those assignments matched", Value::count_of(hit.len(), r.cand.len()))
        .computed_cell("the ratio printed", "f_cb / f_b² (Appendix A: coefficient of c²b² over that of b⁴)", Value::flag(ok))
        .computed_cell("Δ_b = κ (c² − c₁²)(c² − c₂²), κ = f_cb² − 4 f_b² f_c²", "zero at both frames' squared projections of RP (exact)", Value::count_of(r.all.iter().filter(|x| x.zero_at_both).count(), r.all.len()))
        .computed_cell("assignments with κ < 0", "exactly the never-real ones (so Δ_b < 0 for every c above the bound)", Value::flag(kappa_negative == never))
        .computed("κ of the never-real assignments", Value::reals(&r.all.iter().filter(|x| x.never_real).map(|x| x.kappa).collect::<Vec<_>>()))
        .tolerance(Tolerance::bound(0.0, ToleranceSource::Propagated, "half a unit in the sixth significant digit + the first-order effect of the frames' rounding on f_cb / f_b² + 64ε of it"))
        .power(Power::mutant(!determined.is_empty(), "every printed ratio whose digits the frames determine, moved by the mutant's half units either way, matches no assignment (the rest: ex5-debug/undetermined)"))
        .method("\"Fdg_dg / Fdg_g2\" read as f_cb / f_b² of the Appendix A quadratic; Δ_b evaluated exactly over ℚ at the printed frames: it is exactly 0 at the lower bound c² = the longest squared projection of RP for every assignment, so its floating-point sign there is noise; the sign just above the bound and the leading coefficient decide, exactly")
        .detail("mutants rejected", Value::count_of(determined.len(), r.per.len()))
        .detail("Δ_b = 0 exactly at the bound", Value::count_of(r.all.iter().filter(|x| x.zero_at_bound).count(), r.all.len()))
        .detail("a floating-point evaluation at the bound calls it negative (noise)", Value::count_of(float_negative, r.all.len()))
        .detail("never-real assignments' f_cb / f_b²", Value::reals(&r.cand.iter().map(|c| c.0).collect::<Vec<_>>()))
        .detail("never-real assignments", Value::label(format!("{:?}", r.cand.iter().map(|c| c.2).collect::<Vec<_>>())))
        .verdict(if ok { Verdict::ReproducedWithinRounding } else { Verdict::NotReproducible })
}

/// The printed numbers whose check cannot reject the mutant: at rounding level, or with an
/// acceptance wider than the mutant (ill-conditioned at the printed frames).
fn undetermined_result(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    ex: &Example,
    frame1: &[usize; 4],
    blocks: &[Block],
) -> ClaimResult {
    let (mut level, mut wide) = (Vec::new(), Vec::new());
    for (i, q, c) in block_checks(case, blocks) {
        if c.rounding_level {
            level.push(format!("block {} {}", i + 1, case.debug.quantities[q]));
        } else if !c.mutant_rejected {
            wide.push((
                format!("block {} {}", i + 1, case.debug.quantities[q]),
                c.width,
            ));
        }
    }
    let ratios = ratio_checks(case, ex, frame1, blocks);
    for (v, _, rejected, width) in &ratios.per {
        if !rejected {
            wide.push((format!("Fdg ratio {v}"), *width));
        }
    }
    b.claim(&case.debug.claim)
        .suffix("undetermined")
        .printed("numbers whose digits the rounded frames do not determine", Value::count(level.len() + wide.len()))
        .computed_cell("at rounding level (|printed| within the propagated bound", "zero to rounding, sign undetermined)", Value::label(level.join("; ")))
        .computed("agreeing only within a bound wider than the mutant", Value::label(wide.iter().map(|w| w.0.clone()).collect::<Vec<_>>().join("; ")))
        .computed("their acceptance half-widths (half units)", Value::reals(&wide.iter().map(|w| w.1).collect::<Vec<_>>()))
        .power(Power::none("the same test accepts these numbers moved by the mutant's half units: agreement says nothing about their digits"))
        .method("the debug numbers and error ratios whose propagated bound exceeds the mutant's half units (or their own magnitude); the rounding-level (Linie) numbers are explained to the unit in the last place by the program's arithmetic in ex5-debug/linie")
        .verdict(Verdict::Inconclusive)
}

/// The assignments the printout skips although b is real above the bound: by elimination,
/// those of the "Root of deltab negative" lines (each printed once per version).
fn judge_deltab(rest: usize, lines: usize, positive_above: usize) -> Verdict {
    Verdict::holds(rest > 0 && 2 * rest == lines && positive_above == rest)
}

fn deltab_results(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    ex: &Example,
    frame1: &[usize; 4],
    blocks: &[Block],
) -> Vec<ClaimResult> {
    let all = delta_at_bound(ex, frame1);
    let skip = skipped(blocks);
    let rest: Vec<&DeltaAtBound> = all
        .iter()
        .filter(|x| skip.contains(&x.assignment) && !x.never_real)
        .collect();
    let negative: usize = case.debug.errors.iter().map(|e| e.delta_b_negative).sum();
    let above = rest
        .iter()
        .filter(|x| x.sign_above > 0 && x.kappa > 0.0)
        .count();
    let between = rest.iter().filter(|x| x.sign_between < 0).count();
    let at_bound = rest.iter().filter(|x| x.zero_at_bound).count();
    let names = format!(
        "{:?}",
        rest.iter().map(|x| x.assignment).collect::<Vec<_>>()
    );
    let draws = case.debug.rounding_draws;
    let signs: Vec<(usize, usize)> = rest
        .iter()
        .map(|x| float_sign_at_bound(ex, frame1, &x.assignment, draws, case.seed))
        .collect();
    let which = b
        .claim(&case.debug.claim)
        .suffix("errors-deltab")
        .printed("\"ERROR: Root of deltab negative\" lines", Value::count(negative))
        .computed("assignments without a block and with κ > 0 (not Fdg ones)", Value::count(rest.len()))
        .computed("… each once per version", Value::count(2 * rest.len()))
        .computed_cell("of them", "Δ_b > 0 for every c above the bound (exact: κ > 0, positive just above)", Value::count_of(above, rest.len()))
        .tolerance(Tolerance::exact("counts and signs over ℚ"))
        .power(Power::exact_value("any other number of lines, or a skipped assignment with Δ_b < 0 above the bound, is rejected"))
        .method("by elimination: 24 assignments − those with a block − those with an Fdg line (κ < 0) leave these; Δ_b = κ (c² − c₁²)(c² − c₂²) exactly (ex5-debug/errors), so with κ > 0 it is negative only for c² strictly between the two frames' squared projections of RP, and zero at both")
        .detail("assignments", Value::label(names))
        .verdict(judge_deltab(rest.len(), negative, above));
    let negs: Vec<f64> = signs
        .iter()
        .map(|s| s.0 as f64 / draws.max(1) as f64)
        .collect();
    let zeros: Vec<f64> = signs
        .iter()
        .map(|s| s.1 as f64 / draws.max(1) as f64)
        .collect();
    let cause = b
        .claim(&case.debug.claim)
        .suffix("errors-deltab/cause")
        .printed("\"ERROR: Root of deltab negative\" lines", Value::count(negative))
        .computed_cell("hypothesis c² above the longest projection", "Δ_b < 0 there (exact)", Value::count_of(rest.len() - above, rest.len()))
        .computed_cell("hypothesis c² strictly between the two projections (below the text's minimum)", "Δ_b < 0 (exact)", Value::count_of(between, rest.len()))
        .computed_cell("hypothesis c² = the longest projection", "Δ_b = 0 exactly (a double root)", Value::count_of(at_bound, rest.len()))
        .computed("… its floating-point value at the printed frames", Value::reals(&rest.iter().map(|x| x.float_at_bound).collect::<Vec<_>>()))
        .computed("… fraction negative over draws inside the frames' rounding box", Value::reals(&negs))
        .computed("… fraction exactly zero", Value::reals(&zeros))
        .power(Power::none("not reproducible: the d the program used for these two assignments is not printed; c² between the projections and c² at the longest projection (negative by rounding) both give the message, c² above it cannot"))
        .method("Δ_b's sign over ℚ in each range of c², and in floating point at its double root over seeded draws of the frames within ±half a unit (standing in for the author's unrounded data)")
        .detail("draws", Value::count(draws))
        .detail("seed", Value::exact(case.seed))
        .verdict(Verdict::NotReproducible);
    vec![which, cause]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A floating-point error bound of the size the recomputation derives (≈ 450 ulps).
    const FLOAT: f64 = 450.0 * f64::EPSILON;

    #[test]
    fn number_judge_both_sides() {
        let c = judge_number(12.3456, 5e-5, 12.34561, 1e-6, FLOAT, 100.0, 5e-6);
        assert!(c.agree && !c.rounding_level && c.mutant_rejected);
        let far = judge_number(12.3456, 5e-5, 12.3461, 1e-6, FLOAT, 100.0, 5e-6);
        assert!(!far.agree);
        // a printed rounding-level number: agrees, but its digits are not determined
        let z = judge_number(2.3e-14, 5e-20, 3e-7, 1e-6, FLOAT, 100.0, 5e-6);
        assert!(z.agree && z.rounding_level);
        // a bound far wider than the mutant: the mutant is accepted
        let wide = judge_number(1.0, 5e-6, 1.0, 1e-2, 0.0, 100.0, 5e-6);
        assert!(wide.agree && !wide.mutant_rejected);
    }

    #[test]
    fn debug_and_ratio_judges_both_sides() {
        assert_eq!(judge_debug(384, 384, 0), Verdict::ReproducedWithinRounding);
        assert_eq!(judge_debug(383, 384, 0), Verdict::Contradicted);
        assert_eq!(judge_debug(384, 384, 1), Verdict::Contradicted);
        let cand = [(-2.46802, 1e-6), (-1.23456, 1e-6)];
        assert_eq!(match_ratio(-2.46802, 5e-6, &cand), Some(0));
        assert_eq!(match_ratio(-2.4685, 5e-6, &cand), None);
    }

    #[test]
    fn deltab_judge_both_sides() {
        assert_eq!(judge_deltab(2, 4, 2), Verdict::Reproduced);
        assert_eq!(judge_deltab(2, 3, 2), Verdict::Contradicted);
        assert_eq!(judge_deltab(2, 4, 1), Verdict::Contradicted);
        assert_eq!(judge_deltab(0, 0, 0), Verdict::Contradicted);
    }
}
