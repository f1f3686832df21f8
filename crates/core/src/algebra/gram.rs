//! The Gram matrix of a point set from its squared distances.

use nalgebra::DMatrix;

/// The Gram matrix of the vectors from point 0 to points 1 … p−1, from squared distances
/// `d(i, j)`: Gᵢⱼ = (d(0, i) + d(0, j) − d(i, j)) / 2 (the law of cosines). Positive
/// semidefinite of rank ≤ 3 exactly when the distances are those of points in 3-D.
///
/// # Example
/// ```
/// // the unit right angle: P at the origin, Q and R on the axes
/// let d = |i: usize, j: usize| [[0.0, 1.0, 1.0], [1.0, 0.0, 2.0], [1.0, 2.0, 0.0]][i][j];
/// let g = orthocheck_core::algebra::gram(3, d);
/// assert_eq!(g, nalgebra::DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, 1.0]));
/// ```
pub fn gram(p: usize, d: impl Fn(usize, usize) -> f64) -> DMatrix<f64> {
    let s = |i: usize, j: usize| if i == j { 0.0 } else { d(i, j) };
    DMatrix::from_fn(p.saturating_sub(1), p.saturating_sub(1), |i, j| {
        0.5 * (s(0, i + 1) + s(0, j + 1) - s(i + 1, j + 1))
    })
}
