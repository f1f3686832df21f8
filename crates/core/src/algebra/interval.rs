//! Interval arithmetic with outward rounding: enclosures of a computation over a box of
//! inputs (the rounding box of printed data).

use std::ops::{Add, Mul, Neg, Sub};

/// A closed interval [lo, hi] that encloses every value a computation can take.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::Interval;
/// let x = Interval::around(1.38, 0.005);
/// let y = Interval::around(2.58, 0.005);
/// let d = (y - x).square();
/// // (1.2 ± 0.01)² spans about 4·1.2·0.01
/// assert!(d.contains(1.2f64.powi(2)) && d.width() < 0.049);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    /// Lower end.
    pub lo: f64,
    /// Upper end.
    pub hi: f64,
}

impl Interval {
    /// The point interval [x, x].
    pub fn point(x: f64) -> Self {
        Interval { lo: x, hi: x }
    }

    /// [c − h, c + h], rounded outward.
    pub fn around(c: f64, h: f64) -> Self {
        Interval {
            lo: (c - h).next_down(),
            hi: (c + h).next_up(),
        }
    }

    fn outward(lo: f64, hi: f64) -> Self {
        Interval {
            lo: lo.next_down(),
            hi: hi.next_up(),
        }
    }

    /// x², tighter than x·x when the interval contains 0.
    pub fn square(self) -> Self {
        let (a, b) = (product(self.lo, self.lo), product(self.hi, self.hi));
        if self.lo <= 0.0 && self.hi >= 0.0 {
            Interval::outward(0.0, a.max(b)).max_zero()
        } else {
            Interval::outward(a.min(b), a.max(b))
        }
    }

    fn max_zero(self) -> Self {
        Interval {
            lo: self.lo.max(0.0),
            hi: self.hi,
        }
    }

    /// Multiplication by a constant.
    pub fn scale(self, c: f64) -> Self {
        let (a, b) = (product(self.lo, c), product(self.hi, c));
        Interval::outward(a.min(b), a.max(b))
    }

    /// Whether `x` lies in the interval.
    pub fn contains(&self, x: f64) -> bool {
        self.lo <= x && x <= self.hi
    }

    /// hi − lo.
    pub fn width(&self) -> f64 {
        self.hi - self.lo
    }

    /// The midpoint.
    pub fn mid(&self) -> f64 {
        0.5 * (self.lo + self.hi)
    }

    /// The hull of two intervals.
    pub fn hull(self, o: Interval) -> Interval {
        Interval {
            lo: self.lo.min(o.lo),
            hi: self.hi.max(o.hi),
        }
    }

    /// The intersection of two intervals, `None` when they are disjoint.
    pub fn intersect(self, o: Interval) -> Option<Interval> {
        let (lo, hi) = (self.lo.max(o.lo), self.hi.min(o.hi));
        (lo <= hi).then_some(Interval { lo, hi })
    }

    /// Whether every point of `self` lies in `o`.
    pub fn within(&self, o: &Interval) -> bool {
        o.lo <= self.lo && self.hi <= o.hi
    }

    /// 1 / x, `None` when the interval contains 0.
    pub fn recip(self) -> Option<Interval> {
        (self.lo > 0.0 || self.hi < 0.0).then(|| Interval::outward(1.0 / self.hi, 1.0 / self.lo))
    }

    /// √x over the part of the interval at or above 0 (the square root is correctly
    /// rounded, so one step outward encloses it); `None` when the interval is all negative.
    pub fn sqrt(self) -> Option<Interval> {
        (self.hi >= 0.0).then(|| Interval {
            lo: self.lo.max(0.0).sqrt().next_down().max(0.0),
            hi: self.hi.sqrt().next_up(),
        })
    }

    /// The distance from `x` to the interval (0 inside).
    pub fn distance(&self, x: f64) -> f64 {
        (self.lo - x).max(x - self.hi).max(0.0)
    }
}

/// a · b, bit for bit the IEEE product, at the speed of normal numbers: a product with a
/// subnormal operand or result costs the processor a microcode assist (some 50 ns, fifty
/// times a multiplication), and enclosures meet such numbers all the time: a sum of zero
/// derivatives rounded outward is [−2⁻¹⁰⁷⁴, 2⁻¹⁰⁷⁴]. Those products are formed exactly in
/// integers and rounded to nearest, ties to even, as the hardware does.
#[inline]
pub fn product(a: f64, b: f64) -> f64 {
    let (ea, eb) = (exponent_bits(a), exponent_bits(b));
    // both normal with a product ≥ 2⁻¹⁰²² before rounding, or a zero, infinite or NaN
    // operand: no assist
    let normal = ea != 0 && eb != 0 && ea + eb >= 1024;
    if normal || a == 0.0 || b == 0.0 || ea == 0x7ff || eb == 0x7ff {
        return a * b;
    }
    tiny_product(a, b, ea, eb)
}

/// [`product`] of finite nonzero operands with a subnormal one or a product below 2⁻¹⁰²²
/// (exponent fields `ea`, `eb`).
#[inline]
fn tiny_product(a: f64, b: f64, ea: u64, eb: u64) -> f64 {
    // |x| < 2^(max(e, 1) − 1022) for the exponent field e: a product below 2⁻¹⁰⁷⁵, half the
    // least subnormal, rounds to a zero of the product's sign
    let sign = (a.to_bits() ^ b.to_bits()) & (1 << 63);
    if ea.max(1) + eb.max(1) <= 969 {
        return f64::from_bits(sign);
    }
    // a subnormal times a normal: on the subnormal grid the product is m·|b| units of
    // 2⁻¹⁰⁷⁴ (m the subnormal's integer significand), rounded to an integer
    let (m, other) = match (ea, eb) {
        (0, 1..) => (a.to_bits() & ((1 << 52) - 1), b),
        (1.., 0) => (b.to_bits() & ((1 << 52) - 1), a),
        _ => return small_product(a, b),
    };
    // t = m·|other| rounded once; a half-integer is a double here, so t and the exact
    // product lie on the same side of every one, and round to the same integer unless t is
    // one itself
    let t = m as f64 * other.abs();
    if t < 4_503_599_627_370_496.0 {
        let n = t as u64;
        let fraction = t - n as f64;
        if fraction != 0.5 {
            return f64::from_bits(sign | (n + u64::from(fraction > 0.5)));
        }
    }
    small_product(a, b)
}

fn exponent_bits(x: f64) -> u64 {
    (x.to_bits() >> 52) & 0x7ff
}

/// The integer significand m and exponent e of a finite nonzero x = ±m·2ᵉ.
fn split(x: f64) -> (u128, i32) {
    let bits = x.to_bits();
    let fraction = (bits & ((1 << 52) - 1)) as u128;
    match exponent_bits(x) {
        0 => (fraction, -1074),
        e => (fraction | (1 << 52), e as i32 - 1075),
    }
}

/// The product of finite nonzero a and b whose magnitude is below 4 (one of them subnormal,
/// or both small): the exact product m·2ᵉ rounded to 53 bits, or to the subnormal grid
/// 2⁻¹⁰⁷⁴, to nearest with ties to even.
#[cold]
#[inline(never)]
fn small_product(a: f64, b: f64) -> f64 {
    let sign = (a.to_bits() ^ b.to_bits()) & (1 << 63);
    let ((ma, xa), (mb, xb)) = (split(a), split(b));
    let (m, e) = (ma * mb, xa + xb);
    let length = 128 - m.leading_zeros() as i32;
    // the bits to drop: down to 53 significant ones, and none below 2⁻¹⁰⁷⁴
    let drop = (length - 53).max(-1074 - e);
    if drop > 110 {
        // m < 2¹⁰⁶ is below half the last place: rounds to zero
        return f64::from_bits(sign);
    }
    let mut q = if drop <= 0 {
        (m << -drop) as u64
    } else {
        let q = (m >> drop) as u64;
        let rest = m & ((1 << drop) - 1);
        let half = 1 << (drop - 1);
        q + u64::from(rest > half || (rest == half && q & 1 == 1))
    };
    let mut drop = drop;
    if q == 1 << 53 {
        q >>= 1;
        drop += 1;
    }
    // q·2^(e + drop) with e + drop ≥ −1074: the biased exponent and the implicit bit add up
    f64::from_bits(sign | ((((e + drop + 1074) as u64) << 52) + q))
}

impl Add for Interval {
    type Output = Interval;
    fn add(self, o: Interval) -> Interval {
        Interval::outward(self.lo + o.lo, self.hi + o.hi)
    }
}

impl Sub for Interval {
    type Output = Interval;
    fn sub(self, o: Interval) -> Interval {
        Interval::outward(self.lo - o.hi, self.hi - o.lo)
    }
}

impl Neg for Interval {
    type Output = Interval;
    fn neg(self) -> Interval {
        Interval {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

/// The least and the greatest of the four end products of finite, ordered `a` and `b`, as
/// values: chosen by the signs of the ends (rounding is monotone, so the exact order of the
/// products is kept), two products where the signs decide, four only where both intervals
/// hold 0. A zero end may differ in sign from the four products' minimum or maximum, which
/// the outward step does not see.
fn end_products(a: Interval, b: Interval) -> (f64, f64) {
    let p = product;
    if a.lo >= 0.0 {
        if b.lo >= 0.0 {
            (p(a.lo, b.lo), p(a.hi, b.hi))
        } else if b.hi <= 0.0 {
            (p(a.hi, b.lo), p(a.lo, b.hi))
        } else {
            (p(a.hi, b.lo), p(a.hi, b.hi))
        }
    } else if a.hi <= 0.0 {
        if b.lo >= 0.0 {
            (p(a.lo, b.hi), p(a.hi, b.lo))
        } else if b.hi <= 0.0 {
            (p(a.hi, b.hi), p(a.lo, b.lo))
        } else {
            (p(a.lo, b.hi), p(a.lo, b.lo))
        }
    } else if b.lo >= 0.0 {
        (p(a.lo, b.hi), p(a.hi, b.hi))
    } else if b.hi <= 0.0 {
        (p(a.hi, b.lo), p(a.lo, b.lo))
    } else {
        (
            p(a.lo, b.hi).min(p(a.hi, b.lo)),
            p(a.lo, b.lo).max(p(a.hi, b.hi)),
        )
    }
}

impl Mul for Interval {
    type Output = Interval;
    fn mul(self, o: Interval) -> Interval {
        let ordered = |i: &Interval| i.lo.is_finite() && i.hi.is_finite() && i.lo <= i.hi;
        if ordered(&self) && ordered(&o) {
            let (lo, hi) = end_products(self, o);
            return Interval::outward(lo, hi);
        }
        let p = [
            product(self.lo, o.lo),
            product(self.lo, o.hi),
            product(self.hi, o.lo),
            product(self.hi, o.hi),
        ];
        // 0·∞ (an overflowed end) bounds nothing: min and max would drop the NaN
        if p.iter().any(|v| v.is_nan()) {
            return Interval {
                lo: f64::NEG_INFINITY,
                hi: f64::INFINITY,
            };
        }
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Interval::outward(lo, hi)
    }
}
