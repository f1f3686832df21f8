//! Central differences: the one numerical derivative of the crate.

use nalgebra::DMatrix;

/// The Jacobian of `f` at `x` by central differences, ∂fᵢ/∂xⱼ ≈ (f(x + hⱼeⱼ) − f(x − hⱼeⱼ)) /
/// 2hⱼ, with `step(j, xⱼ)` giving hⱼ; a zero step leaves the column zero. `None` when `f` is
/// undefined at a probed point.
///
/// # Example
/// ```
/// let f = |x: &[f64]| Some(vec![x[0] * x[1], x[0] + 2.0 * x[1]]);
/// let j = orthocheck_core::algebra::central_jacobian(&f, &[1.0, 3.0], |_, _| 1e-3).unwrap();
/// approx::assert_relative_eq!(j[(0, 0)], 3.0, epsilon = 1e-9);
/// approx::assert_relative_eq!(j[(1, 1)], 2.0, epsilon = 1e-9);
/// ```
pub fn central_jacobian(
    f: &dyn Fn(&[f64]) -> Option<Vec<f64>>,
    x: &[f64],
    step: impl Fn(usize, f64) -> f64,
) -> Option<DMatrix<f64>> {
    let mut jac: Option<DMatrix<f64>> = None;
    for j in 0..x.len() {
        let h = step(j, x[j]);
        if h == 0.0 {
            continue;
        }
        let (mut up, mut down) = (x.to_vec(), x.to_vec());
        up[j] += h;
        down[j] -= h;
        let (fu, fd) = (f(&up)?, f(&down)?);
        let m = jac.get_or_insert_with(|| DMatrix::zeros(fu.len(), x.len()));
        for i in 0..fu.len().min(m.nrows()) {
            m[(i, j)] = (fu[i] - fd[i]) / (2.0 * h);
        }
    }
    match jac {
        Some(m) => Some(m),
        None => Some(DMatrix::zeros(f(x)?.len(), x.len())),
    }
}
