//! The largest eigenvalue of a symmetric positive semidefinite operator by Lanczos with full
//! reorthogonalisation (a few dozen products instead of a full eigendecomposition).

use nalgebra::{DMatrix, DVector, SymmetricEigen};

/// The largest eigenvalue of the symmetric operator `apply` on ℝⁿ, from the all-ones start:
/// Lanczos steps until the largest Ritz value settles to `tolerance` (relative), at most n.
///
/// # Example
/// ```
/// use nalgebra::{DMatrix, DVector, SymmetricEigen};
/// use orthocheck_core::algebra::largest_eigenvalue;
/// let m = DMatrix::from_fn(50, 50, |i, j| if i == j { (i + 1) as f64 } else { 0.01 });
/// let l = largest_eigenvalue(|v: &DVector<f64>| &m * v, 50, 1e-12);
/// let exact = m.symmetric_eigenvalues().max();
/// assert!((l - exact).abs() <= 1e-10 * exact);
/// ```
pub fn largest_eigenvalue(
    apply: impl Fn(&DVector<f64>) -> DVector<f64>,
    n: usize,
    tolerance: f64,
) -> f64 {
    if n == 0 {
        return 0.0;
    }
    let mut basis: Vec<DVector<f64>> = vec![DVector::from_element(n, 1.0 / (n as f64).sqrt())];
    let (mut alpha, mut beta) = (Vec::new(), Vec::<f64>::new());
    let mut last = f64::NAN;
    for j in 0..n {
        let mut w = apply(&basis[j]);
        alpha.push(w.dot(&basis[j]));
        // full reorthogonalisation (twice is enough) keeps the Ritz values honest
        for _ in 0..2 {
            for b in &basis {
                let c = w.dot(b);
                w.axpy(-c, b, 1.0);
            }
        }
        let t = DMatrix::from_fn(j + 1, j + 1, |r, c| match r.abs_diff(c) {
            0 => alpha[r],
            1 => beta[r.min(c)],
            _ => 0.0,
        });
        let ritz = SymmetricEigen::new(t).eigenvalues.max();
        let norm = w.norm();
        if (ritz - last).abs() <= tolerance * ritz.abs() || norm <= f64::EPSILON * ritz.abs() {
            return ritz;
        }
        last = ritz;
        beta.push(norm);
        basis.push(w / norm);
    }
    last
}
