//! Seeded random points: the second, independent check of an exact identity
//! (Schwartz–Zippel), evaluated modulo word-sized primes ([`crate::algebra::modp`]), with the
//! probability that a false identity passes; and the mutant formula the same check must
//! reject.

use num_rational::BigRational;

use crate::algebra::modp::agree_mod_p;
use crate::algebra::{Monomial, Poly, RatFn};

/// The outcome of evaluating `left = ratio · right` at seeded random points.
pub type PointCheck = crate::algebra::modp::ModPAgreement;

/// Evaluate `left` and `ratio · right` at `points` seeded random points, modulo as many
/// 61-bit primes as the height of their difference asks.
///
/// # Example
/// ```
/// use orthocheck_core::{algebra::{rat, RatFn}, studies::points::agree_at_points};
/// let l = RatFn::parse("(a + b)^2").unwrap();
/// let r = RatFn::parse("a^2 + 2a b + b^2").unwrap();
/// let c = agree_at_points(&l, &r, &rat(1, 1), 16, 3);
/// assert!(c.all_agree() && c.degree == 2);
/// ```
pub fn agree_at_points(
    left: &RatFn,
    right: &RatFn,
    ratio: &BigRational,
    points: usize,
    seed: u64,
) -> PointCheck {
    agree_mod_p(left, right, ratio, points, seed)
}

/// The formula with the sign of the first term of its numerator flipped (a single-term
/// numerator gets `+1` instead, so that a proportional check cannot absorb the change).
pub fn flip_one_term(e: &RatFn) -> Option<(Monomial, RatFn)> {
    let (m, c) = e.num.first_term()?;
    let term = &Poly::from_monomial(m.clone()).scale(&c);
    let num = if e.num.len() == 1 {
        &e.num + &Poly::int(1)
    } else {
        &e.num - &term.scale(&BigRational::from_integer(2.into()))
    };
    Some((
        m.clone(),
        RatFn {
            num,
            den: e.den.clone(),
        },
    ))
}
