//! Every number of §5.2's debug printouts against the author's program as the printouts
//! pin it down (`studies::author_program::program`): the flags, the third coordinates of Pa
//! and Pb (unsigned depths), both sides of every `(Linie)` line, and what their difference
//! measures.

use super::blocks::{judge_number, Block, NumberCheck};
use super::{
    printed_num, ClaimResult, Power, ResultBuilder, Tolerance, ToleranceSource, Value, Verdict,
};
use crate::cases::Printed;
use crate::claims::identity_example::author_program::program::{
    Bounded, LINE_DIFF, LINE_L, LINE_R, P2_X, PA_Z, PB_Z, PRINTED,
};
use crate::claims::identity_example::{DebugAttempt, IdentityExampleCase};

/// Every number a block prints besides flags and version, in the program's print order.
fn printed_all(a: &DebugAttempt) -> [&Printed; PRINTED] {
    [
        &a.b2, &a.b, &a.d2, &a.d, &a.t1[0], &a.t1[1], &a.q1[0], &a.q1[1], &a.t2[0], &a.t2[1],
        &a.q2[0], &a.q2[1], &a.pak[0], &a.pak[1], &a.pak[2], &a.pbk[0], &a.pbk[1], &a.pbk[2],
        &a.pa[0], &a.pa[1], &a.pa[2], &a.pb[0], &a.pb[1], &a.pb[2], &a.p2[0], &a.p2[1], &a.p1[0],
        &a.p1[1], &a.line[0], &a.line[1], &a.line[2],
    ]
}

/// Each printed number of one block against the program: (quantity index, check).
fn checks(case: &IdentityExampleCase, a: &DebugAttempt, r: &Bounded) -> Vec<NumberCheck> {
    let d = case.debug.significant_digits;
    let zero_half = 0.5 * 10f64.powi(1 - d as i32);
    let k = case.debug.mutant_half_units;
    printed_all(a)
        .iter()
        .enumerate()
        .map(|(q, p)| {
            let n = printed_num(p, d);
            let (v, b) = (r.block.values[q], r.bounds[q]);
            judge_number(n.value, n.half, v, b, r.float_bound, k, zero_half)
        })
        .collect()
}

/// The program's numbers: reproduced within rounding when every printed number and flag
/// agrees, every block has a program run, and the mutant of every number whose digits the
/// rounded frames determine is rejected.
fn judge_program(agree: usize, total: usize, flags: usize, flag_total: usize) -> Verdict {
    if agree == total && flags == flag_total && total > 0 {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Contradicted
    }
}

pub(super) fn results(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    blocks: &[Block],
) -> Vec<ClaimResult> {
    vec![
        program_result(b, case, blocks),
        depths_result(b, case, blocks),
        linie_result(b, case, blocks),
    ]
}

fn program_result(b: &ResultBuilder, case: &IdentityExampleCase, blocks: &[Block]) -> ClaimResult {
    let mut per = vec![[0usize; 3]; PRINTED];
    let (mut flags, mut flag_total, mut stable, mut run) = (0, 0, 0, 0);
    let mut wide = Vec::new();
    for (i, bl) in blocks.iter().enumerate() {
        let Some(r) = &bl.program else { continue };
        run += 1;
        stable += usize::from(r.flags_stable);
        for (q, c) in checks(case, bl.attempt, r).iter().enumerate() {
            per[q][0] += usize::from(c.agree);
            if !c.rounding_level && c.mutant_rejected {
                per[q][1] += 1;
            } else if !c.rounding_level {
                wide.push(format!("block {} {}", i + 1, case.debug.printed_labels[q]));
            }
            per[q][2] += usize::from(!c.rounding_level);
        }
        flag_total += 4;
        flags += (0..4)
            .filter(|i| r.block.flags[*i] == bl.attempt.signs[*i])
            .count();
    }
    let total = run * PRINTED;
    let agree: usize = per.iter().map(|x| x[0]).sum();
    let rejected: usize = per.iter().map(|x| x[1]).sum();
    let determined: usize = per.iter().map(|x| x[2]).sum();
    let mut c = b
        .claim(&case.debug.claim)
        .suffix("program")
        .printed("debug blocks", Value::count(blocks.len()))
        .printed("numbers printed per block (besides flags and version)", Value::count(PRINTED))
        .computed("blocks the program runs at their printed d0 and version", Value::count_of(run, blocks.len()))
        .computed("printed numbers reproduced", Value::count_of(agree, total))
        .computed("printed flags reproduced (T1, Q1, T2, Q2)", Value::count_of(flags, flag_total))
        .computed("blocks whose flags are stable over the rounding box", Value::count_of(stable, run))
        .tolerance(Tolerance::bound(0.0, ToleranceSource::Propagated, "per number: half a unit in the sixth significant digit (none for a printed 0) + the first-order effect of the frames' and d0's rounding + 64ε × the block's largest number"))
        .power(Power::mutant(rejected > 0, "the printed numbers above rounding level, each moved by the mutant's half units either way, are rejected by the same test, except those whose propagated bound is wider than the mutant (listed)"))
        .method("the program's conventions as the printouts pin them (Appendix A root with the sign `version`; T's depth positive and Q's flag closing the triangle in both frames; Pa, Pb mapped through E₁, E₂, E₁ × E₂ with signed depths, their printed z through the unsigned ones; (Linie) L = (P2.y − Pa.y)(P2.x − Pb.x), R = (P2.x − Pa.x)(P2.y − Pb.y)), run at each block's printed d0")
        .detail("mutants rejected (numbers above rounding level)", Value::count_of(rejected, determined))
        .detail("numbers whose bound is wider than the mutant", Value::label(wide.join("; ")));
    for (q, name) in case.debug.printed_labels.iter().enumerate() {
        c = c.cell(name, "reproduced", Value::count_of(per[q][0], run));
    }
    c.verdict(judge_program(agree, total, flags, flag_total))
}

/// Pa.z and Pb.z under the program's rule (unsigned depths) and the alternative (signed).
fn depth_counts(case: &IdentityExampleCase, blocks: &[Block]) -> (usize, usize, usize, f64) {
    let d = case.debug.significant_digits;
    let (mut unsigned, mut signed, mut n, mut miss) = (0, 0, 0, 0.0_f64);
    for bl in blocks {
        let Some(r) = &bl.program else { continue };
        for (k, (q, p)) in [(PA_Z, &bl.attempt.pa[2]), (PB_Z, &bl.attempt.pb[2])]
            .into_iter()
            .enumerate()
        {
            let x = printed_num(p, d);
            n += 1;
            let tol_u = r.bounds[q] + x.half + r.float_bound;
            unsigned += usize::from((x.value - r.block.values[q]).abs() <= tol_u);
            let tol_s = r.z_signed_bounds[k] + x.half + r.float_bound;
            let off = (x.value - r.block.z_signed[k]).abs();
            if off <= tol_s {
                signed += 1;
            } else {
                miss = miss.max(off / tol_s);
            }
        }
    }
    (unsigned, signed, n, miss)
}

/// Both sides of every (Linie) line: (agree, blocks).
fn side_counts(case: &IdentityExampleCase, blocks: &[Block]) -> ([usize; 2], usize) {
    let mut agree = [0; 2];
    let mut n = 0;
    for bl in blocks {
        let Some(r) = &bl.program else { continue };
        let c = checks(case, bl.attempt, r);
        n += 1;
        agree[0] += usize::from(c[LINE_L].agree);
        agree[1] += usize::from(c[LINE_R].agree);
    }
    (agree, n)
}

/// Third coordinates: reproduced within rounding when the unsigned-depth rule reproduces
/// every one and both sides of every (Linie) line agree.
fn judge_depths(unsigned: usize, n: usize, sides: [usize; 2], blocks: usize) -> Verdict {
    if unsigned == n && n > 0 && sides == [blocks, blocks] {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Contradicted
    }
}

fn depths_result(b: &ResultBuilder, case: &IdentityExampleCase, blocks: &[Block]) -> ClaimResult {
    let (unsigned, signed, n, miss) = depth_counts(case, blocks);
    let (sides, m) = side_counts(case, blocks);
    b.claim(&case.debug.claim)
        .suffix("depths-and-line-split")
        .printed("third coordinates of Pa and Pb", Value::count(n))
        .printed("(Linie) lines, each with two sides", Value::count(m))
        .computed_cell("rule", "z = α|z_T₂| + β|z_Q₂| + γ (T₂ × Q₂), the unsigned depths: reproduced", Value::count_of(unsigned, n))
        .computed_cell("alternative", "the signed depths (the frame-2 point's true depth): reproduced", Value::count_of(signed, n))
        .computed_cell("alternative", "largest miss (tolerances)", Value::real(miss))
        .computed_cell("(Linie) left side L = (P2.y − Pa.y)(P2.x − Pb.x)", "reproduced", Value::count_of(sides[0], m))
        .computed_cell("(Linie) right side R = (P2.x − Pa.x)(P2.y − Pb.y)", "reproduced", Value::count_of(sides[1], m))
        .tolerance(Tolerance::bound(0.0, ToleranceSource::Propagated, "half a unit in the sixth significant digit + the first-order effect of the frames' and d0's rounding + 64ε × the block's largest number"))
        .power(Power::mutant(signed < n, "the signed-depth convention, through the same test, is rejected (it differs only where Q₂'s flag is −1)"))
        .method("the program run at each block's printed d0 and version; its xy map uses the signed depths, its printed z the magnitudes (the flag is applied in the cross product only)")
        .verdict(judge_depths(unsigned, n, sides, m))
}

/// A printed zero of L: the sign of the zero is the sign of the other factor P2.x − Pb.x
/// (IEEE: +0 × x has the sign of x), the first factor P2.y − Pa.y zero within its bound.
fn zero_sign_ok(printed: &Printed, r: &Bounded) -> bool {
    let negative = printed.text.trim_start().starts_with('-');
    let zero_first = r.block.factors[0].abs() <= r.factor_bounds[0] + r.float_bound;
    zero_first && negative == (r.block.factors[1] < 0.0)
}

/// A rounding-level R printed as `printed` (half-unit `half`) with second factor `y` (bound
/// `yb`): P2.x − Pa.x = −R / y must be a nonzero whole number of units in the last place of
/// P2.x (`ulp`), within the relative uncertainty of both. Returns (k, whole).
pub(super) fn ulps_of(printed: f64, half: f64, y: f64, yb: f64, ulp: f64) -> (f64, bool) {
    let k = -printed / y / ulp;
    let dk = k.abs() * (half / printed.abs() + yb / y.abs());
    (k, k.round() != 0.0 && (k - k.round()).abs() <= dk)
}

/// The unit in the last place of a double of magnitude |x|.
fn ulp(x: f64) -> f64 {
    2f64.powi(x.abs().log2().floor() as i32 - 52)
}

/// The (Linie) numbers at rounding level: zeros of L with their signs, R as whole ulps.
struct Level {
    zeros: (usize, usize),
    ulps: Vec<f64>,
    whole: usize,
    mutants_rejected: usize,
}

fn rounding_level(case: &IdentityExampleCase, blocks: &[Block]) -> Level {
    let d = case.debug.significant_digits;
    let mut out = Level {
        zeros: (0, 0),
        ulps: Vec::new(),
        whole: 0,
        mutants_rejected: 0,
    };
    for bl in blocks {
        let Some(r) = &bl.program else { continue };
        let l = &bl.attempt.line[0];
        if num_traits::Zero::is_zero(&l.value) {
            out.zeros.1 += 1;
            out.zeros.0 += usize::from(zero_sign_ok(l, r));
        }
        let rr = printed_num(&bl.attempt.line[1], d);
        let c = checks(case, bl.attempt, r);
        if !c[LINE_R].rounding_level {
            continue;
        }
        let (y, yb) = (r.block.factors[3], r.factor_bounds[3]);
        let u = ulp(r.block.values[P2_X]);
        let (k, whole) = ulps_of(rr.value, rr.half, y, yb, u);
        out.ulps.push(k);
        out.whole += usize::from(whole);
        let m = case.debug.mutant_half_units * rr.half;
        let moved = |s: f64| ulps_of(rr.value + s * m, rr.half, y, yb, u).1;
        out.mutants_rejected += usize::from(!moved(1.0) && !moved(-1.0));
    }
    out
}

/// What the difference measures, per block: |diff| = distance × |Pb − Pa| (the cross
/// product of Pa − P2 and Pb − P2), and whether the printed diff would pass as the distance.
fn measures(case: &IdentityExampleCase, blocks: &[Block]) -> (usize, usize, Vec<f64>, usize) {
    let d = case.debug.significant_digits;
    let (mut identity, mut as_distance, mut n) = (0, 0, 0);
    let mut segments = Vec::new();
    for bl in blocks {
        let Some(r) = &bl.program else { continue };
        n += 1;
        let v = &r.block;
        let product = v.distance * v.segment;
        identity += usize::from((v.values[LINE_DIFF].abs() - product).abs() <= r.float_bound);
        segments.push(v.segment);
        let p = printed_num(&bl.attempt.line[2], d);
        let tol = r.bounds[LINE_DIFF] / v.segment.max(f64::MIN_POSITIVE) + p.half + r.float_bound;
        as_distance += usize::from((p.value.abs() - v.distance).abs() <= tol);
    }
    (identity, as_distance, segments, n)
}

fn linie_result(b: &ResultBuilder, case: &IdentityExampleCase, blocks: &[Block]) -> ClaimResult {
    let lv = rounding_level(case, blocks);
    let (identity, as_distance, segments, n) = measures(case, blocks);
    let (lo, hi) = segments
        .iter()
        .fold((f64::INFINITY, 0.0_f64), |(l, h), s| (l.min(*s), h.max(*s)));
    let ok = identity == n && lv.zeros.0 == lv.zeros.1 && lv.whole == lv.ulps.len();
    b.claim(&case.debug.claim)
        .suffix("linie")
        .printed("(Linie) lines", Value::count(n))
        .printed("left sides printed as a signed zero", Value::count(lv.zeros.1))
        .printed("right sides at rounding level", Value::count(lv.ulps.len()))
        .computed("printed zeros whose sign is that of P2.x − Pb.x, with P2.y − Pa.y zero within its bound", Value::count_of(lv.zeros.0, lv.zeros.1))
        .computed_cell("rounding-level R", "P2.x − Pa.x = −R / (P2.y − Pb.y) in units of the last place of P2.x", Value::reals(&lv.ulps))
        .computed("… a nonzero whole number of units", Value::count_of(lv.whole, lv.ulps.len()))
        .computed("|diff| = (distance of P2 from the line Pa Pb) × |Pb − Pa| (twice the signed area of P2, Pa, Pb)", Value::count_of(identity, n))
        .computed("|Pb − Pa| over the blocks", Value::interval(lo, hi))
        .computed("diff is the distance the text minimises", Value::flag(false))
        .computed("blocks where the printed diff would pass as that distance", Value::count_of(as_distance, n))
        .tolerance(Tolerance::bound(0.0, ToleranceSource::ErrorBound, "the identity within 64ε × the block's largest number; the whole units within the printed R's half unit and the propagated bound of P2.y − Pb.y"))
        .power(Power::mutant(lv.mutants_rejected == lv.ulps.len() && as_distance < n, "each rounding-level R moved by the mutant's half units is no whole number of units; the distance itself in place of diff is rejected in the blocks off rounding level"))
        .method("diff = L − R = (Pb − P2) × (Pa − P2): its magnitude is the distance of P2 from the line times |Pb − Pa|, which varies from block to block, so diff ranks assignments differently from the distance the text says is minimised")
        .verdict(if ok { Verdict::ReproducedWithinRounding } else { Verdict::Contradicted })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn program_and_depth_judges_both_sides() {
        assert_eq!(
            judge_program(10, 10, 4, 4),
            Verdict::ReproducedWithinRounding
        );
        assert_eq!(judge_program(9, 10, 4, 4), Verdict::Contradicted);
        assert_eq!(judge_program(10, 10, 3, 4), Verdict::Contradicted);
        assert_eq!(
            judge_depths(8, 8, [4, 4], 4),
            Verdict::ReproducedWithinRounding
        );
        assert_eq!(judge_depths(7, 8, [4, 4], 4), Verdict::Contradicted);
        assert_eq!(judge_depths(8, 8, [3, 4], 4), Verdict::Contradicted);
    }

    #[test]
    fn whole_units_both_sides() {
        // 3 units of 2⁻⁵⁰ times a factor 10: R = −3·2⁻⁵⁰·10
        let u = 2f64.powi(-50);
        let r = -3.0 * u * 10.0;
        assert!(ulps_of(r, r.abs() * 1e-6, 10.0, 1e-5, u).1);
        assert!(!ulps_of(r * 1.2, r.abs() * 1e-6, 10.0, 1e-5, u).1);
        assert!(!ulps_of(r * 0.1, r.abs() * 1e-6, 10.0, 1e-5, u).1);
    }
}
