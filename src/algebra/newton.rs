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
/// use orthocheck::algebra::min_norm_newton;
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
    let norm = |r: &[f64]| r.iter().fold(0.0_f64, |a, b| a.max(b.abs()));
    let mut x = x0.to_vec();
    let mut r = f(&x)?;
    let mut best = (x.clone(), norm(&r));
    for _ in 0..max_iter {
        if best.1 <= tolerance {
            break;
        }
        let (m, n) = (r.len(), x.len());
        let mut jac = DMatrix::zeros(m, n);
        for j in 0..n {
            let h = 1e-7 * x[j].abs().max(1.0);
            let mut xp = x.clone();
            let mut xm = x.clone();
            xp[j] += h;
            xm[j] -= h;
            let (Some(fp), Some(fm)) = (f(&xp), f(&xm)) else {
                return Some(best);
            };
            for i in 0..m {
                jac[(i, j)] = (fp[i] - fm[i]) / (2.0 * h);
            }
        }
        let rv = DVector::from_vec(r.clone());
        let Ok(step) = jac.clone().svd(true, true).solve(&rv, 1e-14) else {
            return Some(best);
        };
        for j in 0..n {
            x[j] -= step[j];
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
