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
        let (a, b) = (self.lo * self.lo, self.hi * self.hi);
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
        let (a, b) = (self.lo * c, self.hi * c);
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

    /// The distance from `x` to the interval (0 inside).
    pub fn distance(&self, x: f64) -> f64 {
        (self.lo - x).max(x - self.hi).max(0.0)
    }
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

impl Mul for Interval {
    type Output = Interval;
    fn mul(self, o: Interval) -> Interval {
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Interval::outward(lo, hi)
    }
}
