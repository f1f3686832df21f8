//! Claims of a noise study (§2, §3): its printed body, and the paper's words about its noisy
//! runs, each level judged by the shared noise judge ([`crate::claims::shared::Context`]).

use super::run_study;
use crate::check::{ClaimResult, Power, ResultBuilder, Tolerance, ToleranceSource, Value, Verdict};
use crate::claims::noise_study::NoiseStudyCase;
use crate::claims::shared::{setting, Context};
use crate::derivations::solver::default_edge_names;
use crate::error::Result;

pub(super) fn results(b: &ResultBuilder, case: &NoiseStudyCase) -> Result<Vec<ClaimResult>> {
    let mut out = Vec::new();
    let lengths: Vec<f64> = case.body.lengths.iter().map(|p| p.to_f64()).collect();
    // the printed squares when there are any (the runs are compared with them), else the
    // squares of the printed lengths
    let truth: Vec<f64> = if case.body.squares.is_empty() {
        lengths.iter().map(|x| x * x).collect()
    } else {
        case.body.squares.iter().map(|p| p.to_f64()).collect()
    };
    if let Some(claim) = &case.body.claim {
        out.push(body_result(b, claim, case));
    }
    let results = run_study(case)?;
    let ctx = Context {
        truth: &truth,
        names: &default_edge_names(truth.len()),
        trials: case.trials,
        seed: case.seed,
        setting: setting(truth.len(), case.frames),
        scene: false,
    };
    for (i, (lv, res)) in case.levels.iter().zip(&results).enumerate() {
        // one claim quoted at several levels gets one result per level
        let repeated = case
            .levels
            .iter()
            .filter(|l| l.claim.claim == lv.claim.claim)
            .count()
            > 1;
        let neighbour = results
            .get(i + 1)
            .or(i.checked_sub(1).and_then(|j| results.get(j)));
        out.extend(ctx.level(b, lv, repeated, res, neighbour.map(|n| n.as_slice())));
    }
    Ok(out)
}

/// The printed body: its squares against the squares of its printed lengths.
fn body_result(
    b: &ResultBuilder,
    claim: &crate::cases::ClaimRef,
    case: &NoiseStudyCase,
) -> ClaimResult {
    let digits = case.body.significant_digits.unwrap_or(6);
    let pairs: Vec<(f64, f64, f64)> = case
        .body
        .lengths
        .iter()
        .zip(&case.body.squares)
        .map(|(l, s)| {
            (
                l.to_f64() * l.to_f64(),
                s.to_f64(),
                s.half_unit_significant(digits),
            )
        })
        .collect();
    let agree = pairs.iter().all(|(sq, s, h)| (sq - s).abs() <= *h);
    // the acceptance region of the edge with the widest half unit: the printed squares the
    // same check would pass there
    let widest = pairs
        .iter()
        .copied()
        .max_by(|a, b| a.2.total_cmp(&b.2))
        .unwrap_or((0.0, 0.0, 0.0));
    let mut r = b.claim(claim);
    for l in &case.body.lengths {
        r = r.printed("length", l);
    }
    for s in &case.body.squares {
        r = r.printed("square", s);
    }
    let squares: Vec<f64> = pairs.iter().map(|p| p.0).collect();
    let halves: Vec<f64> = pairs.iter().map(|p| p.2).collect();
    r.computed("squares of the printed lengths", Value::reals(&squares))
        .tolerance(Tolerance::bound(
            widest.2,
            ToleranceSource::PrintedPrecision,
            "half a unit in the last significant digit the program printed, per square",
        ))
        // the region is the printed squares within half a unit of the computed square: exactly
        // those the printed digits would call right, so it is centred on the computed square
        .power(Power::interval(
            widest.0 - widest.2,
            widest.0 + widest.2,
            widest.0,
            widest.2,
            "printed squares the same check accepts for the edge with the widest half unit",
        ))
        .method("squares of the printed lengths against the printed squares")
        .detail("half units of the printed squares", Value::reals(&halves))
        .verdict(Verdict::holds(agree))
}
