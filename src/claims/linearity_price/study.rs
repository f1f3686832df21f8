//! The price of linearity (§4, "the sensitivity to measurement errors"): the paper's linear
//! solvers against the standard method for orthographic tracks — Tomasi–Kanade factorisation
//! with its metric upgrade, refined by bundle adjustment — on the same seeded noisy scenes.
//!
//! Every trial draws one scene (the body, or a random body, under random rotations, P at the
//! origin of every image as in the paper's figures) and one draw of the paper's coordinate
//! noise (`NoiseModel::RelativeCoordinate`: every image coordinate x becomes x(1 + u), u
//! uniform in [−ε, ε]); every method then solves those same tracks. The relative-length model
//! perturbs lengths, not tracks, so it has no tracks for a factorisation to work on: it
//! applies to the length-based solvers only and is not part of this comparison.
//!
//! The error of a trial is the largest relative edge-length error over the body's edges,
//! max |ℓ̂/ℓ − 1| ("errors for edge lengths", §4); a trial a method cannot solve (a singular
//! system, a negative square, a failed factorisation) counts as an error larger than every
//! finite one, so that all methods are summarised over the same trials.

use nalgebra::Vector2;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use crate::derivations::p3f4;
use crate::derivations::p4f3::{self, edge_index};
use crate::derivations::solver::SquaredLengths;
use crate::model::{edges, random_rotation, Body, Motion, NoiseModel, Scene, Tracks};

pub mod bounds;
mod standard;

pub use bounds::{Bound, RatioBounds};

/// Frames of every scene: the §3 solver needs four; the §4 solver takes the first three.
pub const FRAMES: usize = 4;

/// The methods compared, in report order.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// §3's linear solver (three points, four frames), on every triangle through the first
    /// point; an edge from the first point is the mean of its triangles' estimates.
    P3f4Triangles,
    /// §4's linear solver (four points, three frames), on the first three frames.
    P4f3,
    /// §4's least-squares form (p ≥ 4 points, every frame).
    LeastSquares,
    /// Tomasi–Kanade factorisation with its metric upgrade, every frame.
    TomasiKanade,
    /// Tomasi–Kanade refined by bundle adjustment, every frame.
    TomasiKanadeBa,
    /// Tomasi–Kanade + bundle adjustment on the first three frames only: the §4 solver's data.
    TomasiKanadeBa3,
    /// The §4 solver again on a second, independent noise draw of the same scene: the null
    /// comparison (true ratio 1) that controls the ratio's confidence bounds.
    P4f3FreshNoise,
}

impl Method {
    /// Every method, in report order.
    pub const ALL: [Method; 7] = [
        Method::P3f4Triangles,
        Method::P4f3,
        Method::LeastSquares,
        Method::TomasiKanade,
        Method::TomasiKanadeBa,
        Method::TomasiKanadeBa3,
        Method::P4f3FreshNoise,
    ];

    /// A short name for tables and legends.
    pub fn name(self) -> &'static str {
        match self {
            Method::P3f4Triangles => "§3 linear, per triangle (4 frames)",
            Method::P4f3 => "§4 linear (frames 1–3)",
            Method::LeastSquares => "§4 least squares (4 frames)",
            Method::TomasiKanade => "Tomasi–Kanade (4 frames)",
            Method::TomasiKanadeBa => "Tomasi–Kanade + BA (4 frames)",
            Method::TomasiKanadeBa3 => "Tomasi–Kanade + BA (frames 1–3)",
            Method::P4f3FreshNoise => "§4 linear, fresh noise (null control)",
        }
    }

    /// Why the method does not apply to a body of `points` points in this build, if it does not.
    pub fn unavailable(self, points: usize) -> Option<Unavailable> {
        match self {
            Method::P3f4Triangles => None,
            Method::P4f3 | Method::P4f3FreshNoise if points != 4 => Some(
                Unavailable::NotApplicable("the §4 linear solver takes exactly four points"),
            ),
            Method::P4f3 | Method::P4f3FreshNoise => None,
            Method::LeastSquares if points < 4 => Some(Unavailable::NotApplicable(
                "the least-squares form needs four points or more",
            )),
            Method::LeastSquares => None,
            Method::TomasiKanade | Method::TomasiKanadeBa | Method::TomasiKanadeBa3 => {
                if points < 4 {
                    Some(Unavailable::NotApplicable(
                        "three points span a plane: the registered measurements have rank 2, no rank-3 factorisation",
                    ))
                } else if !standard::AVAILABLE {
                    Some(Unavailable::NotInThisBuild)
                } else {
                    None
                }
            }
        }
    }
}

/// Why a method has no numbers for a body.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(tag = "kind", content = "why", rename_all = "kebab-case")]
pub enum Unavailable {
    /// The method does not take such a body (the reason).
    NotApplicable(&'static str),
    /// The method is not in this build of the library.
    NotInThisBuild,
}

/// The body of one series of scenes.
#[derive(Clone, Debug, PartialEq)]
pub enum BodySpec {
    /// A fixed body (the paper's).
    Fixed(Body),
    /// A new random body per trial: `points` points uniform in [−1, 1]³.
    Random {
        /// Points.
        points: usize,
    },
}

impl BodySpec {
    /// Points of the body.
    pub fn points(&self) -> usize {
        match self {
            BodySpec::Fixed(b) => b.points.len(),
            BodySpec::Random { points } => *points,
        }
    }
}

/// What the study runs.
#[derive(Clone, Debug, PartialEq)]
pub struct Design {
    /// Named bodies, in report order.
    pub bodies: Vec<(String, BodySpec)>,
    /// Noise levels ε.
    pub levels: Vec<f64>,
    /// Trials per body and level.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
}

/// One method's errors over the trials of one body and level.
#[derive(Clone, Debug, PartialEq)]
pub enum MethodErrors {
    /// The errors, sorted, failures last as +∞ (never leaves the library: see
    /// [`ErrorSummary`]).
    Ran(Vec<f64>),
    /// No numbers, and why.
    Unavailable(Unavailable),
}

/// A quantile that may lie among the failed trials.
pub type Quantile = Bound;

/// One method's error distribution, summarised.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct ErrorSummary {
    /// Trials run.
    pub trials: usize,
    /// Trials the method could not solve.
    pub failures: usize,
    /// Median of the largest relative edge-length error.
    pub median: Quantile,
    /// 90th percentile.
    pub p90: Quantile,
}

impl MethodErrors {
    /// The summary, `None` when unavailable.
    pub fn summary(&self) -> Option<ErrorSummary> {
        let MethodErrors::Ran(v) = self else {
            return None;
        };
        let q = |q: f64| {
            crate::derivations::rounding::quantile(v, q).map_or(Bound::Infinite, Bound::of)
        };
        Some(ErrorSummary {
            trials: v.len(),
            failures: v.iter().filter(|x| !x.is_finite()).count(),
            median: q(0.5),
            p90: q(0.9),
        })
    }

    /// The sorted errors, when the method ran.
    pub fn sorted(&self) -> Option<&[f64]> {
        match self {
            MethodErrors::Ran(v) => Some(v),
            MethodErrors::Unavailable(_) => None,
        }
    }
}

/// Every method at one body and level.
#[derive(Clone, Debug, PartialEq)]
pub struct Cell {
    /// ε.
    pub level: f64,
    /// One entry per [`Method::ALL`], in that order.
    pub methods: Vec<(Method, MethodErrors)>,
}

impl Cell {
    /// The errors of `m`.
    pub fn of(&self, m: Method) -> &MethodErrors {
        // every cell holds every method (built from Method::ALL)
        &self.methods[Method::ALL.iter().position(|x| *x == m).unwrap_or(0)].1
    }

    /// The ratio of medians `num / den` with bounds of one-sided confidence 1 − `alpha`;
    /// `Err` names the side that has no numbers.
    pub fn ratio(&self, num: Method, den: Method, alpha: f64) -> Result<RatioBounds, Unavailable> {
        let side = |m: Method| match self.of(m) {
            MethodErrors::Ran(v) => Ok(v.as_slice()),
            MethodErrors::Unavailable(u) => Err(*u),
        };
        let (a, b) = (side(num)?, side(den)?);
        bounds::ratio_of_medians(a, b, alpha).ok_or(Unavailable::NotApplicable(
            "too few trials for a bound at this confidence",
        ))
    }
}

/// The study's results: per body, one [`Cell`] per level.
#[derive(Clone, Debug, PartialEq)]
pub struct Results {
    /// Per body (name, points, cells by level).
    pub bodies: Vec<(String, usize, Vec<Cell>)>,
    /// Trials per cell.
    pub trials: usize,
}

/// Run the study: every body at every level, the trials in parallel, each with its own
/// random stream (`(body · levels + level) << 32 | trial`), so that the result does not
/// depend on the thread count.
pub fn compare(design: &Design) -> Results {
    let nl = design.levels.len();
    let bodies = design
        .bodies
        .iter()
        .enumerate()
        .map(|(bi, (name, spec))| {
            let cells = design
                .levels
                .iter()
                .enumerate()
                .map(|(li, &eps)| {
                    let stream = ((bi * nl + li) as u64) << 32;
                    run_cell(spec, eps, design, stream)
                })
                .collect();
            (name.clone(), spec.points(), cells)
        })
        .collect();
    Results {
        bodies,
        trials: design.trials,
    }
}

/// One body at one level: every method over the same trials.
fn run_cell(spec: &BodySpec, eps: f64, design: &Design, stream: u64) -> Cell {
    let per_trial: Vec<[f64; 7]> = (0..design.trials)
        .into_par_iter()
        .map(|t| {
            let mut g = ChaCha8Rng::seed_from_u64(design.seed);
            g.set_stream(stream | t as u64);
            trial(spec, eps, &mut g)
        })
        .collect();
    let methods = Method::ALL
        .iter()
        .enumerate()
        .map(|(k, &m)| {
            let errors = match m.unavailable(spec.points()) {
                Some(u) => MethodErrors::Unavailable(u),
                None => {
                    let mut v: Vec<f64> = per_trial.iter().map(|e| e[k]).collect();
                    v.sort_by(f64::total_cmp);
                    MethodErrors::Ran(v)
                }
            };
            (m, errors)
        })
        .collect();
    Cell {
        level: eps,
        methods,
    }
}

/// A random body: `p` points uniform in [−1, 1]³.
fn random_body<R: Rng>(p: usize, g: &mut R) -> Body {
    Body::new(
        (0..p)
            .map(|_| {
                nalgebra::Vector3::new(
                    g.random_range(-1.0..1.0),
                    g.random_range(-1.0..1.0),
                    g.random_range(-1.0..1.0),
                )
            })
            .collect(),
    )
}

/// The noise-free tracks of a scene with P (the first point) at the origin of every image.
fn centred_tracks(scene: &Scene) -> Tracks {
    let mut tracks = scene.tracks();
    for f in &mut tracks.frames {
        let o = f[0];
        for p in f.iter_mut() {
            *p -= o;
        }
    }
    tracks
}

/// One trial: the errors of every method of [`Method::ALL`] (+∞ for a failure or a method
/// that does not apply; those are not read).
fn trial(spec: &BodySpec, eps: f64, g: &mut ChaCha8Rng) -> [f64; 7] {
    let body = match spec {
        BodySpec::Fixed(b) => b.clone(),
        BodySpec::Random { points } => random_body(*points, g),
    };
    let scene = Scene {
        motions: (0..FRAMES)
            .map(|_| Motion {
                rotation: random_rotation(g),
                translation: Vector2::zeros(),
            })
            .collect(),
        body,
    };
    let clean = centred_tracks(&scene);
    let model = NoiseModel::RelativeCoordinate { eps };
    let tracks = model.perturb_tracks(&clean, g);
    let fresh = model.perturb_tracks(&clean, g);
    let p = scene.body.points.len();
    let truth: Vec<f64> = edges(p)
        .iter()
        .map(|&(i, j)| scene.body.squared_distance(i, j))
        .collect();
    let err = |s: Option<Vec<f64>>| {
        s.and_then(|s| length_error(&s, &truth))
            .unwrap_or(f64::INFINITY)
    };
    let lengths = SquaredLengths::from_tracks(&tracks);
    let mut out = [f64::INFINITY; 7];
    for (k, m) in Method::ALL.iter().enumerate() {
        if m.unavailable(p).is_some() {
            continue;
        }
        out[k] = match m {
            Method::P3f4Triangles => err(per_triangle(&lengths)),
            Method::P4f3 => err(linear_four(&lengths)),
            Method::P4f3FreshNoise => err(linear_four(&SquaredLengths::from_tracks(&fresh))),
            Method::LeastSquares => err(least_squares(&lengths)),
            Method::TomasiKanade => err(standard::squares(&tracks, FRAMES, false)),
            Method::TomasiKanadeBa => err(standard::squares(&tracks, FRAMES, true)),
            Method::TomasiKanadeBa3 => err(standard::squares(&tracks, 3, true)),
        };
    }
    out
}

/// The largest relative edge-length error of squared edges `s` against the true squares `t`;
/// `None` for a negative or non-finite square.
pub fn length_error(s: &[f64], t: &[f64]) -> Option<f64> {
    if s.len() != t.len() || s.iter().any(|v| !(v.is_finite() && *v >= 0.0)) {
        return None;
    }
    Some(
        s.iter()
            .zip(t)
            .map(|(a, b)| (a / b).sqrt() - 1.0)
            .fold(0.0, |m: f64, e| m.max(e.abs())),
    )
}

/// §3's solver on every triangle (0, i, j) through the first point: edges (i, j) from their
/// one triangle, edges (0, i) the mean over the p − 2 triangles holding them. `None` when a
/// triangle's system is singular.
pub fn per_triangle(l: &SquaredLengths) -> Option<Vec<f64>> {
    let p = l.names.len();
    if p < 3 || l.frames.len() < 4 {
        return None;
    }
    let mut sum = vec![0.0; l.edges.len()];
    let mut count = vec![0usize; l.edges.len()];
    for i in 1..p {
        for j in i + 1..p {
            let e = [edge_index(0, i), edge_index(i, j), edge_index(j, 0)];
            let frame = |f: usize| e.map(|k| l.frames[f][k]);
            let (x, _) = p3f4::solve_core(&[frame(0), frame(1), frame(2), frame(3)])?;
            for (k, v) in e.iter().zip(x) {
                sum[*k] += v;
                count[*k] += 1;
            }
        }
    }
    Some(sum.iter().zip(&count).map(|(s, c)| s / *c as f64).collect())
}

/// §4's solver on the first three frames of four points.
pub fn linear_four(l: &SquaredLengths) -> Option<Vec<f64>> {
    if l.names.len() != 4 || l.frames.len() < 3 {
        return None;
    }
    let f: [[f64; 6]; 3] = std::array::from_fn(|i| std::array::from_fn(|e| l.frames[i][e]));
    p4f3::solve_core(&f).squares.map(|x| x.to_vec())
}

/// §4's least-squares form over every frame.
pub fn least_squares(l: &SquaredLengths) -> Option<Vec<f64>> {
    p4f3::solve_least_squares(l)
        .ok()?
        .solutions
        .into_iter()
        .next()
        .map(|s| s.squared_edges)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tetra() -> Body {
        Body::new(vec![
            nalgebra::Vector3::new(0.0, 0.0, 0.0),
            nalgebra::Vector3::new(2.0, 0.0, 0.0),
            nalgebra::Vector3::new(0.5, 1.7, 0.0),
            nalgebra::Vector3::new(0.7, 0.4, 1.9),
        ])
    }

    #[test]
    fn without_noise_every_method_recovers_the_body() {
        let mut g = ChaCha8Rng::seed_from_u64(3);
        let e = trial(&BodySpec::Fixed(tetra()), 0.0, &mut g);
        for m in [
            Method::TomasiKanade,
            Method::TomasiKanadeBa,
            Method::TomasiKanadeBa3,
            Method::P3f4Triangles,
            Method::P4f3,
            Method::LeastSquares,
            Method::P4f3FreshNoise,
        ] {
            let k = Method::ALL.iter().position(|x| *x == m).unwrap();
            assert!(e[k] < 1e-8, "{m:?}: {}", e[k]);
        }
    }

    #[test]
    fn the_study_is_seeded_and_the_same_on_one_thread() {
        let d = Design {
            bodies: vec![
                ("tetra".into(), BodySpec::Fixed(tetra())),
                ("random 8".into(), BodySpec::Random { points: 8 }),
            ],
            levels: vec![0.01],
            trials: 40,
            seed: 5,
        };
        let a = compare(&d);
        let one = rayon::ThreadPoolBuilder::new()
            .num_threads(1)
            .build()
            .unwrap();
        assert_eq!(a, one.install(|| compare(&d)));
        // the null control sees the same scenes under other noise: not the same errors
        let c = &a.bodies[0].2[0];
        assert_ne!(c.of(Method::P4f3), c.of(Method::P4f3FreshNoise));
        assert!(matches!(
            a.bodies[1].2[0].of(Method::P4f3),
            MethodErrors::Unavailable(Unavailable::NotApplicable(_))
        ));
    }

    #[test]
    fn length_error_is_the_worst_edge_in_lengths() {
        let e = length_error(&[4.0, 9.0 * 1.21], &[4.0, 9.0]).unwrap();
        assert!((e - 0.1).abs() < 1e-12);
        assert_eq!(length_error(&[-1.0, 9.0], &[4.0, 9.0]), None);
    }
}
