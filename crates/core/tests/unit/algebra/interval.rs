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

#[test]
fn division_and_roots_refuse_what_they_cannot_enclose() {
    assert!(Interval::around(0.0, 1.0).recip().is_none());
    let r = Interval::around(2.0, 0.5)
        .recip()
        .unwrap_or(Interval::point(f64::NAN));
    assert!(r.contains(0.4) && r.contains(1.0 / 1.5) && !r.contains(0.39));
    assert!(Interval::around(-2.0, 0.5).sqrt().is_none());
    let s = Interval::around(0.0, 4.0)
        .sqrt()
        .unwrap_or(Interval::point(f64::NAN));
    assert!(s.lo == 0.0 && s.contains(2.0));
    // outward: the exact 1/3 and √2 lie strictly inside their enclosures
    let t = Interval::point(3.0)
        .recip()
        .unwrap_or(Interval::point(f64::NAN));
    // 1/3 and √2 are not doubles: each end must lie beyond the nearest double
    let third = 1.0_f64 / 3.0;
    assert!(t.lo < third && third < t.hi);
    let q = Interval::point(2.0)
        .sqrt()
        .unwrap_or(Interval::point(f64::NAN));
    assert!(q.lo < std::f64::consts::SQRT_2 && std::f64::consts::SQRT_2 < q.hi);
    let a = Interval::around(1.0, 1.0);
    assert_eq!(a.intersect(Interval::around(3.0, 0.5)), None);
    assert!(Interval::around(1.0, 0.5).within(&a) && !a.within(&Interval::around(1.0, 0.5)));
}

#[test]
fn the_centred_range_beats_the_naive_one_where_terms_cancel() {
    use orthocheck_core::algebra::{centre, Grad, Scalar};
    // f = x − x² + (1 − x)²  = 1 − x  over x ∈ [0.4, 0.6]
    let cell = [Interval::around(0.5, 0.1)];
    let (mid, off) = centre(&cell);
    let [x] = Grad::variables(&mid, &off);
    let one = Grad::constant(1.0);
    let f = x - x * x + (one - x) * (one - x);
    let naive = cell[0] - cell[0] * cell[0] + (Interval::point(1.0) - cell[0]).square();
    let r = f.value;
    assert!(r.contains(0.4) && r.contains(0.6) && r.contains(0.5));
    assert!(r.width() < 0.6 * naive.width(), "{r:?} against {naive:?}");
    // a reciprocal through 0 has no enclosure
    assert!((x - Grad::constant(0.5)).recip().is_none());
}
