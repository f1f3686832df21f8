//! Distribution-free confidence bounds for a median and for a ratio of two medians, from
//! order statistics: the k-th smallest of n independent draws lies below the median with
//! probability P(Bin(n, ½) ≥ k), whatever the distribution (failed trials count as errors
//! larger than every finite one, so they take part as the largest values).

/// The terms P(Bin(n, ½) = j) for j = 0, 1, …, each from the one before by the factor
/// (n − j + 1)/j, in logarithms: free of the binomial coefficient's overflow for n up to
/// millions, and one step per term (the median's ranks need about n/2 of them).
fn half_pmf(n: usize) -> impl Iterator<Item = f64> {
    let ln_half_n = n as f64 * 0.5f64.ln();
    (0..=n).scan(0.0, move |ln_choose, j| {
        if j > 0 {
            *ln_choose += ((n - j + 1) as f64 / j as f64).ln();
        }
        Some((*ln_choose + ln_half_n).exp())
    })
}

/// P(Bin(n, ½) ≤ k).
pub fn binomial_half_cdf(n: usize, k: usize) -> f64 {
    if k >= n {
        return 1.0;
    }
    half_pmf(n).take(k + 1).sum::<f64>().min(1.0)
}

/// The 0-based ranks (l, u) of the order statistics that bound the median of n draws from
/// below and from above, each with confidence at least 1 − `alpha`: X₍ₗ₎ ≤ median with
/// probability P(Bin(n, ½) ≥ l + 1) ≥ 1 − α, and symmetrically X₍ᵤ₎ ≥ median, u = n − 1 − l.
/// `None` when n is too small for that confidence (even the extremes do not reach it).
pub fn median_ranks(n: usize, alpha: f64) -> Option<(usize, usize)> {
    if n == 0 {
        return None;
    }
    // the largest l with P(Bin ≤ l) ≤ α: then P(at least l + 1 draws ≤ median) ≥ 1 − α
    let mut cdf = 0.0;
    let l = half_pmf(n)
        .take(n / 2 + 1)
        .enumerate()
        .take_while(|&(k, p)| {
            cdf += p;
            (if k >= n { 1.0 } else { cdf.min(1.0) }) <= alpha
        })
        .last()
        .map(|(k, _)| k);
    l.map(|l| (l, n - 1 - l))
}

/// A bound that may lie among the failed trials (beyond every finite error).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
#[serde(tag = "kind", content = "value", rename_all = "kebab-case")]
pub enum Bound {
    /// A finite value.
    Finite(f64),
    /// Larger than any finite value: the order statistic is a failed trial.
    Infinite,
}

impl Bound {
    /// From a float where failures were sorted as +∞.
    pub fn of(x: f64) -> Bound {
        if x.is_finite() {
            Bound::Finite(x)
        } else {
            Bound::Infinite
        }
    }

    /// The value, `None` when infinite.
    pub fn finite(self) -> Option<f64> {
        match self {
            Bound::Finite(x) => Some(x),
            Bound::Infinite => None,
        }
    }

    /// `a / b` of two error statistics (non-negative), read on the side of a lower bound:
    /// ∞/∞ and 0/0 say nothing and give 0, the side that never claims more than it knows.
    pub fn ratio_low(a: Bound, b: Bound) -> Bound {
        match (a, b) {
            (Bound::Infinite, Bound::Finite(_)) => Bound::Infinite,
            (_, Bound::Infinite) => Bound::Finite(0.0),
            (Bound::Finite(x), Bound::Finite(y)) if y > 0.0 => Bound::Finite(x / y),
            (Bound::Finite(x), Bound::Finite(_)) if x > 0.0 => Bound::Infinite,
            (Bound::Finite(_), Bound::Finite(_)) => Bound::Finite(0.0),
        }
    }

    /// `a / b` read on the side of an upper bound: ∞/∞ and 0/0 give ∞.
    pub fn ratio_high(a: Bound, b: Bound) -> Bound {
        match (a, b) {
            (Bound::Infinite, _) => Bound::Infinite,
            (Bound::Finite(_), Bound::Infinite) => Bound::Finite(0.0),
            (Bound::Finite(x), Bound::Finite(y)) if y > 0.0 => Bound::Finite(x / y),
            (Bound::Finite(_), Bound::Finite(_)) => Bound::Infinite,
        }
    }

    /// Whether this bound exceeds `x`.
    pub fn exceeds(self, x: f64) -> bool {
        match self {
            Bound::Infinite => true,
            Bound::Finite(v) => v > x,
        }
    }
}

/// The ratio of two medians with a confidence interval from the order statistics of both
/// samples, each one-sided bound at confidence 1 − α (Bonferroni over the two samples: each
/// sample's bound is taken at α/2).
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct RatioBounds {
    /// The ratio of the sample medians.
    pub point: Bound,
    /// Lower bound: numerator's lower median bound over the denominator's upper one.
    pub lower: Bound,
    /// Upper bound: numerator's upper median bound over the denominator's lower one.
    pub upper: Bound,
    /// The smallest ratio of sample medians this sample size could have declared above 1:
    /// the lower bound's shortfall from the point, (X₍ₘ₎/X₍ₗ₎)ⁿᵘᵐ · (X₍ᵤ₎/X₍ₘ₎)ᵈᵉⁿ, when
    /// finite.
    pub detectable: Option<f64>,
}

/// The sorted errors' order statistics at 0-based rank `k` (failures sorted last as +∞).
fn at(sorted: &[f64], k: usize) -> Bound {
    Bound::of(sorted.get(k).copied().unwrap_or(f64::INFINITY))
}

/// Median index of n values (the convention of [`crate::derivations::rounding::quantile`]).
fn mid(n: usize) -> usize {
    ((0.5 * (n.max(1) - 1) as f64).round()) as usize
}

/// The ratio of medians `num / den` of two sorted samples (failures as +∞) with bounds of
/// joint one-sided confidence 1 − `alpha` each; `None` when a sample is too small.
pub fn ratio_of_medians(num: &[f64], den: &[f64], alpha: f64) -> Option<RatioBounds> {
    let (nl, nu) = median_ranks(num.len(), alpha / 2.0)?;
    let (dl, du) = median_ranks(den.len(), alpha / 2.0)?;
    let (nm, dm) = (at(num, mid(num.len())), at(den, mid(den.len())));
    let point = Bound::ratio_high(nm, dm);
    let lower = Bound::ratio_low(at(num, nl), at(den, du));
    let upper = Bound::ratio_high(at(num, nu), at(den, dl));
    let detectable = match (
        Bound::ratio_low(nm, at(num, nl)),
        Bound::ratio_low(at(den, du), dm),
    ) {
        (Bound::Finite(a), Bound::Finite(b)) => Some(a * b),
        _ => None,
    };
    Some(RatioBounds {
        point,
        lower,
        upper,
        detectable,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binomial_cdf_is_exact_on_small_n() {
        // P(Bin(4, ½) ≤ 1) = (1 + 4)/16
        assert!((binomial_half_cdf(4, 1) - 5.0 / 16.0).abs() < 1e-15);
        assert_eq!(binomial_half_cdf(4, 4), 1.0);
        // large n does not overflow
        assert!((binomial_half_cdf(10_000, 4_999) - 0.496).abs() < 0.01);
    }

    #[test]
    fn median_ranks_match_the_tables() {
        // n = 100, two-sided 95 %: X₍₄₀₎ and X₍₆₁₎ (1-based), coverage 0.965
        assert_eq!(median_ranks(100, 0.025), Some((39, 60)));
        // n = 5: P(Bin ≤ 0) = 1/32 > 0.025, no bound at that confidence; at 0.05 the extremes
        assert_eq!(median_ranks(5, 0.025), None);
        assert_eq!(median_ranks(5, 0.05), Some((0, 4)));
        // one step per term: a million draws are ranked at once; the normal approximation
        // puts l near n/2 − 1.96·√n/2 = 499,020
        let (l, u) = median_ranks(1_000_000, 0.025).unwrap();
        assert!((499_015..=499_025).contains(&l) && u == 999_999 - l);
    }

    #[test]
    fn ratio_bounds_bracket_the_point_and_see_failures() {
        let a: Vec<f64> = (1..=200).map(|i| 3.0 * i as f64).collect();
        let b: Vec<f64> = (1..=200).map(|i| i as f64).collect();
        let r = ratio_of_medians(&a, &b, 0.05).unwrap();
        let (lo, p, hi) = (
            r.lower.finite().unwrap(),
            r.point.finite().unwrap(),
            r.upper.finite().unwrap(),
        );
        assert!(lo < p && p < hi && lo > 1.0 && (p - 3.0).abs() < 0.1);
        // the same sample against itself: the bounds straddle 1
        let s = ratio_of_medians(&b, &b, 0.05).unwrap();
        assert!(!s.lower.exceeds(1.0) && s.upper.exceeds(1.0));
        // a numerator failing in more than half the trials: the ratio is unbounded above
        let mut f = b.clone();
        for v in f.iter_mut().skip(50) {
            *v = f64::INFINITY;
        }
        let r = ratio_of_medians(&f, &b, 0.05).unwrap();
        assert_eq!(r.point, Bound::Infinite);
        assert_eq!(r.lower, Bound::Infinite);
    }
}
