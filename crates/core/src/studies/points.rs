//! Seeded random points: the second, independent check of an exact identity
//! (Schwartz–Zippel), evaluated modulo word-sized primes ([`crate::algebra::modp`]), with the
//! probability that a false identity passes.

use num_rational::BigRational;

use crate::algebra::modp::agree_mod_p;
use crate::algebra::RatFn;

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
