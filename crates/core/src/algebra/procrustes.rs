//! Orthogonal Procrustes: the rotation (or orthonormal rows) nearest a linear map.

use nalgebra::{Matrix2x3, Matrix3, Rotation3, Vector3};

/// The proper rotation `R` minimising Σ‖R·fromⱼ − toⱼ‖² (Kabsch: the polar factor of
/// Σ toⱼ fromⱼᵀ with its determinant forced to +1). Both sets are taken as they are (centre
/// them first if the translation is free).
///
/// # Example
/// ```
/// use nalgebra::{Rotation3, Vector3};
/// let r = Rotation3::from_euler_angles(0.3, -0.2, 0.9);
/// let from = [Vector3::new(1.0, 0.0, 0.0), Vector3::new(0.0, 2.0, 0.0), Vector3::new(0.0, 0.0, 3.0)];
/// let to = from.map(|x| r * x);
/// let k = orthocheck_core::algebra::kabsch(&from, &to);
/// approx::assert_relative_eq!(k.matrix(), r.matrix(), epsilon = 1e-12);
/// ```
pub fn kabsch(from: &[Vector3<f64>], to: &[Vector3<f64>]) -> Rotation3<f64> {
    let h: Matrix3<f64> = from.iter().zip(to).map(|(f, t)| t * f.transpose()).sum();
    Rotation3::from_matrix_unchecked(nearest_rotation(&h))
}

/// The proper rotation nearest `m` in the Frobenius norm: its polar factor U Vᵀ, the last
/// singular direction reversed when that has determinant −1. The identity when the SVD fails.
pub fn nearest_rotation(m: &Matrix3<f64>) -> Matrix3<f64> {
    let svd = m.svd(true, true);
    let (Some(u), Some(vt)) = (svd.u, svd.v_t) else {
        return Matrix3::identity();
    };
    let d = (u * vt).determinant().signum();
    u * Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, d)) * vt
}

/// The 2×3 matrix with orthonormal rows nearest `a` in the Frobenius norm (its polar factor
/// U Vᵀ): the orthographic camera nearest an affine one. Zero when the SVD fails.
pub fn orthonormal_rows(a: &Matrix2x3<f64>) -> Matrix2x3<f64> {
    let svd = a.svd(true, true);
    match (svd.u, svd.v_t) {
        (Some(u), Some(vt)) => u * vt,
        _ => Matrix2x3::zeros(),
    }
}

/// The rotation whose first two rows are the orthonormal rows `c`, completed by their cross
/// product.
pub fn complete_rotation(c: &Matrix2x3<f64>) -> Matrix3<f64> {
    let (a, b) = (c.row(0).transpose(), c.row(1).transpose());
    Matrix3::from_rows(&[a.transpose(), b.transpose(), a.cross(&b).transpose()])
}
