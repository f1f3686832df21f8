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

/// `product` is the IEEE product bit for bit, on the subnormal and tiny operands its
/// integer path takes and on the boundary to the hardware's.
#[test]
fn the_exact_product_is_the_hardware_product() {
    use rand::{Rng, SeedableRng};
    let mut g = rand_chacha::ChaCha8Rng::seed_from_u64(7);
    let draw = |g: &mut rand_chacha::ChaCha8Rng| {
        let exponent: u64 = match g.random_range(0..4) {
            0 => 0,
            1 => g.random_range(1..40),
            2 => g.random_range(900..1100),
            _ => g.random_range(0..2047),
        };
        let fraction = match g.random_range(0..4) {
            0 => g.random_range(0..4),
            1 => (1 << 52) - 1 - g.random_range(0..4),
            _ => g.random_range(0..1u64 << 52),
        };
        let sign = u64::from(g.random_bool(0.5)) << 63;
        f64::from_bits(sign | exponent << 52 | fraction)
    };
    for _ in 0..400_000 {
        let (a, b) = (draw(&mut g), draw(&mut g));
        let (p, q) = (product(a, b), a * b);
        assert!(
            p.to_bits() == q.to_bits() || (p.is_nan() && q.is_nan()),
            "{a:e} · {b:e}: {p:e} vs {q:e}"
        );
    }
    // ties on the subnormal grid: (2k + 1)/2 units round to the even neighbour
    let tiny = f64::from_bits(1);
    for k in 0..64_u64 {
        let a = f64::from_bits(2 * k + 1);
        assert_eq!(product(a, 0.5).to_bits(), (a * 0.5).to_bits());
        assert_eq!(
            product(tiny, k as f64 + 0.5).to_bits(),
            (tiny * (k as f64 + 0.5)).to_bits()
        );
    }
}

/// The product of intervals, which picks its end products by sign, is bit for bit the
/// outward hull of all four hardware products, zeros and subnormal ends included.
#[test]
fn interval_products_are_the_hull_of_the_four() {
    use rand::{Rng, SeedableRng};
    let mut g = rand_chacha::ChaCha8Rng::seed_from_u64(11);
    let end = |g: &mut rand_chacha::ChaCha8Rng| -> f64 {
        let v = match g.random_range(0..5) {
            0 => 0.0,
            1 => f64::from_bits(g.random_range(1..64)),
            2 => g.random_range(-3.0..3.0),
            3 => g.random_range(-1e-3..1e-3),
            _ => g.random_range(-1e200..1e200),
        };
        if g.random_bool(0.5) {
            -v
        } else {
            v
        }
    };
    for _ in 0..200_000 {
        let (a, b, c, d) = (end(&mut g), end(&mut g), end(&mut g), end(&mut g));
        let (x, y) = (
            Interval {
                lo: a.min(b),
                hi: a.max(b),
            },
            Interval {
                lo: c.min(d),
                hi: c.max(d),
            },
        );
        let p = [x.lo * y.lo, x.lo * y.hi, x.hi * y.lo, x.hi * y.hi];
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min).next_down();
        let hi = p
            .iter()
            .copied()
            .fold(f64::NEG_INFINITY, f64::max)
            .next_up();
        let z = x * y;
        assert_eq!(
            (z.lo.to_bits(), z.hi.to_bits()),
            (lo.to_bits(), hi.to_bits()),
            "{x:?} · {y:?}"
        );
    }
}
