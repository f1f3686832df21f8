//! The physical world: rigid point bodies, rotations, orthographic projection, tracks,
//! seeded synthetic scenes and named noise models.

use nalgebra::{Rotation3, UnitQuaternion, Vector2, Vector3, Vector4};
use num_rational::BigRational;
use num_traits::{One, Zero};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

use crate::error::{Error, Result};

pub mod image;
pub use image::{image_size, point_line_distance};

/// The seeded, portable generator used everywhere (ChaCha8: same stream on every platform).
pub fn rng(seed: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(seed)
}

/// The paper's point names: P, Q, R, T, S, then P6, P7, …
///
/// # Example
/// ```
/// assert_eq!(orthocheck_core::model::default_names(6), ["P", "Q", "R", "T", "S", "P6"]);
/// ```
pub fn default_names(p: usize) -> Vec<String> {
    const FIRST: [&str; 5] = ["P", "Q", "R", "T", "S"];
    (0..p)
        .map(|i| match FIRST.get(i) {
            Some(n) => n.to_string(),
            None => format!("P{}", i + 1),
        })
        .collect()
}

/// The edges of a p-point body in the paper's order: PQ (a), QR (b), RP (c), then for each
/// further point its edges to the earlier ones (TP, TQ, TR, SP, SQ, SR, ST, …).
///
/// # Example
/// ```
/// use orthocheck_core::model::edges;
/// assert_eq!(edges(4), [(0, 1), (1, 2), (2, 0), (3, 0), (3, 1), (3, 2)]);
/// ```
pub fn edges(p: usize) -> Vec<(usize, usize)> {
    let mut e = Vec::new();
    if p >= 2 {
        e.push((0, 1));
    }
    if p >= 3 {
        e.push((1, 2));
        e.push((2, 0));
    }
    for j in 3..p {
        for i in 0..j {
            e.push((j, i));
        }
    }
    e
}

/// The `e`-th edge of [`edges`] (the same for every body that has it), without building
/// the list: the edges of point j ≥ 3 start at j(j − 1)/2.
///
/// # Example
/// ```
/// use orthocheck_core::model::{edge, edges};
/// assert!(edges(6).iter().enumerate().all(|(e, pair)| edge(e) == *pair));
/// ```
pub fn edge(e: usize) -> (usize, usize) {
    if e < 3 {
        return [(0, 1), (1, 2), (2, 0)][e];
    }
    let mut j = 3;
    while (j + 1) * j / 2 <= e {
        j += 1;
    }
    (j, e - j * (j - 1) / 2)
}

/// Squared lengths of every edge (in [`edges`] order) of one frame's image points
/// `[x, y]`: the one place image coordinates become the paper's aᵢ², bᵢ², cᵢ², ….
///
/// # Example
/// ```
/// let l = orthocheck_core::model::squared_lengths(&[[0.0, 0.0], [3.0, 4.0], [3.0, 0.0]]);
/// assert_eq!(l, [25.0, 16.0, 9.0]);
/// ```
pub fn squared_lengths(points: &[[f64; 2]]) -> Vec<f64> {
    edges(points.len())
        .iter()
        .map(|&(i, j)| {
            let (a, b) = (points[i], points[j]);
            (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)
        })
        .collect()
}

/// A rigid body of named points.
#[derive(Clone, Debug, PartialEq)]
pub struct Body {
    /// Point names.
    pub names: Vec<String>,
    /// Positions in the body frame (= the first camera frame).
    pub points: Vec<Vector3<f64>>,
}

impl Body {
    /// A body with the default names.
    pub fn new(points: Vec<Vector3<f64>>) -> Self {
        Body {
            names: default_names(points.len()),
            points,
        }
    }

    /// Squared distance between points `i` and `j`.
    pub fn squared_distance(&self, i: usize, j: usize) -> f64 {
        (self.points[i] - self.points[j]).norm_squared()
    }
}

/// One frame's rigid motion: image = first two coordinates of `rotation · X` + `translation`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Motion {
    /// Rotation of the body into the camera frame.
    pub rotation: Rotation3<f64>,
    /// Translation within the image plane (depth translation is invisible).
    pub translation: Vector2<f64>,
}

impl Motion {
    /// The identity motion (the first frame's convention).
    pub fn identity() -> Self {
        Motion {
            rotation: Rotation3::identity(),
            translation: Vector2::zeros(),
        }
    }

    /// Orthographic image of one point.
    pub fn project(&self, x: &Vector3<f64>) -> Vector2<f64> {
        let y = self.rotation * x;
        Vector2::new(y.x, y.y) + self.translation
    }
}

/// Image points: `frames[i][j]` is point `j` in frame `i`.
#[derive(Clone, Debug, PartialEq)]
pub struct Tracks {
    /// Point names, one per column.
    pub names: Vec<String>,
    /// Frames, each with one image point per name.
    pub frames: Vec<Vec<Vector2<f64>>>,
}

impl Tracks {
    /// Validated tracks: at least one frame, equal counts, finite coordinates.
    pub fn new(names: Vec<String>, frames: Vec<Vec<Vector2<f64>>>) -> Result<Self> {
        if frames.is_empty() {
            return Err(Error::InvalidInput("no frames".into()));
        }
        for (i, f) in frames.iter().enumerate() {
            if f.len() != names.len() {
                return Err(Error::InvalidInput(format!(
                    "frame {} has {} points, expected {}",
                    i + 1,
                    f.len(),
                    names.len()
                )));
            }
            if let Some(j) = f.iter().position(|p| !p.x.is_finite() || !p.y.is_finite()) {
                return Err(Error::InvalidInput(format!(
                    "frame {}, point {}: coordinate is not finite",
                    i + 1,
                    names[j]
                )));
            }
        }
        Ok(Tracks { names, frames })
    }

    /// Number of points.
    pub fn points(&self) -> usize {
        self.names.len()
    }

    /// Projected squared length between points `i` and `j` in frame `f`.
    pub fn squared_length(&self, f: usize, i: usize, j: usize) -> f64 {
        (self.frames[f][i] - self.frames[f][j]).norm_squared()
    }
}

/// A body seen under a sequence of motions.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// The body.
    pub body: Body,
    /// One motion per frame; the first is the identity.
    pub motions: Vec<Motion>,
}

impl Scene {
    /// A generic random scene: `p` points uniform in [−1, 1]³, `k` frames, the first the
    /// identity, the others uniform random rotations with random image translations.
    pub fn random(p: usize, k: usize, seed: u64) -> Scene {
        let mut g = rng(seed);
        let points = (0..p)
            .map(|_| {
                Vector3::new(
                    g.random_range(-1.0..1.0),
                    g.random_range(-1.0..1.0),
                    g.random_range(-1.0..1.0),
                )
            })
            .collect();
        let mut motions = vec![Motion::identity()];
        for _ in 1..k {
            motions.push(Motion {
                rotation: random_rotation(&mut g),
                translation: Vector2::new(g.random_range(-1.0..1.0), g.random_range(-1.0..1.0)),
            });
        }
        Scene {
            body: Body::new(points),
            motions,
        }
    }

    /// The tracks this scene produces.
    pub fn tracks(&self) -> Tracks {
        Tracks {
            names: self.body.names.clone(),
            frames: self
                .motions
                .iter()
                .map(|m| self.body.points.iter().map(|x| m.project(x)).collect())
                .collect(),
        }
    }
}

/// A rotation uniform on SO(3) (normalised quaternion drawn uniformly from the unit 4-ball).
pub fn random_rotation<R: Rng>(g: &mut R) -> Rotation3<f64> {
    loop {
        let q = Vector4::new(
            g.random_range(-1.0..1.0),
            g.random_range(-1.0..1.0),
            g.random_range(-1.0..1.0),
            g.random_range(-1.0..1.0),
        );
        let n = q.norm();
        if n > 1e-3 && n <= 1.0 {
            let q = nalgebra::Quaternion::new(q[0], q[1], q[2], q[3]);
            return UnitQuaternion::from_quaternion(q).to_rotation_matrix();
        }
    }
}

/// An exact rational 3×3 matrix.
pub type RationalMatrix3 = [[BigRational; 3]; 3];

/// The Cayley transform `(I − K)⁻¹(I + K)` of the skew matrix `K = [v]×`: an exact rational
/// rotation for a rational `v`.
///
/// # Example
/// ```
/// use orthocheck_core::{algebra::rat, model::cayley};
/// let r = cayley(&[rat(1, 1), rat(0, 1), rat(0, 1)]);
/// // rotation by 90° about x
/// assert_eq!(r[1][2], rat(-1, 1));
/// ```
pub fn cayley(v: &[BigRational; 3]) -> RationalMatrix3 {
    // Closed form: R = ((1 − |v|²) I + 2 v vᵀ + 2 [v]×) / (1 + |v|²).
    let n2: BigRational = v.iter().map(|x| x * x).sum();
    let den = BigRational::one() + &n2;
    let two = BigRational::from_integer(2.into());
    let skew = [
        [BigRational::zero(), -v[2].clone(), v[1].clone()],
        [v[2].clone(), BigRational::zero(), -v[0].clone()],
        [-v[1].clone(), v[0].clone(), BigRational::zero()],
    ];
    std::array::from_fn(|i| {
        std::array::from_fn(|j| {
            let diag = if i == j {
                BigRational::one() - &n2
            } else {
                BigRational::zero()
            };
            (diag + &two * &v[i] * &v[j] + &two * &skew[i][j]) / &den
        })
    })
}

/// A scene with exact rational coordinates and rotations (for exact ranks).
#[derive(Clone, Debug, PartialEq)]
pub struct RationalScene {
    /// Points, exact.
    pub points: Vec<[BigRational; 3]>,
    /// Rotations, exact; the first is the identity.
    pub rotations: Vec<RationalMatrix3>,
}

impl RationalScene {
    /// A generic random rational scene: integer points in [−9, 9]³ and Cayley rotations of
    /// vectors with components n/4, n ∈ [−8, 8].
    pub fn random(p: usize, k: usize, seed: u64) -> RationalScene {
        let mut g = rng(seed);
        let int = |g: &mut ChaCha8Rng, lo: i64, hi: i64, d: i64| {
            BigRational::new(g.random_range(lo..=hi).into(), d.into())
        };
        let points = (0..p)
            .map(|_| std::array::from_fn(|_| int(&mut g, -9, 9, 1)))
            .collect();
        let mut rotations = vec![cayley(&std::array::from_fn(|_| BigRational::zero()))];
        for _ in 1..k {
            let v: [BigRational; 3] = std::array::from_fn(|_| int(&mut g, -8, 8, 4));
            rotations.push(cayley(&v));
        }
        RationalScene { points, rotations }
    }
}

/// A named noise model: uniform relative error up to ε.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
#[serde(tag = "model", rename_all = "kebab-case")]
pub enum NoiseModel {
    /// Each image coordinate x becomes x·(1 + u), u uniform in [−ε, ε].
    RelativeCoordinate {
        /// ε.
        eps: f64,
    },
    /// Each projected length ℓ becomes ℓ·(1 + u), u uniform in [−ε, ε].
    RelativeLength {
        /// ε.
        eps: f64,
    },
}

impl NoiseModel {
    /// The model's name as used on the command line and in reports.
    pub fn name(&self) -> &'static str {
        match self {
            NoiseModel::RelativeCoordinate { .. } => "relative-coordinate",
            NoiseModel::RelativeLength { .. } => "relative-length",
        }
    }

    /// Perturb tracks (coordinate model) — the length model leaves tracks unchanged and acts
    /// on lengths through [`NoiseModel::perturb_length`].
    pub fn perturb_tracks<R: Rng>(&self, tracks: &Tracks, g: &mut R) -> Tracks {
        let mut frames = tracks.frames.clone();
        self.perturb_points(&mut frames, g);
        Tracks {
            names: tracks.names.clone(),
            frames,
        }
    }

    /// [`NoiseModel::perturb_tracks`] in place, on image points `frames[i][j]`: the same
    /// draws in the same order (frame by frame, point by point, x before y).
    pub fn perturb_points<R: Rng>(&self, frames: &mut [Vec<Vector2<f64>>], g: &mut R) {
        if let NoiseModel::RelativeCoordinate { eps } = *self {
            for p in frames.iter_mut().flatten() {
                let x = p.x * (1.0 + g.random_range(-eps..=eps));
                let y = p.y * (1.0 + g.random_range(-eps..=eps));
                *p = Vector2::new(x, y);
            }
        }
    }

    /// Perturb one projected length (length model); the coordinate model leaves it unchanged.
    pub fn perturb_length<R: Rng>(&self, length: f64, g: &mut R) -> f64 {
        match *self {
            NoiseModel::RelativeLength { eps } => length * (1.0 + g.random_range(-eps..=eps)),
            NoiseModel::RelativeCoordinate { .. } => length,
        }
    }
}

impl Body {
    /// The triangle with PQ = a, QR = b, RP = c, in the plane z = 0 with P at the origin.
    ///
    /// # Example
    /// ```
    /// let b = orthocheck_core::model::Body::triangle(2.0, 3.0, 4.0).unwrap();
    /// assert!((b.squared_distance(1, 2) - 9.0).abs() < 1e-12);
    /// ```
    pub fn triangle(a: f64, b: f64, c: f64) -> Result<Body> {
        if !(a > 0.0 && b > 0.0 && c > 0.0) || a + b <= c || b + c <= a || a + c <= b {
            return Err(Error::InvalidInput(format!(
                "edges {a}, {b}, {c} do not form a triangle"
            )));
        }
        let rx = (a * a + c * c - b * b) / (2.0 * a);
        let ry = (c * c - rx * rx).max(0.0).sqrt();
        Ok(Body::new(vec![
            Vector3::zeros(),
            Vector3::new(a, 0.0, 0.0),
            Vector3::new(rx, ry, 0.0),
        ]))
    }
}

/// Which solver a study runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum StudySolver {
    /// §2: three points, three frames.
    P3f3,
    /// §3: three points, four frames.
    P3f4,
    /// §4: four points, three frames.
    P4f3,
}
