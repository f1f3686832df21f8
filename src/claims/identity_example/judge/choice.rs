//! The program's choice of d (the paper's "a priori selected value for c") in each block:
//! the rules tried, each with how far it misses, and why no rule can change a verdict.

use nalgebra::Vector2;

use super::blocks::Block;
use super::{printed_num, ClaimResult, Power, ResultBuilder, Value, Verdict};
use crate::claims::identity_example::author_program::choice_d::{
    distance_spread, fit_rules, PrintedD, Rule,
};
use crate::claims::identity_example::author_program::program::LINE_DIFF;
use crate::claims::identity_example::author_program::Example;
use crate::claims::identity_example::IdentityExampleCase;

/// The rule's name in the report.
fn rule_name(r: Rule) -> &'static str {
    match r {
        Rule::Longest => "d² = longest squared projection of RT",
        Rule::LongestPlusOne => "d² = longest + 1",
        Rule::LongestPlusTenth => "d = longest projection + 0.1",
        Rule::TenPercentLonger => "d = 1.1 × longest projection",
        Rule::TwiceLongestMinusShorter => "d² = 2 × longest − shorter",
        Rule::LongestPlusShorter => "d² = longest + shorter",
        Rule::PlusLongestB => "d² = longest + longest squared projection of QR",
        Rule::PlusLongestG => "d² = longest + longest squared projection of TQ",
        Rule::PlusLongestBAndG => "d² = longest + both",
        Rule::RatioFbFcb => "d² = −f_b / f_cb",
        Rule::VertexFc => "d² = −f_c / (2 f_c²)",
        Rule::AsymptoteSmall => "d² = longest squared QR / smaller slope of b²/d²",
        Rule::AsymptoteLarge => "d² = longest squared QR / larger slope of b²/d²",
        Rule::SmallestAdmissible => "d = smallest admissible value",
        Rule::MinimumBMinus => "d² at the smallest b² of the − root",
        Rule::MinimumBPlus => "d² at the smallest b² of the + root",
        Rule::MinimumGMinus => "d² at the smallest g² of the − root",
        Rule::MinimumGPlus => "d² at the smallest g² of the + root",
    }
}

fn frame(f: &[Vector2<f64>; 4], order: &[usize; 4]) -> [Vector2<f64>; 4] {
    std::array::from_fn(|j| f[order[j]])
}

/// One entry per assignment with a block: frames in program order, printed d² = d0² and
/// its rounding 2·d0·h (d0 has more digits than d).
fn printed_d(
    case: &IdentityExampleCase,
    ex: &Example,
    frame1: &[usize; 4],
    blocks: &[Block],
) -> Vec<PrintedD> {
    let digits = case.debug.significant_digits;
    let mut seen = Vec::new();
    let mut out = Vec::new();
    for bl in blocks {
        let Some(asg) = bl.assignment() else { continue };
        if seen.contains(&asg) {
            continue;
        }
        seen.push(asg);
        let d0 = printed_num(&bl.attempt.d, digits);
        out.push((
            frame(&ex.frame1, frame1),
            frame(&ex.frame2, &asg),
            d0.value * d0.value,
            2.0 * d0.value * d0.half,
        ));
    }
    out
}

/// The largest relative change of the distance over the d factors, over the blocks off
/// rounding level (the true blocks' distances are rounding noise).
fn spread(case: &IdentityExampleCase, ex: &Example, frame1: &[usize; 4], blocks: &[Block]) -> f64 {
    let digits = case.debug.significant_digits;
    blocks
        .iter()
        .filter_map(|bl| {
            let (asg, r) = (bl.assignment()?, bl.program.as_ref()?);
            let diff = r.block.values[LINE_DIFF].abs();
            if diff <= r.bounds[LINE_DIFF] + r.float_bound {
                return None;
            }
            let d0 = printed_num(&bl.attempt.d, digits).value;
            let (f1, f2) = (frame(&ex.frame1, frame1), frame(&ex.frame2, &asg));
            distance_spread(
                &f1,
                &f2,
                d0,
                f64::from(bl.attempt.version),
                &case.debug.d_factors,
            )
        })
        .fold(0.0, f64::max)
}

pub(super) fn result(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    ex: &Example,
    frame1: &[usize; 4],
    blocks: &[Block],
) -> ClaimResult {
    let printed = printed_d(case, ex, frame1, blocks);
    let fits = fit_rules(&printed, ex.coord_half);
    let ratio: Vec<f64> = printed
        .iter()
        .map(|(f1, f2, d2, _)| {
            let lo = (f1[3] - f1[2])
                .norm_squared()
                .max((f2[3] - f2[2]).norm_squared());
            (d2 / lo).sqrt()
        })
        .collect();
    let (lo, hi) = ratio
        .iter()
        .fold((f64::INFINITY, 0.0_f64), |(l, h), x| (l.min(*x), h.max(*x)));
    let full = fits.iter().filter(|f| f.hits == printed.len()).count();
    let mut c = b
        .claim(&case.debug.claim)
        .suffix("choice-of-d")
        .printed("d0 per block", Value::count(blocks.len()))
        .printed("assignments with a block (both versions share d)", Value::count(printed.len()))
        .computed("rules tried", Value::count(fits.len()))
        .computed("rules that give every printed d", Value::count(full))
        .computed_cell("d0 / longest projection of RT", "no constant factor", Value::interval(lo, hi))
        .computed("largest relative change of a block's distance over d0 × the d factors", Value::real(spread(case, ex, frame1, blocks)))
        .power(Power::none("not reproducible: the paper gives no rule for \"the a priori selected value for c\", and none of the rules tried gives every printed d; the distance of P₂ from its line does not depend on d (the line is the affine epipolar line), so no verdict depends on the rule"))
        .method("each rule's d² against the printed d0² of every assignment with a block; a hit is within d0's rounding plus the rule's propagated bound over the frames' rounding; misses relative to the printed d²")
        .detail("d factors", Value::reals(&case.debug.d_factors));
    for f in &fits {
        let name = rule_name(f.rule);
        c = c
            .cell(name, "hits", Value::count_of(f.hits, f.defined))
            .cell(
                name,
                "worst and median relative miss",
                Value::reals(&[f.worst, f.median]),
            );
    }
    c.verdict(Verdict::NotReproducible)
}
