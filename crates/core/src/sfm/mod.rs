//! Orthographic structure from motion at any size: Tomasi–Kanade factorisation with a metric
//! upgrade ([`tomasi_kanade`]), bundle adjustment ([`bundle_adjust`]), tracks with gaps
//! ([`gaps`]), RANSAC over the paper's four-point solver with a judgement of every
//! observation ([`robust`], [`judge`], the threshold from the data: [`threshold`]), and the
//! whole pipeline behind `orthocheck reconstruct` ([`reconstruct`]): what cannot take part
//! dropped, the frames split into groups that share too few points ([`groups`]), each
//! reconstructed on its own, and a warning wherever a step can tell its answer may be wrong.
//!
//! The camera model is the paper's: image = the first two rows of a rotation times the point,
//! plus a translation in the image plane. Every function works on tracks brought to unit size
//! (a power of two, exact) and maps its answer back.

pub mod bundle;
mod covariance;
pub mod factor;
pub mod gaps;
pub mod groups;
pub mod judge;
pub mod metric;
pub mod missing;
mod observations;
pub mod output;
pub mod pipeline;
pub mod robust;
pub mod threshold;
mod tk;
pub mod turntable;

use nalgebra::{Matrix2x3, Matrix3, Vector2, Vector3};

pub use crate::derivations::solver::Degenerate;
pub use bundle::{bundle_adjust, Adjusted, BundleOptions, BundleReport, FrameStd};
pub use observations::Observations;
pub(crate) use pipeline::fit;
pub use pipeline::{reconstruct, Component, Options, Outcome};
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
    /// What may be wrong with it, as the steps that made it can tell (a search stopped at
    /// its limit, a metric upgrade clipped, bundle adjustment skipped, points implausibly
    /// deep); empty when none can.
    pub warnings: Vec<String>,
}

impl Reconstruction {
    /// A scene's true body and motions as a reconstruction: the start of an adjustment from
    /// the truth, the reference a fit's cost is judged against.
    pub fn of_scene(scene: &crate::model::Scene) -> Reconstruction {
        Reconstruction {
            names: scene.body.names.clone(),
            points: scene.body.points.clone(),
            frames: scene
                .motions
                .iter()
                .map(|m| Frame {
                    rotation: *m.rotation.matrix(),
                    translation: m.translation,
                })
                .collect(),
            method: Vec::new(),
            conditioning: None,
            warnings: Vec::new(),
        }
    }

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
            warnings: self.warnings.clone(),
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
