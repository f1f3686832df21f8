//! RANSAC over the paper's own minimal solver: samples of four points in three frames solved
//! by §4's linear system (`derivations::p4f3::solve_core`), the body realised from its
//! squared edges, every frame's camera fitted to the four points, every other point
//! intersected from those cameras; a point is an inlier when each of its images is within
//! the threshold (image units) of its reprojection. The best sample's inliers go on to
//! Tomasi–Kanade and bundle adjustment.

use nalgebra::{Vector2, Vector3};
use rand::Rng;

use super::gaps::{intersect, resect};
use super::{Error, Frame, Observations};
use crate::derivations::p4f3::{realize, solve_core};
use crate::model::{rng, squared_lengths};

/// The generator's seed when none is given.
pub const DEFAULT_SEED: u64 = 1;
/// The probability that some sample is all inliers, which sets the number of samples.
pub const CONFIDENCE: f64 = 0.999;

/// Options of [`ransac`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RansacOptions {
    /// Largest distance (image units) from an image to its reprojection for an inlier.
    pub threshold: f64,
    /// The seed of the sample generator.
    pub seed: u64,
    /// Samples at most.
    pub max_samples: usize,
}

impl RansacOptions {
    /// Options with the threshold, the default seed and the sample limit.
    pub fn new(threshold: f64) -> Self {
        RansacOptions {
            threshold,
            seed: DEFAULT_SEED,
            max_samples: crate::limits::RANSAC_SAMPLES,
        }
    }
}

/// The cameras of one sample: the four points' body from their squared edges in three
/// frames, fitted into every frame that sees all four.
fn sample_cameras(
    obs: &Observations,
    pts: &[usize; 4],
    frames3: &[usize; 3],
) -> Option<Vec<Option<Frame>>> {
    let images = |f: usize| -> Option<Vec<[f64; 2]>> {
        pts.iter()
            .map(|&j| obs.frames[f][j].map(|y| [y.x, y.y]))
            .collect()
    };
    let mut l = [[0.0; 6]; 3];
    for (i, &f) in frames3.iter().enumerate() {
        let sq = squared_lengths(&images(f)?);
        l[i] = std::array::from_fn(|e| sq[e]);
    }
    let core = solve_core(&l);
    if !core.feasible || !core.realizable {
        return None;
    }
    let body = realize(&core.squares?, 4);
    if body.rank < 3 {
        return None;
    }
    let mut known: Vec<Option<Vector3<f64>>> = vec![None; obs.names.len()];
    for (i, &j) in pts.iter().enumerate() {
        known[j] = Some(body.points[i]);
    }
    let cams = (0..obs.frames.len())
        .map(|f| {
            let seen: Vec<(usize, Vector2<f64>)> = pts
                .iter()
                .filter_map(|&j| obs.frames[f][j].map(|y| (j, y)))
                .collect();
            resect(&known, &seen)
        })
        .collect();
    Some(cams)
}

/// The points (indices) whose every image under the cameras lies within `threshold` of the
/// reprojection of their intersection.
pub fn inliers(obs: &Observations, cams: &[Option<Frame>], threshold: f64) -> Vec<usize> {
    (0..obs.names.len())
        .filter(|&j| {
            let seen: Vec<(usize, Vector2<f64>)> = (0..obs.frames.len())
                .filter(|&f| cams[f].is_some())
                .filter_map(|f| obs.frames[f][j].map(|y| (f, y)))
                .collect();
            let Some(x) = intersect(cams, &seen) else {
                return false;
            };
            seen.iter()
                .all(|(f, y)| cams[*f].is_some_and(|c| (c.project(&x) - y).norm() <= threshold))
        })
        .collect()
}

/// Samples needed for [`CONFIDENCE`] that one is all inliers, at inlier share `w`.
fn samples_needed(w: f64, cap: usize) -> usize {
    let good = w.powi(4);
    if good >= 1.0 {
        return 1;
    }
    if good <= 0.0 {
        return cap;
    }
    let n = (1.0 - CONFIDENCE).ln() / (1.0 - good).ln();
    if n.is_finite() {
        (n.ceil() as usize).min(cap)
    } else {
        cap
    }
}

/// Distinct random indices below `n`.
fn distinct<const N: usize>(g: &mut impl Rng, n: usize) -> [usize; N] {
    let mut out = [usize::MAX; N];
    for i in 0..N {
        let mut v = g.random_range(0..n);
        while out[..i].contains(&v) {
            v = g.random_range(0..n);
        }
        out[i] = v;
    }
    out
}

/// The inlier points (indices, ascending) of the best sample; an error when no sample gives
/// [`super::MIN_POINTS`] inliers.
pub fn ransac(obs: &Observations, o: &RansacOptions) -> Result<Vec<usize>, Error> {
    obs.check_counts()?;
    if !(o.threshold.is_finite() && o.threshold > 0.0) {
        return Err(Error::InvalidOption(format!(
            "--threshold {}: the inlier threshold must be a positive number of image units",
            o.threshold
        )));
    }
    let (p, k) = (obs.names.len(), obs.frames.len());
    let mut g = rng(o.seed);
    let mut best: Vec<usize> = Vec::new();
    let mut needed = o.max_samples.max(1);
    let mut drawn = 0;
    while drawn < needed {
        drawn += 1;
        let pts: [usize; 4] = distinct(&mut g, p);
        let frames3: [usize; 3] = distinct(&mut g, k);
        let Some(cams) = sample_cameras(obs, &pts, &frames3) else {
            continue;
        };
        let ins = inliers(obs, &cams, o.threshold);
        if ins.len() > best.len() {
            best = ins;
            needed = samples_needed(best.len() as f64 / p as f64, o.max_samples).max(drawn);
        }
    }
    if best.len() < super::MIN_POINTS {
        return Err(Error::Unreachable(format!(
            "ransac: no sample of {drawn} gave {} inliers within {} image units",
            super::MIN_POINTS,
            o.threshold
        )));
    }
    Ok(best)
}
