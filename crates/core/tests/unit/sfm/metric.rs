//! Tests of `orthocheck_core::sfm::metric`.

use nalgebra::{Cholesky, Matrix3, Vector3};
use orthocheck_core::sfm::metric::*;

#[test]
fn an_indefinite_l_is_clipped_to_positive_definite() {
    let l = Matrix3::from_diagonal(&Vector3::new(2.0, 1.0, -0.5));
    let q = clipped_factor(&l).unwrap();
    let back = q * q.transpose();
    assert!(Cholesky::new(back).is_some());
    // the positive part is kept exactly (up to rounding of the square roots)
    assert!((back[(0, 0)] - 2.0).abs() <= 8.0 * f64::EPSILON * 2.0);
    assert!(clipped_factor(&(-l.abs())).is_err());
}
