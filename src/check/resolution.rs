//! How finely an acceptance interval resolves a printed value: the rule that turns a
//! check's acceptance interval into `reproduced`, `reproduced-within-rounding` or
//! `inconclusive` (docs/verdicts.md, "Resolution").

use serde::Serialize;

use super::Real;

/// How finely an acceptance interval resolves a printed value: the significant digits of the
/// printed value that every accepted value shares up to half a unit (`digits` of `printed`),
/// and the interval's half-width, absolute and relative to the printed value.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Resolution {
    /// Significant digits resolved: the interval lies within half a unit of the printed
    /// value's `digits`-th significant digit.
    pub digits: u32,
    /// Significant digits printed (from the printed value and its half unit).
    pub printed: u32,
    /// The interval's half-width (its larger side).
    pub half_width: Real,
    /// The half-width relative to the printed value.
    pub relative: Real,
}

/// The component of an alternative (the other root in place of a solution, say) that lies
/// outside its accepted region: the first such, or `None` when every component is accepted,
/// so that the check cannot tell the alternative from the printed value.
pub fn excluded_by(regions: &[(f64, f64)], alternative: &[f64]) -> Option<usize> {
    regions
        .iter()
        .zip(alternative)
        .position(|(&(lo, hi), &v)| !(lo <= v && v <= hi))
}

/// A positive verdict stands only when the check excludes the nearest alternative; one that
/// accepts it could not tell the claim from its alternative.
pub fn alternative_verdict(v: super::Verdict, excluded: bool) -> super::Verdict {
    if v.is_positive() && !excluded {
        super::Verdict::Inconclusive
    } else {
        v
    }
}

impl Resolution {
    /// The resolution of `[lo, hi]` around `printed`, whose half unit is `half_unit`; `None`
    /// when an end is not finite or the printed value is 0 (it has no significant digit).
    pub fn of(lo: f64, hi: f64, printed: f64, half_unit: f64) -> Option<Resolution> {
        if !(lo.is_finite() && hi.is_finite() && printed.is_finite()) || printed == 0.0 {
            return None;
        }
        let w = (printed - lo).max(hi - printed).max(0.0);
        // the rounding of the two subtractions and of the powers of ten below: a few units in
        // the last place of the largest number involved
        let slack = 4.0 * f64::EPSILON * lo.abs().max(hi.abs()).max(printed.abs());
        // the exponent of the leading digit, from exact comparisons with powers of ten
        let mut lead = printed.abs().log10().floor() as i32;
        if 10f64.powi(lead) > printed.abs() {
            lead -= 1;
        } else if 10f64.powi(lead + 1) <= printed.abs() {
            lead += 1;
        }
        // half a unit of the k-th significant digit
        let half = |k: u32| 0.5 * 10f64.powi(lead + 1 - k as i32);
        let shown = (1..=17)
            .find(|&k| half(k) <= half_unit + slack)
            .unwrap_or(17);
        let digits = (1..=shown)
            .rev()
            .find(|&k| w <= half(k) + slack)
            .unwrap_or(0);
        Some(Resolution {
            digits,
            printed: shown,
            half_width: Real(w),
            relative: Real(w / printed.abs()),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::Power;

    #[test]
    fn an_alternative_is_excluded_by_its_first_component_outside() {
        let regions = [(1.0, 2.0), (3.0, 4.0), (5.0, 7.0)];
        assert_eq!(excluded_by(&regions, &[2.5, 3.5, 6.0]), Some(0));
        assert_eq!(excluded_by(&regions, &[1.5, 4.5, 6.0]), Some(1));
        // inside every region, ends included: not excluded
        assert_eq!(excluded_by(&regions, &[1.5, 3.5, 6.0]), None);
        assert_eq!(excluded_by(&regions, &[2.0, 3.0, 7.0]), None);
    }

    #[test]
    fn resolution_counts_the_printed_digits_an_interval_keeps() {
        // 12.34 printed (half unit 0.005): 4 digits; ±0.005 keeps all, ±0.05 three, ±0.5 two
        let r = |w: f64| Resolution::of(12.34 - w, 12.34 + w, 12.34, 0.005).unwrap();
        assert_eq!((r(0.005).digits, r(0.005).printed), (4, 4));
        assert_eq!(r(0.0051).digits, 3);
        assert_eq!(r(0.05).digits, 3);
        assert_eq!(r(0.051).digits, 2);
        assert_eq!(r(5.0).digits, 1);
        assert_eq!(r(5.1).digits, 0);
        // a leading digit at a power of ten and below one
        let one = Resolution::of(0.995, 1.005, 1.0, 0.005).unwrap();
        assert_eq!((one.digits, one.printed), (3, 3));
        let small = Resolution::of(0.0121, 0.0125, 0.0123, 0.00005).unwrap();
        assert_eq!((small.digits, small.printed), (2, 3));
        assert!(Resolution::of(f64::NEG_INFINITY, 1.0, 0.5, 0.05).is_none());
    }

    #[test]
    fn an_interval_is_weak_only_when_it_resolves_no_digit() {
        let tight = Power::interval(12.335, 12.345, 12.34, 0.005, "");
        assert!(!tight.weak && !tight.coarser_than_printed());
        let coarse = Power::interval(12.3, 12.38, 12.34, 0.005, "");
        assert!(!coarse.weak && coarse.coarser_than_printed());
        let none = Power::interval(-10.0, 93.0, 41.0, 0.5, "");
        assert!(none.weak);
        let zero = Power::interval(-0.004, 0.004, 0.0, 0.005, "");
        assert!(!zero.weak && zero.resolution.is_none());
        assert!(Power::interval(-0.006, 0.004, 0.0, 0.005, "").weak);
    }
}
