//! Orthographic structure from motion at any size: Tomasi–Kanade factorisation with a metric
//! upgrade ([`tomasi_kanade`]), bundle adjustment ([`bundle_adjust`]), tracks with gaps
//! ([`gaps`]), RANSAC over the paper's four-point solver with a judgement of every
//! observation ([`robust`], [`judge`], the threshold from the data: [`threshold`]), and the
//! whole pipeline behind `orthocheck reconstruct` ([`reconstruct`]).
//!
//! The camera model is the paper's: image = the first two rows of a rotation times the point,
//! plus a translation in the image plane. Every function works on tracks brought to unit size
//! (a power of two, exact) and maps its answer back.

pub mod bundle;
mod covariance;
pub mod factor;
pub mod gaps;
pub mod judge;
pub mod metric;
pub mod missing;
mod observations;
pub mod output;
pub mod robust;
pub mod threshold;
mod tk;
pub mod turntable;

use nalgebra::{Matrix2x3, Matrix3, Vector2, Vector3};

pub use crate::derivations::solver::Degenerate;
pub use bundle::{bundle_adjust, Adjusted, BundleOptions, BundleReport};
pub use observations::Observations;
pub use tk::tomasi_kanade;

/// Fewer than this many points: the factorisation's rank-3 structure is not overdetermined.
pub const MIN_POINTS: usize = 4;
/// Fewer than this many frames: two frames never determine the body (§5).
pub const MIN_FRAMES: usize = 3;

/// Iterations an SVD or symmetric eigen-decomposition may take (the same bound as
/// `algebra`'s numerical rank: they converge in a few per value on finite input; the bound
/// only stops a loop). Non-finite matrices never reach them.
pub const ITERATION_LIMIT: usize = 10_000;

/// Why a reconstruction failed: a typed outcome, never NaN.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum Error {
    /// Too few points.
    #[error("{points} point(s): at least {MIN_POINTS} are needed")]
    TooFewPoints {
        /// The number given.
        points: usize,
    },
    /// Too few frames.
    #[error("{frames} frame(s): at least {MIN_FRAMES} are needed (two frames never determine the body, §5)")]
    TooFewFrames {
        /// The number given.
        frames: usize,
    },
    /// A degenerate configuration, named as the paper's solvers name it.
    #[error("degenerate input: {0}")]
    Degenerate(Degenerate),
    /// With gaps: a point or frame no reconstructed part of the scene reaches.
    #[error("{0}")]
    Unreachable(String),
    /// An option out of its range.
    #[error("{0}")]
    InvalidOption(String),
    /// Input whose work, by the cost model, exceeds a declared limit.
    #[error("{0}")]
    TooLarge(String),
    /// A numerical method failed where it should not.
    #[error("numerical failure: {0}")]
    Numerical(String),
}

impl From<Error> for crate::Error {
    fn from(e: Error) -> crate::Error {
        match e {
            Error::Numerical(m) => crate::Error::Numerical(m),
            e => crate::Error::InvalidInput(e.to_string()),
        }
    }
}

/// One frame's camera: image = the first two rows of `rotation` · X + `translation`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// A proper rotation (frame 1's is the identity after alignment).
    pub rotation: Matrix3<f64>,
    /// The translation in the image plane.
    pub translation: Vector2<f64>,
}

impl Frame {
    /// The two rows of the rotation that the camera sees.
    pub fn rows(&self) -> Matrix2x3<f64> {
        self.rotation.fixed_rows::<2>(0).into_owned()
    }

    /// The image of a point.
    pub fn project(&self, x: &Vector3<f64>) -> Vector2<f64> {
        self.rows() * x + self.translation
    }
}

/// Conditioning of a factorisation, for error bounds: a noiseless reconstruction is exact to
/// about `ε · size · factor² · metric` (the Gram route squares the factor's condition).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Conditioning {
    /// σ₁/σ₃ of the registered measurement matrix.
    pub factor: f64,
    /// σ₁/σ₅ of the metric constraints on L (the gap above their one-dimensional null space).
    pub metric: f64,
}

/// A body and its cameras.
#[derive(Clone, Debug, PartialEq)]
pub struct Reconstruction {
    /// Point names, in the tracks' order.
    pub names: Vec<String>,
    /// The points, in frame 1's camera coordinates, centred on their centroid.
    pub points: Vec<Vector3<f64>>,
    /// One camera per frame, in the tracks' order.
    pub frames: Vec<Frame>,
    /// The steps that made it, in order (e.g. "tomasi-kanade", "metric upgrade: cholesky").
    pub method: Vec<String>,
    /// Conditioning of the factorisation, where one was made.
    pub conditioning: Option<Conditioning>,
}

impl Reconstruction {
    /// The mirror (Necker) solution: the structure reflected in frame 1's image plane,
    /// X ↦ DX, and every rotation R ↦ DRD with D = diag(1, 1, −1). Both give the same images:
    /// the first two rows of DRD·DX are those of R·X.
    pub fn mirror(&self) -> Reconstruction {
        let d = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
        Reconstruction {
            names: self.names.clone(),
            points: self.points.iter().map(|x| d * x).collect(),
            frames: self
                .frames
                .iter()
                .map(|f| Frame {
                    rotation: d * f.rotation * d,
                    translation: f.translation,
                })
                .collect(),
            method: self.method.clone(),
            conditioning: self.conditioning,
        }
    }

    /// Root mean square of the reprojection distance over the observed points of `obs`
    /// (whose points are `self.names`, in order).
    pub fn rms(&self, obs: &Observations) -> f64 {
        let (mut sum, mut n) = (0.0, 0usize);
        for (frame, row) in self.frames.iter().zip(&obs.frames) {
            for (x, seen) in self.points.iter().zip(row) {
                if let Some(y) = seen {
                    sum += (frame.project(x) - y).norm_squared();
                    n += 1;
                }
            }
        }
        if n == 0 {
            0.0
        } else {
            (sum / n as f64).sqrt()
        }
    }

    /// Whether every number is finite.
    pub fn is_finite(&self) -> bool {
        self.points.iter().all(|x| x.iter().all(|v| v.is_finite()))
            && self.frames.iter().all(|f| {
                f.rotation.iter().all(|v| v.is_finite())
                    && f.translation.iter().all(|v| v.is_finite())
            })
    }

    /// Turn every frame so that frame 1's rotation is the identity (the points follow).
    pub fn align_to_first(&mut self) {
        let Some(r1) = self.frames.first().map(|f| f.rotation) else {
            return;
        };
        for x in &mut self.points {
            *x = r1 * *x;
        }
        for f in &mut self.frames {
            f.rotation *= r1.transpose();
        }
    }

    /// Move the points' centroid to the origin; the translations absorb the shift, so every
    /// image is unchanged (the gauge of the translation).
    pub fn centre(&mut self) {
        let n = self.points.len().max(1) as f64;
        let c = self.points.iter().sum::<Vector3<f64>>() / n;
        for x in &mut self.points {
            *x -= c;
        }
        for f in &mut self.frames {
            f.translation += f.rows() * c;
        }
    }
}

/// The unit of a computation: observations are mapped by y ↦ (y − centre)/scale, `scale` a
/// power of two (exact), so every solver sees coordinates of size about 1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Units {
    /// The mean of every observed point.
    pub centre: Vector2<f64>,
    /// A power of two near the largest distance from the centre.
    pub scale: f64,
}

impl Units {
    /// The units of `obs`; an error when its size cannot be represented.
    pub fn of(obs: &Observations) -> Result<Units, Error> {
        Units::of_points(|| obs.seen().map(|(_, _, y)| y))
    }

    /// The units of complete tracks (as [`Units::of`] of their observations, without the
    /// copy).
    pub fn of_tracks(t: &crate::model::Tracks) -> Result<Units, Error> {
        Units::of_points(|| t.frames.iter().flatten().copied())
    }

    /// The units of the points `all()` yields (three passes over them).
    fn of_points<I: Iterator<Item = Vector2<f64>>>(all: impl Fn() -> I) -> Result<Units, Error> {
        // a first pass by the largest magnitude keeps the sum from overflowing
        let big = all().fold(0.0_f64, |m, y| m.max(y.amax()));
        let pre = if big > 0.0 { pow2_floor(big) } else { 1.0 };
        let n = all().count().max(1) as f64;
        let centre = all().fold(Vector2::zeros(), |s, y| s + y / pre) / n * pre;
        let extent = all().fold(0.0_f64, |m, y| m.max((y - centre).amax()));
        let scale = if extent > 0.0 {
            pow2_floor(extent)
        } else {
            1.0
        };
        if !scale.is_finite() || !centre.iter().all(|v| v.is_finite()) {
            return Err(Error::Numerical(
                "the coordinates' size cannot be represented".into(),
            ));
        }
        Ok(Units { centre, scale })
    }

    /// `obs` in these units.
    pub fn to_unit(&self, obs: &Observations) -> Observations {
        Observations {
            names: obs.names.clone(),
            frames: obs
                .frames
                .iter()
                .map(|f| {
                    f.iter()
                        .map(|y| y.map(|y| (y - self.centre) / self.scale))
                        .collect()
                })
                .collect(),
        }
    }

    /// A reconstruction of the unit observations in the input's units.
    pub fn back(&self, r: &mut Reconstruction) {
        for x in &mut r.points {
            *x *= self.scale;
        }
        for f in &mut r.frames {
            f.translation = f.translation * self.scale + self.centre;
        }
    }

    /// A reconstruction in the input's units mapped into these units.
    pub fn forward(&self, r: &mut Reconstruction) {
        for x in &mut r.points {
            *x /= self.scale;
        }
        for f in &mut r.frames {
            f.translation = (f.translation - self.centre) / self.scale;
        }
    }
}

/// The power of two nearest below `v` (v > 0, finite).
fn pow2_floor(v: f64) -> f64 {
    2f64.powi(v.log2().floor() as i32)
}

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

/// What [`reconstruct`] returns.
#[derive(Clone, Debug, PartialEq)]
pub struct Outcome {
    /// The reconstruction.
    pub reconstruction: Reconstruction,
    /// Its mirror (Necker) twin: the same images.
    pub mirror: Reconstruction,
    /// Root mean square reprojection distance, in image units, over the points used.
    pub rms: f64,
    /// In robust mode: the names of the points kept (each with its inlier images).
    pub inliers: Option<Vec<String>>,
    /// The bundle adjustment, when it ran.
    pub bundle: Option<BundleReport>,
    /// In robust mode: the threshold, the dropped observations, the rejected points.
    pub robust: Option<robust::RobustReport>,
}

/// The pipeline of `orthocheck reconstruct`: in robust mode RANSAC and the judgement of every
/// observation ([`robust::run`]: the kept images go on), then Tomasi–Kanade (complete
/// tracks) or the largest complete block grown by intersection and resection (tracks with
/// gaps), then bundle adjustment, then the mirror twin.
pub fn reconstruct(obs: &Observations, options: &Options) -> Result<Outcome, Error> {
    obs.check_counts()?;
    let (rec, bundle, robust, rms) = match &options.robust {
        Some(r) => {
            let f = robust::run(obs, r, options)?;
            let rms = f.reconstruction.rms(&f.used);
            (f.reconstruction, f.bundle, Some(f.report), rms)
        }
        None => {
            let (rec, bundle) = fit(obs, options, None)?;
            let rms = rec.rms(obs);
            (rec, bundle, None, rms)
        }
    };
    Ok(Outcome {
        mirror: rec.mirror(),
        reconstruction: rec,
        rms,
        inliers: robust.as_ref().map(|r| r.kept.clone()),
        bundle,
        robust,
    })
}

/// The start of tracks with gaps. With most entries missing (a turntable), variable
/// projection from the chained pairs ([`missing::reconstruct`]) first, the largest complete
/// block grown when it fails; with fewer missing, the other way round. `method` names the
/// path taken, and why the first failed.
fn with_gaps(used: &Observations, options: &Options) -> Result<Reconstruction, Error> {
    // identical frames, or frames differing in-plane only, judged on what is observed: the
    // same refusal as for complete tracks, whichever path would start
    if let Some((first, second)) = missing::same_view(&judge::views(used)) {
        return Err(Error::Degenerate(Degenerate::InPlaneMotion {
            first,
            second,
        }));
    }
    let seed = options.seed;
    let cells = used.frames.len() * used.names.len();
    let mostly_missing = 2 * used.count() < cells;
    let (first, first_name): (Result<Reconstruction, Error>, &str) = if mostly_missing {
        (missing::reconstruct(used, seed), "variable projection")
    } else {
        (gaps::initial(used), "largest complete block")
    };
    match first {
        Ok(r) => Ok(r),
        Err(Error::Unreachable(why)) | Err(Error::Numerical(why)) => {
            let mut r = if mostly_missing {
                gaps::initial(used)?
            } else {
                missing::reconstruct(used, seed)?
            };
            r.method.insert(0, format!("{first_name}: {why}"));
            Ok(r)
        }
        Err(e) => Err(e),
    }
}

/// The fit of observations: Tomasi–Kanade (complete tracks) or the largest complete block
/// grown (gaps), then bundle adjustment when asked and within its limits (`method` says
/// when it was skipped); an error on a non-finite coordinate.
pub(crate) fn fit(
    used: &Observations,
    options: &Options,
    huber: Option<f64>,
) -> Result<(Reconstruction, Option<BundleReport>), Error> {
    let mut rec = match used.complete() {
        Some(t) => tomasi_kanade(&t)?,
        None => with_gaps(used, options)?,
    };
    let mut report = None;
    if options.bundle {
        let frames = used.frames.len();
        if frames > crate::limits::BUNDLE_FRAMES {
            rec.method.push(format!(
                "bundle adjustment skipped: {frames} frames, more than the limit of {} (see docs/limits.md)",
                crate::limits::BUNDLE_FRAMES
            ));
        } else if used.count() > crate::limits::BUNDLE_OBSERVATIONS {
            rec.method.push(format!(
                "bundle adjustment skipped: {} observations, more than the limit of {} (see docs/limits.md)",
                used.count(),
                crate::limits::BUNDLE_OBSERVATIONS
            ));
        } else if bundle::work(used) <= crate::limits::BUNDLE_WORK {
            let bo = bundle::BundleOptions {
                huber,
                ..bundle::BundleOptions::with(options)
            };
            let adjusted = bundle_adjust(used, &rec, &bo)?;
            rec = adjusted.reconstruction;
            report = Some(adjusted.report);
        } else {
            rec.method.push(format!(
                "bundle adjustment skipped: its work (Σ frames² per point) exceeds the limit of {} (see docs/limits.md)",
                crate::limits::BUNDLE_WORK
            ));
        }
    }
    if !rec.is_finite() {
        return Err(Error::Numerical(
            "a non-finite coordinate in the reconstruction".into(),
        ));
    }
    Ok((rec, report))
}
