//! Tests of `orthocheck_core::studies::family_samples`.

use nalgebra::Vector2;
use orthocheck_core::error::Error;
use orthocheck_core::studies::family_samples::*;

#[test]
fn betas_are_evenly_spread_inside_zero_pi() {
    let b = betas(3);
    assert_eq!(b.len(), 3);
    let step = std::f64::consts::PI / 4.0;
    for (i, x) in b.iter().enumerate() {
        assert!((x - step * (i + 1) as f64).abs() <= f64::EPSILON * 4.0);
    }
    assert!(betas(0).is_empty());
}

#[test]
fn too_few_points_is_invalid_input() {
    let f = vec![Vector2::new(0.0, 0.0); 3];
    assert!(matches!(
        sample_family(&f, &f, 2),
        Err(Error::InvalidInput(_))
    ));
}
