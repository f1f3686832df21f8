//! The one place where typed claim values become text.

use crate::check::{ClaimResult, Power, PowerKind, Quantity, Tolerance, ToleranceSource, Value};
use crate::numfmt::sig;

/// A value as text.
pub fn value_text(v: &Value) -> String {
    match v {
        Value::Printed { text, .. } => text.clone(),
        Value::Real { value } => sig(value.0),
        Value::Below { exponent } => match exponent {
            Some(e) => format!("< 1e{e}"),
            None => "0".into(),
        },
        Value::Reals { values } => format!(
            "({})",
            values
                .iter()
                .map(|r| sig(r.0))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Value::Interval { lo, hi } => format!("[{}, {}]", sig(lo.0), sig(hi.0)),
        Value::Exact { value } => value.clone(),
        Value::Count { count, of } => match of {
            Some(n) => format!("{count} of {n}"),
            None => count.to_string(),
        },
        Value::Flag { value } => if *value { "yes" } else { "no" }.into(),
        Value::Formula { text } | Value::Label { text } => text.clone(),
    }
}

/// Named values as one line: `name: value; …` (a lone unnamed-looking `paper`/`computed`
/// entry prints its value only).
pub fn quantities_text(qs: &[Quantity]) -> String {
    match qs {
        [q] if q.name == "paper" || q.name == "computed" => value_text(&q.value),
        _ => qs
            .iter()
            .map(|q| format!("{}: {}", q.name, value_text(&q.value)))
            .collect::<Vec<_>>()
            .join("; "),
    }
}

/// A tolerance as text: the bound, then where it comes from.
pub fn tolerance_text(t: &Tolerance) -> String {
    let bound = t
        .bound
        .map_or("exact".to_string(), |b| format!("± {}", sig(b.0)));
    let source = match &t.source {
        ToleranceSource::Exact => "exact arithmetic".to_string(),
        ToleranceSource::PrintedPrecision => "printed precision".to_string(),
        ToleranceSource::Propagated => "propagated rounding".to_string(),
        ToleranceSource::ErrorBound => "derived floating-point error bound".to_string(),
        ToleranceSource::MonteCarlo { percentile, trials } => format!(
            "Monte Carlo percentile {} of {trials} trials",
            sig(percentile.0)
        ),
    };
    if t.how.is_empty() {
        format!("{bound} ({source})")
    } else {
        format!("{bound} ({source}: {})", t.how)
    }
}

/// A verdict's power in one short phrase.
pub fn power_text(p: &Power) -> String {
    let kind = match p.kind {
        PowerKind::Interval => "accepts",
        PowerKind::Mutant => "rejects",
        PowerKind::None => "no control",
    };
    let region = p
        .accepts
        .as_ref()
        .map(|v| format!(" {}", value_text(v)))
        .unwrap_or_default();
    let weak = if p.weak { " (weak)" } else { "" };
    format!("{kind}{region}: {}{weak}", p.detail)
}

/// What the paper printed, as one line.
pub fn printed_text(c: &ClaimResult) -> String {
    quantities_text(&c.printed)
}

/// What was computed, as one line.
pub fn computed_text(c: &ClaimResult) -> String {
    quantities_text(&c.computed)
}

/// The first word of `text` that spells a non-finite float as the formatters print one.
pub fn non_finite_token(text: &str) -> Option<&str> {
    text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-' || c == '.'))
        .map(|w| w.trim_matches('.'))
        .find(|w| {
            matches!(
                *w,
                "NaN" | "-NaN" | "nan" | "inf" | "-inf" | "infinity" | "-infinity"
            )
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_output_guard_finds_non_finite_numbers_only() {
        assert_eq!(non_finite_token("PQ²=NaN, QR²=4"), Some("NaN"));
        assert_eq!(non_finite_token("residual -inf."), Some("-inf"));
        assert_eq!(non_finite_token(r#"{"x": "inf"}"#), Some("inf"));
        assert_eq!(
            non_finite_token("information: infeasible; 1e-9; nano"),
            None
        );
        assert_eq!(non_finite_token(&crate::numfmt::sig(f64::NAN)), Some("NaN"));
    }
}
