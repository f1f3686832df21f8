//! The pipeline of `orthocheck reconstruct`: the points and frames that cannot take part
//! dropped and the rest split into groups ([`groups`]), then each group reconstructed in its
//! own frame of reference, with a warning wherever a step can tell that its answer may be
//! wrong (kept in [`Reconstruction::warnings`]).

use super::groups::{self, DroppedFrame, DroppedPoint, Group, Partition};
use super::{
    bundle, factor, gaps, judge, missing, robust, tomasi_kanade, BundleReport, Degenerate, Error,
    Observations, Reconstruction,
};
use crate::numfmt::sig;

mod starts;

/// Options of [`reconstruct`].
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// Refine by bundle adjustment.
    pub bundle: bool,
    /// Levenberg–Marquardt iterations at most.
    pub max_iterations: usize,
    /// RANSAC over the four-point solver, when given.
    pub robust: Option<robust::RansacOptions>,
    /// The seed of variable projection's random starts (tried when the chain of frame pairs
    /// breaks); RANSAC's samples take theirs from `robust`.
    pub seed: u64,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            bundle: true,
            max_iterations: bundle::MAX_ITERATIONS,
            robust: None,
            seed: robust::DEFAULT_SEED,
        }
    }
}

/// One group of frames (see [`groups`]), reconstructed in its own frame of reference.
#[derive(Clone, Debug, PartialEq)]
pub struct Component {
    /// The input's number (from 1) of each of the reconstruction's frames, in order.
    pub frames: Vec<usize>,
    /// The reconstruction; its `warnings` say what may be wrong with it.
    pub reconstruction: Reconstruction,
    /// Its mirror (Necker) twin: the same images.
    pub mirror: Reconstruction,
    /// Root mean square reprojection distance, in image units, over the points used.
    pub rms: f64,
    /// In robust mode: the names of the points kept (each with its inlier images).
    pub inliers: Option<Vec<String>>,
    /// The bundle adjustment, when it ran.
    pub bundle: Option<BundleReport>,
    /// In robust mode: the threshold, the dropped observations (frames numbered as in the
    /// input), the rejected points.
    pub robust: Option<robust::RobustReport>,
}

/// What [`reconstruct`] returns.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// The groups, in the order of their first frames: one when every frame kept is linked
    /// to the others.
    pub components: Vec<Component>,
    /// The points that could not take part, in the tracks' order.
    pub dropped_points: Vec<DroppedPoint>,
    /// The frames that could not take part, in order.
    pub dropped_frames: Vec<DroppedFrame>,
}

impl Outcome {
    /// The one component, when the frames form one group.
    pub fn into_single(self) -> Option<Component> {
        match <[Component; 1]>::try_from(self.components) {
            Ok([c]) => Some(c),
            Err(_) => None,
        }
    }

    /// Every component's warnings, each led by its group's label when there are several.
    pub fn warnings(&self) -> Vec<String> {
        let n = self.components.len();
        let mut out = Vec::new();
        for (i, c) in self.components.iter().enumerate() {
            for w in &c.reconstruction.warnings {
                out.push(match n {
                    1 => w.clone(),
                    _ => format!("{}: {w}", group_label(i, n, &c.frames)),
                });
            }
        }
        out
    }
}

/// "group 2 of 3 (frames 4–6, 9)".
pub fn group_label(i: usize, n: usize, frames: &[usize]) -> String {
    format!("group {} of {n} (frames {})", i + 1, ranges(frames))
}

/// Whole numbers, ascending, as runs: "1–3, 7, 9–10".
pub fn ranges(v: &[usize]) -> String {
    let mut parts: Vec<String> = Vec::new();
    for run in v.chunk_by(|a, b| *a + 1 == *b) {
        parts.push(match run {
            [one] => one.to_string(),
            [a, b] => format!("{a}, {b}"),
            _ => format!("{}–{}", run[0], run[run.len() - 1]),
        });
    }
    parts.join(", ")
}

/// The pipeline of `orthocheck reconstruct`: the points and frames that cannot take part
/// dropped and the frames split into groups ([`groups::partition`]); each group by RANSAC and
/// the judgement of every observation in robust mode ([`robust::run`]: the kept images go
/// on), Tomasi–Kanade (complete tracks) or the paths for gaps, bundle adjustment, the depth
/// check ([`depth_warning`]) and the mirror twin. An error when no frame can take part, or
/// when a group fails (named, when there are several).
pub fn reconstruct(obs: &Observations, options: &Options) -> Result<Outcome, Error> {
    obs.check_counts()?;
    let parts = groups::partition(obs);
    if parts.groups.is_empty() {
        return Err(nothing_left(&parts));
    }
    let n = parts.groups.len();
    let mut components = Vec::with_capacity(n);
    for (i, g) in parts.groups.iter().enumerate() {
        let c = component(obs, g, options).map_err(|e| match n {
            1 => e,
            _ => in_group(e, &group_label(i, n, &numbers(g))),
        })?;
        components.push(c);
    }
    Ok(Outcome {
        components,
        dropped_points: parts.dropped_points,
        dropped_frames: parts.dropped_frames,
    })
}

/// The input's numbers (from 1) of a group's frames.
fn numbers(g: &Group) -> Vec<usize> {
    g.frames.iter().map(|f| f + 1).collect()
}

/// One group's reconstruction.
fn component(obs: &Observations, g: &Group, options: &Options) -> Result<Component, Error> {
    let numbers = numbers(g);
    let whole = g.frames.len() == obs.frames.len() && g.points.len() == obs.names.len();
    let part;
    let used = if whole {
        obs
    } else {
        part = g.observations(obs);
        &part
    };
    let (mut rec, bundle, robust, rms) = match &options.robust {
        Some(r) => {
            let f = robust::run(used, r, options, &numbers)?;
            let rms = f.reconstruction.rms(&f.used);
            (f.reconstruction, f.bundle, Some(f.report), rms)
        }
        None => {
            let (rec, bundle) = starts::best_fit(used, options, &numbers)?;
            let rms = rec.rms(used);
            (rec, bundle, None, rms)
        }
    };
    rec.warnings.extend(depth_warning(&rec));
    Ok(Component {
        frames: numbers,
        mirror: rec.mirror(),
        reconstruction: rec,
        rms,
        inliers: robust.as_ref().map(|r| r.kept.clone()),
        bundle,
        robust,
    })
}

/// The error when every frame was dropped: how many, and the first few with their reasons.
fn nothing_left(parts: &Partition) -> Error {
    const LISTED: usize = 5;
    let d = &parts.dropped_frames;
    let mut why: Vec<String> = d
        .iter()
        .take(LISTED)
        .map(|f| format!("frame {}: {}", f.frame, f.why))
        .collect();
    if d.len() > LISTED {
        why.push(format!("and {} more", d.len() - LISTED));
    }
    Error::Unreachable(format!(
        "no frame can take part: all {} frames were dropped ({})",
        d.len(),
        why.join("; ")
    ))
}

/// A group's error, led by its label.
fn in_group(e: Error, label: &str) -> Error {
    match e {
        Error::Numerical(m) => Error::Numerical(format!("{label}: {m}")),
        Error::TooLarge(m) => Error::TooLarge(format!("{label}: {m}")),
        e => Error::Unreachable(format!("{label}: {e}")),
    }
}

/// An error about frames of a part (counted from 1 within it) with the frames' own numbers:
/// `numbers[i]` for the part's frame i + 1.
pub(crate) fn renumber(e: Error, numbers: &[usize]) -> Error {
    let n = |i: usize| {
        i.checked_sub(1)
            .and_then(|i| numbers.get(i))
            .copied()
            .unwrap_or(i)
    };
    match e {
        Error::Degenerate(Degenerate::InPlaneMotion { first, second }) => {
            Error::Degenerate(Degenerate::InPlaneMotion {
                first: n(first),
                second: n(second),
            })
        }
        Error::Degenerate(Degenerate::IdenticalFrames { first, second }) => {
            Error::Degenerate(Degenerate::IdenticalFrames {
                first: n(first),
                second: n(second),
            })
        }
        e => e,
    }
}

/// `why` led by the path's name, unless it names the path already.
fn labelled(name: &str, why: &str) -> String {
    if why.starts_with(name) {
        why.to_string()
    } else {
        format!("{name}: {why}")
    }
}

/// The start of tracks with gaps. With most entries missing (a turntable), variable
/// projection from the chained pairs ([`missing::reconstruct`]) first, the largest complete
/// block grown when it fails; with fewer missing, the other way round. `method` names the
/// path taken, and why the first failed; when both fail, the error gives both reasons.
/// `numbers`: the input's number of each frame, for the messages.
fn with_gaps(
    used: &Observations,
    options: &Options,
    numbers: &[usize],
) -> Result<Reconstruction, Error> {
    // identical frames, or frames differing in-plane only, judged on what is observed: the
    // same refusal as for complete tracks, whichever path would start
    if let Some((first, second)) = factor::same_view(&judge::views(used)) {
        let e = Error::Degenerate(Degenerate::InPlaneMotion { first, second });
        return Err(renumber(e, numbers));
    }
    let cells = used.frames.len() * used.names.len();
    let mostly_missing = 2 * used.count() < cells;
    let run = |varpro: bool| {
        if varpro {
            missing::reconstruct(used, options.seed).map_err(|e| renumber(e, numbers))
        } else {
            gaps::initial_numbered(used, numbers)
        }
    };
    let name = |varpro: bool| {
        if varpro {
            "variable projection"
        } else {
            "largest complete block"
        }
    };
    let why = match run(mostly_missing) {
        Err(Error::Unreachable(why) | Error::Numerical(why)) => why,
        done => return done,
    };
    let first = labelled(name(mostly_missing), &why);
    match run(!mostly_missing) {
        Ok(mut r) => {
            r.method.insert(0, first);
            Ok(r)
        }
        Err(Error::Unreachable(second)) => Err(Error::Unreachable(format!(
            "{first}; {}",
            labelled(name(!mostly_missing), &second)
        ))),
        Err(e) => Err(e),
    }
}

/// The fit of observations: Tomasi–Kanade (complete tracks) or the paths for gaps, then
/// bundle adjustment when asked and within its limits; an error on a non-finite coordinate.
/// `numbers`: the input's number of each frame of `used`, for the messages.
pub(crate) fn fit(
    used: &Observations,
    options: &Options,
    huber: Option<f64>,
    numbers: &[usize],
) -> Result<(Reconstruction, Option<BundleReport>), Error> {
    let mut rec = match used.complete() {
        Some(t) => tomasi_kanade(&t).map_err(|e| renumber(e, numbers))?,
        None => with_gaps(used, options, numbers)?,
    };
    let report = if options.bundle {
        let bo = bundle::BundleOptions {
            huber,
            ..bundle::BundleOptions::with(options)
        };
        adjust(used, &mut rec, &bo)?
    } else {
        None
    };
    if !rec.is_finite() {
        return Err(Error::Numerical(
            "a non-finite coordinate in the reconstruction".into(),
        ));
    }
    Ok((rec, report))
}

/// Bundle adjustment of `rec` within its limits; beyond them it is skipped, and `method` and
/// a warning say so (the body is then the unrefined start).
fn adjust(
    used: &Observations,
    rec: &mut Reconstruction,
    bo: &bundle::BundleOptions,
) -> Result<Option<BundleReport>, Error> {
    let frames = used.frames.len();
    let skipped = if frames > crate::limits::BUNDLE_FRAMES {
        Some(format!(
            "{frames} frames, more than the limit of {}",
            crate::limits::BUNDLE_FRAMES
        ))
    } else if used.count() > crate::limits::BUNDLE_OBSERVATIONS {
        Some(format!(
            "{} observations, more than the limit of {}",
            used.count(),
            crate::limits::BUNDLE_OBSERVATIONS
        ))
    } else if bundle::work(used) > crate::limits::BUNDLE_WORK {
        Some(format!(
            "its work (Σ frames² per point) exceeds the limit of {}",
            crate::limits::BUNDLE_WORK
        ))
    } else {
        None
    };
    if let Some(why) = skipped {
        rec.method.push(format!(
            "bundle adjustment skipped: {why} (see docs/limits.md)"
        ));
        rec.warnings.push(format!(
            "bundle adjustment was skipped ({why}; docs/limits.md): the body is the unrefined start, not the least-squares fit"
        ));
        return Ok(None);
    }
    let adjusted = bundle::bundle_adjust(used, rec, bo)?;
    *rec = adjusted.reconstruction;
    Ok(Some(adjusted.report))
}

/// Depths beyond this many times the body's image extent are warned of. A rigid body whose
/// images all lie within E of their centroid has a depth d along one frame's viewing
/// direction of at most 2E / sin φ, φ the largest angle between that direction and another
/// frame's (d sin φ shows in that frame's image, less the in-plane part, at most E). So
/// d > 100 E needs every frame within arcsin(1/50) ≈ 1.1° of one view: depth resting on
/// image differences 50 times smaller than the body, where an ill-posed metric upgrade puts
/// points, and far more motion than that is what the data of a real body show.
pub const DEPTH_FACTOR: f64 = 100.0;

/// Points named in the depth warning at most.
const DEEP_NAMED: usize = 5;

/// The warning of points at depths (from the centroid) beyond [`DEPTH_FACTOR`] × the body's
/// image extent (the largest distance of a point's reprojection from the centroid's, over
/// every frame), in any frame, the deepest named first; `None` when there are none.
pub fn depth_warning(rec: &Reconstruction) -> Option<String> {
    let n = rec.points.len().max(1) as f64;
    let c = rec.points.iter().sum::<nalgebra::Vector3<f64>>() / n;
    let depth_image = |x: &nalgebra::Vector3<f64>| {
        rec.frames.iter().fold((0.0_f64, 0.0_f64), |(d, e), f| {
            let v = f.rotation * (x - c);
            (d.max(v.z.abs()), e.max(v.xy().norm()))
        })
    };
    let per_point: Vec<(f64, f64)> = rec.points.iter().map(depth_image).collect();
    let extent = per_point.iter().fold(0.0_f64, |m, p| m.max(p.1));
    let mut deep: Vec<(usize, f64)> = per_point
        .iter()
        .enumerate()
        .filter(|(_, p)| p.0 > DEPTH_FACTOR * extent)
        .map(|(j, p)| (j, p.0))
        .collect();
    // the deepest named first
    deep.sort_by(|a, b| b.1.total_cmp(&a.1));
    let deepest = deep.first().map_or(0.0, |d| d.1);
    let mut names: Vec<&str> = deep
        .iter()
        .take(DEEP_NAMED)
        .map(|&(j, _)| rec.names[j].as_str())
        .collect();
    let more = format!("and {} more", deep.len().saturating_sub(DEEP_NAMED));
    if deep.len() > DEEP_NAMED {
        names.push(&more);
    }
    (!deep.is_empty()).then(|| {
        format!(
            "{} point(s) ({}) lie at depths beyond {} × the body's image extent {} (the deepest at {}): that needs every frame within about 1° of one view, where depth is barely fixed; a sign of an ill-posed metric upgrade",
            deep.len(),
            names.join(", "),
            sig(DEPTH_FACTOR),
            sig(extent),
            sig(deepest)
        )
    })
}

/// How far beyond its typical share a frame's residual may go before the fit is called
/// uneven: the Wilson–Hilferty point of χ²_ν/ν at z = 5 (about 3·10⁻⁷ one-sided per frame,
/// so a fit at its optimum with iid noise warns about once in 30,000 runs of 100 frames).
pub const UNEVEN_Z: f64 = 5.0;

/// The least ratio that calls a frame's fit uneven, whatever its degrees of freedom: a
/// frame's noise may well be twice the median frame's (a tracker's accuracy varies with the
/// image, relative noise with the body's extent in the frame), a mean square four times as
/// large. A chosen factor: at turntable rates the frames of good fits stayed below 3.8, those
/// of local optima reached 3 to 480 (`turntable_family`, docs/limits.md). On a real sequence
/// the images themselves differ more: the Oxford dinosaur's frames 13–16 fit 4.5–5.6 times
/// worse than the median frame under the sequence's own calibrated cameras, and the
/// warning names 14 and 15 at the optimum (`real_turntable`, docs/limits.md), so it names
/// both causes.
pub const UNEVEN_FLOOR: f64 = 4.0;

/// The warning of frames whose reprojection error is far beyond the others': a fit at its
/// optimum leaves every frame a share of the noise in proportion to its observations, a
/// local optimum leaves some frames fitting badly, and so do images worse than the rest
/// (mismatched tracks). Each frame's mean squared residual per
/// degree of freedom (ν = 2 n − 5 for its n images and five parameters) is compared with
/// the median frame's, scaled by the χ²_ν/ν point at [`UNEVEN_Z`] and at least
/// [`UNEVEN_FLOOR`]; `None` when every frame
/// is within it (or fewer than three frames have residual freedom). `numbers` names the
/// frames as the input does.
pub fn uneven_warning(
    obs: &Observations,
    rec: &Reconstruction,
    numbers: &[usize],
) -> Option<String> {
    let bad = uneven_frames(obs, rec);
    let named: Vec<String> = bad
        .iter()
        .take(DEEP_NAMED)
        .map(|(f, r)| {
            format!(
                "{} ({}×)",
                numbers.get(*f).copied().unwrap_or(f + 1),
                sig(*r)
            )
        })
        .collect();
    (!bad.is_empty()).then(|| {
        format!(
            "{} frame(s) fit far worse than the median frame (frame, mean squared residual over the median's): {}{}: a local optimum, not the best fit, or images in those frames worse than the rest (--robust drops observations beyond its threshold)",
            bad.len(),
            named.join(", "),
            if bad.len() > DEEP_NAMED { ", …" } else { "" }
        )
    })
}

/// The frames of [`uneven_warning`] (indices into `rec.frames`), each with its mean squared
/// residual over the median frame's, the worst first.
pub(crate) fn uneven_frames(obs: &Observations, rec: &Reconstruction) -> Vec<(usize, f64)> {
    let k = rec.frames.len();
    let (mut ss, mut n) = (vec![0.0f64; k], vec![0usize; k]);
    for (f, j, y) in obs.seen() {
        ss[f] += (rec.frames[f].project(&rec.points[j]) - y).norm_squared();
        n[f] += 1;
    }
    let per: Vec<(usize, f64, f64)> = (0..k)
        .filter(|&f| 2 * n[f] > 5)
        .map(|f| {
            let nu = (2 * n[f] - 5) as f64;
            (f, ss[f] / nu, nu)
        })
        .collect();
    if per.len() < 3 {
        return Vec::new();
    }
    let mut means: Vec<f64> = per.iter().map(|p| p.1).collect();
    means.sort_by(f64::total_cmp);
    let median = means[means.len() / 2];
    if median.is_nan() || median <= 0.0 {
        return Vec::new();
    }
    let limit = |nu: f64| {
        let a = 2.0 / (9.0 * nu);
        (1.0 - a + UNEVEN_Z * a.sqrt()).powi(3)
    };
    let mut bad: Vec<(usize, f64)> = per
        .iter()
        .filter(|(_, m, nu)| *m > median * limit(*nu).max(UNEVEN_FLOOR))
        .map(|(f, m, _)| (*f, m / median))
        .collect();
    bad.sort_by(|a, b| b.1.total_cmp(&a.1));
    bad
}
