//! The metric upgrade: the affine motion M is M_true Q⁻¹ for some invertible Q; L = QQᵀ is
//! linear in the constraints that each frame's two rows a, b have equal norms and are
//! orthogonal (aᵀLa − bᵀLb = 0, aᵀLb = 0), its scale fixed by frame 1 (aᵀLa + bᵀLb = 2).
//! Q is L's Cholesky factor; when L is not positive definite (noise, or too little motion),
//! the nearest positive definite matrix by eigenvalue clipping is used instead, and said so.

use nalgebra::{Cholesky, DMatrix, Matrix3, SymmetricEigen, Vector3, SVD};

use super::ITERATION_LIMIT as SVD_MAX_ITERATIONS;
use super::{Degenerate, Error};
use crate::algebra::negligible;

/// The coefficients of aᵀLb in L's six unknowns (L₁₁, L₁₂, L₁₃, L₂₂, L₂₃, L₃₃).
fn coeffs(a: &Vector3<f64>, b: &Vector3<f64>) -> [f64; 6] {
    [
        a.x * b.x,
        a.x * b.y + a.y * b.x,
        a.x * b.z + a.z * b.x,
        a.y * b.y,
        a.y * b.z + a.z * b.y,
        a.z * b.z,
    ]
}

/// The symmetric matrix of six unknowns.
fn symmetric(l: &[f64]) -> Matrix3<f64> {
    Matrix3::new(l[0], l[1], l[2], l[1], l[3], l[4], l[2], l[4], l[5])
}

/// The warning when L was clipped: the upgrade is then not the one the constraints fix.
pub const CLIPPED: &str = "the metric upgrade found L not positive definite and clipped its eigenvalues (noise, or too little motion): the start is not metric, and the body may be distorted";

/// The upgrade found.
#[derive(Clone, Debug, PartialEq)]
pub struct Upgrade {
    /// Q: the true motion is M Q, the true shape Q⁻¹ S.
    pub q: Matrix3<f64>,
    /// Whether L had to be clipped to positive definite.
    pub clipped: bool,
    /// σ₁/σ₅ of the constraint matrix.
    pub condition: f64,
}

/// The rows of frame `f` of M.
fn rows(m: &DMatrix<f64>, f: usize) -> (Vector3<f64>, Vector3<f64>) {
    let r = |i: usize| Vector3::new(m[(i, 0)], m[(i, 1)], m[(i, 2)]);
    (r(2 * f), r(2 * f + 1))
}

/// L from the motion matrix M (2k × 3): the null vector of the 2k homogeneous constraints,
/// scaled by frame 1. A null space of dimension two or more (σ₅ within 64ε·2k of σ₁: the
/// constraint entries are products of M's entries, rounded to about ε|M|²) means too little
/// motion to fix the metric: two frames that differ in the image plane only, or a special
/// motion.
pub fn constraint_l(m: &DMatrix<f64>) -> Result<(Matrix3<f64>, f64), Error> {
    let k = m.nrows() / 2;
    let mut a = DMatrix::zeros(2 * k, 6);
    for f in 0..k {
        let (r1, r2) = rows(m, f);
        let (aa, bb, ab) = (coeffs(&r1, &r1), coeffs(&r2, &r2), coeffs(&r1, &r2));
        for c in 0..6 {
            a[(2 * f, c)] = aa[c] - bb[c];
            a[(2 * f + 1, c)] = ab[c];
        }
    }
    if !a.iter().all(|v| v.is_finite()) {
        return Err(Error::Numerical("a non-finite metric constraint".into()));
    }
    let svd = SVD::try_new(a, false, true, f64::EPSILON, SVD_MAX_ITERATIONS)
        .ok_or_else(|| Error::Numerical("the metric constraints' SVD did not converge".into()))?;
    let vt = svd
        .v_t
        .ok_or_else(|| Error::Numerical("the metric constraints' SVD has no vectors".into()))?;
    let mut order: Vec<usize> = (0..svd.singular_values.len()).collect();
    order.sort_by(|&x, &y| svd.singular_values[y].total_cmp(&svd.singular_values[x]));
    let s = |i: usize| order.get(i).map_or(0.0, |&o| svd.singular_values[o]);
    if order.len() < 6 || negligible(s(4), 2.0 * k as f64 * s(0)) {
        return Err(Error::Degenerate(Degenerate::SpecialMotion {
            rank: order
                .iter()
                .filter(|&&o| !negligible(svd.singular_values[o], 2.0 * k as f64 * s(0)))
                .count(),
            unknowns: 6,
        }));
    }
    let null = order[5];
    let l: Vec<f64> = (0..6).map(|c| vt[(null, c)]).collect();
    let mut lm = symmetric(&l);
    let (r1, r2) = rows(m, 0);
    let norm = (r1.dot(&(lm * r1)) + r2.dot(&(lm * r2))) / 2.0;
    if norm == 0.0 || !norm.is_finite() {
        return Err(Error::Numerical(
            "frame 1 fixes no scale of the metric".into(),
        ));
    }
    lm /= norm;
    Ok((lm, s(0) / s(4)))
}

/// The upgrade Q from M.
pub fn upgrade(m: &DMatrix<f64>) -> Result<Upgrade, Error> {
    let (l, condition) = constraint_l(m)?;
    if let Some(c) = Cholesky::new(l) {
        return Ok(Upgrade {
            q: c.l(),
            clipped: false,
            condition,
        });
    }
    Ok(Upgrade {
        q: clipped_factor(&l)?,
        clipped: true,
        condition,
    })
}

/// Q with QQᵀ the nearest positive definite matrix to L: eigenvalues below λ_max·√ε raised
/// to it. Zero (the nearest semidefinite matrix) would make Q singular and the shape Q⁻¹S
/// infinite; the floor keeps Q's condition below ε^-¼, so the shape loses at most a quarter
/// of its digits, and the refit of the points from the rotations removes Q from them anyway.
pub fn clipped_factor(l: &Matrix3<f64>) -> Result<Matrix3<f64>, Error> {
    let e = SymmetricEigen::try_new(*l, f64::EPSILON, SVD_MAX_ITERATIONS)
        .ok_or_else(|| Error::Numerical("L's eigen-decomposition did not converge".into()))?;
    let top = e.eigenvalues.max();
    if top <= 0.0 || !top.is_finite() {
        return Err(Error::Numerical(
            "the metric upgrade has no positive direction (L is negative semidefinite)".into(),
        ));
    }
    let floor = top * f64::EPSILON.sqrt();
    let root = e.eigenvalues.map(|v| v.max(floor).sqrt());
    Ok(e.eigenvectors * Matrix3::from_diagonal(&root))
}
