//! §3: three points, four or more frames — the linear solver.
//!
//! Subtracting frame 1's twofold-squared equation from frame i's (i = 2, 3, 4, …) leaves
//! 2(αᵢ − α₁)a² + 2(βᵢ − β₁)b² + 2(γᵢ − γ₁)c² = −(Kᵢ − K₁), linear in (a², b², c²).
//! Four frames give a square system; more frames are solved by least squares.

use nalgebra::{DMatrix, DVector, Matrix3, Vector3};

use super::solver::{feasibility, Degenerate, Solution, SolverOutput, SquaredLengths};
use super::twofold::FrameCoefficients;
use crate::algebra::{svd_rank_above, NEGLIGIBLE_ULPS};
use crate::error::{Error, Result};

/// Four frames of projected squared lengths (PQ, QR, RP) → (a², b², c²) and whether it is
/// feasible; `None` when the 3×3 system is singular.
///
/// # Example
/// ```
/// use orthocheck_core::derivations::{p3f4::solve_core, solver::SquaredLengths};
/// use orthocheck_core::model::Scene;
/// let scene = Scene::random(3, 4, 9);
/// let l = SquaredLengths::from_tracks(&scene.tracks());
/// let (x, feasible) = solve_core(&[0, 1, 2, 3].map(|i| [l.frames[i][0], l.frames[i][1], l.frames[i][2]])).unwrap();
/// approx::assert_relative_eq!(x[0], scene.body.squared_distance(0, 1), max_relative = 1e-9);
/// assert!(feasible);
/// ```
pub fn solve_core(l: &[[f64; 3]; 4]) -> Option<([f64; 3], bool)> {
    let f1 = FrameCoefficients::new(l[0]);
    let mut m = Matrix3::zeros();
    let mut rhs = Vector3::zeros();
    for i in 1..4 {
        let (d, k) = FrameCoefficients::new(l[i]).difference(&f1);
        for c in 0..3 {
            m[(i - 1, c)] = d[c];
        }
        rhs[i - 1] = -k;
    }
    let x = m.lu().solve(&rhs)?;
    let x = [x[0], x[1], x[2]];
    let feasible = super::solver::first_violation(&x, l.iter().map(|f| &f[..])).is_none();
    Some((x, feasible))
}

/// The linear system, one row per later frame, with bounds on the Frobenius norm of the
/// rounding error of its matrix and of its right-hand side.
pub struct System {
    /// The matrix.
    pub m: DMatrix<f64>,
    /// The right-hand side.
    pub rhs: DVector<f64>,
    /// Bound on the rounding of the matrix (Frobenius).
    pub noise_m: f64,
    /// Bound on the rounding of the right-hand side.
    pub noise_rhs: f64,
}

/// The linear system of §3 at `input`, with its rounding bounds.
pub fn system(input: &SquaredLengths) -> System {
    let tri = |i: usize| [input.frames[i][0], input.frames[i][1], input.frames[i][2]];
    let f1 = FrameCoefficients::new(tri(0));
    let n = input.frames.len() - 1;
    let mut m = DMatrix::zeros(n, 3);
    let mut rhs = DVector::zeros(n);
    let (mut noise_m, mut noise_rhs) = (0.0, 0.0);
    let u = NEGLIGIBLE_ULPS * f64::EPSILON;
    for i in 1..=n {
        let fi = FrameCoefficients::new(tri(i));
        // entries 2(αᵢ − α₁) come from terms bounded by the frames' scales, Kᵢ − K₁ by squares
        noise_m += 3.0 * (u * 2.0 * (fi.scale + f1.scale)).powi(2);
        noise_rhs += (u * 2.0 * (fi.scale.powi(2) + f1.scale.powi(2))).powi(2);
        let (d, k) = fi.difference(&f1);
        for c in 0..3 {
            m[(i - 1, c)] = d[c];
        }
        rhs[i - 1] = -k;
    }
    System {
        m,
        rhs,
        noise_m: noise_m.sqrt(),
        noise_rhs: noise_rhs.sqrt(),
    }
}

/// The p3f4 solver in the shared calling convention: three points, four or more frames.
pub fn solve(input: &SquaredLengths) -> Result<SolverOutput> {
    if input.names.len() != 3 || input.frames.len() < 4 {
        return Err(Error::InvalidInput(format!(
            "p3f4 needs 3 points in at least 4 frames, got {} points in {} frames",
            input.names.len(),
            input.frames.len()
        )));
    }
    if let Some(d) = super::degenerate::classify(input, 4) {
        return Ok(SolverOutput::degenerate("p3f4", input, d));
    }
    let sys = system(input);
    let rank = svd_rank_above(&sys.m, sys.noise_m);
    let mut out = SolverOutput {
        method: "p3f4".into(),
        edges: input.edge_names(),
        solutions: Vec::new(),
        degenerate: None,
        condition: rank.condition,
    };
    if rank.rank < 3 {
        out.degenerate = Some(Degenerate::SpecialMotion {
            rank: rank.rank,
            unknowns: 3,
        });
        return Ok(out);
    }
    // Least squares by Householder QR (rank 3 is established): backward stable, and more
    // accurate here than nalgebra's SVD solve, which lost ~1e-10 on well-conditioned systems.
    let qr = sys.m.clone().qr();
    let qtb = qr.q().transpose() * &sys.rhs;
    let x = qr
        .r()
        .solve_upper_triangular(&qtb)
        .ok_or_else(|| Error::Numerical("singular triangular factor".into()))?;
    let squares = vec![x[0], x[1], x[2]];
    let r = &sys.m * &x - &sys.rhs;
    let scale = squares
        .iter()
        .fold(f64::MIN_POSITIVE, |a, b| a.max(b.abs()));
    let smin = rank.singular_values.last().copied().unwrap_or(0.0);
    out.solutions.push(Solution {
        feasibility: feasibility(&squares, &[0.0; 3], input),
        residual: r.amax() / (scale * scale),
        error_bound: Some((sys.noise_m * x.norm() + sys.noise_rhs) / smin),
        imaginary: vec![0.0; 3],
        squared_edges: squares,
    });
    Ok(out)
}
