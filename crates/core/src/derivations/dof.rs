//! §2.1: degrees of freedom — the paper's count, and the real answer from the Jacobian rank.
//!
//! Parametrisation (the paper's count made concrete): frame 1 is the identity motion, so the
//! structure is written in frame 1's coordinates, with the depth of the first point fixed
//! (the invisible depth of the whole body); every later frame has a rotation (3, a left
//! perturbation `exp([ω]×)·Rᵢ`) and an image translation (2). The map sends these
//! −1 + 3p + 5(k − 1) parameters to the 2kp image coordinates.

use std::ops::{Add, Mul, Neg};

use nalgebra::DMatrix;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};

use crate::algebra::{exact_rank, svd_rank, ExactRankMethod};
use crate::error::{Error, Result};
use crate::model::RationalScene;

/// The paper's degree-of-freedom count for `p` points over `k` frames.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct DofCount {
    /// p.
    pub points: usize,
    /// k.
    pub frames: usize,
    /// −1 + 3p + 5(k − 1).
    pub unknowns: i64,
    /// 2kp.
    pub measurements: i64,
    /// measurements − unknowns (the paper requires ≥ 0).
    pub balance: i64,
}

/// The paper's count.
///
/// # Example
/// ```
/// let c = orthocheck_core::derivations::dof::count(5, 4);
/// assert_eq!((c.unknowns, c.measurements), (29, 40));
/// ```
pub fn count(p: usize, k: usize) -> DofCount {
    let (pi, ki) = (p as i64, k as i64);
    let unknowns = -1 + 3 * pi + 5 * (ki - 1);
    let measurements = 2 * ki * pi;
    DofCount {
        points: p,
        frames: k,
        unknowns,
        measurements,
        balance: measurements - unknowns,
    }
}

/// The Jacobian of the image coordinates with respect to the parameters, over any field-like
/// scalar (used with `f64` and with exact rationals). Rows: frame, point, (x, y). Columns:
/// point 1 (x, y), points 2.. (x, y, z), then per later frame (ω₁, ω₂, ω₃, t₁, t₂).
pub fn jacobian_generic<T>(points: &[[T; 3]], rotations: &[[[T; 3]; 3]]) -> Vec<Vec<T>>
where
    T: Clone + Zero + One + Neg<Output = T> + Add<Output = T> + Mul<Output = T>,
{
    let p = points.len();
    let k = rotations.len();
    let cols = 3 * p + 5 * k.saturating_sub(1) - 1;
    let point_col = |j: usize| if j == 0 { 0 } else { 3 * j - 1 };
    let frame_col = |i: usize| 3 * p - 1 + 5 * (i - 1);
    let mut rows = Vec::with_capacity(2 * p * k);
    for (i, r) in rotations.iter().enumerate() {
        for (j, x) in points.iter().enumerate() {
            let mut ru = vec![T::zero(); cols];
            let mut rv = vec![T::zero(); cols];
            let dims = if j == 0 { 2 } else { 3 };
            for d in 0..dims {
                ru[point_col(j) + d] = r[0][d].clone();
                rv[point_col(j) + d] = r[1][d].clone();
            }
            if i > 0 {
                // y = R x; d(Rx) = ω × y, whose first two rows are [0, y3, −y2], [−y3, 0, y1].
                let y: Vec<T> = (0..3)
                    .map(|a| (0..3).fold(T::zero(), |s, b| s + r[a][b].clone() * x[b].clone()))
                    .collect();
                let c = frame_col(i);
                ru[c + 1] = y[2].clone();
                ru[c + 2] = -y[1].clone();
                rv[c] = -y[2].clone();
                rv[c + 2] = y[0].clone();
                ru[c + 3] = T::one();
                rv[c + 4] = T::one();
            }
            rows.push(ru);
            rows.push(rv);
        }
    }
    rows
}

/// The exact Jacobian at a rational scene.
pub fn exact_jacobian(scene: &RationalScene) -> Vec<Vec<BigRational>> {
    jacobian_generic(&scene.points, &scene.rotations)
}

/// The floating Jacobian at (the `f64` image of) a rational scene.
pub fn float_jacobian(scene: &RationalScene) -> DMatrix<f64> {
    let f = |x: &BigRational| x.to_f64().unwrap_or(f64::NAN);
    let points: Vec<[f64; 3]> = scene
        .points
        .iter()
        .map(|x| std::array::from_fn(|d| f(&x[d])))
        .collect();
    let rotations: Vec<[[f64; 3]; 3]> = scene
        .rotations
        .iter()
        .map(|r| std::array::from_fn(|a| std::array::from_fn(|b| f(&r[a][b]))))
        .collect();
    to_matrix(&jacobian_generic(&points, &rotations))
}

/// Rows of equal length as a dense matrix.
pub fn to_matrix(rows: &[Vec<f64>]) -> DMatrix<f64> {
    let (m, n) = (rows.len(), rows.first().map_or(0, Vec::len));
    DMatrix::from_fn(m, n, |i, j| rows[i][j])
}

/// Identifiability of `p` points over `k` frames at one seeded generic rational scene.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Identifiability {
    /// The paper's count.
    #[serde(flatten)]
    pub count: DofCount,
    /// Number of parameters (Jacobian columns) — equals the paper's `unknowns`.
    pub parameters: usize,
    /// Rank by SVD (tolerance σmax·max(m,n)·ε).
    pub jacobian_rank: usize,
    /// Exact rank at the same rational point.
    pub exact_rank: usize,
    /// How the exact rank was proven.
    pub exact_method: ExactRankMethod,
    /// parameters − rank: the dimension of the set of scenes giving the same images, near
    /// the generic scene (0 means finitely many solutions locally).
    pub deficiency: usize,
    /// Condition number of the Jacobian (σmax/σmin); `None` when rank-deficient.
    pub condition: Option<f64>,
    /// Seed of the scene.
    pub seed: u64,
}

/// Rank analysis at a seeded random rational scene.
///
/// # Example
/// ```
/// let r = orthocheck_core::derivations::dof::identifiability(6, 2, 1).unwrap();
/// assert!(r.count.balance > 0);   // the count says "enough"
/// assert!(r.deficiency > 0);      // the Jacobian says the images leave an ambiguity
/// ```
pub fn identifiability(p: usize, k: usize, seed: u64) -> Result<Identifiability> {
    if p == 0 || k == 0 {
        return Err(Error::InvalidInput(format!(
            "need at least one point and one frame, got {p} points and {k} frames"
        )));
    }
    let scene = RationalScene::random(p, k, seed);
    let exact = exact_jacobian(&scene);
    let float = float_jacobian(&scene);
    let svd = svd_rank(&float);
    let (er, method) = exact_rank(&exact);
    let parameters = float.ncols();
    Ok(Identifiability {
        count: count(p, k),
        parameters,
        jacobian_rank: svd.rank,
        exact_rank: er,
        exact_method: method,
        deficiency: parameters - er,
        condition: svd.condition,
        seed,
    })
}

/// The grid p = 1..=max_points, k = 1..=max_frames.
pub fn table(max_points: usize, max_frames: usize, seed: u64) -> Result<Vec<Identifiability>> {
    let mut out = Vec::new();
    for p in 1..=max_points {
        for k in 1..=max_frames {
            out.push(identifiability(p, k, seed)?);
        }
    }
    Ok(out)
}

/// Whether two count formulas in `p` and `k` give, in every cell of `grid`, the number of
/// parameters (Jacobian columns) and of image coordinates (rows, 2kp).
pub fn formulas_count_the_jacobian(
    grid: &[Identifiability],
    unknowns: &crate::algebra::Poly,
    measurements: &crate::algebra::Poly,
) -> bool {
    let at = |f: &crate::algebra::Poly, r: &Identifiability| {
        let values = std::collections::BTreeMap::from([
            (
                "p".to_string(),
                BigRational::from_integer(r.count.points.into()),
            ),
            (
                "k".to_string(),
                BigRational::from_integer(r.count.frames.into()),
            ),
        ]);
        f.eval(&values)
    };
    let int = |n: usize| Some(BigRational::from_integer(n.into()));
    grid.iter().all(|r| {
        at(unknowns, r) == int(r.parameters)
            // the Jacobian's rows: two image coordinates per point and frame
            && at(measurements, r) == int(2 * r.count.points * r.count.frames)
    })
}

/// Fewest points of a body with a shape: a single point has nothing to recover but its image
/// position, so its "identifiability" says nothing about structure and motion.
pub const SHAPE_POINTS: usize = 2;

/// The cell (p, k) of `grid` is identifiable (deficiency 0).
pub fn identifiable_at(grid: &[Identifiability], p: usize, k: usize) -> bool {
    grid.iter()
        .any(|r| r.count.points == p && r.count.frames == k && r.deficiency == 0)
}

/// The smallest p and the smallest k among identifiable cells of bodies with a shape.
pub fn smallest_identifiable(grid: &[Identifiability]) -> (Option<usize>, Option<usize>) {
    let ok = || {
        grid.iter()
            .filter(|r| r.deficiency == 0 && r.count.points >= SHAPE_POINTS)
    };
    (
        ok().map(|r| r.count.points).min(),
        ok().map(|r| r.count.frames).min(),
    )
}

/// (p, k) is identifiable and no identifiable body with a shape has fewer points or frames.
pub fn is_minimum(grid: &[Identifiability], p: usize, k: usize) -> bool {
    identifiable_at(grid, p, k) && smallest_identifiable(grid) == (Some(p), Some(k))
}

/// Every cell with `k` frames is rank-deficient (and there is at least one).
pub fn deficient_for_every_p(grid: &[Identifiability], k: usize) -> bool {
    let cells: Vec<&Identifiability> = grid.iter().filter(|r| r.count.frames == k).collect();
    !cells.is_empty() && cells.iter().all(|r| r.deficiency > 0)
}
