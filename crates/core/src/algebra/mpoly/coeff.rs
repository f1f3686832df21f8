//! Integer coefficients: an i64 in the common case, a big integer when it does not fit.
//!
//! Like FLINT's `fmpz`, a coefficient is a machine word until it overflows; products are
//! accumulated in i128 and promoted to [`BigInt`] only when the i128 sum itself would
//! overflow. Every constructor normalises, so a value that fits an i64 is always `Small`.

use std::fmt;

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{Signed, ToPrimitive, Zero};

/// An integer, stored in a machine word when it fits.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Coef {
    /// Fits an i64.
    Small(i64),
    /// Does not fit an i64.
    Big(BigInt),
}

impl Coef {
    /// From an i128, small when it fits.
    #[inline]
    pub fn from_i128(v: i128) -> Coef {
        match i64::try_from(v) {
            Ok(s) => Coef::Small(s),
            Err(_) => Coef::Big(BigInt::from(v)),
        }
    }

    /// From a big integer, small when it fits.
    pub fn from_big(v: BigInt) -> Coef {
        match v.to_i64() {
            Some(s) => Coef::Small(s),
            None => Coef::Big(v),
        }
    }

    /// As a big integer.
    pub fn to_big(&self) -> BigInt {
        match self {
            Coef::Small(s) => BigInt::from(*s),
            Coef::Big(b) => b.clone(),
        }
    }

    /// Whether zero.
    #[inline]
    pub fn is_zero(&self) -> bool {
        matches!(self, Coef::Small(0))
    }

    /// Whether negative.
    pub fn is_negative(&self) -> bool {
        match self {
            Coef::Small(s) => *s < 0,
            Coef::Big(b) => b.is_negative(),
        }
    }

    /// The i64 value, when small.
    #[inline]
    pub fn small(&self) -> Option<i64> {
        match self {
            Coef::Small(s) => Some(*s),
            Coef::Big(_) => None,
        }
    }

    /// `-self`.
    pub fn neg(&self) -> Coef {
        match self {
            Coef::Small(s) => Coef::from_i128(-i128::from(*s)),
            Coef::Big(b) => Coef::from_big(-b),
        }
    }

    /// `self + other`.
    pub fn add(&self, other: &Coef) -> Coef {
        match (self, other) {
            (Coef::Small(a), Coef::Small(b)) => Coef::from_i128(i128::from(*a) + i128::from(*b)),
            _ => Coef::from_big(self.to_big() + other.to_big()),
        }
    }

    /// `self · other`.
    pub fn mul(&self, other: &Coef) -> Coef {
        match (self, other) {
            (Coef::Small(a), Coef::Small(b)) => Coef::from_i128(i128::from(*a) * i128::from(*b)),
            _ => Coef::from_big(self.to_big() * other.to_big()),
        }
    }

    /// `self / d` when `d` divides `self` exactly (`d ≠ 0`), else `None`.
    pub fn div_exact(&self, d: &Coef) -> Option<Coef> {
        match (self, d) {
            (_, Coef::Small(0)) => None,
            (Coef::Small(a), Coef::Small(b)) => {
                let (a, b) = (i128::from(*a), i128::from(*b));
                (a % b == 0).then(|| Coef::from_i128(a / b))
            }
            _ => {
                let (q, r) = self.to_big().div_rem(&d.to_big());
                r.is_zero().then(|| Coef::from_big(q))
            }
        }
    }

    /// The non-negative gcd.
    pub fn gcd(&self, other: &Coef) -> Coef {
        match (self, other) {
            (Coef::Small(a), Coef::Small(b)) => {
                Coef::from_i128(i128::from(a.unsigned_abs().gcd(&b.unsigned_abs())))
            }
            _ => Coef::from_big(crate::algebra::integer::gcd(
                &self.to_big(),
                &other.to_big(),
            )),
        }
    }

    /// Whether this is ±1.
    pub fn is_unit(&self) -> bool {
        matches!(self, Coef::Small(1) | Coef::Small(-1))
    }

    /// Bit length of the absolute value.
    pub fn bits(&self) -> u64 {
        match self {
            Coef::Small(s) => u64::from(64 - s.unsigned_abs().leading_zeros()),
            Coef::Big(b) => b.bits(),
        }
    }
}

impl From<i64> for Coef {
    fn from(v: i64) -> Coef {
        Coef::Small(v)
    }
}

impl From<&BigInt> for Coef {
    fn from(v: &BigInt) -> Coef {
        Coef::from_big(v.clone())
    }
}

impl fmt::Display for Coef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Coef::Small(s) => write!(f, "{s}"),
            Coef::Big(b) => write!(f, "{b}"),
        }
    }
}

/// A running sum of coefficient products: i128 until it overflows, then a big integer.
#[derive(Clone, Debug, Default)]
pub struct Acc {
    small: i128,
    big: Option<BigInt>,
}

impl Acc {
    /// Add `a · b`.
    #[inline]
    pub fn add_mul(&mut self, a: &Coef, b: &Coef) {
        if let (Coef::Small(x), Coef::Small(y)) = (a, b) {
            let p = i128::from(*x) * i128::from(*y);
            match self.small.checked_add(p) {
                Some(s) => self.small = s,
                None => self.spill(BigInt::from(p)),
            }
        } else {
            self.spill(a.to_big() * b.to_big());
        }
    }

    /// Add a product of two small coefficients.
    #[inline]
    pub fn add_i128(&mut self, p: i128) {
        match self.small.checked_add(p) {
            Some(s) => self.small = s,
            None => self.spill(BigInt::from(p)),
        }
    }

    /// Add `a`.
    #[inline]
    pub fn add(&mut self, a: &Coef) {
        match a {
            Coef::Small(x) => match self.small.checked_add(i128::from(*x)) {
                Some(s) => self.small = s,
                None => self.spill(BigInt::from(*x)),
            },
            Coef::Big(b) => self.spill(b.clone()),
        }
    }

    /// Subtract `a · b`.
    #[inline]
    pub fn sub_mul(&mut self, a: &Coef, b: &Coef) {
        self.add_mul(&a.neg(), b);
    }

    fn spill(&mut self, v: BigInt) {
        let big = self.big.get_or_insert_with(BigInt::zero);
        *big += v;
    }

    /// The sum, reset to zero.
    #[inline]
    pub fn take(&mut self) -> Coef {
        let s = std::mem::take(&mut self.small);
        match self.big.take() {
            None => Coef::from_i128(s),
            Some(b) => Coef::from_big(b + BigInt::from(s)),
        }
    }
}

/// The gcd of all `coefs` (non-negative; zero for an empty slice), stopping early at one.
pub fn content(coefs: &[Coef]) -> Coef {
    let mut g = Coef::Small(0);
    for c in coefs {
        g = g.gcd(c);
        if g.is_unit() {
            break;
        }
    }
    g
}
