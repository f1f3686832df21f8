//! The one place where typed claim values become text.

use crate::check::{
    ClaimResult, Power, PowerKind, Quantity, Resolution, Role, Tolerance, ToleranceSource, Value,
};
use crate::numfmt::{sampled_digits, sig, sig_digits};

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
        Value::Quote { text } => super::math::prose_text(text),
    }
}

/// Named values as one line: `name: value; …` (a lone [`Role::ValueOnly`] value prints
/// alone).
pub fn quantities_text(qs: &[Quantity]) -> String {
    quantities_line(qs, |n| n.to_string(), |q| value_text(&q.value))
}

/// A tolerance as text: the bound, then where it comes from.
pub fn tolerance_text(t: &Tolerance) -> String {
    if let ToleranceSource::FalsePass { log10 } = &t.source {
        return format!(
            "exact: a false identity would pass this check with probability below 10{} ({})",
            false_pass_exponent(log10.0),
            t.how
        );
    }
    let bound = t
        .bound
        .map_or("exact".to_string(), |b| format!("± {}", sig(b.0)));
    let source = match &t.source {
        ToleranceSource::Exact => "exact arithmetic".to_string(),
        ToleranceSource::PrintedPrecision => "printed precision".to_string(),
        ToleranceSource::Propagated => "propagated rounding".to_string(),
        ToleranceSource::ErrorBound => "derived floating-point error bound".to_string(),
        ToleranceSource::FalsePass { .. } => "random-point screen".to_string(),
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

/// The exponent of a false-pass bound 10^x, rounded up (a weaker bound than the one derived,
/// never a stronger): e.g. −307.
/// The exponent of a false-pass bound, as a superscript (`⁻¹³²`; `^−132` if it had a
/// character without one).
fn false_pass_exponent(log10: f64) -> String {
    let e = sig(log10.ceil()).replace('-', "−");
    e.chars()
        .map(crate::numfmt::superscript)
        .collect::<Option<String>>()
        .unwrap_or(format!("^{e}"))
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
    let resolution = p
        .resolution
        .map(|r| format!("; {}", resolution_text(&r)))
        .unwrap_or_default();
    format!("{kind}{region}: {}{resolution}{weak}", p.detail)
}

/// An acceptance interval's resolution: the printed digits it resolves, its half-width.
pub fn resolution_text(r: &Resolution) -> String {
    format!(
        "resolves {} of the {} printed significant digits (± {}, {} relative)",
        r.digits,
        r.printed,
        sig(r.half_width.0),
        percent_text(r.relative.0)
    )
}

/// A ratio as a percentage with the one formatter's digits.
fn percent_text(ratio: f64) -> String {
    format!("{} %", sig(ratio * 100.0))
}

/// A verdict's power in a few words (the full phrase is [`power_text`]).
pub fn power_phrase(p: &Power) -> String {
    let head = match (p.kind, &p.accepts) {
        (PowerKind::Interval, Some(v)) => {
            format!("would have rejected any value outside {}", value_text(v))
        }
        (PowerKind::Interval, None) => "would have rejected any other value".to_string(),
        (PowerKind::Mutant, _) => "would have rejected a changed formula or target".to_string(),
        (PowerKind::None, _) => "nothing it would have rejected".to_string(),
    };
    let head = match p.resolution {
        Some(r) if p.coarser_than_printed() => {
            format!("{head}, {} of {} printed digits", r.digits, r.printed)
        }
        _ => head,
    };
    if p.weak && p.kind != PowerKind::None {
        format!("{head} (weak: values the paper would call wrong pass too)")
    } else {
        head
    }
}

/// A value estimated from `trials` Monte Carlo trials: its floats with
/// [`sampled_digits`]; other values as [`value_text`].
pub fn sampled_text(v: &Value, trials: u64) -> String {
    let d = sampled_digits(trials);
    match v {
        Value::Real { value } => sig_digits(value.0, d),
        Value::Reals { values } => format!(
            "({})",
            values
                .iter()
                .map(|r| sig_digits(r.0, d))
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Value::Interval { lo, hi } => {
            format!("[{}, {}]", sig_digits(lo.0, d), sig_digits(hi.0, d))
        }
        v => value_text(v),
    }
}

/// The trial count behind a claim's numbers, when it rests on a Monte Carlo study: the
/// tolerance's, or an evidence detail counting the trials.
pub fn trials_of(c: &ClaimResult) -> Option<u64> {
    if let Some(Tolerance {
        source: ToleranceSource::MonteCarlo { trials, .. },
        ..
    }) = &c.tolerance
    {
        return Some(*trials);
    }
    c.evidence.details.iter().find_map(|d| match d.value {
        Value::Count { count, of: None } if d.role == Role::Trials => Some(count),
        _ => None,
    })
}

/// A value as shown: a model's statistic (a [`Role::Cell`]) in a claim resting on `trials`
/// trials with [`sampled_digits`], anything else in full (a printed run's own errors, say,
/// are computed from printed digits, not sampled).
pub fn shown_text(role: &Role, v: &Value, trials: Option<u64>) -> String {
    match (trials, role) {
        (Some(n), Role::Cell { .. }) => sampled_text(v, n),
        _ => value_text(v),
    }
}

/// Named values as one line, like [`quantities_text`], each shown with [`shown_text`].
pub fn quantities_shown(qs: &[Quantity], trials: Option<u64>) -> String {
    quantities_line(
        qs,
        |n| n.to_string(),
        |q| shown_text(&q.role, &q.value, trials),
    )
}

/// Named values as one line, `name: value; …`, the name dropped when the only value's name
/// adds nothing ([`Role::ValueOnly`]); each renderer passes its own escape and value rendering.
pub fn quantities_line(
    qs: &[Quantity],
    name: impl Fn(&str) -> String,
    value: impl Fn(&Quantity) -> String,
) -> String {
    match qs {
        [q] if q.role == Role::ValueOnly => value(q),
        _ => qs
            .iter()
            .map(|q| format!("{}: {}", name(&q.name), value(q)))
            .collect::<Vec<_>>()
            .join("; "),
    }
}

/// What the paper printed, as one line.
pub fn printed_text(c: &ClaimResult) -> String {
    quantities_text(&c.printed)
}

/// What was computed, as one line.
pub fn computed_text(c: &ClaimResult) -> String {
    quantities_text(&c.computed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_false_pass_bound_reads_as_a_power_of_ten() {
        assert_eq!(false_pass_exponent(-131.2), "⁻¹³¹");
        assert_eq!(false_pass_exponent(-0.5), "⁰");
    }

    #[test]
    fn sampled_digits_follow_the_trial_count() {
        assert_eq!(sampled_digits(0), 1);
        assert_eq!(sampled_digits(99), 1);
        assert_eq!(sampled_digits(100), 2);
        assert_eq!(sampled_digits(9_999), 2);
        assert_eq!(sampled_digits(10_000), 3);
        assert_eq!(sampled_digits(1_000_000), 4);
        assert_eq!(sig_digits(0.0226423, 3), "0.0226");
        assert_eq!(sig_digits(0.0016, 3), "0.00160");
        assert_eq!(sig_digits(79.1051, 3), "79.1");
        assert_eq!(sig_digits(0.7, 3), "0.700");
        assert_eq!(sig_digits(123456.0, 2), "120000");
        assert_eq!(sig_digits(2.6e-9, 1), "3e-9");
        assert_eq!(
            sampled_text(&Value::reals(&[0.00633492, 0.683381]), 10_000),
            "(0.00633, 0.683)"
        );
    }
}
