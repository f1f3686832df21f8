//! Several starts for tracks with gaps, the best kept. Variable projection from the chain
//! of frame pairs can reach a local optimum, or a metric upgrade that has to be clipped,
//! when the tracks are short: the chain's error grows along it, and a fit can converge in
//! a wrong basin with nothing in it to warn of (docs/limits.md). So for every fit of tracks
//! with gaps, the chain is started again from other frames, forwards and backwards
//! ([`CHAIN_STARTS`]; where most entries are missing, as variable projection needs; a chain
//! that fails falls back on the largest complete block grown in its order), from the
//! largest complete block, and from random rotations ([`rotations`]: of every frame in a
//! small group, window by window in a larger one); each is adjusted briefly
//! ([`SCREEN_ITERATIONS`]), the best [`FINISHED`] are adjusted in full; the frames the best
//! of those fits leaves uneven are started again with the rest kept ([`reseat`]); and the fit
//! of least cost, theirs or the first's, is kept with its own warnings; a warning when only
//! one of those fits reached that cost, or only fits from random rotations ([`unconfirmed`]).

use rayon::prelude::*;

use super::{adjust, fit, uneven_warning, with_gaps};
use crate::numfmt::sig;
use crate::sfm::bundle::BundleOptions;
use crate::sfm::{BundleReport, Error, Observations, Options, Reconstruction};

mod reseat;
mod rotations;

pub use rotations::{ROTATION_FRAMES, ROTATION_STARTS, WINDOW_FRAMES};

/// Iterations each other start is adjusted for before the best is chosen; the chosen one
/// then goes on to the full adjustment (with its standard errors).
pub const SCREEN_ITERATIONS: usize = 20;

/// A fit and its adjustment's report.
type Fitted = (Reconstruction, Option<BundleReport>);

/// The first fit ([`fit`], with the uneven-frames check); on tracks with gaps, the best of
/// it, the other starts ([`orders`], the largest complete block, [`search`]) and the best of
/// those re-seated ([`reseated`]) by the adjustment's final cost. Errors other than an
/// unreachable part or a numerical failure (too large, degenerate) are returned as they are.
pub(super) fn best_fit(
    used: &Observations,
    options: &Options,
    numbers: &[usize],
) -> Result<Fitted, Error> {
    let first = fit(used, options, None, numbers).map(|(mut rec, b)| {
        rec.warnings.extend(uneven_warning(used, &rec, numbers));
        (rec, b)
    });
    let retry = match &first {
        // not only where it warns: a fit in a wrong basin can look clean (docs/limits.md)
        Ok((_, b)) => b.is_some(),
        Err(Error::Unreachable(_) | Error::Numerical(_)) => true,
        Err(_) => false,
    };
    if !retry || !options.bundle || used.complete().is_some() {
        return first;
    }
    let (screened, tried) = screen_starts(used, options, numbers);
    let finished = finish(used, options, numbers, screened);
    let mut fits: Vec<(Fitted, Start)> = Vec::new();
    if let Ok(f) = &first {
        fits.push((f.clone(), Start::named("the first")));
    }
    fits.extend(finished);
    let floor = rounding(used);
    fits.extend(reseated(used, options, numbers, &fits, floor));
    let least = fits
        .iter()
        .map(|f| cost(&f.0))
        .fold(f64::INFINITY, f64::min);
    if !least.is_finite() {
        return first;
    }
    // the earliest fit at the least cost (the first before the others): the same optimum
    // reached again by another start does not replace the first fit
    let at_least_cost = |c: f64| same_optimum(c, least, floor);
    let Some(best) = fits.iter().position(|f| at_least_cost(cost(&f.0))) else {
        return first;
    };
    let reached: Vec<&Start> = fits
        .iter()
        .filter(|f| at_least_cost(cost(&f.0)))
        .map(|f| &f.1)
        .collect();
    let unconfirmed = unconfirmed(&reached, fits.len(), least, tried);
    let ((mut rec, b), start) = fits.swap_remove(best);
    rec.method.push(format!(
        "tracks with gaps: of {tried} starts, the one of least final cost ({}) kept: {}",
        sig(least),
        start.name
    ));
    rec.warnings.extend(unconfirmed);
    Ok((rec, b))
}

/// The warning when the least cost is not confirmed (`reached`: the starts of the fits that
/// reached it, of `finished`): one fit alone reached it, or only random starts of a whole
/// group, since many draws of one kind of start can all fall into the same wrong basin
/// (measured on uniform windows of three frames, docs/limits.md). The chained windows count
/// as a start of their own; a re-seated fit counts among the `finished`, its own starts not
/// among the `tried` (a re-seated fit alone at the least cost is warned of like any other).
fn unconfirmed(reached: &[&Start], finished: usize, least: f64, tried: usize) -> Option<String> {
    let least = sig(least);
    if reached.len() < 2 {
        Some(format!(
            "of the {finished} fits finished from {tried} starts only one reached the least cost ({least}): a lower optimum may exist"
        ))
    } else if reached.iter().all(|s| s.random) {
        Some(format!(
            "of the {finished} fits finished from {tried} starts only those from random rotations reached the least cost ({least}): a lower optimum may exist"
        ))
    } else {
        None
    }
}

/// Where a fit started, as its method line names it, and whether from random rotations of
/// every frame (which do not confirm each other's optimum, [`unconfirmed`]; a re-seated fit
/// is its base's kind).
#[derive(Clone, Debug)]
struct Start {
    name: String,
    random: bool,
}

impl Start {
    /// A start that is not random.
    fn named(name: impl Into<String>) -> Start {
        Start {
            name: name.into(),
            random: false,
        }
    }
}

/// Fits finished in full from the other starts, the best by their screening's cost.
pub const FINISHED: usize = 2;

/// The best [`FINISHED`] of the screened fits (by their screening's cost) adjusted in full,
/// on every core; one that fails, or ends without a finite cost, is replaced by the next.
fn finish(
    used: &Observations,
    options: &Options,
    numbers: &[usize],
    screened: Vec<(Fitted, Start)>,
) -> Vec<(Fitted, Start)> {
    let full = BundleOptions::with(options);
    let mut out = Vec::new();
    let mut rest = screened.into_iter();
    while out.len() < FINISHED {
        let batch: Vec<(Fitted, Start)> = rest.by_ref().take(FINISHED - out.len()).collect();
        if batch.is_empty() {
            break;
        }
        let done: Vec<(Fitted, Start)> = batch
            .into_par_iter()
            .filter_map(|((rec, _), name)| adjusted(used, numbers, rec, &full).map(|f| (f, name)))
            .filter(|(f, _)| cost(f).is_finite())
            .collect();
        out.extend(done);
    }
    out
}

/// Two fits agree on their optimum when their costs are within this, relative: a chosen
/// margin, not derived from the adjustment's stopping rule (a step gaining at most 4ε of
/// the cost), which a slow final descent can leave far above; distinct optima on the
/// turntable family differ by factors, far beyond it.
const AGREE: f64 = 1e-6;

/// Whether a fit of cost `c` is at the optimum of cost `least` (the lower): within [`AGREE`]
/// of it, relative, or within the rounding `floor` ([`rounding`]).
fn same_optimum(c: f64, least: f64, floor: f64) -> bool {
    c <= least * (1.0 + AGREE) + floor
}

/// The cost's rounding floor at an exact fit: each residual y − (C x + t) is computed to
/// within a few ε of the coordinates' magnitude, at most s (the largest; an upper bound,
/// since the adjustment works in centred units), so ½ Σ (4ε s)² over every coordinate
/// observed. Costs within it of the least are at the least (exact data).
fn rounding(used: &Observations) -> f64 {
    let s = used.seen().map(|(_, _, y)| y.amax()).fold(0.0, f64::max);
    let coordinates = 2 * used.count();
    0.5 * coordinates as f64 * (4.0 * f64::EPSILON * s).powi(2)
}

/// The other starts ([`orders`], the largest complete block, [`search`]), each adjusted for
/// [`SCREEN_ITERATIONS`] on every core, by cost (the earlier start on a tie); those that
/// fail are left out.
fn screen_starts(
    used: &Observations,
    options: &Options,
    numbers: &[usize],
) -> (Vec<(Fitted, Start)>, usize) {
    let screen = screening(options);
    // the chain's orders matter where variable projection starts (most entries missing)
    let cells = used.frames.len() * used.names.len();
    let chains = if 2 * used.count() < cells {
        orders(used.frames.len())
    } else {
        Vec::new()
    };
    let mut starts: Vec<(String, Option<Vec<usize>>)> = chains
        .into_iter()
        .map(|(name, order)| (name, Some(order)))
        .collect();
    starts.push(("the largest complete block".to_string(), None));
    let mut screened: Vec<(Fitted, Start)> = starts
        .par_iter()
        .filter_map(|(name, order)| match order {
            Some(order) => from_order(used, options, numbers, (name, order), &screen),
            None => from_block(used, numbers, &screen).map(|f| (f, Start::named(name))),
        })
        .collect();
    let (global, searched) = search(used, options.seed, &screen);
    screened.extend(global);
    let tried = 1 + starts.len() + searched;
    // a stable sort: the earlier start first on a tie
    screened.sort_by(|a, b| cost(&a.0).total_cmp(&cost(&b.0)));
    (screened, tried)
}

/// The short adjustment each start is screened by.
fn screening(options: &Options) -> BundleOptions {
    BundleOptions {
        max_iterations: SCREEN_ITERATIONS.min(options.max_iterations),
        standard_errors: false,
        ..BundleOptions::with(options)
    }
}

/// The fit of least cost of `fits` with its uneven frames re-seated ([`reseat`]), named
/// after it, where that lowers its cost.
fn reseated(
    used: &Observations,
    options: &Options,
    numbers: &[usize],
    fits: &[(Fitted, Start)],
    floor: f64,
) -> Option<(Fitted, Start)> {
    let (best, start) = fits
        .iter()
        .min_by(|a, b| cost(&a.0).total_cmp(&cost(&b.0)))?;
    let reseat = reseat::Reseat {
        used,
        numbers,
        seed: options.seed,
        screen: &screening(options),
        full: &BundleOptions::with(options),
        floor,
    };
    let (fit, frames) = reseat.run(best)?;
    let name = format!(
        "{}, then frames {frames} re-seated (started again, the other frames' rotations kept)",
        start.name
    );
    Some((
        fit,
        Start {
            name,
            ..start.clone()
        },
    ))
}

/// The global search of [`rotations`]: a group of at most [`ROTATION_FRAMES`] frames from
/// [`ROTATION_STARTS`] random rotations, each named by its seed's place; a larger one from
/// windows of [`WINDOW_FRAMES`] chained. With the number of starts it counts.
fn search(used: &Observations, seed: u64, bo: &BundleOptions) -> (Vec<(Fitted, Start)>, usize) {
    if used.frames.len() <= ROTATION_FRAMES {
        let fits = rotations::random_fits(used, seed, bo);
        let named = fits
            .into_iter()
            .map(|(i, f)| {
                let name = format!("random rotations {} of {ROTATION_STARTS}", i + 1);
                (f, Start { name, random: true })
            })
            .collect();
        return (named, ROTATION_STARTS);
    }
    let chained = rotations::windowed(used, seed, bo).and_then(|rec| screened(used, rec, bo));
    let name = format!("windows of {WINDOW_FRAMES} frames from random rotations, chained");
    (
        chained
            .map(|f| (f, Start::named(name)))
            .into_iter()
            .collect(),
        1,
    )
}

/// The adjustment's final cost (½ Σ ‖r‖²); infinite without one.
fn cost(f: &Fitted) -> f64 {
    f.1.as_ref()
        .and_then(|b| b.costs.last().copied())
        .filter(|c| c.is_finite())
        .unwrap_or(f64::INFINITY)
}

/// Points along the frames the chain is started again from, each forwards and backwards:
/// 0, ¼, ½ and ¾ of the way (the first forwards is the first start). Measured on the
/// turntable family (docs/limits.md): three points both ways reached the optimum in 85.2 %
/// of scenes, four in 87.5 %, six in 87.8 % at half as much work again.
pub const CHAIN_STARTS: usize = 4;

/// The other orders of the frames the chain is started in (see [`CHAIN_STARTS`]): from a
/// frame on, the frames before it appended (as a turntable comes round), and backwards
/// from the frame before it.
fn orders(k: usize) -> Vec<(String, Vec<usize>)> {
    let mut out: Vec<(String, Vec<usize>)> = Vec::new();
    let identity: Vec<usize> = (0..k).collect();
    for i in 0..CHAIN_STARTS {
        let shift = i * k / CHAIN_STARTS;
        let forwards = (
            format!("the chain from frame {} on", shift + 1),
            (0..k).map(|f| (f + shift) % k).collect::<Vec<usize>>(),
        );
        let backwards = (
            format!("the chain backwards from frame {}", (shift + k - 1) % k + 1),
            (0..k).map(|f| (shift + 2 * k - 1 - f) % k).collect(),
        );
        for o in [forwards, backwards] {
            // few frames repeat an order; the first start's own is not a new one
            if o.1 != identity && out.iter().all(|p| p.1 != o.1) {
                out.push(o);
            }
        }
    }
    out
}

/// The fit from the frames in `order` (`order[i]`: the frame taken i-th) by the paths for
/// gaps ([`with_gaps`]: the chain of frame pairs, or where its variable projection fails
/// the largest complete block grown in that order, which the name then says), brought back
/// to the frames' own order and adjusted.
fn from_order(
    used: &Observations,
    options: &Options,
    numbers: &[usize],
    (name, order): (&str, &[usize]),
    bo: &BundleOptions,
) -> Option<(Fitted, Start)> {
    let permuted = used.select_frames(order);
    let renumbered: Vec<usize> = order.iter().map(|&f| numbers[f]).collect();
    let mut rec = with_gaps(&permuted, options, &renumbered).ok()?;
    let grown = rec
        .method
        .iter()
        .any(|m| m.contains("largest complete block"));
    let name = if grown {
        format!(
            "the largest complete block grown in the order from frame {} (its chain failed)",
            order[0] + 1
        )
    } else {
        name.to_string()
    };
    let mut frames = rec.frames.clone();
    for (i, &f) in order.iter().enumerate() {
        frames[f] = rec.frames[i];
    }
    rec.frames = frames;
    rec.align_to_first();
    rec.centre();
    screened(used, rec, bo).map(|f| (f, Start::named(name)))
}

/// The fit from the largest complete block, grown.
fn from_block(used: &Observations, numbers: &[usize], bo: &BundleOptions) -> Option<Fitted> {
    let rec = crate::sfm::gaps::initial_numbered(used, numbers).ok()?;
    screened(used, rec, bo)
}

/// `rec` adjusted for the screening; its warnings and steps stay the start's (the short
/// adjustment's stop is not the final fit's).
fn screened(used: &Observations, mut rec: Reconstruction, bo: &BundleOptions) -> Option<Fitted> {
    let (warnings, method) = (rec.warnings.clone(), rec.method.clone());
    let report = adjust(used, &mut rec, bo).ok()?;
    if !rec.is_finite() {
        return None;
    }
    rec.warnings = warnings;
    rec.method = method;
    Some((rec, report))
}

/// `rec` adjusted, with the uneven-frames check; `None` when the adjustment fails or leaves
/// a non-finite coordinate.
fn adjusted(
    used: &Observations,
    numbers: &[usize],
    mut rec: Reconstruction,
    bo: &BundleOptions,
) -> Option<Fitted> {
    let report = adjust(used, &mut rec, bo).ok()?;
    if !rec.is_finite() {
        return None;
    }
    rec.warnings.extend(uneven_warning(used, &rec, numbers));
    Some((rec, report))
}
