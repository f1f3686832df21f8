//! Seeded random rational points: the second, independent check of an exact identity
//! (Schwartz–Zippel), with the probability that a false identity passes.

use std::collections::BTreeMap;

use num_rational::BigRational;
use rand::Rng;

use crate::algebra::RatFn;
use crate::model::rng;

/// Numerators are drawn from `−NUMERATORS ..= NUMERATORS`.
pub const NUMERATORS: i64 = 1_000_000;
/// Denominators are drawn from `1 ..= DENOMINATORS`.
pub const DENOMINATORS: i64 = 1000;

/// The outcome of evaluating `left = ratio · right` at seeded random rational points.
#[derive(Clone, Debug, PartialEq)]
pub struct PointCheck {
    /// Points drawn.
    pub points: usize,
    /// Seed.
    pub seed: u64,
    /// Points where both sides are defined and agree.
    pub agreeing: usize,
    /// Total degree bound of the difference `n₁d₂ − ratio·n₂d₁`.
    pub degree: u32,
}

impl PointCheck {
    /// Whether every point agreed.
    pub fn all_agree(&self) -> bool {
        self.agreeing == self.points
    }

    /// Size of the set each coordinate is drawn from once its denominator is fixed: the
    /// numerators, `2·NUMERATORS + 1` distinct values.
    pub fn sample_size() -> u64 {
        2 * NUMERATORS as u64 + 1
    }

    /// Schwartz–Zippel: a non-zero difference of total degree `D` vanishes at one point with
    /// probability at most `D / |S|` (per coordinate, conditionally on the drawn denominators,
    /// the value is uniform over |S| distinct rationals).
    pub fn per_point_bound(&self) -> f64 {
        (self.degree as f64 / Self::sample_size() as f64).min(1.0)
    }

    /// The probability that a false identity agrees at every point: the per-point bound to the
    /// power of the number of points (independent points). Where it underflows, the smallest
    /// normal float, still an upper bound.
    pub fn failure_bound(&self) -> f64 {
        let exp = i32::try_from(self.points).unwrap_or(i32::MAX);
        self.per_point_bound().powi(exp).max(f64::MIN_POSITIVE)
    }

    /// log₁₀ of the failure bound, without underflow.
    pub fn log10_failure_bound(&self) -> f64 {
        let p = self.per_point_bound();
        if p == 0.0 {
            // degree 0: a non-zero constant never vanishes
            return f64::MIN_POSITIVE.log10();
        }
        self.points as f64 * p.log10()
    }
}

/// Evaluate `left` and `ratio · right` at `points` seeded random rational points.
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
    let mut g = rng(seed);
    let mut vars = left.variables();
    vars.extend(right.variables());
    vars.sort();
    vars.dedup();
    let mut agreeing = 0;
    for _ in 0..points {
        let values: BTreeMap<String, BigRational> = vars
            .iter()
            .map(|v| {
                let d: i64 = g.random_range(1..=DENOMINATORS);
                let n: i64 = g.random_range(-NUMERATORS..=NUMERATORS);
                (v.clone(), BigRational::new(n.into(), d.into()))
            })
            .collect();
        if let (Some(l), Some(r)) = (left.eval(&values), right.eval(&values))
            && l == r * ratio
        {
            agreeing += 1;
        }
    }
    let degree =
        (left.num.degree() + right.den.degree()).max(right.num.degree() + left.den.degree());
    PointCheck {
        points,
        seed,
        agreeing,
        degree,
    }
}
