//! Random-point screens modulo a 61-bit prime (Schwartz–Zippel over 𝔽ₚ).
//!
//! A non-zero polynomial of total degree d vanishes at a uniformly random point of 𝔽ₚⁿ with
//! probability at most d/p. Comparing two rational functions through the cross-multiplied
//! polynomial `l.num · r.den − k · r.num · l.den` needs no division, so a point where a
//! denominator vanishes is as good as any other. With p = 2⁶¹ − 1 every evaluation is a few
//! word multiplications: a fast screen beside the exact comparison, never instead of it.

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::ToPrimitive;
use rand::Rng;

use super::mpoly::{Coef, Scalar};
use super::{Poly, RatFn};

/// The Mersenne prime 2⁶¹ − 1.
pub const PRIME: u64 = (1 << 61) - 1;

/// An element of 𝔽ₚ, p = [`PRIME`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Fp(pub u64);

impl Fp {
    /// The residue of an integer.
    pub fn from_big(v: &BigInt) -> Fp {
        let r = v.mod_floor(&BigInt::from(PRIME));
        Fp(r.to_u64().unwrap_or(0))
    }

    /// `self^e`.
    pub fn pow(self, mut e: u64) -> Fp {
        let (mut r, mut b) = (Fp(1), self);
        while e > 0 {
            if e & 1 == 1 {
                r = r.mul(&b);
            }
            b = b.mul(&b);
            e >>= 1;
        }
        r
    }

    /// The inverse (Fermat), `None` for zero.
    pub fn inv(self) -> Option<Fp> {
        (self.0 != 0).then(|| self.pow(PRIME - 2))
    }

    /// The residue of a rational, `None` when p divides its denominator.
    pub fn from_rational(q: &BigRational) -> Option<Fp> {
        Some(Fp::from_big(q.numer()).mul(&Fp::from_big(q.denom()).inv()?))
    }

    /// `self − o`.
    pub fn sub(&self, o: &Fp) -> Fp {
        Fp::add(self, &Fp(PRIME - o.0))
    }
}

impl Scalar for Fp {
    fn zero() -> Self {
        Fp(0)
    }
    fn one() -> Self {
        Fp(1)
    }
    fn from_coef(c: &Coef) -> Self {
        match c {
            Coef::Small(s) => Fp(s.rem_euclid(PRIME as i64) as u64),
            Coef::Big(b) => Fp::from_big(b),
        }
    }
    #[inline]
    fn add(&self, o: &Self) -> Self {
        let s = self.0 + o.0; // < 2⁶², no overflow
        Fp(if s >= PRIME { s - PRIME } else { s })
    }
    #[inline]
    fn mul(&self, o: &Self) -> Self {
        // 2⁶¹ ≡ 1: fold the high bits of the 122-bit product onto the low ones
        let t = u128::from(self.0) * u128::from(o.0);
        let s = (t as u64 & PRIME) + (t >> 61) as u64;
        Fp(if s >= PRIME { s - PRIME } else { s })
    }
}

/// The value of `p` at `at` (one residue per variable of `p`'s ring), `None` when p divides
/// the denominator of its content.
pub fn eval_poly(p: &Poly, at: &[Fp]) -> Option<Fp> {
    let (content, prim) = p.primitive();
    if p.is_zero() {
        return Some(Fp(0));
    }
    Some(Fp::from_rational(content)?.mul(&prim.eval(at)))
}

/// Outcome of [`agree_mod_p`].
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct ModPAgreement {
    /// Points tried.
    pub points: usize,
    /// Seed of the points.
    pub seed: u64,
    /// Points where `l.num · r.den = k · r.num · l.den` held in 𝔽ₚ.
    pub agreeing: usize,
    /// The prime.
    pub prime: u64,
    /// Total degree bound d of the cross-multiplied difference.
    pub degree: u32,
    /// d/p: the chance that one point agrees although the two differ (all points agreeing:
    /// this to the power `points`).
    pub failure_bound: f64,
}

/// Schwartz–Zippel screen of `left = ratio · right` at `points` seeded uniform points of
/// 𝔽ₚⁿ, p = 2⁶¹ − 1.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::{modp::agree_mod_p, rat, RatFn};
/// let l = RatFn::parse("(a + b)^2 / (a - b)").unwrap();
/// let r = RatFn::parse("(a^2 + 2a b + b^2) / (a - b)").unwrap();
/// let s = agree_mod_p(&l, &r, &rat(1, 1), 8, 1);
/// assert_eq!(s.agreeing, 8);
/// assert!(s.failure_bound < 1e-17);
/// assert_eq!(agree_mod_p(&l, &r, &rat(2, 1), 8, 1).agreeing, 0);
/// ```
pub fn agree_mod_p(
    left: &RatFn,
    right: &RatFn,
    ratio: &BigRational,
    points: usize,
    seed: u64,
) -> ModPAgreement {
    let k = Fp::from_rational(ratio);
    let values = cross_values(left, right, points, seed);
    let agreeing = values
        .iter()
        .filter(|v| matches!((v, k), (Some((l, r)), Some(k)) if *l == k.mul(r)))
        .count();
    agreement(left, right, points, seed, agreeing)
}

/// The same screen for `left = k · right` with an unknown non-zero constant k (an equation
/// `= 0` printed with another sign or scale): k is read off the first point where the right
/// side does not vanish, every point (that one included) must then agree with it.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::{modp::proportional_mod_p, RatFn};
/// let l = RatFn::parse("-3 (a + b)^2").unwrap();
/// let r = RatFn::parse("a^2 + 2a b + b^2").unwrap();
/// assert_eq!(proportional_mod_p(&l, &r, 8, 1).agreeing, 8);
/// let m = RatFn::parse("a^2 + 3a b + b^2").unwrap();
/// assert_eq!(proportional_mod_p(&l, &m, 8, 1).agreeing, 1);
/// ```
pub fn proportional_mod_p(left: &RatFn, right: &RatFn, points: usize, seed: u64) -> ModPAgreement {
    let values = cross_values(left, right, points, seed);
    let k = values
        .iter()
        .flatten()
        .find(|(_, r)| r.0 != 0)
        .and_then(|(l, r)| Some(l.mul(&r.inv()?)))
        .filter(|k| k.0 != 0);
    let agreeing = values
        .iter()
        .filter(|v| matches!((v, k), (Some((l, r)), Some(k)) if *l == k.mul(r)))
        .count();
    agreement(left, right, points, seed, agreeing)
}

/// At each seeded point: (`left.num · right.den`, `right.num · left.den`) in 𝔽ₚ, `None`
/// where p divides the denominator of a content.
fn cross_values(left: &RatFn, right: &RatFn, points: usize, seed: u64) -> Vec<Option<(Fp, Fp)>> {
    // the same portable stream as every seeded study (ChaCha8)
    let mut g = <rand_chacha::ChaCha8Rng as rand::SeedableRng>::seed_from_u64(seed);
    let mut vars = left.variables();
    vars.extend(right.variables());
    vars.sort();
    vars.dedup();
    (0..points)
        .map(|_| {
            let values: Vec<(String, Fp)> = vars
                .iter()
                .map(|v| (v.clone(), Fp(g.random_range(0..PRIME))))
                .collect();
            let at = |p: &Poly| -> Option<Fp> {
                let point: Vec<Fp> = p
                    .ring()
                    .names()
                    .iter()
                    .map(|n| values.iter().find(|(v, _)| **v == **n).map(|(_, x)| *x))
                    .collect::<Option<_>>()?;
                eval_poly(p, &point)
            };
            let l = at(&left.num)?.mul(&at(&right.den)?);
            let r = at(&right.num)?.mul(&at(&left.den)?);
            Some((l, r))
        })
        .collect()
}

fn agreement(
    left: &RatFn,
    right: &RatFn,
    points: usize,
    seed: u64,
    agreeing: usize,
) -> ModPAgreement {
    let degree =
        (left.num.degree() + right.den.degree()).max(right.num.degree() + left.den.degree());
    ModPAgreement {
        points,
        seed,
        agreeing,
        prime: PRIME,
        degree,
        failure_bound: f64::from(degree) / PRIME as f64,
    }
}
