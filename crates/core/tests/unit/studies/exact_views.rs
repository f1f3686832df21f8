//! Tests of `orthocheck_core::studies::exact_views`.

use orthocheck_core::studies::exact_views::*;

#[test]
fn a_view_of_the_body_satisfies_the_rigidity_condition() {
    // P = 0, Q = (1, 1, √2), R = (0, 2, √12 − …): a body with a² = 4, c² = 16
    let (q, r) = ([1.0, 1.0], [0.5, 3.0]);
    let zq = 2.0_f64.sqrt();
    let zr = (16.0_f64 - 0.25 - 9.0).sqrt();
    let b2 = (zr - zq).powi(2) + 0.25 + 4.0;
    let d = rigidity([4.0, b2, 16.0], q, r, 1.0).unwrap_or(f64::NAN);
    assert!(d.abs() < 1e-12);
    let ys = solve_ry([4.0, b2, 16.0], q, 0.5, 2.9, 3.1);
    assert!(ys.iter().any(|y| (y - 3.0).abs() < 1e-12));
    assert!(solve_ry([4.0, b2 + 1.0, 16.0], q, 0.5, 2.99, 3.01).is_empty());
}
