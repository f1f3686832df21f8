//! Tests of `orthocheck_core::algebra::interval`.

use orthocheck_core::algebra::interval::*;

#[test]
fn enclosures_hold_at_sampled_points() {
    let x = Interval::around(0.3, 0.1);
    let y = Interval::around(-1.2, 0.05);
    let f = |x: f64, y: f64| (x - y) * (x - y) - 2.0 * x * y + x * x;
    let enc = (x - y).square() - (x * y).scale(2.0) + x.square();
    for i in 0..=10 {
        for j in 0..=10 {
            let (a, b) = (0.2 + 0.02 * i as f64, -1.25 + 0.01 * j as f64);
            assert!(enc.contains(f(a, b)));
        }
    }
    assert!(Interval::around(0.0, 1.0).square().lo >= 0.0);
}
