//! Judging every observation against cameras: robust mode keeps each point whose images the
//! cameras explain, less the images they do not.
//!
//! A point's rule: intersect it from all its images (least squares); while some image lies
//! farther than the threshold from its reprojection, drop the worst (a point with n ≥ 2 ×
//! [`BATCH`] images left drops its worst ⌊n/[`BATCH`]⌋ beyond the threshold at once) and
//! intersect again. Elimination never leaves fewer than [`MIN_IMAGES`] images: a
//! point that would need it is rejected, all its images dropped. A point seen in two frames
//! only is kept when both images are inliers (one check, and no choice made among images).
//! Residuals are compared with the threshold as their coordinates' weights under the
//! threshold's mix of noise scales give them ([`scaled`]).

use nalgebra::{Vector2, Vector3};

use super::gaps::intersect;
use super::threshold::{scaled, Mix};
use super::{Frame, Observations};

/// The fewest images elimination may leave. Two images of a point give four coordinates for
/// three unknowns, a single check; when the two are the survivors of a longer track, chosen
/// among its pairs, the check is weak: in a simulation of random tracks (image points
/// uniform in a square of side 4, six random cameras, threshold 0.02) elimination to two
/// images kept about 10 % of them, to three about 0.005 %.
pub const MIN_IMAGES: usize = 3;
/// Images dropped per round of elimination: one, or ⌊n/`BATCH`⌋ of the n left when that is
/// more (a point of k images needs at most about `BATCH` · ln k rounds, not k, each of O(k)
/// residuals and a sort).
pub const BATCH: usize = 16;

/// One point's images: (frame, image).
pub type Images = Vec<(usize, Vector2<f64>)>;
/// Every point's images, by point in the observations' order.
pub type Views = Vec<Images>;

/// The images of every point.
pub fn views(obs: &Observations) -> Views {
    let mut v: Views = vec![Vec::new(); obs.names.len()];
    for (f, j, y) in obs.seen() {
        v[j].push((f, y));
    }
    v
}

/// An observation not kept: point and frame (indices), and its distance (image units) to
/// the reprojection of the point as last intersected (`None` when its images did not fix
/// it, or its frame has no camera).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Out {
    /// The point (index).
    pub point: usize,
    /// The frame (index).
    pub frame: usize,
    /// The residual, image units.
    pub residual: Option<f64>,
}

/// The verdict on every observation.
#[derive(Clone, Debug, PartialEq)]
pub struct Judgement {
    /// `inlier[f][j]`: whether point j's image in frame f is kept (false where unseen).
    pub inlier: Vec<Vec<bool>>,
    /// The points with images kept (indices, ascending).
    pub kept: Vec<usize>,
    /// The observations not kept, point by point, frame by frame.
    pub dropped: Vec<Out>,
}

impl Judgement {
    /// The kept points with their kept images (a dropped image becomes a gap).
    pub fn observations(&self, obs: &Observations) -> Observations {
        Observations {
            names: self.kept.iter().map(|&j| obs.names[j].clone()).collect(),
            frames: obs
                .frames
                .iter()
                .zip(&self.inlier)
                .map(|(row, ins)| {
                    self.kept
                        .iter()
                        .map(|&j| row[j].filter(|_| ins[j]))
                        .collect()
                })
                .collect(),
        }
    }
}

/// One point's verdict: per image, kept or not, and its residual.
struct Verdict {
    inlier: Vec<bool>,
    residual: Vec<Option<f64>>,
}

/// The distance (image units) of an image to the reprojection of `x` (`None` without a
/// camera for its frame).
fn residual(cams: &[Option<Frame>], view: &(usize, Vector2<f64>), x: &Vector3<f64>) -> Option<f64> {
    cams[view.0].map(|c| (c.project(x) - view.1).norm())
}

/// An image's residual against the threshold: its coordinates divided by their weights.
fn scaled_residual(
    cams: &[Option<Frame>],
    view: &(usize, Vector2<f64>),
    x: &Vector3<f64>,
    mix: &Mix,
) -> Option<f64> {
    cams[view.0].map(|c| scaled(c.project(x) - view.1, view.1, mix))
}

/// The residuals of every image of the point at `x` (`None` without a camera or a point).
fn residuals_at(
    cams: &[Option<Frame>],
    views: &[(usize, Vector2<f64>)],
    x: Option<Vector3<f64>>,
) -> Vec<Option<f64>> {
    views
        .iter()
        .map(|v| x.and_then(|x| residual(cams, v, &x)))
        .collect()
}

/// The verdict on one point's images (see the module's rule). Images in frames without a
/// camera cannot be judged: while fewer than two can, the point is kept as it is; otherwise
/// the unjudged images follow the point's verdict.
fn judge_point(
    cams: &[Option<Frame>],
    views: &[(usize, Vector2<f64>)],
    (t, mix): (f64, &Mix),
) -> Verdict {
    let reject = |x: Option<Vector3<f64>>| Verdict {
        inlier: vec![false; views.len()],
        residual: residuals_at(cams, views, x),
    };
    // on[i]: image i is judged and not (yet) eliminated
    let mut on: Vec<bool> = views.iter().map(|v| cams[v.0].is_some()).collect();
    let mut active: Vec<usize> = (0..views.len()).filter(|&i| on[i]).collect();
    if views.len() < 2 {
        return reject(None);
    }
    if active.len() < 2 {
        return Verdict {
            inlier: vec![true; views.len()],
            residual: vec![None; views.len()],
        };
    }
    let mut first = None;
    loop {
        let seen: Vec<(usize, Vector2<f64>)> = active.iter().map(|&i| views[i]).collect();
        let Some(x) = intersect(cams, &seen) else {
            return reject(first);
        };
        if first.is_none() {
            first = Some(x);
        }
        let mut beyond: Vec<(f64, usize)> = active
            .iter()
            .filter_map(|&i| scaled_residual(cams, &views[i], &x, mix).map(|r| (r, i)))
            .filter(|(r, _)| r.is_nan() || *r > t)
            .collect();
        if beyond.is_empty() {
            let inlier = views
                .iter()
                .zip(&on)
                .map(|(v, &o)| o || cams[v.0].is_none())
                .collect();
            return Verdict {
                inlier,
                residual: residuals_at(cams, views, Some(x)),
            };
        }
        let take = (active.len() / BATCH)
            .max(1)
            .min(beyond.len())
            .min(active.len().saturating_sub(MIN_IMAGES));
        if take == 0 {
            return reject(first);
        }
        // the worst first (a NaN residual counts as the worst)
        beyond.sort_by(|a, b| b.0.total_cmp(&a.0));
        for &(_, i) in &beyond[..take] {
            on[i] = false;
        }
        active.retain(|&i| on[i]);
    }
}

/// The verdict on every observation of the points `views` (of observations with `frames`
/// frames) under the cameras `cams` (one per frame, `None` where unknown) at threshold `t`,
/// residuals weighed by `mix`.
pub fn judge(
    views: &[Images],
    frames: usize,
    cams: &[Option<Frame>],
    (t, mix): (f64, Mix),
) -> Judgement {
    let mut inlier = vec![vec![false; views.len()]; frames];
    let mut kept = Vec::new();
    let mut dropped = Vec::new();
    for (j, v) in views.iter().enumerate() {
        let verdict = judge_point(cams, v, (t, &mix));
        let mut any = false;
        for (((f, _), ok), r) in v.iter().zip(&verdict.inlier).zip(&verdict.residual) {
            if *ok {
                inlier[*f][j] = true;
                any = true;
            } else {
                dropped.push(Out {
                    point: j,
                    frame: *f,
                    residual: *r,
                });
            }
        }
        if any {
            kept.push(j);
        }
    }
    Judgement {
        inlier,
        kept,
        dropped,
    }
}
