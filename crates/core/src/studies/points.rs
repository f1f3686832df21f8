//! Seeded random rational points: the second, independent check of an exact identity
//! (Schwartz–Zippel), with the probability that a false identity passes.

use std::collections::BTreeMap;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::Zero;
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

/// Whether `left = ratio · right` at `values`; `None` where a side is undefined (its
/// denominator vanishes). Exact, by cross-multiplying the sides' unreduced fractions: the same
/// answer as comparing [`RatFn::eval`]s, without the gcds that dominate it.
fn agree_at(
    left: &RatFn,
    right: &RatFn,
    ratio: &BigRational,
    values: &BTreeMap<String, BigRational>,
) -> Option<bool> {
    // p/q with p = n₁/d₁ and q = n₂/d₂: (n₁ d₂) / (d₁ n₂), undefined when n₂ = 0
    let side = |f: &RatFn| -> Option<(BigInt, BigInt)> {
        let (n1, d1) = f.num.eval_unreduced(values)?;
        let (n2, d2) = f.den.eval_unreduced(values)?;
        (!n2.is_zero()).then(|| (n1 * d2, d1 * n2))
    };
    let (ln, ld) = side(left)?;
    let (rn, rd) = side(right)?;
    // ln/ld = (a/b)(rn/rd) ⇔ ln · rd · b = a · rn · ld (ld, rd, b non-zero)
    Some(ln * &rd * ratio.denom() == ratio.numer() * rn * ld)
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
        if agree_at(left, right, ratio, &values) == Some(true) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::rat;

    /// The cross-multiplied comparison answers as comparing the reduced values does: equal,
    /// different, and undefined where a denominator vanishes (signs of every kind).
    #[test]
    fn cross_multiplying_answers_as_the_reduced_values_do() {
        let l = RatFn::parse("(a^2 - b^2) / (3 a - 6 b)").unwrap();
        // l = −r/6 wherever both are defined; (6, 7) makes both denominators vanish
        let r = RatFn::parse("(a^2 - b^2) / (b - a/2)").unwrap();
        let mut seen = Vec::new();
        for (a, b) in [(5, 7), (-4, 3), (2, 1), (1, -9), (0, 2), (6, 7)] {
            let values: BTreeMap<String, BigRational> =
                [("a".to_string(), rat(a, 3)), ("b".to_string(), rat(b, 7))].into();
            for ratio in [rat(-1, 6), rat(1, 6), rat(2, 1)] {
                let reduced = match (l.eval(&values), r.eval(&values)) {
                    (Some(x), Some(y)) => Some(x == y * &ratio),
                    _ => None,
                };
                assert_eq!(
                    agree_at(&l, &r, &ratio, &values),
                    reduced,
                    "{a}, {b}, {ratio}"
                );
                seen.push(reduced);
            }
        }
        for outcome in [Some(true), Some(false), None] {
            assert!(seen.contains(&outcome), "{outcome:?} is tried");
        }
    }
}
