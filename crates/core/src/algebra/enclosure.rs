//! A computation written once for three kinds of number: `f64`, an [`Interval`] (the naive
//! enclosure over a box) and a [`Grad`], an interval with the enclosure of its gradient, which
//! gives the mean-value form f(X) ⊆ f(m) + ∇f(X)·(X − m). The mean-value form's excess over
//! the true range shrinks with the square of the box's width, the naive form's only with the
//! width, which is what lets a branch-and-bound close in on a narrow range.

use std::ops::{Add, Mul, Neg, Sub};

use super::Interval;

/// The arithmetic a computation enclosed by intervals may use.
pub trait Scalar:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Neg<Output = Self>
{
    /// A constant.
    fn constant(x: f64) -> Self;
    /// 1 / x, `None` where it is not defined (0, or an interval containing 0).
    fn recip(self) -> Option<Self>;
    /// √x, `None` where it is not defined: x < 0; for an interval, all of it below 0 (√ of
    /// its part at or above 0 otherwise); for a gradient, a range reaching 0.
    fn sqrt(self) -> Option<Self>;
}

impl Scalar for f64 {
    #[inline]
    fn constant(x: f64) -> Self {
        x
    }
    #[inline]
    fn recip(self) -> Option<Self> {
        (self != 0.0).then(|| 1.0 / self)
    }
    #[inline]
    fn sqrt(self) -> Option<Self> {
        (self >= 0.0).then(|| f64::sqrt(self))
    }
}

impl Scalar for Interval {
    fn constant(x: f64) -> Self {
        Interval::point(x)
    }
    fn recip(self) -> Option<Self> {
        Interval::recip(self)
    }
    fn sqrt(self) -> Option<Self> {
        Interval::sqrt(self)
    }
}

/// A function of `N` variables over a cell, as three enclosures: of its value over the cell,
/// of its value at the cell's midpoint m, and of its gradient over the cell. Every operation
/// works on the operands' centred ranges, f(X) ∩ (f(m) + ∇f(X)·(X − m)), so an
/// intermediate quantity that varies little over the cell (a determinant to be inverted, a
/// square root's argument) is not lost to the dependency of its own terms.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grad<'a, const N: usize> {
    /// The enclosure of the value over the cell: the naive one met with the mean-value
    /// form, formed as each value is made.
    pub value: Interval,
    /// The enclosure of the value at the midpoint.
    pub mid: Interval,
    /// The enclosure of ∂f/∂xᵢ over the cell.
    pub grad: [Interval; N],
    /// X − m per variable (`None` for a constant).
    offsets: Option<&'a [Interval; N]>,
}

/// A cell's midpoint and each coordinate's offsets from it, X − m: what [`Grad::variables`]
/// centres on.
pub fn centre<const N: usize>(cell: &[Interval; N]) -> ([f64; N], [Interval; N]) {
    let mid = cell.map(|i| i.mid());
    let off = std::array::from_fn(|i| cell[i] - Interval::point(mid[i]));
    (mid, off)
}

impl<'a, const N: usize> Grad<'a, N> {
    /// The variable xᵢ over a cell whose offsets from its midpoint `mid` are `offsets`.
    pub fn variable(mid: &[f64; N], offsets: &'a [Interval; N], i: usize) -> Self {
        let mut grad = [Interval::point(0.0); N];
        grad[i] = Interval::point(1.0);
        Grad {
            value: Interval::point(mid[i]) + offsets[i],
            mid: Interval::point(mid[i]),
            grad,
            offsets: Some(offsets),
        }
    }

    /// Every variable x₁ … x_N of the cell that [`centre`] gave `mid` and `offsets`.
    pub fn variables(mid: &[f64; N], offsets: &'a [Interval; N]) -> [Self; N] {
        std::array::from_fn(|i| Grad::variable(mid, offsets, i))
    }

    /// A value from its naive range, midpoint value and gradient, its range centred.
    fn make(
        naive: Interval,
        mid: Interval,
        grad: [Interval; N],
        offsets: Option<&'a [Interval; N]>,
    ) -> Self {
        let value = offsets.map_or(naive, |off| {
            let mut e = mid;
            for (g, o) in grad.iter().zip(off) {
                e = e + *g * *o;
            }
            // both enclose the range: disjoint only through a NaN, which the naive one keeps
            e.intersect(naive).unwrap_or(naive)
        });
        Grad {
            value,
            mid,
            grad,
            offsets,
        }
    }

    fn with(self, o: &Self, value: Interval, mid: Interval, grad: [Interval; N]) -> Self {
        Grad::make(value, mid, grad, self.offsets.or(o.offsets))
    }
}

impl<const N: usize> Add for Grad<'_, N> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        let g = std::array::from_fn(|i| self.grad[i] + o.grad[i]);
        self.with(&o, self.value + o.value, self.mid + o.mid, g)
    }
}

impl<const N: usize> Sub for Grad<'_, N> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        let g = std::array::from_fn(|i| self.grad[i] - o.grad[i]);
        self.with(&o, self.value - o.value, self.mid - o.mid, g)
    }
}

impl<const N: usize> Neg for Grad<'_, N> {
    type Output = Self;
    fn neg(self) -> Self {
        Grad {
            value: -self.value,
            mid: -self.mid,
            grad: self.grad.map(|g| -g),
            offsets: self.offsets,
        }
    }
}

impl<const N: usize> Mul for Grad<'_, N> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        let (a, b) = (self.value, o.value);
        let g = std::array::from_fn(|i| self.grad[i] * b + a * o.grad[i]);
        self.with(&o, a * b, self.mid * o.mid, g)
    }
}

impl<const N: usize> Scalar for Grad<'_, N> {
    fn constant(x: f64) -> Self {
        Grad {
            value: Interval::point(x),
            mid: Interval::point(x),
            grad: [Interval::point(0.0); N],
            offsets: None,
        }
    }
    fn recip(self) -> Option<Self> {
        let r = self.value.recip()?;
        let d = -r.square();
        let grad = self.grad.map(|g| g * d);
        Some(Grad::make(r, self.mid.recip()?, grad, self.offsets))
    }
    fn sqrt(self) -> Option<Self> {
        let s = self.value.sqrt()?;
        // d√v = dv / (2√v): unbounded where v reaches 0
        let d = s.scale(2.0).recip()?;
        let grad = self.grad.map(|g| g * d);
        Some(Grad::make(s, self.mid.sqrt()?, grad, self.offsets))
    }
}
