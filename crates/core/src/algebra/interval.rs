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
