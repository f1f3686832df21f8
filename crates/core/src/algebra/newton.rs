//! Minimum-norm Gauss–Newton for underdetermined systems (finding a witness point).

use nalgebra::{DMatrix, DVector};

/// Find `x` near `x0` with `f(x) ≈ 0` when there are more unknowns than equations: each step
/// is the minimum-norm solution of the linearised system (Jacobian by central differences
/// with step `1e-7·max(1, |xⱼ|)`, so the step stays well above rounding of `f`). Stops when
/// every |fᵢ| ≤ `tolerance` or after `max_iter` steps; returns the best point and its largest
/// |fᵢ|, or `None` when `f` is undefined at `x0`.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::min_norm_newton;
/// // the point of the unit circle nearest (2, 0)
/// let f = |x: &[f64]| Some(vec![x[0] * x[0] + x[1] * x[1] - 1.0]);
/// let (x, r) = min_norm_newton(&f, &[2.0, 0.0], 1e-14, 50).unwrap();
/// assert!(r <= 1e-14 && (x[0] - 1.0).abs() < 1e-12);
/// ```
pub fn min_norm_newton(
    f: &dyn Fn(&[f64]) -> Option<Vec<f64>>,
    x0: &[f64],
    tolerance: f64,
    max_iter: usize,
) -> Option<(Vec<f64>, f64)> {
    min_norm_newton_step(f, x0, tolerance, max_iter, 1e-7)
}

/// [`min_norm_newton`] with the difference step `step·max(1, |xⱼ|)`: a larger step for `f`
/// whose values are large against their own rounding (residuals divided by small
/// tolerances), where the default step would leave the Jacobian's rounding noise above its
/// smallest meaningful singular values.
pub fn min_norm_newton_step(
    f: &dyn Fn(&[f64]) -> Option<Vec<f64>>,
    x0: &[f64],
    tolerance: f64,
    max_iter: usize,
    step: f64,
) -> Option<(Vec<f64>, f64)> {
    let jac = |x: &[f64]| super::central_jacobian(f, x, |_, xj| step * xj.abs().max(1.0));
    min_norm_newton_with(f, &jac, x0, tolerance, max_iter)
}

/// [`min_norm_newton`] with the Jacobian `jac` of `f` (`None`: undefined there), for a
/// caller that forms the central differences of [`min_norm_newton_step`] faster than by
/// evaluating all of `f` at every probe.
pub fn min_norm_newton_with(
    f: &dyn Fn(&[f64]) -> Option<Vec<f64>>,
    jac: &dyn Fn(&[f64]) -> Option<DMatrix<f64>>,
    x0: &[f64],
    tolerance: f64,
    max_iter: usize,
) -> Option<(Vec<f64>, f64)> {
    let norm = |r: &[f64]| r.iter().fold(0.0_f64, |a, b| a.max(b.abs()));
    let mut x = x0.to_vec();
    let mut r = f(&x)?;
    let mut best = (x.clone(), norm(&r));
    for _ in 0..max_iter {
        if best.1 <= tolerance {
            break;
        }
        let n = x.len();
        let Some(jac) = jac(&x) else {
            return Some(best);
        };
        let rv = DVector::from_column_slice(&r);
        // a bounded SVD: the unbounded one may never converge on badly scaled Jacobians
        let Some(svd) = jac.try_svd(true, true, 5.0 * f64::EPSILON, 10_000) else {
            return Some(best);
        };
        let Ok(dx) = svd.solve(&rv, 1e-14) else {
            return Some(best);
        };
        for j in 0..n {
            x[j] -= dx[j];
        }
        r = match f(&x) {
            Some(r) => r,
            None => return Some(best),
        };
        let nr = norm(&r);
        if nr < best.1 {
            best = (x.clone(), nr);
        }
    }
    Some(best)
}
