//! §4's "the linearity has clearly its price: that is the sensitivity to measurement errors",
//! read as a comparison with the standard method on the same noisy scenes: the ratio of the
//! median edge-length error of the §4 linear solver to that of Tomasi–Kanade + bundle
//! adjustment on the same three frames, with distribution-free confidence bounds; the rule
//! is in `docs/verdicts.md` ("The price of linearity").

use crate::cases::Printed;
use crate::check::Role;
use crate::check::{ClaimResult, Power, ResultBuilder, Tolerance, ToleranceSource, Value, Verdict};
use crate::claims::linearity_price::study::{
    self, length_error, BodySpec, Bound, Cell, Design, Method, MethodErrors, RatioBounds, Results,
    Unavailable,
};
use crate::claims::linearity_price::{LinearityBody, LinearityPriceCase};
use crate::error::Result;

mod figure;

/// The ratio that decides: the §4 linear solver over the standard method on its frames.
const PRICE: (Method, Method) = (Method::P4f3, Method::TomasiKanadeBa3);
/// The same ratio for the least-squares form, every frame (evidence).
const PRICE_LSQ: (Method, Method) = (Method::LeastSquares, Method::TomasiKanadeBa);
/// The null comparison: the §4 solver on fresh noise over itself (true ratio 1).
const NULL: (Method, Method) = (Method::P4f3FreshNoise, Method::P4f3);

pub(super) fn results(b: &ResultBuilder, case: &LinearityPriceCase) -> Result<Vec<ClaimResult>> {
    let design = design_of(case)?;
    let res = study::compare(&design);
    let alpha = case.alpha.to_f64();
    let Some((_, _, cells)) = res.bodies.iter().find(|(n, _, _)| *n == case.deciding_body) else {
        // the loader checks that the deciding body is one of the bodies
        return Ok(Vec::new());
    };
    let deciding: Vec<&Cell> = case
        .deciding_levels
        .iter()
        .filter_map(|l| cells.iter().find(|c| c.level == l.to_f64()))
        .collect();
    let price: Vec<_> = deciding
        .iter()
        .map(|c| c.ratio(PRICE.0, PRICE.1, alpha))
        .collect();
    let null: Vec<_> = deciding
        .iter()
        .map(|c| c.ratio(NULL.0, NULL.1, alpha))
        .collect();
    let decision = decide(&price);
    let null_decision = decide(&null);
    let mut r = b
        .claim(&case.claim)
        .printed_as("paper", Value::label(case.claim.quote.clone()), Role::ValueOnly)
        .tolerance(Tolerance::bound(
            1.0,
            ToleranceSource::MonteCarlo {
                percentile: crate::check::Real(50.0),
                trials: res.trials as u64,
            },
            "the ratio of median errors against 1, with order-statistic bounds of one-sided confidence 1 − α each (Bonferroni over the two samples)",
        ))
        .method("seeded scenes of the §4 body under random rotations, the paper's coordinate noise, every method on the same noisy tracks; error = largest relative edge-length error")
        .detail_as("trials per body and level", Value::count(res.trials), Role::Trials)
        .detail("seed", Value::count(case.seed as usize))
        .detail("α (each one-sided bound)", Value::real(alpha));
    for (lv, p) in case.deciding_levels.iter().zip(&price) {
        r = ratio_quantities(
            r,
            &format!("{} at {} %", case.deciding_body, percent(lv)),
            p,
        );
    }
    r = printed_runs(r, case, cells);
    r = tables(r, &res, case, alpha);
    let power = match (&decision, &null_decision) {
        (Decision::Unavailable(_), _) | (_, Decision::Unavailable(_)) => {
            Power::none("the standard method is not in this build: no comparison to control")
        }
        _ => Power::mutant(
            null_decision != Decision::Holds,
            "the null comparison (the §4 solver on a fresh noise draw of the same scenes over itself, true ratio 1) must not be declared a price; a lower bound at or below 1 at a deciding level would have left the claim unproven, an upper bound below 1 would have failed it",
        ),
    };
    b.figure(figure::figure(&res, case));
    Ok(vec![r.power(power).verdict(decision.verdict())])
}

/// What the rule of `docs/verdicts.md` decides from the price ratios at the deciding levels.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Decision {
    /// Every lower bound above 1.
    Holds,
    /// Some upper bound below 1: the linear solver is better there.
    Fails,
    /// Neither: the bounds straddle 1 somewhere.
    TooClose,
    /// A side of a ratio has no numbers.
    Unavailable(Unavailable),
}

impl Decision {
    fn verdict(self) -> Verdict {
        match self {
            Decision::Holds => Verdict::StatisticalHolds,
            Decision::Fails => Verdict::StatisticalFails,
            Decision::TooClose | Decision::Unavailable(_) => Verdict::Inconclusive,
        }
    }
}

/// The judge: holds when the ratio's lower bound exceeds 1 at every deciding level, fails
/// when its upper bound is below 1 at one, else too close; unavailable when a ratio is.
fn decide(ratios: &[std::result::Result<RatioBounds, Unavailable>]) -> Decision {
    let mut ok = Vec::new();
    for r in ratios {
        match r {
            Ok(b) => ok.push(*b),
            Err(u) => return Decision::Unavailable(*u),
        }
    }
    if ok.is_empty() {
        return Decision::Unavailable(Unavailable::NotApplicable("no deciding level"));
    }
    if ok.iter().any(|b| b.upper.finite().is_some_and(|u| u < 1.0)) {
        Decision::Fails
    } else if ok.iter().all(|b| b.lower.exceeds(1.0)) {
        Decision::Holds
    } else {
        Decision::TooClose
    }
}

/// A bound as a value: a number, or the words for one among the failed trials.
fn bound_value(b: Bound) -> Value {
    match b {
        Bound::Finite(x) => Value::real(x),
        Bound::Infinite => Value::label("unbounded (among the failed trials)"),
    }
}

/// A fraction's printed digits in percent ("0.001" → "0.1").
fn percent(p: &Printed) -> String {
    crate::check::figure::percent_text(p)
}

/// The ratio, its bounds and the smallest detectable ratio, named `at: …`.
fn ratio_quantities<'a>(
    mut r: crate::check::ClaimBuilder<'a>,
    at: &str,
    p: &std::result::Result<RatioBounds, Unavailable>,
) -> crate::check::ClaimBuilder<'a> {
    match p {
        Ok(b) => {
            r = r
                .computed_cell(at, "ratio of medians", bound_value(b.point))
                .computed_cell(at, "lower bound", bound_value(b.lower))
                .computed_cell(at, "upper bound", bound_value(b.upper));
            if let Some(d) = b.detectable {
                r = r.cell(at, "smallest ratio the trials resolve", Value::real(d));
            }
            r
        }
        Err(u) => r.computed_cell(at, "ratio of medians", unavailable_value(*u)),
    }
}

fn unavailable_value(u: Unavailable) -> Value {
    match u {
        Unavailable::NotApplicable(why) => Value::label(format!("not applicable: {why}")),
        Unavailable::NotInThisBuild => Value::label("not available in this build"),
    }
}

/// The paper's printed runs: their largest edge-length error against the §4 body's printed
/// squares, and its rank among the §4 solver's trials at that level.
fn printed_runs<'a>(
    mut r: crate::check::ClaimBuilder<'a>,
    case: &LinearityPriceCase,
    cells: &[Cell],
) -> crate::check::ClaimBuilder<'a> {
    let Some(body) = case.bodies.iter().find(|b| b.name == case.deciding_body) else {
        return r;
    };
    let truth: Vec<f64> = body.squares.iter().map(Printed::to_f64).collect();
    for run in &case.printed_runs {
        let x: Vec<f64> = run.squares.iter().map(Printed::to_f64).collect();
        let at = format!("printed run at {} %", percent(&run.level));
        r = r.printed(&at, Value::reals(&x));
        let Some(e) = length_error(&x, &truth) else {
            continue;
        };
        r = r.computed(&format!("{at}: largest edge-length error"), Value::real(e));
        let cell = cells.iter().find(|c| c.level == run.level.to_f64());
        if let Some(v) = cell.and_then(|c| c.of(Method::P4f3).sorted()) {
            let rank = crate::derivations::rounding::rank_of(v, e);
            r = r.detail(
                &format!("{at}: rank among the §4 solver's trials"),
                Value::real(rank),
            );
        }
    }
    r
}

/// Every body, level and method as details `column: row` (one table, methods as columns).
fn tables<'a>(
    mut r: crate::check::ClaimBuilder<'a>,
    res: &Results,
    case: &LinearityPriceCase,
    alpha: f64,
) -> crate::check::ClaimBuilder<'a> {
    for (name, _, cells) in &res.bodies {
        for (c, lv) in cells.iter().zip(&case.levels) {
            let row = format!("{name}, {} %", percent(lv));
            for (m, e) in &c.methods {
                r = method_cells(r, m.name(), &row, e);
            }
            // a ratio is a cell of its kind ("price", "null"), the ratio and the row its column
            for (kind, ratio, (n, d)) in [
                ("price", "§4 linear ÷ TK+BA (frames 1–3)", PRICE),
                ("price", "least squares ÷ TK+BA (4 frames)", PRICE_LSQ),
                ("null", "§4 fresh noise ÷ §4", NULL),
            ] {
                let at = |what: &str| format!("{ratio}: {row} {what}");
                r = match c.ratio(n, d, alpha) {
                    Ok(b) => r
                        .cell(kind, &at("median"), bound_value(b.point))
                        .cell(kind, &at("lower bound"), bound_value(b.lower))
                        .cell(kind, &at("upper bound"), bound_value(b.upper)),
                    Err(u) => r.cell(kind, &at("median"), unavailable_value(u)),
                };
            }
        }
    }
    r
}

fn method_cells<'a>(
    r: crate::check::ClaimBuilder<'a>,
    method: &str,
    row: &str,
    e: &MethodErrors,
) -> crate::check::ClaimBuilder<'a> {
    match e.summary() {
        Some(s) => r
            .cell(method, &format!("{row} median"), bound_value(s.median))
            .cell(
                method,
                &format!("{row} 90th percentile"),
                bound_value(s.p90),
            )
            .cell(
                method,
                &format!("{row} failures"),
                Value::count_of(s.failures, s.trials),
            ),
        None => r.cell(
            method,
            &format!("{row} median"),
            unavailable_value(match e {
                MethodErrors::Unavailable(u) => *u,
                MethodErrors::Ran(_) => Unavailable::NotInThisBuild,
            }),
        ),
    }
}

/// The study a case describes.
fn design_of(case: &LinearityPriceCase) -> Result<Design> {
    let bodies = case
        .bodies
        .iter()
        .map(|b| Ok((b.name.clone(), spec_of(b)?)))
        .collect::<Result<Vec<_>>>()?;
    Ok(Design {
        bodies,
        levels: case.levels.iter().map(Printed::to_f64).collect(),
        trials: case.trials,
        seed: case.seed,
    })
}

fn spec_of(b: &LinearityBody) -> Result<BodySpec> {
    if let Some(points) = b.random_points {
        return Ok(BodySpec::Random { points });
    }
    let lengths: Vec<f64> = b.lengths.iter().map(Printed::to_f64).collect();
    let squares: Vec<f64> = b.squares.iter().map(Printed::to_f64).collect();
    Ok(BodySpec::Fixed(crate::studies::noise::body_of(
        &lengths, &squares,
    )?))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bounds(lo: f64, hi: f64) -> std::result::Result<RatioBounds, Unavailable> {
        Ok(RatioBounds {
            point: Bound::Finite(0.5 * (lo + hi)),
            lower: Bound::Finite(lo),
            upper: Bound::Finite(hi),
            detectable: None,
        })
    }

    #[test]
    fn the_judge_needs_every_lower_bound_above_one() {
        assert_eq!(
            decide(&[bounds(1.2, 3.0), bounds(1.01, 2.0)]),
            Decision::Holds
        );
        assert_eq!(
            decide(&[bounds(1.2, 3.0), bounds(0.99, 2.0)]),
            Decision::TooClose
        );
        assert_eq!(
            decide(&[bounds(1.2, 3.0), bounds(0.5, 0.99)]),
            Decision::Fails
        );
        let unbounded = Ok(RatioBounds {
            point: Bound::Infinite,
            lower: Bound::Infinite,
            upper: Bound::Infinite,
            detectable: None,
        });
        assert_eq!(decide(&[unbounded]), Decision::Holds);
        assert_eq!(
            decide(&[bounds(2.0, 3.0), Err(Unavailable::NotInThisBuild)]),
            Decision::Unavailable(Unavailable::NotInThisBuild)
        );
    }
}
