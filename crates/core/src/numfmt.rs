//! Number formatting, in one place, so reports and snapshots never drift across machines.

use std::sync::atomic::{AtomicUsize, Ordering};

/// Significant digits used for every floating value shown to a reader or snapshotted.
pub const SIGNIFICANT: usize = 6;

/// Non-finite values formatted so far in this process, by any formatter here. An output
/// guard reads it ([`non_finite_formatted`]): it counts numbers as they become text, so a
/// name that happens to read `inf` is never mistaken for one.
static NON_FINITE: AtomicUsize = AtomicUsize::new(0);

/// How many non-finite values the formatters here have turned into text in this process.
/// Zero means no `NaN` or `inf` from a number can be in any text they made.
pub fn non_finite_formatted() -> usize {
    NON_FINITE.load(Ordering::Relaxed)
}

/// Count `x` if it is not finite; true when it is.
fn counted(x: f64) -> bool {
    if x.is_finite() {
        return true;
    }
    NON_FINITE.fetch_add(1, Ordering::Relaxed);
    false
}

/// The shortest text that reads back as exactly `x` (Rust's `{:?}`), for data files that
/// must round-trip; a non-finite value is counted ([`non_finite_formatted`]).
pub fn round_trip(x: f64) -> String {
    counted(x);
    format!("{x:?}")
}

/// Format with [`SIGNIFICANT`] significant digits: plain notation for magnitudes in
/// [1e-4, 1e6), scientific otherwise; trailing zeros trimmed; `-0` printed as `0`.
///
/// # Example
/// ```
/// use orthocheck_core::numfmt::sig;
/// assert_eq!(sig(12.34560004), "12.3456");
/// assert_eq!(sig(2.5e-9), "2.5e-9");
/// assert_eq!(sig(-0.0), "0");
/// assert_eq!(sig(f64::INFINITY), "inf");
/// assert!(orthocheck_core::numfmt::non_finite_formatted() > 0);
/// ```
pub fn sig(x: f64) -> String {
    if !counted(x) {
        return non_finite_text(x);
    }
    if x == 0.0 {
        return "0".into();
    }
    let s = sig_digits(x, SIGNIFICANT);
    match s.split_once('e') {
        Some((m, e)) => format!("{}e{}", trim_zeros(m), e),
        None => trim_zeros(&s),
    }
}

fn non_finite_text(x: f64) -> String {
    match x {
        f64::INFINITY => "inf".into(),
        f64::NEG_INFINITY => "-inf".into(),
        _ => "NaN".into(),
    }
}

/// Significant digits a Monte Carlo estimate from `trials` trials carries. Its relative
/// sampling error is about 1/√trials (a quantile's or a share's standard error scales so), so
/// the digits kept are those up to and including the first uncertain one:
/// ⌊log₁₀ √trials⌋ + 1 (100 trials: 2 digits; 10 000 trials: 3 digits; at least 1).
pub fn sampled_digits(trials: u64) -> usize {
    if trials < 1 {
        return 1;
    }
    // ⌊log₁₀ √n⌋ = ⌊log₁₀ n / 2⌋, computed on integers so that 10 000 gives exactly 2
    let mut magnitude = 0usize;
    let mut n = trials;
    while n >= 10 {
        n /= 10;
        magnitude += 1;
    }
    magnitude / 2 + 1
}

/// `x` with `digits` significant digits: plain notation for magnitudes in [1e-4, 1e6),
/// scientific otherwise (the notation of [`sig`]); trailing zeros are kept,
/// since they are digits the estimate carries.
pub fn sig_digits(x: f64, digits: usize) -> String {
    if !x.is_finite() || x == 0.0 {
        return sig(x);
    }
    let digits = digits.max(1);
    let a = x.abs();
    if (1e-4..1e6).contains(&a) {
        let magnitude = a.log10().floor() as i32;
        let decimals = digits as i32 - 1 - magnitude;
        if decimals >= 0 {
            format!("{x:.0$}", decimals as usize)
        } else {
            // digits left of the point beyond the significant ones are zeros
            let scale = 10f64.powi(-decimals);
            format!("{:.0}", (x / scale).round() * scale)
        }
    } else {
        format!("{:.*e}", digits - 1, x)
    }
}

fn trim_zeros(s: &str) -> String {
    if s.contains('.') {
        let t = s.trim_end_matches('0').trim_end_matches('.');
        if t == "-0" {
            "0".into()
        } else {
            t.into()
        }
    } else {
        s.into()
    }
}

/// A list of floats, each with [`sig`], comma-separated in parentheses.
pub fn sig_list(xs: &[f64]) -> String {
    format!(
        "({})",
        xs.iter().map(|x| sig(*x)).collect::<Vec<_>>().join(", ")
    )
}

/// A rounding-level quantity as the power of ten above it (`"< 1e-11"`), so that values at
/// machine precision never make output differ between machines; exact zero prints `"0"`.
///
/// # Example
/// ```
/// assert_eq!(orthocheck_core::numfmt::below(2.06e-12), "< 1e-11");
/// ```
pub fn below(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    if !x.is_finite() {
        return sig(x);
    }
    let e = x.abs().log10().floor() as i32 + 1;
    format!("< 1e{e}")
}

/// The Unicode superscript of `c`, if it has one.
pub fn superscript(c: char) -> Option<char> {
    glyph(c, "0123456789+-−=()ni", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁻⁼⁽⁾ⁿⁱ")
}

/// The Unicode subscript of `c`, if it has one.
pub fn subscript(c: char) -> Option<char> {
    glyph(
        c,
        "0123456789+-−=(),aeoxhklmnpstijruv",
        "₀₁₂₃₄₅₆₇₈₉₊₋₋₌₍₎,ₐₑₒₓₕₖₗₘₙₚₛₜᵢⱼᵣᵤᵥ",
    )
}

/// The glyph of `to` at the place of `c` in `from`.
fn glyph(c: char, from: &str, to: &str) -> Option<char> {
    from.chars()
        .position(|x| x == c)
        .and_then(|i| to.chars().nth(i))
}

/// A monomial as a reader writes it, `a²·aᵢ²` for `[("a", 2), ("a_i", 2)]`: a name's `_x`
/// as a subscript and its exponent as a superscript where Unicode has the glyphs, as written
/// otherwise.
pub fn monomial(factors: &[(&str, u32)]) -> String {
    if factors.is_empty() {
        return "1".into();
    }
    let script =
        |t: &str, map: fn(char) -> Option<char>| t.chars().map(map).collect::<Option<String>>();
    let factor = |(name, e): &(&str, u32)| {
        let mut out = match name.split_once('_') {
            Some((base, sub)) => match script(sub, subscript) {
                Some(s) => format!("{base}{s}"),
                None => name.to_string(),
            },
            None => name.to_string(),
        };
        if *e > 1 {
            let e = e.to_string();
            out.push_str(&script(&e, superscript).unwrap_or(format!("^{e}")));
        }
        out
    };
    factors.iter().map(factor).collect::<Vec<_>>().join("·")
}
