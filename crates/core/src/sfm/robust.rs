//! Robust mode: RANSAC over the paper's own minimal solver, then a judgement of every
//! observation.
//!
//! Samples of four points in three frames are solved by §4's linear system
//! (`derivations::p4f3::solve_core`), the body realised from its squared edges, every frame's
//! camera fitted to the four points, every point intersected from those cameras. Where the
//! three frames share only three of the four points (tracks with gaps), §3's three-point
//! solver (`derivations::p3f3`) gives the hypotheses instead: each feasible edge solution's
//! depth-sign patterns, the other frames resected from the points they place. With a
//! threshold, the best sample puts the most observations within it of their reprojections;
//! without one, the best has the least median residual (least median of squares), and the
//! threshold comes from that median ([`threshold`]: the Rayleigh rule on
//! residual norms).
//!
//! The best sample's cameras judge every observation ([`judge`]: a point keeps
//! the images its cameras explain, at least three of them, or both of two). The kept images
//! go on to Tomasi–Kanade (or, with dropped images, the gaps machinery) and bundle
//! adjustment; that fit's residuals give the threshold again (σ now corrected for the fit's
//! parameters) and its cameras judge every observation again, up to [`REJUDGE_ROUNDS`] times
//! until the judgement no longer changes.
//!
//! On a long sequence of short tracks three random frames rarely share four points, and no
//! sample's cameras may reproject half the observations. Where the tracks have gaps, the
//! first judgement then comes from the pipeline's fit of every observation instead, and the
//! rounds above narrow its threshold (docs/limits.md, "Long sequences of short tracks").

use nalgebra::{Vector2, Vector3};
use rand::Rng;

use super::gaps::{intersect, resect};
use super::judge::{self, Images, Judgement};
use super::threshold::{self, Mix, Threshold};
use super::{BundleReport, Error, Frame, Observations, Reconstruction, Units, MIN_POINTS};
use crate::derivations::p3f3;
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

/// Huber's corner in σ of the residual, 1.345 (95 % of least squares' efficiency on normal
/// errors): the kept observations are adjusted with that loss, so an outlier the judgement
/// missed pulls with a bounded force; σ is the threshold's (the threshold over its multiple of
/// σ, 3.035 for a given one).
pub const HUBER_CORNER: f64 = 1.345;

/// Options of [`ransac`] and [`run`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RansacOptions {
    /// Largest distance (image units) from an image to its reprojection for an inlier;
    /// `None`: from the data (see [`threshold`]).
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

/// The sample's points, or, when the three frames do not see all four (tracks with gaps),
/// four drawn from the points they all see (three and a repeat when they share only three):
/// complete tracks draw nothing more, so their stream of samples is unchanged.
fn seen_in_all(
    obs: &Observations,
    pts: [usize; 4],
    frames3: &[usize; 3],
    g: &mut impl Rng,
) -> [usize; 4] {
    let all = |j: usize| frames3.iter().all(|&f| obs.frames[f][j].is_some());
    if pts.iter().all(|&j| all(j)) {
        return pts;
    }
    let common: Vec<usize> = (0..obs.names.len()).filter(|&j| all(j)).collect();
    match common.len() {
        0..=2 => pts,
        3 => [common[0], common[1], common[2], common[0]],
        n => distinct::<4>(g, n).map(|i| common[i]),
    }
}

/// The camera hypotheses of one sample: the four-point body's ([`sample_cameras`]), or,
/// where the three frames share only three of the four points, the paper's three-point
/// solver's ([`triangle_cameras`]).
fn hypotheses(
    obs: &Observations,
    views: &[Images],
    pts: &[usize; 4],
    frames3: &[usize; 3],
) -> (Vec<Vec<Option<Frame>>>, bool) {
    if let Some(cams) = sample_cameras(obs, pts, frames3) {
        return (vec![cams], false);
    }
    let mut shared: Vec<usize> = pts
        .iter()
        .copied()
        .filter(|&j| frames3.iter().all(|&f| obs.frames[f][j].is_some()))
        .collect();
    shared.sort_unstable();
    shared.dedup();
    match shared[..] {
        [a, b, c] => (triangle_cameras(obs, views, &[a, b, c], frames3), true),
        _ => (Vec::new(), false),
    }
}

/// Every camera hypothesis of three points in three frames by §3's solver: each feasible
/// edge solution's structure-and-motion solutions (a triangle's depth signs flip frame by
/// frame, 4 patterns in 3 frames up to the mirror), frame `frames3[0]`'s camera the
/// identity; then the other frames resected from the points those cameras place.
fn triangle_cameras(
    obs: &Observations,
    views: &[Images],
    pts: &[usize; 3],
    frames3: &[usize; 3],
) -> Vec<Vec<Option<Frame>>> {
    let image = |f: usize, j: usize| obs.frames[f][j].unwrap_or_default();
    let frames: Vec<Vec<Vector2<f64>>> = frames3
        .iter()
        .map(|&f| pts.iter().map(|&j| image(f, j)).collect())
        .collect();
    let l: [[f64; 3]; 3] = std::array::from_fn(|i| {
        let sq = squared_lengths(&frames[i].iter().map(|y| [y.x, y.y]).collect::<Vec<_>>());
        [sq[0], sq[1], sq[2]]
    });
    let core = p3f3::solve_core(&l);
    let names = pts.iter().map(|&j| obs.names[j].clone()).collect();
    let Ok(tracks) = crate::model::Tracks::new(names, frames) else {
        return Vec::new();
    };
    let mut out = Vec::new();
    for k in (0..core.count).filter(|&k| core.feasible[k]) {
        let recs = p3f3::reconstructions(&tracks, &core.squares[k]).unwrap_or_default();
        for rec in recs {
            let mut cams: Vec<Option<Frame>> = vec![None; obs.frames.len()];
            for (i, &f) in frames3.iter().enumerate() {
                // P is the origin of frame frames3[0]'s camera coordinates: t = P's image
                cams[f] = Some(Frame {
                    rotation: rec.rotations[i].into_inner(),
                    translation: image(f, pts[0]),
                });
            }
            out.push(extend_cameras(views, cams));
        }
    }
    out
}

/// The cameras extended to every frame that sees four points they place (each point
/// intersected from the cameras that see it). The frames' images are gathered from `views`,
/// point by point, so the work follows the images, not the frames × points table.
fn extend_cameras(views: &[Images], mut cams: Vec<Option<Frame>>) -> Vec<Option<Frame>> {
    let placed: Vec<Option<Vector3<f64>>> = views.iter().map(|v| intersect(&cams, v)).collect();
    let mut seen: Vec<Vec<(usize, Vector2<f64>)>> = vec![Vec::new(); cams.len()];
    for (j, v) in views.iter().enumerate() {
        for (f, y) in v {
            if cams[*f].is_none() {
                seen[*f].push((j, *y));
            }
        }
    }
    for (f, images) in seen.iter().enumerate() {
        if cams[f].is_none() {
            cams[f] = resect(&placed, images);
        }
    }
    cams
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
    /// Of them, those solved by the three-point solver (three frames sharing only three of
    /// the sample's points).
    pub triangles: usize,
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
    best_sample(obs, &judge::views(obs), o)?.map_err(|(drawn, _)| no_sample(drawn, o))
}

/// The error of a search in which no sample gave cameras (that reproject half the
/// observations, without a threshold).
fn no_sample(drawn: usize, o: &RansacOptions) -> Error {
    Error::Unreachable(format!(
        "ransac: none of {drawn} samples of four points in three frames gave cameras{}",
        if o.threshold.is_some() {
            ""
        } else {
            " that reproject half the observations"
        }
    ))
}

/// What a search found: the best sample, or, when no sample gave cameras, the samples drawn
/// and of them those by the three-point solver.
type Search = Result<Sample, (usize, usize)>;

/// The samples needed once a sample of score `s` and residuals `res` is the best: from the
/// share of clean points its threshold (given, or from its median) counts.
fn needed_after(views: &[Images], res: &[f64], s: f64, o: &RansacOptions, floor: f64) -> usize {
    let (t, cap) = match o.threshold {
        Some(t) => (t, 1.0),
        None => (
            Threshold::from_median(s, res.len(), 1.0, floor).map_or(f64::INFINITY, |t| t.value),
            LMEDS_SHARE,
        ),
    };
    samples_needed(clean_share(views, res, t).min(cap), o.max_samples)
}

/// [`ransac`] on the observations' images by point.
fn best_sample(obs: &Observations, views: &[Images], o: &RansacOptions) -> Result<Search, Error> {
    let (p, k) = (obs.names.len(), obs.frames.len());
    let floor = threshold::floor(Units::of(obs)?.scale, 1.0);
    let mut g = rng(o.seed);
    let mut best: Option<(f64, Vec<Option<Frame>>)> = None;
    let (mut res, mut scratch) = (Vec::with_capacity(obs.count()), Vec::new());
    let mut needed = o.max_samples.max(1);
    let (mut drawn, mut triangles) = (0, 0);
    while drawn < needed {
        drawn += 1;
        let pts: [usize; 4] = distinct(&mut g, p);
        let frames3: [usize; 3] = distinct(&mut g, k);
        let pts = seen_in_all(obs, pts, &frames3, &mut g);
        let (hyps, by_three) = hypotheses(obs, views, &pts, &frames3);
        triangles += usize::from(by_three && !hyps.is_empty());
        for cams in hyps {
            sample_residuals(views, &cams, &mut res);
            let s = score(&res, o.threshold, &mut scratch);
            let bar = best.as_ref().map_or(f64::INFINITY, |b| b.0);
            if s.is_nan() || s >= bar {
                continue;
            }
            needed = needed_after(views, &res, s, o, floor).max(drawn);
            best = Some((s, cams));
        }
    }
    let Some((s, cameras)) = best else {
        return Ok(Err((drawn, triangles)));
    };
    let threshold = match o.threshold {
        Some(t) => Threshold::given(t),
        None => Threshold::from_median(s, obs.count(), 1.0, floor).ok_or_else(|| {
            Error::Numerical("ransac: the best sample's median residual is not finite".into())
        })?,
    };
    Ok(Ok(Sample {
        cameras,
        threshold,
        samples: drawn,
        triangles,
    }))
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
    /// `None` when they do not fix it. The plain distance: the judgement weighed each
    /// coordinate by the threshold's mix of noise scales ([`threshold::scaled`]), so where
    /// the noise grows with the coordinates a dropped image near the image's origin may lie
    /// nearer than the threshold's value (and one far from it farther).
    pub residual: Option<f64>,
}

/// What robust mode did.
#[derive(Clone, Debug, PartialEq)]
pub struct RobustReport {
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
    /// Of them, those solved by the three-point solver.
    pub triangles: usize,
    /// Judgements from a fit after the sample's.
    pub rounds: usize,
    /// Whether the first judgement came from the fit of every observation, not from a
    /// sample: tracks with gaps where no sample's cameras reprojected half the observations
    /// (three frames of a long sequence rarely share four points).
    pub whole_fit: bool,
}

/// The samples drawn, of them those by the three-point solver, and whether the first
/// judgement came from the fit of every observation rather than the best sample.
#[derive(Clone, Copy, Debug)]
struct Start {
    samples: usize,
    triangles: usize,
    whole_fit: bool,
}

/// The first judgement of tracks with gaps where no sample's cameras reprojected half the
/// observations: the pipeline's fit of every observation (least squares: no threshold is
/// known yet), its residuals' threshold (or the one given), its cameras' judgement and the
/// fit of what that judgement keeps (with the Huber loss of the threshold). Outliers pull
/// the first fit, so its threshold is wide; the rounds of [`run`] narrow it.
fn from_whole_fit(
    obs: &Observations,
    views: &[Images],
    o: &RansacOptions,
    size: f64,
    (options, numbers): (&super::Options, &[usize]),
) -> Result<(Threshold, Judgement, Fit), Error> {
    let k = obs.frames.len();
    let (rec, bundle) = super::fit(obs, options, None, numbers)?;
    // every observation kept, every point in the fit's order
    let every = Judgement {
        inlier: obs
            .frames
            .iter()
            .map(|row| row.iter().map(Option::is_some).collect())
            .collect(),
        kept: (0..obs.names.len()).collect(),
        dropped: Vec::new(),
    };
    let whole = (obs.clone(), rec, bundle);
    let t = match o.threshold {
        Some(t) => Threshold::given(t),
        // the fit places every point and camera, so every observation has a residual and
        // this cannot fail; an error rather than a panic all the same
        None => fit_threshold(views, &whole, &every, size).ok_or_else(|| {
            Error::Unreachable("the fit reprojects fewer than half the observations".into())
        })?,
    };
    let judged = judge::judge(views, k, &cameras_of(&whole.1, k), (t.value, t.mix()));
    let fit = fit_judged(obs, &judged, &t, (options, numbers))?;
    Ok((t, judged, fit))
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
    pub report: RobustReport,
}

/// A fit of a judgement's kept observations.
type Fit = (Observations, Reconstruction, Option<BundleReport>);

/// The pipeline's fit ([`super::fit`]) of a judgement's kept observations; an error when
/// fewer than [`MIN_POINTS`] points are kept.
fn fit_judged(
    obs: &Observations,
    judged: &Judgement,
    t: &Threshold,
    (options, numbers): (&super::Options, &[usize]),
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
    let corner = t.value * HUBER_CORNER / t.multiple();
    let (rec, bundle) = super::fit(&used, options, Some(corner), numbers)?;
    Ok((used, rec, bundle))
}

/// A reconstruction's cameras for `frames` frames (`None` past its own).
fn cameras_of(rec: &Reconstruction, frames: usize) -> Vec<Option<Frame>> {
    (0..frames).map(|f| rec.frames.get(f).copied()).collect()
}

/// The residual of every observation (in [`judge::views`]' order) under a fit of the points
/// `kept`: a kept point at its fitted position, any other intersected from all its images;
/// `None` where its images do not fix it.
fn fit_errors(
    views: &[Images],
    frames: usize,
    rec: &Reconstruction,
    kept: &[usize],
) -> Vec<Option<Vector2<f64>>> {
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
            (Some(x), Some(c)) => Some(c.project(&x) - y),
            _ => None,
        }));
    }
    out
}

/// The mix of noise scales of most likelihood for the kept observations' residuals,
/// coordinate by coordinate (each with its coordinate's square), and whether it was
/// estimated: one scale when the fit leaves fewer than [`threshold::MIX_MIN_FREEDOM`]
/// residual degrees of freedom.
fn fit_mix(views: &[Images], errors: &[Option<Vector2<f64>>], judged: &Judgement) -> (Mix, bool) {
    let mut items = Vec::new();
    let mut at = 0;
    for (j, v) in views.iter().enumerate() {
        for ((f, y), e) in v.iter().zip(&errors[at..at + v.len()]) {
            if let (true, Some(e)) = (judged.inlier[*f][j], e) {
                items.push((e.x, y.x * y.x));
                items.push((e.y, y.y * y.y));
            }
        }
        at += v.len();
    }
    let parameters = threshold::parameters(judged.kept.len(), judged.inlier.len());
    if items.len() < parameters + threshold::MIX_MIN_FREEDOM {
        return (Mix::UNIFORM, false);
    }
    (Mix::most_likely(&items), true)
}

/// The threshold from a fit's residuals (σ corrected for the fit's 3p + 5k − 6 parameters,
/// the floor for its conditioning; each residual weighed by the mix of noise scales the
/// kept ones give); `None` when more than half the observations have no residual.
fn fit_threshold(views: &[Images], fit: &Fit, judged: &Judgement, size: f64) -> Option<Threshold> {
    let (used, rec, _) = fit;
    let (frames, kept) = (used.frames.len(), &judged.kept);
    let errors = fit_errors(views, frames, rec, kept);
    let (mix, estimated) = fit_mix(views, &errors, judged);
    let mut res: Vec<f64> = views
        .iter()
        .flatten()
        .zip(&errors)
        .map(|((_, y), e)| e.map_or(f64::INFINITY, |e| threshold::scaled(e, *y, &mix)))
        .collect();
    let (coordinates, parameters) = (2 * used.count(), threshold::parameters(kept.len(), frames));
    let shrink = threshold::shrink(coordinates, parameters);
    let rounding = threshold::rounding(rec.conditioning, kept.len(), frames);
    // one degree more is spent on the mix where it was estimated; without residual freedom
    // σ is rounding, and the floor decides
    let freedom = coordinates.saturating_sub(parameters + usize::from(estimated));
    Threshold::from_residuals(&mut res, shrink, threshold::floor(size, rounding)).map(|t| {
        let t = t.with_mix(mix);
        if freedom > 0 {
            t.with_freedom(freedom)
        } else {
            t
        }
    })
}

/// The first judgement and the fit of what it keeps: from the best sample, or, on tracks
/// with gaps where no sample gave cameras, from the fit of every observation
/// ([`from_whole_fit`]; an error of that fit says that no sample gave cameras either).
fn first_judgement(
    obs: &Observations,
    views: &[Images],
    o: &RansacOptions,
    size: f64,
    (options, numbers): (&super::Options, &[usize]),
) -> Result<(Threshold, Judgement, Fit, Start), Error> {
    let k = obs.frames.len();
    match best_sample(obs, views, o)? {
        Ok(sample) => {
            let t = sample.threshold;
            let judged = judge::judge(views, k, &sample.cameras, (t.value, t.mix()));
            let fit = fit_judged(obs, &judged, &t, (options, numbers))?;
            let start = Start {
                samples: sample.samples,
                triangles: sample.triangles,
                whole_fit: false,
            };
            Ok((t, judged, fit, start))
        }
        Err((drawn, triangles)) if obs.count() < obs.names.len() * k => {
            let (t, judged, fit) = from_whole_fit(obs, views, o, size, (options, numbers))
                .map_err(|e| {
                    let none = no_sample(drawn, o);
                    let then = |why: String| {
                        format!("{none}, and from the fit of every observation: {why}")
                    };
                    match e {
                        Error::Unreachable(why) => Error::Unreachable(then(why)),
                        Error::TooLarge(why) => Error::TooLarge(then(why)),
                        Error::Numerical(why) => Error::Numerical(then(why)),
                        e => e,
                    }
                })?;
            let start = Start {
                samples: drawn,
                triangles,
                whole_fit: true,
            };
            Ok((t, judged, fit, start))
        }
        Err((drawn, _)) => Err(no_sample(drawn, o)),
    }
}

/// RANSAC, the judgement of every observation, the fit of the kept ones, and the judgement
/// again from the fit (see the module). `numbers`: the input's number (from 1) of each frame
/// of `obs`, as the report and the messages name them.
pub fn run(
    obs: &Observations,
    o: &RansacOptions,
    options: &super::Options,
    numbers: &[usize],
) -> Result<Fitted, Error> {
    obs.check_counts()?;
    check_threshold(o)?;
    let views = judge::views(obs);
    let (k, size) = (obs.frames.len(), Units::of(obs)?.scale);
    let (mut threshold, mut judged, mut fit, start) =
        first_judgement(obs, &views, o, size, (options, numbers))?;
    let (mut rounds, mut note) = (0, None);
    while rounds < REJUDGE_ROUNDS {
        rounds += 1;
        let t = match o.threshold {
            Some(t) => Threshold::given(t),
            None => match fit_threshold(&views, &fit, &judged, size) {
                Some(t) => t,
                None => {
                    note = Some("the fit reprojects fewer than half the observations: the earlier judgement kept".to_string());
                    break;
                }
            },
        };
        let next = judge::judge(&views, k, &cameras_of(&fit.1, k), (t.value, t.mix()));
        if next.inlier == judged.inlier {
            judged = next;
            threshold = t;
            break;
        }
        match fit_judged(obs, &next, &t, (options, numbers)) {
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
    let report = summary((obs, numbers), &judged, threshold, start, rounds);
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

/// The report of the final judgement (frames by their numbers in the input).
fn summary(
    (obs, numbers): (&Observations, &[usize]),
    judged: &Judgement,
    threshold: Threshold,
    start: Start,
    rounds: usize,
) -> RobustReport {
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
                .map(|f| numbers[f])
                .collect()
        })
        .collect();
    RobustReport {
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
                frame: numbers[d.frame],
                residual: d.residual,
            })
            .collect(),
        samples: start.samples,
        triangles: start.triangles,
        rounds,
        whole_fit: start.whole_fit,
    }
}

/// The `method` line of robust mode.
fn method_line(r: &RobustReport, given: bool, note: Option<String>) -> String {
    let by_three = if r.triangles > 0 {
        format!(
            " ({} of them by the three-point solver: three frames sharing only three points)",
            r.triangles
        )
    } else {
        String::new()
    };
    let first = match (r.whole_fit, given) {
        (true, _) => format!(
            "ransac over the four-point solver: none of {} samples{by_three} gave cameras{} (tracks with gaps: three frames rarely share four points), so the first judgement came from the fit of every observation",
            r.samples,
            if given {
                ""
            } else {
                " that reproject half the observations"
            }
        ),
        (false, true) => format!(
            "ransac over the four-point solver: {} samples{by_three}, the best by the most observations within the threshold",
            r.samples
        ),
        (false, false) => format!(
            "ransac over the four-point solver: {} samples{by_three}, the best by the least median residual",
            r.samples
        ),
    };
    let mut s = format!(
        "{first}; judged again from the fit {} time(s): {} of {} observations dropped beyond {} image units, {} of {} points kept",
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
