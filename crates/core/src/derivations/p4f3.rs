//! §4: four points, three frames — the paper's linear system, its general least-squares form
//! for p ≥ 4 points and k ≥ 3 frames, and the body and motions behind a solution.
//!
//! Every triangle of the body obeys eq. p3f3sqr in every frame; the difference of frame i's
//! equation and frame 1's, Fᵢ − F₁ = 0, is linear in the triangle's three squared edges:
//! 2(αᵢ − α₁)u² + 2(βᵢ − β₁)v² + 2(γᵢ − γ₁)w² + (Kᵢ − K₁) = 0. The paper takes the triangles
//! PQT, QRT, RPT and frames 2, 3: six equations in the six squared edges.

use nalgebra::{DMatrix, DVector, Matrix2x3, Matrix3, SMatrix, SVector, SymmetricEigen, Vector3};
use num_rational::BigRational;
use num_traits::Zero;

use super::solver::{feasibility, Degenerate, Feasibility, Solution, SolverOutput, SquaredLengths};
use super::twofold::FrameCoefficients;
use crate::algebra::{largest_eigenvalue, svd_rank_above, SvdRank, NEGLIGIBLE_ULPS};
use crate::error::{Error, Result};
use crate::model::Tracks;

pub mod lsq;
pub use lsq::{lsq_triangles, solve_least_squares, MAX_LSQ_POINTS};

/// The index of the edge {i, j} in [`edges`](super::solver::edges) order.
///
/// # Example
/// ```
/// use orthocheck_core::derivations::p4f3::edge_index;
/// assert_eq!(edge_index(2, 0), 2); // RP
/// assert_eq!(edge_index(1, 3), 4); // TQ
/// ```
pub fn edge_index(i: usize, j: usize) -> usize {
    let (lo, hi) = if i < j { (i, j) } else { (j, i) };
    match (lo, hi) {
        (0, 1) => 0,
        (1, 2) => 1,
        (0, 2) => 2,
        // point hi ≥ 3 has its edges to 0..hi after the 3 + 4 + … + (hi − 1) earlier ones
        _ => 3 + (3..hi).sum::<usize>() + lo,
    }
}

/// The Cayley–Menger determinant of four points from their six squared distances (in
/// [`edges`](super::solver::edges) order), exactly: 288 V² for the tetrahedron's volume V,
/// computed as 8 det G with G the Gram matrix of the edges from point 0 (G = (s₀ᵢ + s₀ⱼ − sᵢⱼ)/2).
/// Negative when no tetrahedron has these distances, zero for a planar one.
pub fn cayley_menger(squares: &[BigRational; 6]) -> BigRational {
    let two = BigRational::from_integer(2.into());
    let g = |i: usize, j: usize| {
        (&squares[edge_index(0, i)] + &squares[edge_index(0, j)]
            - if i == j {
                BigRational::zero()
            } else {
                squares[edge_index(i, j)].clone()
            })
            / &two
    };
    let m: Vec<Vec<BigRational>> = (1..4).map(|i| (1..4).map(|j| g(i, j)).collect()).collect();
    let det = &m[0][0] * (&m[1][1] * &m[2][2] - &m[1][2] * &m[2][1])
        - &m[0][1] * (&m[1][0] * &m[2][2] - &m[1][2] * &m[2][0])
        + &m[0][2] * (&m[1][0] * &m[2][1] - &m[1][1] * &m[2][0]);
    det * BigRational::from_integer(8.into())
}

/// Sixteen times the squared area of a triangle from its squared sides (Heron's formula in
/// squares: 2ab + 2bc + 2ca − a² − b² − c²), exactly; negative when no triangle has them.
pub fn heron16(a: &BigRational, b: &BigRational, c: &BigRational) -> BigRational {
    let two = BigRational::from_integer(2.into());
    &two * (a * b + b * c + c * a) - a * a - b * b - c * c
}

/// A triangle as the indices of its three edges (in [`edges`](super::solver::edges) order).
pub type Triangle = [usize; 3];

/// The paper's triangles PQT, QRT, RPT (edges a g f, d b g, d f c).
pub const PAPER_TRIANGLES: [Triangle; 3] = [[0, 4, 3], [5, 1, 4], [5, 3, 2]];

/// Every triangle of `p` points, in lexicographic order of its points.
pub fn all_triangles(p: usize) -> Vec<Triangle> {
    let mut t = Vec::new();
    for i in 0..p {
        for j in i + 1..p {
            for k in j + 1..p {
                t.push([edge_index(i, j), edge_index(j, k), edge_index(k, i)]);
            }
        }
    }
    t
}

/// One equation Fᵢ − F₁ = 0 of a triangle: coefficients of its three squared edges, and the
/// constant (the equation is `coefficients · x + constant = 0`, the paper's printed form).
pub fn triangle_row(frames: &[Vec<f64>], tri: Triangle, frame: usize) -> ([f64; 3], f64) {
    let pick = |f: &[f64]| [f[tri[0]], f[tri[1]], f[tri[2]]];
    FrameCoefficients::new(pick(&frames[frame]))
        .difference(&FrameCoefficients::new(pick(&frames[0])))
}

/// The paper's 6×6 system in the printed row order (frame 2: PQT, QRT, RPT; then frame 3)
/// and column order x1 … x6 = PQ, QR, RP, TP, TQ, TR: `A x + b = 0`.
pub fn paper_system(l: &[[f64; 6]; 3]) -> (SMatrix<f64, 6, 6>, SVector<f64, 6>) {
    let mut a = SMatrix::<f64, 6, 6>::zeros();
    let mut b = SVector::<f64, 6>::zeros();
    let frames: Vec<Vec<f64>> = l.iter().map(|f| f.to_vec()).collect();
    for (fi, frame) in [1, 2].into_iter().enumerate() {
        for (ti, tri) in PAPER_TRIANGLES.iter().enumerate() {
            let (c, k) = triangle_row(&frames, *tri, frame);
            let r = 3 * fi + ti;
            for (col, v) in tri.iter().zip(c) {
                a[(r, *col)] = v;
            }
            b[r] = k;
        }
    }
    (a, b)
}

/// The allocation-free result of [`solve_core`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Core {
    /// x1 … x6 = PQ², QR², RP², TP², TQ², TR²; `None` when the system is singular.
    pub squares: Option<[f64; 6]>,
    /// No negative square and no edge shorter than a projection.
    pub feasible: bool,
    /// The squares are the distances of four points in 3-D (positive semidefinite Gram).
    pub realizable: bool,
}

/// The paper's system for four points in three frames (projected squared lengths in
/// [`edges`](super::solver::edges) order), solved with the feasibility and realizability checks.
///
/// # Example
/// ```
/// use orthocheck_core::derivations::{p4f3::solve_core, solver::SquaredLengths};
/// let scene = orthocheck_core::model::Scene::random(4, 3, 5);
/// let l = SquaredLengths::from_tracks(&scene.tracks());
/// let core = solve_core(&std::array::from_fn(|i| std::array::from_fn(|e| l.frames[i][e])));
/// let x = core.squares.unwrap();
/// approx::assert_relative_eq!(x[5], scene.body.squared_distance(3, 2), max_relative = 1e-9);
/// assert!(core.feasible && core.realizable);
/// ```
pub fn solve_core(l: &[[f64; 6]; 3]) -> Core {
    let (a, b) = paper_system(l);
    let Some(x) = a.lu().solve(&(-b)) else {
        return Core {
            squares: None,
            feasible: false,
            realizable: false,
        };
    };
    let x: [f64; 6] = std::array::from_fn(|i| x[i]);
    let feasible = super::solver::first_violation(&x, l.iter().map(|f| &f[..])).is_none();
    Core {
        squares: Some(x),
        feasible,
        realizable: gram3_is_psd(&x),
    }
}

/// The Gram matrix of the edge vectors from point 0: Gᵢⱼ = (s₀ᵢ + s₀ⱼ − sᵢⱼ)/2, i, j ≥ 1.
pub fn gram(squares: &[f64], p: usize) -> DMatrix<f64> {
    crate::algebra::gram(p, |i, j| squares[edge_index(i, j)])
}

/// Whether the 3×3 Gram matrix of four points is positive semidefinite, by its principal
/// minors (all of them: the leading ones alone do not decide semidefiniteness).
fn gram3_is_psd(x: &[f64; 6]) -> bool {
    let g = gram(x, 4);
    // each minor is a sum of products of up to three entries, each a sum of three squares
    let tol = NEGLIGIBLE_ULPS * f64::EPSILON * (x.iter().map(|v| v.abs()).sum::<f64>()).powi(3);
    let minor2 = |i: usize, j: usize| g[(i, i)] * g[(j, j)] - g[(i, j)] * g[(i, j)];
    (0..3).all(|i| g[(i, i)] >= 0.0)
        && minor2(0, 1) >= -tol
        && minor2(0, 2) >= -tol
        && minor2(1, 2) >= -tol
        && g.determinant() >= -tol
}

/// The body behind squared edges: coordinates from the Gram matrix (classical
/// multidimensional scaling about point 0).
#[derive(Clone, Debug, PartialEq)]
pub struct Realization {
    /// Points, the first at the origin (a 3-D frame of the body's own).
    pub points: Vec<Vector3<f64>>,
    /// Gram eigenvalues, descending.
    pub eigenvalues: Vec<f64>,
    /// Eigenvalues above the rounding floor.
    pub rank: usize,
    /// No eigenvalue below −floor and rank ≤ 3: the squares are distances in 3-D.
    pub realizable: bool,
    /// The rounding floor used: 64ε · (largest eigenvalue magnitude) · (p − 1).
    pub floor: f64,
}

/// Realize squared edges of `p` points in 3-D.
///
/// # Example
/// ```
/// use orthocheck_core::derivations::p4f3::realize;
/// // a regular tetrahedron of edge 1
/// let r = realize(&[1.0; 6], 4);
/// assert!(r.realizable && r.rank == 3);
/// ```
pub fn realize(squares: &[f64], p: usize) -> Realization {
    let g = gram(squares, p);
    let eig = SymmetricEigen::new(g);
    let mut order: Vec<usize> = (0..p - 1).collect();
    order.sort_by(|&a, &b| eig.eigenvalues[b].total_cmp(&eig.eigenvalues[a]));
    let eigenvalues: Vec<f64> = order.iter().map(|&i| eig.eigenvalues[i]).collect();
    let big = eigenvalues.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    let floor = NEGLIGIBLE_ULPS * f64::EPSILON * big * (p - 1) as f64;
    let rank = eigenvalues.iter().filter(|v| **v > floor).count();
    let realizable = eigenvalues.iter().all(|v| *v >= -floor) && rank <= 3;
    let mut points = vec![Vector3::zeros()];
    for i in 0..p - 1 {
        let mut v = Vector3::zeros();
        for (d, &k) in order.iter().take(3).enumerate() {
            let lam = eig.eigenvalues[k].max(0.0);
            v[d] = eig.eigenvectors[(i, k)] * lam.sqrt();
        }
        points.push(v);
    }
    Realization {
        points,
        eigenvalues,
        rank,
        realizable,
        floor,
    }
}

/// A body fitted to tracks: each frame's orthographic camera by orthogonal Procrustes.
#[derive(Clone, Debug, PartialEq)]
pub struct BodyFit {
    /// The body in frame 1's camera coordinates, the first point at the origin.
    pub points: Vec<Vector3<f64>>,
    /// Per frame, the two rows of the rotation (orthonormal) taking those coordinates into
    /// the image (frame 1's is the identity's, up to rounding).
    pub cameras: Vec<Matrix2x3<f64>>,
    /// Largest reprojection error over frames and points, relative to the body's size.
    pub residual: f64,
}

/// Fit the body of `squares` to the tracks. Per frame, the affine camera A minimising
/// ‖Y − A X‖ over the centred body X and image Y (A = Y Xᵀ (X Xᵀ)⁺), then its polar factor,
/// the nearest 2×3 matrix with orthonormal rows: exact data give the rotation's first two
/// rows exactly; noisy data an approximation whose residual is reported.
pub fn fit(tracks: &Tracks, squares: &[f64]) -> BodyFit {
    let p = tracks.points();
    let body = realize(squares, p).points;
    let centre = body.iter().sum::<Vector3<f64>>() / p as f64;
    let size = body
        .iter()
        .map(|x| (x - centre).norm())
        .fold(f64::MIN_POSITIVE, f64::max);
    let xxt: Matrix3<f64> = body
        .iter()
        .map(|x| (x - centre) * (x - centre).transpose())
        .sum();
    let pinv = xxt
        .pseudo_inverse(NEGLIGIBLE_ULPS * f64::EPSILON * xxt.norm())
        .unwrap_or_else(|_| Matrix3::zeros());
    let mut cameras = Vec::new();
    let mut residual: f64 = 0.0;
    for f in &tracks.frames {
        let c2 = f.iter().sum::<nalgebra::Vector2<f64>>() / p as f64;
        let mut yxt = Matrix2x3::zeros();
        for (y, x) in f.iter().zip(&body) {
            yxt += (y - c2) * (x - centre).transpose();
        }
        let cam = crate::algebra::orthonormal_rows(&(yxt * pinv));
        for (y, x) in f.iter().zip(&body) {
            residual = residual.max((cam * (x - centre) - (y - c2)).norm() / size);
        }
        cameras.push(cam);
    }
    // the body in frame 1's camera coordinates (the third axis completes the first camera's
    // rows to a rotation), first point at the origin
    let r1 = cameras
        .first()
        .map_or_else(Matrix3::identity, crate::algebra::complete_rotation);
    let points = body.iter().map(|x| r1 * (x - body[0])).collect();
    let cameras = cameras.iter().map(|c| c * r1.transpose()).collect();
    BodyFit {
        points,
        cameras,
        residual,
    }
}

/// Whether every frame could be an affine image of one plane: the ratios of the triangles'
/// areas (area² = −K/16 from the projected squared lengths) are the same in every frame, up
/// to rounding. A planar body forces this; so does a motion that only turns the image plane.
fn planar_images(input: &SquaredLengths) -> bool {
    let tris = all_triangles(input.names.len());
    let k = |f: &[f64], t: &Triangle| FrameCoefficients::new([f[t[0]], f[t[1]], f[t[2]]]).k;
    let first = &input.frames[0];
    let Some(reference) = tris
        .iter()
        .max_by(|a, b| k(first, a).abs().total_cmp(&k(first, b).abs()))
    else {
        return false;
    };
    let scale = input
        .frames
        .iter()
        .flatten()
        .fold(0.0_f64, |m, v| m.max(*v));
    // frames with the same lengths as the first: the motion, not the body, is at fault
    let same_lengths = input.frames.iter().all(|f| {
        f.iter()
            .zip(first)
            .all(|(a, b)| crate::algebra::negligible(a - b, a + b))
    });
    !same_lengths
        && input.frames.iter().all(|f| {
            tris.iter().all(|t| {
                let cross = k(f, t) * k(first, reference) - k(first, t) * k(f, reference);
                // each K is at most (3·scale)² in size
                crate::algebra::negligible(cross, 2.0 * (9.0 * scale * scale).powi(2))
            })
        })
}

/// Bounds on the rounding noise of a system's entries (Frobenius norms of matrix and
/// right-hand side), for the numerical rank.
pub fn noise(input: &SquaredLengths, rows: usize) -> (f64, f64) {
    let u = NEGLIGIBLE_ULPS * f64::EPSILON;
    let scale = input
        .frames
        .iter()
        .flat_map(|f| f.iter())
        .fold(0.0_f64, |m, v| m.max(*v));
    // entries 2(αᵢ − α₁) are sums of ±6 squares; constants Kᵢ − K₁ of ±12 products of squares
    let n = (rows as f64).sqrt();
    (n * 3.0 * u * 12.0 * scale, n * u * 24.0 * scale * scale)
}

/// The solver output from a solution `x` (absent when singular), the rank analysis and the
/// largest equation residual |Ax + b|.
#[allow(clippy::too_many_arguments)]
fn finish(
    input: &SquaredLengths,
    method: &str,
    unknowns: usize,
    x: Option<DVector<f64>>,
    residual: impl Fn(&DVector<f64>) -> f64,
    rank: Rank,
    noise_m: f64,
    noise_b: f64,
) -> SolverOutput {
    let mut out = SolverOutput {
        method: method.into(),
        edges: input.edge_names(),
        solutions: Vec::new(),
        degenerate: None,
        condition: rank.condition,
    };
    let (true, Some(x)) = (rank.rank == unknowns, x) else {
        out.degenerate = Some(if planar_images(input) {
            Degenerate::Coplanar
        } else {
            Degenerate::SpecialMotion {
                rank: rank.rank,
                unknowns,
            }
        });
        return out;
    };
    let squares: Vec<f64> = x.iter().copied().collect();
    let scale = squares
        .iter()
        .fold(f64::MIN_POSITIVE, |a, v| a.max(v.abs()));
    let smin = rank.smin;
    let bound = (noise_m * x.norm() + noise_b) / smin;
    let mut real = realize(&squares, input.names.len());
    // the Gram entries (s₀ᵢ + s₀ⱼ − sᵢⱼ)/2 carry up to 1.5 × the squares' error bound, so its
    // eigenvalues move by at most (p − 1)·1.5·bound: a rank above 3 within that is rounding
    let slack = (input.names.len() - 1) as f64 * 1.5 * bound;
    if !real.realizable
        && real
            .eigenvalues
            .iter()
            .all(|v| *v >= -real.floor.max(slack))
        && real
            .eigenvalues
            .iter()
            .skip(3)
            .all(|v| *v <= real.floor.max(slack))
    {
        real.realizable = true;
    }
    let mut feas = feasibility(&squares, &vec![0.0; squares.len()], input);
    if feas.is_feasible() && !real.realizable {
        feas = Feasibility::NotRealizable {
            eigenvalue: real.eigenvalues.last().copied().unwrap_or(0.0),
        };
    }
    out.solutions.push(Solution {
        feasibility: feas,
        residual: residual(&x) / (scale * scale),
        error_bound: Some(bound),
        imaginary: vec![0.0; squares.len()],
        squared_edges: squares,
    });
    out
}

/// The paper's solver in the shared calling convention: four points, three frames.
pub fn solve(input: &SquaredLengths) -> Result<SolverOutput> {
    if input.names.len() != 4 || input.frames.len() != 3 {
        return Err(Error::InvalidInput(format!(
            "p4f3 needs 4 points in 3 frames, got {} points in {} frames",
            input.names.len(),
            input.frames.len()
        )));
    }
    if let Some(d) = super::degenerate::classify(input, 3) {
        return Ok(SolverOutput::degenerate("p4f3", input, d));
    }
    let l: [[f64; 6]; 3] = std::array::from_fn(|i| std::array::from_fn(|e| input.frames[i][e]));
    let (a, b) = paper_system(&l);
    let m = DMatrix::from_fn(6, 6, |i, j| a[(i, j)]);
    let rhs = DVector::from_fn(6, |i, _| b[i]);
    let (noise_m, noise_b) = noise(input, 6);
    let rank = svd_rank_above(&m, noise_m);
    let x = m.clone().lu().solve(&(-&rhs));
    let residual = |x: &DVector<f64>| (&m * x + &rhs).amax();
    Ok(finish(
        input,
        "p4f3",
        6,
        x,
        residual,
        rank.into(),
        noise_m,
        noise_b,
    ))
}

/// The general system: every triangle of the body, every later frame against frame 1.
pub fn general_system(input: &SquaredLengths) -> (DMatrix<f64>, DVector<f64>) {
    let tris = all_triangles(input.names.len());
    let rows = tris.len() * (input.frames.len() - 1);
    let mut m = DMatrix::zeros(rows, input.edges.len());
    let mut b = DVector::zeros(rows);
    let mut r = 0;
    for frame in 1..input.frames.len() {
        for tri in &tris {
            let (c, k) = triangle_row(&input.frames, *tri, frame);
            for (col, v) in tri.iter().zip(c) {
                m[(r, *col)] = v;
            }
            b[r] = k;
            r += 1;
        }
    }
    (m, b)
}

/// The rank analysis a solution needs.
struct Rank {
    rank: usize,
    condition: Option<f64>,
    smin: f64,
}

impl From<SvdRank> for Rank {
    fn from(r: SvdRank) -> Self {
        Rank {
            rank: r.rank,
            condition: r.condition,
            smin: r.singular_values.last().copied().unwrap_or(0.0),
        }
    }
}

/// Residuals that vanish exactly when `frame` (image points) is an orthographic view of
/// `body`: the affine camera's misfit Y − A X (centred) and A Aᵀ − I (its rows orthonormal).
pub fn view_residual(body: &[Vector3<f64>], frame: &[[f64; 2]]) -> Vec<f64> {
    let p = body.len();
    let centre = body.iter().sum::<Vector3<f64>>() / p as f64;
    let c2 = frame.iter().fold([0.0, 0.0], |a, c| {
        [a[0] + c[0] / p as f64, a[1] + c[1] / p as f64]
    });
    let xxt: Matrix3<f64> = body
        .iter()
        .map(|x| (x - centre) * (x - centre).transpose())
        .sum();
    let Some(inv) = xxt.try_inverse() else {
        return vec![f64::NAN];
    };
    let mut yxt = Matrix2x3::zeros();
    for (y, x) in frame.iter().zip(body) {
        yxt += nalgebra::Vector2::new(y[0] - c2[0], y[1] - c2[1]) * (x - centre).transpose();
    }
    let a = yxt * inv;
    let mut r = Vec::with_capacity(2 * p + 3);
    for (y, x) in frame.iter().zip(body) {
        let q = a * (x - centre);
        r.push(q.x - (y[0] - c2[0]));
        r.push(q.y - (y[1] - c2[1]));
    }
    let g = a * a.transpose();
    r.extend([g[(0, 0)] - 1.0, g[(1, 1)] - 1.0, g[(0, 1)]]);
    r
}

/// The paper's system solved from image points (`frames[f][point] = [x, y]`, 4 points in
/// 3 frames); `None` when singular.
pub fn solve_points(frames: &[Vec<[f64; 2]>]) -> Option<[f64; 6]> {
    let l: [[f64; 6]; 3] = std::array::from_fn(|f| {
        let sq = crate::model::squared_lengths(&frames[f]);
        std::array::from_fn(|e| sq[e])
    });
    solve_core(&l).squares
}

/// First-order prediction of the spread of each squared edge when every image coordinate c
/// becomes c·(1 + u·ε), u uniform in [−1, 1] (variance 1/3): the relative standard deviation
/// ε·√(Σₖ (∂xⱼ/∂cₖ · cₖ)² / 3) / xⱼ, the derivatives by central differences. `None` when the
/// system is singular.
pub fn first_order_spread(frames: &[Vec<[f64; 2]>], eps: f64) -> Option<[f64; 6]> {
    let x0 = solve_points(frames)?;
    let p = frames.first().map_or(0, Vec::len);
    let unflat = |c: &[f64]| -> Vec<Vec<[f64; 2]>> {
        (0..frames.len())
            .map(|f| {
                (0..p)
                    .map(|j| [c[2 * (p * f + j)], c[2 * (p * f + j) + 1]])
                    .collect()
            })
            .collect()
    };
    let flat: Vec<f64> = frames.iter().flatten().flatten().copied().collect();
    let solve = |c: &[f64]| solve_points(&unflat(c)).map(|x| x.to_vec());
    // a relative step of 1e-6: well above the solve's rounding, well inside its curvature
    let jac = crate::algebra::central_jacobian(&solve, &flat, |_, c| 1e-6 * c.abs())?;
    Some(std::array::from_fn(|j| {
        let acc: f64 = (0..flat.len())
            .map(|k| (jac[(j, k)] * flat[k]).powi(2))
            .sum();
        eps * (acc / 3.0).sqrt() / x0[j].abs()
    }))
}
