//! The noise studies of the paper's cases (§2, §3, §4): the study a case describes, its seeded
//! runs at every printed level under both noise models, and the errors of a printed run with
//! the rounding of its digits carried along. Numbers only; the judging is in `check`.

use crate::derivations::noise::{models, run_level, stream, LevelResult, Study};
use crate::derivations::p4f3::realize;
use crate::derivations::rounding::quantile;
use crate::error::{Error, Result};
use crate::model::Body;

/// The body of printed `lengths` (three points), or the body realizing the printed `squares`
/// (the squares of the lengths when none are printed) for more points.
pub fn body_of(lengths: &[f64], squares: &[f64]) -> Result<Body> {
    if let [a, b, c] = lengths {
        return Body::triangle(*a, *b, *c);
    }
    let squares: Vec<f64> = if squares.is_empty() {
        lengths.iter().map(|x| x * x).collect()
    } else {
        squares.to_vec()
    };
    let p = (1..)
        .find(|p| p * (p - 1) / 2 >= squares.len())
        .unwrap_or(2);
    let r = realize(&squares, p);
    if !r.realizable {
        return Err(Error::InvalidInput(format!(
            "the printed edges are not realizable in 3-D (Gram eigenvalues {:?})",
            r.eigenvalues
        )));
    }
    Ok(Body::new(r.points))
}

/// Every level under both noise models (coordinate model first); level `i` under model `m`
/// uses random stream `2i + m`, as the `noise` command does.
pub fn run_both(study: &Study, levels: &[f64]) -> Vec<[LevelResult; 2]> {
    levels
        .iter()
        .enumerate()
        .map(|(i, &eps)| {
            let models = models(eps);
            std::array::from_fn(|m| run_level(study, models[m], stream(i, m), &|_| {}))
        })
        .collect()
}

/// How near printed values are to the true squares and to the true lengths: the largest
/// relative distance over the edges to each.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SymbolDistances {
    /// Largest |x/t − 1| against the true squares t.
    pub to_squares: f64,
    /// Largest |x/√t − 1| against the true lengths √t.
    pub to_lengths: f64,
}

impl SymbolDistances {
    /// Distances of `values` to the true squares `truth` and to their roots.
    pub fn of(values: &[f64], truth: &[f64]) -> SymbolDistances {
        let far = |t: &dyn Fn(f64) -> f64| {
            values
                .iter()
                .zip(truth)
                .map(|(x, s)| (x / t(*s) - 1.0).abs())
                .fold(0.0, f64::max)
        };
        SymbolDistances {
            to_squares: far(&|s| s),
            to_lengths: far(&|s| s.sqrt()),
        }
    }

    /// Whether the values are nearer the squares (ties read as squares).
    pub fn are_squares(&self) -> bool {
        self.to_squares <= self.to_lengths
    }
}

/// The errors of a printed run against the truth, as intervals over the rounding of its digits.
#[derive(Clone, Debug, PartialEq)]
pub struct RunErrors {
    /// The errors at the printed digits, in the order of [`crate::derivations::noise::METRICS`].
    pub metrics: [f64; 4],
    /// The range each metric takes over the rounding box of the printed digits.
    pub ranges: [(f64, f64); 4],
    /// Per edge: relative error in squares.
    pub edge_squares: Vec<f64>,
    /// Per edge: relative error in lengths.
    pub edge_lengths: Vec<f64>,
}

/// The errors of a printed run: `values` with half-units `half`, squares when `as_squares`,
/// lengths otherwise (squared first), against the true squares `truth`. `None` when a value's
/// rounding interval reaches a negative square or the lengths disagree in count.
pub fn run_errors(
    values: &[f64],
    half: &[f64],
    as_squares: bool,
    truth: &[f64],
) -> Option<RunErrors> {
    if values.len() != truth.len() || half.len() != truth.len() {
        return None;
    }
    // each edge's square: its value and the interval of its printed digits
    let boxes: Vec<(f64, f64, f64)> = values
        .iter()
        .zip(half)
        .map(|(x, h)| {
            if as_squares {
                (*x, x - h, x + h)
            } else {
                (x * x, (x - h).max(0.0).powi(2), (x + h).powi(2))
            }
        })
        .collect();
    if boxes.iter().any(|b| b.1 < 0.0 || !b.2.is_finite()) {
        return None;
    }
    // |f(x/t) − 1| for increasing f over [lo, hi]: its range is [0 if 1 is inside, else the
    // nearer end; the farther end]
    let range = |f: fn(f64) -> f64, lo: f64, hi: f64| {
        let (a, b) = (f(lo) - 1.0, f(hi) - 1.0);
        let near = if a <= 0.0 && b >= 0.0 {
            0.0
        } else {
            a.abs().min(b.abs())
        };
        (near, a.abs().max(b.abs()))
    };
    let per = |f: fn(f64) -> f64| -> (Vec<f64>, Vec<(f64, f64)>) {
        boxes
            .iter()
            .zip(truth)
            .map(|((x, lo, hi), t)| ((f(x / t) - 1.0).abs(), range(f, lo / t, hi / t)))
            .unzip()
    };
    let (sq, sq_r) = per(|r| r);
    let (ln, ln_r) = per(f64::sqrt);
    let n = truth.len() as f64;
    let max = |v: &[f64]| v.iter().fold(0.0, |a: f64, b| a.max(*b));
    let mean = |v: &[f64]| v.iter().sum::<f64>() / n;
    let ends = |r: &[(f64, f64)], agg: &dyn Fn(&[f64]) -> f64| {
        let (lo, hi): (Vec<f64>, Vec<f64>) = r.iter().copied().unzip();
        (agg(&lo), agg(&hi))
    };
    Some(RunErrors {
        metrics: [max(&sq), mean(&sq), max(&ln), mean(&ln)],
        ranges: [
            ends(&sq_r, &max),
            ends(&sq_r, &mean),
            ends(&ln_r, &max),
            ends(&ln_r, &mean),
        ],
        edge_squares: sq,
        edge_lengths: ln,
    })
}

/// The median relative error of every edge over a level's successful trials, in squares
/// (`[0]`) and in lengths (`[1]`); 0 for a level without successful trials.
pub fn edge_medians(r: &LevelResult) -> [Vec<f64>; 2] {
    std::array::from_fn(|k| {
        (0..r.edges)
            .map(|e| quantile(&r.edge_errors(e, k == 1), 0.5).unwrap_or(0.0))
            .collect()
    })
}
