//! Tests of `orthocheck_core::studies::joint_fit`.

mod jacobian;

use orthocheck_core::studies::joint_fit::*;

#[test]
fn the_tetrahedron_has_its_edges() {
    let s = [4.0, 9.0, 12.0, 20.0, 21.0, 18.0];
    let b = tetrahedron(&s).unwrap_or_else(|| unreachable!());
    let e = orthocheck_core::model::edges(4);
    for (k, (i, j)) in e.iter().enumerate() {
        approx::assert_relative_eq!((b[*i] - b[*j]).norm_squared(), s[k], max_relative = 1e-12);
    }
    assert!(tetrahedron(&[1.0, 1.0, 9.0, 1.0, 1.0, 1.0]).is_none());
}

#[test]
fn the_lp_stages_approach_the_minimax_point() {
    // r = x − aᵢ for a = 0, 1, 5: least squares stops at the mean 2 (largest |r| 3), the
    // minimax point is 2.5 (largest |r| 2.5). The L⁶⁴ optimum's largest |r| is at most
    // 3^(1/64) times the minimax one (‖r‖∞ ≤ ‖r‖₆₄ ≤ 3^(1/64) ‖r‖∞ for three residuals).
    let f = |x: &[f64]| Some(vec![x[0], x[0] - 1.0, x[0] - 5.0]);
    let x = lp_minimax(&f, &[0.0]).expect("defined at the start");
    let largest = f(&x).unwrap().iter().fold(0.0f64, |m, r| m.max(r.abs()));
    assert!(
        largest >= 2.5 && largest <= 2.5 * 3f64.powf(1.0 / 64.0),
        "{x:?}: {largest}"
    );
    // undefined at the start: none
    let nowhere = |_: &[f64]| None;
    assert!(lp_minimax(&nowhere, &[0.0]).is_none());
}
