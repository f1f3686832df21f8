//! Tests of `orthocheck_core::algebra::cholesky`: the blocked factor agrees with the
//! unblocked one across block boundaries, reads only the lower triangle, and refuses a matrix
//! that is not positive definite.

use nalgebra::{DMatrix, DVector};
use orthocheck_core::algebra::cholesky::{cholesky_lower, cholesky_solve};
use rand::{Rng, SeedableRng};

/// A random symmetric positive definite matrix B Bᵀ + n I, its strict upper triangle
/// overwritten by garbage that must not be read.
fn spd(n: usize, seed: u64) -> (DMatrix<f64>, DMatrix<f64>) {
    let mut g = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    let b = DMatrix::from_fn(n, n, |_, _| g.random_range(-1.0..1.0));
    let a = &b * b.transpose() + DMatrix::identity(n, n) * n as f64;
    let mut lower = a.clone();
    for j in 1..n {
        for i in 0..j {
            lower[(i, j)] = 1e300;
        }
    }
    (a, lower)
}

/// γₘ = mε / (1 − mε), the rounding of m operations (Higham, Accuracy and Stability, §3.1).
fn gamma(m: usize) -> f64 {
    let me = m as f64 * f64::EPSILON / 2.0;
    me / (1.0 - me)
}

#[test]
fn the_blocked_factor_is_backward_stable() {
    // sizes below, at and across the 64-column blocks
    for (n, seed) in [(1, 1), (5, 2), (64, 3), (65, 4), (200, 5)] {
        let (a, lower) = spd(n, seed);
        let l = cholesky_lower(lower).expect("positive definite");
        assert!((0..n).all(|j| (0..j).all(|i| l[(i, j)] == 0.0)));
        // Higham's bound: |L Lᵀ − A| ≤ γₙ₊₁ |L| |Lᵀ| entry by entry (the blocks' triangular
        // inverses would add their condition, about 1 for these diagonally dominant blocks)
        let abs = l.abs();
        let bound = (&abs * abs.transpose()) * gamma(n + 1);
        let err = (&l * l.transpose() - &a).abs();
        let worst = err.zip_map(&bound, |e, b| e / b).max();
        assert!(worst <= 1.0, "n = {n}: {worst} times the bound");
        // the solve: (A + ΔA) x̂ = b with |ΔA| ≤ γ₃ₙ₊₁ |L| |Lᵀ|, so the relative error is at
        // most κ δ / (1 − κ δ), δ = ‖ΔA‖ / ‖A‖
        let eig = a.clone().symmetric_eigen().eigenvalues;
        let kappa = eig.max() / eig.min();
        let delta = gamma(3 * n + 1) * (&abs * abs.transpose()).norm() / a.norm();
        let x = DVector::from_fn(n, |i, _| i as f64 - 0.5 * n as f64 + 0.25);
        let solved = cholesky_solve(&l, &(&a * &x)).expect("a solution");
        let rel = (solved - &x).norm() / x.norm();
        assert!(
            rel <= kappa * delta / (1.0 - kappa * delta),
            "n = {n}: {rel}"
        );
    }
}

#[test]
fn a_matrix_that_is_not_positive_definite_is_refused() {
    let (mut a, _) = spd(130, 6);
    // a negative pivot in the third block
    a[(129, 129)] = -1.0;
    assert!(cholesky_lower(a).is_none());
    assert!(cholesky_lower(DMatrix::from_element(3, 3, f64::NAN)).is_none());
    assert!(cholesky_lower(DMatrix::zeros(2, 3)).is_none());
}
