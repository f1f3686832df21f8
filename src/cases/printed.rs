//! A number as the paper printed it: its exact value and its precision.

use std::fmt;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use serde::de::{self, Deserializer, Visitor};
use serde::Deserialize;

use crate::algebra::parse_decimal;

/// The largest decimal exponent a printed number may carry (f64 reaches about 1e±308).
const MAX_EXPONENT: u32 = 330;

/// A number as the paper printed it: exact value plus precision.
///
/// # Example
/// ```
/// use orthocheck::cases::Printed;
/// let x = Printed::parse("1.2345").unwrap();
/// assert_eq!(x.decimals, 4);
/// assert_eq!(x.half_unit(), 0.00005);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Printed {
    /// The digits as printed.
    pub text: String,
    /// The exact value of those digits.
    pub value: BigRational,
    /// Digits after the decimal point, less the printed exponent (`"2.5e-3"` has 4).
    pub decimals: i32,
}

impl Printed {
    /// Parse printed digits (`"12.345"`, `"-0.5"`, `"18"`, `".25"`, `"1.5e-14"`).
    pub fn parse(text: &str) -> Option<Printed> {
        let t = text.trim();
        let (mantissa, exponent) = match t.split_once(['e', 'E']) {
            Some((m, e)) => (m, e.parse::<i32>().ok()?),
            None => (t, 0),
        };
        // beyond f64's range no printed digit could be compared (and the loop below is bounded)
        if exponent.unsigned_abs() > MAX_EXPONENT {
            return None;
        }
        let mantissa_value = parse_decimal(mantissa)?;
        let scale = || {
            BigRational::from_integer(num_traits::pow(
                BigInt::from(10),
                exponent.unsigned_abs() as usize,
            ))
        };
        let value = match exponent.signum() {
            0 => mantissa_value,
            1 => mantissa_value * scale(),
            _ => mantissa_value / scale(),
        };
        let decimals = mantissa.split_once('.').map_or(0, |(_, f)| f.len() as i32) - exponent;
        // an exact value f64 cannot hold (overflow, or a non-zero number underflowing to 0)
        let f = value.to_f64().unwrap_or(f64::NAN);
        if !f.is_finite() || (f == 0.0 && !value.is_zero()) {
            return None;
        }
        Some(Printed {
            text: t.to_string(),
            value,
            decimals,
        })
    }

    /// Half a unit in the last printed digit: the rounding bound of the printed value.
    pub fn half_unit(&self) -> f64 {
        0.5 * 10f64.powi(-self.decimals)
    }

    /// Half a unit in the `digits`-th significant digit: the precision of a number printed
    /// with a fixed count of significant digits and trailing zeros dropped (C's `%g`, C++
    /// stream defaults), where "4" printed with six digits means 4.00000.
    pub fn half_unit_significant(&self, digits: u32) -> f64 {
        let v = self.to_f64().abs();
        if v == 0.0 {
            return self.half_unit();
        }
        let magnitude = v.log10().floor() as i32;
        0.5 * 10f64.powi(magnitude - digits as i32 + 1)
    }

    /// The value as `f64`.
    pub fn to_f64(&self) -> f64 {
        self.value.to_f64().unwrap_or(f64::NAN)
    }

    /// The value as an integer, when it is one.
    pub fn to_integer(&self) -> Option<BigInt> {
        self.value.is_integer().then(|| self.value.to_integer())
    }
}

impl Printed {
    /// Printed numbers as printed, comma-separated.
    pub fn join(v: &[Printed]) -> String {
        v.iter()
            .map(|p| p.text.as_str())
            .collect::<Vec<_>>()
            .join(", ")
    }
}

/// The first edge whose printed length and printed square cannot both be right: no length
/// within half a unit of the printed one squares to a value within half a unit of the printed
/// square (exact arithmetic; both printed values are read at their own precision). With it,
/// the words that say so.
pub fn contradicting_square(lengths: &[Printed], squares: &[Printed]) -> Option<(usize, String)> {
    let i = lengths.iter().zip(squares).position(|(l, s)| {
        let half = |p: &Printed| BigRational::new(1.into(), 2.into()) * pow10(-p.decimals);
        let (hl, hs) = (half(l), half(s));
        let low = (l.value.abs() - &hl).max(BigRational::zero());
        let high = l.value.abs() + hl;
        &low * &low > &s.value + &hs || &high * &high < &s.value - hs
    })?;
    let (l, s) = (&lengths[i], &squares[i]);
    Some((
        i,
        format!(
            "the printed square {s} contradicts the printed length {l}: no length within half \
             a unit of {l} squares to within half a unit of {s}"
        ),
    ))
}

/// 10^e, exactly.
fn pow10(e: i32) -> BigRational {
    let p = BigRational::from_integer(BigInt::from(10).pow(e.unsigned_abs()));
    if e < 0 {
        p.recip()
    } else {
        p
    }
}

impl fmt::Display for Printed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

/// Whether `s` is written as a decimal (`-1.5e-3`), whatever its size.
fn decimal_syntax(s: &str) -> bool {
    let t = s.trim();
    let (m, e) = t.split_once(['e', 'E']).unwrap_or((t, "0"));
    e.parse::<i64>().is_ok() && parse_decimal(m).is_some()
}

impl<'de> Deserialize<'de> for Printed {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = Printed;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a printed number as a quoted string, e.g. \"1.2345\"")
            }
            fn visit_str<E: de::Error>(self, s: &str) -> std::result::Result<Printed, E> {
                Printed::parse(s).ok_or_else(|| {
                    E::custom(if decimal_syntax(s) {
                        format!("'{s}' lies outside the range of a float (about 1e±308)")
                    } else {
                        format!("'{s}' is not a printed decimal number")
                    })
                })
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> std::result::Result<Printed, E> {
                self.visit_str(&v.to_string())
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> std::result::Result<Printed, E> {
                self.visit_str(&v.to_string())
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> std::result::Result<Printed, E> {
                Err(E::custom(format!(
                    "{v} is an unquoted float: quote it so its printed digits are kept"
                )))
            }
        }
        d.deserialize_str(V)
    }
}

#[cfg(test)]
mod range_tests {
    use super::*;

    #[test]
    fn numbers_a_float_cannot_hold_are_refused() {
        assert!(Printed::parse("1e308").is_some());
        assert!(Printed::parse("1e999").is_none());
        assert!(Printed::parse("1e-999").is_none());
        assert!(Printed::parse("0e-999").is_none());
        assert!(Printed::parse("1e2000000000").is_none());
        assert!(Printed::parse("-0.0").is_some());
        assert!(decimal_syntax("1e999") && !decimal_syntax("1x8"));
    }

    #[test]
    fn a_square_contradicts_its_length_only_beyond_both_roundings() {
        let p = |v: &[&str]| {
            v.iter()
                .map(|t| Printed::parse(t).unwrap())
                .collect::<Vec<_>>()
        };
        let lengths = p(&["2", "3", "5.371"]);
        assert_eq!(
            contradicting_square(&lengths, &p(&["4", "9", "28.8476"])),
            None
        );
        assert_eq!(
            contradicting_square(&lengths, &p(&["4", "9", "99"])).map(|c| c.0),
            Some(2)
        );
        // 5.371 ± 0.0005 squares to [28.84227, 28.85302]: 28.853 still meets it, 28.854 not
        assert_eq!(
            contradicting_square(&lengths, &p(&["4", "9", "28.853"])),
            None
        );
        assert_eq!(
            contradicting_square(&lengths, &p(&["4", "9", "28.854"])).map(|c| c.0),
            Some(2)
        );
        assert_eq!(
            contradicting_square(&lengths, &p(&["4", "9", "28.8417"])).map(|c| c.0),
            Some(2)
        );
    }
}
