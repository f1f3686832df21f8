//! Tests of `orthocheck_core::algebra::float_roots`.

use num_complex::Complex64;
use orthocheck_core::algebra::float_roots::*;

#[test]
fn quadratic_cases() {
    assert_eq!(quadratic(0.0, 0.0, 1.0), vec![]);
    assert_eq!(quadratic(0.0, 2.0, -4.0), vec![Complex64::new(2.0, 0.0)]);
    let r = quadratic(1.0, 0.0, 1.0);
    assert_eq!(r, vec![Complex64::new(0.0, -1.0), Complex64::new(0.0, 1.0)]);
    let r = quadratic(1.0, -3.0, 2.0);
    assert_eq!(r, vec![Complex64::new(1.0, 0.0), Complex64::new(2.0, 0.0)]);
    assert!(quadratic(1.0, 0.0, 0.0).iter().all(|z| z.norm() == 0.0));
}

#[test]
fn companion_matches_known_roots() {
    // (x-1)(x-2)(x+3) = x^3 - 7x + 6
    let (r, m) = companion_roots(&[6.0, -7.0, 0.0, 1.0]);
    assert_eq!(m, EigenMethod::Schur);
    let re: Vec<f64> = r.iter().map(|z| z.re).collect();
    for (x, w) in re.iter().zip([-3.0, 1.0, 2.0]) {
        assert!((x - w).abs() < 1e-12);
    }
    let agree = compare_methods(&[6.0, -7.0, 0.0, 1.0], 1e-9);
    assert!(agree.same_count && agree.max_disagreement < 1e-12);
}

#[test]
fn durand_kerner_fallback_finds_roots() {
    let z = durand_kerner(&[6.0, -7.0, 0.0, 1.0]);
    for w in [-3.0, 1.0, 2.0] {
        assert!(z
            .iter()
            .any(|r| (r.re - w).abs() < 1e-10 && r.im.abs() < 1e-10));
    }
}
