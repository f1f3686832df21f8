//! Tests of `orthocheck_core::sfm::threshold`.

use orthocheck_core::sfm::threshold::*;

#[test]
fn the_constants_are_their_formulas() {
    let close = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b;
    assert!(close(RAYLEIGH_MEDIAN, (2.0 * 2f64.ln()).sqrt()));
    assert!(close(
        RAYLEIGH_INLIER,
        (-2.0 * (1.0 - INLIER_QUANTILE).ln()).sqrt()
    ));
    // the Rayleigh distribution function at the two points
    let cdf = |r: f64| 1.0 - (-r * r / 2.0).exp();
    assert!((cdf(RAYLEIGH_MEDIAN) - 0.5).abs() < 1e-15);
    assert!((cdf(RAYLEIGH_INLIER) - INLIER_QUANTILE).abs() < 1e-15);
}

#[test]
fn the_threshold_follows_the_median_and_never_falls_to_zero() {
    let mut r = vec![3.0, f64::INFINITY, 1.0, 2.0, 100.0];
    // the lower median of [1, 2, 3, 100, ∞] is 3
    let t = Threshold::from_residuals(&mut r, 1.0, 0.0).unwrap();
    assert_eq!(t.value, RAYLEIGH_INLIER * (3.0 / RAYLEIGH_MEDIAN / 1.0));
    assert!(!t.floored());
    let mut zeros = vec![0.0; 7];
    let f = floor(4.0, 1.0);
    let z = Threshold::from_residuals(&mut zeros, 1.0, f).unwrap();
    assert!(z.value > 0.0 && z.value == f && z.floored());
    let mut unexplained = vec![1.0, f64::INFINITY, f64::INFINITY];
    assert!(Threshold::from_residuals(&mut unexplained, 1.0, f).is_none());
    assert!(median(&mut []).is_none());
}

#[test]
fn a_fit_s_residuals_are_corrected_for_its_parameters() {
    assert_eq!(shrink(100, 75), 0.5);
    assert_eq!(shrink(10, 12), 1.0);
    assert_eq!(parameters(40, 8), 154);
    assert_eq!(rounding(None, 40, 8), 1.0);
}
