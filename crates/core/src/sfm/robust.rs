//! Robust mode: RANSAC over the paper's own minimal solver, then a judgement of every
//! observation.
//!
//! Samples of four points in three frames are solved by §4's linear system
//! (`derivations::p4f3::solve_core`), the body realised from its squared edges, every frame's
//! camera fitted to the four points, every point intersected from those cameras. With a
//! threshold, the best sample puts the most observations within it of their reprojections;
//! without one, the best has the least median residual (least median of squares), and the
//! threshold comes from that median ([`threshold`](super::threshold): the Rayleigh rule on
//! residual norms).
//!
//! The best sample's cameras judge every observation ([`judge`](super::judge): a point keeps
//! the images its cameras explain, at least three of them, or both of two). The kept images
//! go on to Tomasi–Kanade (or, with dropped images, the gaps machinery) and bundle
//! adjustment; that fit's residuals give the threshold again (σ now corrected for the fit's
//! parameters) and its cameras judge every observation again, up to [`REJUDGE_ROUNDS`] times
//! until the judgement no longer changes.

use nalgebra::{Vector2, Vector3};
use rand::Rng;

use super::gaps::{intersect, resect};
use super::judge::{self, Images, Judgement};
use super::threshold::{self, Threshold};
use super::{BundleReport, Error, Frame, Observations, Reconstruction, Units, MIN_POINTS};
use crate::derivations::p4f3::{realize, solve_core};
use crate::model::{rng, squared_lengths};
use crate::numfmt::sig;

/// The generator's seed when none is given.
pub const DEFAULT_SEED: u64 = 1;
/// The probability that some sample is all inliers, which sets the number of samples.
pub const CONFIDENCE: f64 = 0.999;
/// Without a threshold, the share of clean points that sets the number of samples is taken
/// at most this (the median's breakdown point): the lenient threshold of a bad early sample
/// would count nearly every point clean and end the search after a sample or two. With it,
/// at least 108 samples are drawn (1 − ½⁴ per sample, 99.9 % confidence).
pub const LMEDS_SHARE: f64 = 0.5;
/// Judgements from a fit, at most, after the sample's: each refits when the judgement
/// changed.
pub const REJUDGE_ROUNDS: usize = 3;

/// Options of [`ransac`] and [`run`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RansacOptions {
    /// Largest distance (image units) from an image to its reprojection for an inlier;
    /// `None`: from the data (see [`threshold`](super::threshold)).
    pub threshold: Option<f64>,
    /// The seed of the sample generator.
    pub seed: u64,
    /// Samples at most.
    pub max_samples: usize,
}

impl RansacOptions {
    /// Options with the threshold, the default seed and the sample limit.
    pub fn new(threshold: f64) -> Self {
        RansacOptions {
            threshold: Some(threshold),
            ..RansacOptions::from_data()
        }
    }

    /// Options with the threshold from the data, the default seed and the sample limit.
    pub fn from_data() -> Self {
        RansacOptions {
            threshold: None,
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

/// Samples needed for [`CONFIDENCE`] that one is all inliers, at inlier share `w`.
pub fn samples_needed(w: f64, cap: usize) -> usize {
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
pub fn distinct<const N: usize>(g: &mut impl Rng, n: usize) -> [usize; N] {
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

/// The residual norm of every observation, point by point in `views` order, under the
/// cameras `cams`: each point intersected from all its images that have a camera; infinite
/// where the frame has no camera or the images do not fix the point.
fn sample_residuals(views: &[Images], cams: &[Option<Frame>], out: &mut Vec<f64>) {
    out.clear();
    for v in views {
        let x = intersect(cams, v);
        out.extend(v.iter().map(|(f, y)| match (x, cams[*f]) {
            (Some(x), Some(c)) => (c.project(&x) - y).norm(),
            _ => f64::INFINITY,
        }));
    }
}

/// A sample's score, the smaller the better: with a threshold, minus the number of
/// residuals within it; without, the median residual.
fn score(residuals: &[f64], given: Option<f64>, scratch: &mut Vec<f64>) -> f64 {
    match given {
        Some(t) => -(residuals.iter().filter(|&&r| r <= t).count() as f64),
        None => {
            scratch.clear();
            scratch.extend_from_slice(residuals);
            threshold::median(scratch).unwrap_or(f64::INFINITY)
        }
    }
}

/// The share of points whose every residual (in [`sample_residuals`]' order) is within `t`.
fn clean_share(views: &[Images], residuals: &[f64], t: f64) -> f64 {
    let (mut at, mut clean) = (0, 0usize);
    for v in views {
        let r = &residuals[at..at + v.len()];
        at += v.len();
        clean += usize::from(!r.is_empty() && r.iter().all(|&x| x <= t));
    }
    clean as f64 / views.len().max(1) as f64
}

/// The best sample: its cameras (one per frame, `None` in frames that do not see all four
/// points), the threshold it gives, and the samples drawn.
#[derive(Clone, Debug, PartialEq)]
pub struct Sample {
    /// The cameras.
    pub cameras: Vec<Option<Frame>>,
    /// The threshold given, or from the sample's median residual.
    pub threshold: Threshold,
    /// The samples drawn.
    pub samples: usize,
}

/// The options' threshold, when given, is a positive number.
fn check_threshold(o: &RansacOptions) -> Result<(), Error> {
    match o.threshold {
        Some(t) if !(t.is_finite() && t > 0.0) => Err(Error::InvalidOption(format!(
            "--threshold {t}: the inlier threshold must be a positive number of image units"
        ))),
        _ => Ok(()),
    }
}

/// The best sample of the observations (see the module); an error when no sample gives
/// cameras (that reproject at least half the observations, without a threshold).
pub fn ransac(obs: &Observations, o: &RansacOptions) -> Result<Sample, Error> {
    obs.check_counts()?;
    check_threshold(o)?;
    best_sample(obs, &judge::views(obs), o)
}

/// [`ransac`] on the observations' images by point.
fn best_sample(obs: &Observations, views: &[Images], o: &RansacOptions) -> Result<Sample, Error> {
    let (p, k) = (obs.names.len(), obs.frames.len());
    let floor = threshold::floor(Units::of(obs)?.scale, 1.0);
    let mut g = rng(o.seed);
    let mut best: Option<(f64, Vec<Option<Frame>>)> = None;
    let (mut res, mut scratch) = (Vec::with_capacity(obs.count()), Vec::new());
    let mut needed = o.max_samples.max(1);
    let mut drawn = 0;
    while drawn < needed {
        drawn += 1;
        let pts: [usize; 4] = distinct(&mut g, p);
        let frames3: [usize; 3] = distinct(&mut g, k);
        let Some(cams) = sample_cameras(obs, &pts, &frames3) else {
            continue;
        };
        sample_residuals(views, &cams, &mut res);
        let s = score(&res, o.threshold, &mut scratch);
        let bar = best.as_ref().map_or(f64::INFINITY, |b| b.0);
        if s.is_nan() || s >= bar {
            continue;
        }
        let (t, cap) = match o.threshold {
            Some(t) => (t, 1.0),
            None => (
                Threshold::from_median(s, res.len(), 1.0, floor).map_or(f64::INFINITY, |t| t.value),
                LMEDS_SHARE,
            ),
        };
        let share = clean_share(views, &res, t).min(cap);
        needed = samples_needed(share, o.max_samples).max(drawn);
        best = Some((s, cams));
    }
    let Some((s, cameras)) = best else {
        return Err(Error::Unreachable(format!(
            "ransac: none of {drawn} samples of four points in three frames gave cameras{}",
            if o.threshold.is_some() {
                ""
            } else {
                " that reproject half the observations"
            }
        )));
    };
    let threshold = match o.threshold {
        Some(t) => Threshold::given(t),
        None => Threshold::from_median(s, obs.count(), 1.0, floor).ok_or_else(|| {
            Error::Numerical("ransac: the best sample's median residual is not finite".into())
        })?,
    };
    Ok(Sample {
        cameras,
        threshold,
        samples: drawn,
    })
}

/// An observation robust mode dropped.
#[derive(Clone, Debug, PartialEq)]
pub struct Dropped {
    /// The point's name.
    pub point: String,
    /// The frame, counted from 1.
    pub frame: usize,
    /// Its distance (image units) from the reprojection of the point intersected from the
    /// final cameras: from its kept images, or from all its images for a rejected point;
    /// `None` when they do not fix it.
    pub residual: Option<f64>,
}

/// What robust mode did.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// The threshold of the final judgement.
    pub threshold: Threshold,
    /// The observations judged (every observation of the input).
    pub observations: usize,
    /// The points kept, in the tracks' order.
    pub kept: Vec<String>,
    /// Each kept point's inlier frames (counted from 1), in the tracks' order.
    pub inlier_frames: Vec<Vec<usize>>,
    /// The points rejected (fewer than [`judge::MIN_IMAGES`] images within the threshold, or
    /// not both of two), in the tracks' order.
    pub rejected: Vec<String>,
    /// The observations dropped, point by point (a rejected point's every image), frame by
    /// frame.
    pub dropped: Vec<Dropped>,
    /// RANSAC samples drawn.
    pub samples: usize,
    /// Judgements from a fit after the sample's.
    pub rounds: usize,
}

/// Robust mode's answer: the kept observations, their reconstruction, its bundle
/// adjustment, and the report.
#[derive(Clone, Debug, PartialEq)]
pub struct Fitted {
    /// The kept points with their kept images.
    pub used: Observations,
    /// The reconstruction of `used`.
    pub reconstruction: Reconstruction,
    /// Its bundle adjustment, when it ran.
    pub bundle: Option<BundleReport>,
    /// What robust mode did.
    pub report: Report,
}

/// A fit of a judgement's kept observations.
type Fit = (Observations, Reconstruction, Option<BundleReport>);

/// The pipeline's fit ([`super::fit`]) of a judgement's kept observations; an error when
/// fewer than [`MIN_POINTS`] points are kept.
fn fit_judged(
    obs: &Observations,
    judged: &Judgement,
    t: &Threshold,
    options: &super::Options,
) -> Result<Fit, Error> {
    if judged.kept.len() < MIN_POINTS {
        return Err(Error::Unreachable(format!(
            "ransac: {} point(s) keep {} images (or both of two) within {} image units: at least {MIN_POINTS} points are needed",
            judged.kept.len(),
            judge::MIN_IMAGES,
            sig(t.value)
        )));
    }
    let used = judged.observations(obs);
    let (rec, bundle) = super::fit(&used, options)?;
    Ok((used, rec, bundle))
}

/// A reconstruction's cameras for `frames` frames (`None` past its own).
fn cameras_of(rec: &Reconstruction, frames: usize) -> Vec<Option<Frame>> {
    (0..frames).map(|f| rec.frames.get(f).copied()).collect()
}

/// The residual norm of every observation (in [`judge::views`]' order) under a fit of the
/// points `kept`: a kept point at its fitted position, any other intersected from all its
/// images; infinite where its images do not fix it.
fn fit_residuals(
    views: &[Images],
    frames: usize,
    rec: &Reconstruction,
    kept: &[usize],
) -> Vec<f64> {
    let cams = cameras_of(rec, frames);
    let mut fitted: Vec<Option<Vector3<f64>>> = vec![None; views.len()];
    for (&j, x) in kept.iter().zip(&rec.points) {
        if let Some(slot) = fitted.get_mut(j) {
            *slot = Some(*x);
        }
    }
    let mut out = Vec::new();
    for (v, x) in views.iter().zip(fitted) {
        let x = x.or_else(|| intersect(&cams, v));
        out.extend(v.iter().map(|(f, y)| match (x, cams[*f]) {
            (Some(x), Some(c)) => (c.project(&x) - y).norm(),
            _ => f64::INFINITY,
        }));
    }
    out
}

/// The threshold from a fit's residuals (σ corrected for the fit's 3p + 5k − 6 parameters,
/// the floor for its conditioning); `None` when more than half the observations have no
/// residual.
fn fit_threshold(views: &[Images], fit: &Fit, kept: &[usize], size: f64) -> Option<Threshold> {
    let (used, rec, _) = fit;
    let frames = used.frames.len();
    let mut res = fit_residuals(views, frames, rec, kept);
    let shrink = threshold::shrink(2 * used.count(), threshold::parameters(kept.len(), frames));
    let rounding = threshold::rounding(rec.conditioning, kept.len(), frames);
    Threshold::from_residuals(&mut res, shrink, threshold::floor(size, rounding))
}

/// RANSAC, the judgement of every observation, the fit of the kept ones, and the judgement
/// again from the fit (see the module).
pub fn run(
    obs: &Observations,
    o: &RansacOptions,
    options: &super::Options,
) -> Result<Fitted, Error> {
    obs.check_counts()?;
    check_threshold(o)?;
    let views = judge::views(obs);
    let sample = best_sample(obs, &views, o)?;
    let (k, size) = (obs.frames.len(), Units::of(obs)?.scale);
    let mut threshold = sample.threshold;
    let mut judged = judge::judge(&views, k, &sample.cameras, threshold.value);
    let mut fit = fit_judged(obs, &judged, &threshold, options)?;
    let (mut rounds, mut note) = (0, None);
    while rounds < REJUDGE_ROUNDS {
        rounds += 1;
        let t = match o.threshold {
            Some(t) => Threshold::given(t),
            None => match fit_threshold(&views, &fit, &judged.kept, size) {
                Some(t) => t,
                None => {
                    note = Some("the fit reprojects fewer than half the observations: the earlier judgement kept".to_string());
                    break;
                }
            },
        };
        let next = judge::judge(&views, k, &cameras_of(&fit.1, k), t.value);
        if next.inlier == judged.inlier {
            judged = next;
            threshold = t;
            break;
        }
        match fit_judged(obs, &next, &t, options) {
            Ok(f) => {
                judged = next;
                threshold = t;
                fit = f;
            }
            Err(e) => {
                note = Some(format!(
                    "the judgement from the fit was not refitted ({e}): the earlier one kept"
                ));
                break;
            }
        }
    }
    let report = summary(obs, &judged, threshold, sample.samples, rounds);
    let (used, mut reconstruction, bundle) = fit;
    reconstruction
        .method
        .insert(0, method_line(&report, o.threshold.is_some(), note));
    Ok(Fitted {
        used,
        reconstruction,
        bundle,
        report,
    })
}

/// The report of the final judgement.
fn summary(
    obs: &Observations,
    judged: &Judgement,
    threshold: Threshold,
    samples: usize,
    rounds: usize,
) -> Report {
    let mut is_kept = vec![false; obs.names.len()];
    for &j in &judged.kept {
        is_kept[j] = true;
    }
    let names = |keep: bool| -> Vec<String> {
        obs.names
            .iter()
            .zip(&is_kept)
            .filter(|(_, k)| **k == keep)
            .map(|(n, _)| n.clone())
            .collect()
    };
    let inlier_frames = judged
        .kept
        .iter()
        .map(|&j| {
            (0..obs.frames.len())
                .filter(|&f| judged.inlier[f][j])
                .map(|f| f + 1)
                .collect()
        })
        .collect();
    Report {
        threshold,
        observations: obs.count(),
        kept: names(true),
        inlier_frames,
        rejected: names(false),
        dropped: judged
            .dropped
            .iter()
            .map(|d| Dropped {
                point: obs.names[d.point].clone(),
                frame: d.frame + 1,
                residual: d.residual,
            })
            .collect(),
        samples,
        rounds,
    }
}

/// The `method` line of robust mode.
fn method_line(r: &Report, given: bool, note: Option<String>) -> String {
    let mut s = format!(
        "ransac over the four-point solver: {} samples, the best by {}; judged again from the fit {} time(s): {} of {} observations dropped beyond {} image units, {} of {} points kept",
        r.samples,
        if given {
            "the most observations within the threshold"
        } else {
            "the least median residual"
        },
        r.rounds,
        r.dropped.len(),
        r.observations,
        sig(r.threshold.value),
        r.kept.len(),
        r.kept.len() + r.rejected.len()
    );
    if let Some(n) = note {
        s.push_str(" (");
        s.push_str(&n);
        s.push(')');
    }
    s
}
