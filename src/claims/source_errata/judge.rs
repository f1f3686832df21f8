//! Errata of the text, judged: each finding's quote located at its lines of the LaTeX source
//! (with mutant line ranges that must miss it), its other quoted places, and the computation
//! that decides the correction where one exists. An `erratum` changes what the text says; a
//! `note` does not (the rule is in `docs/verdicts.md`).

use crate::cases::{parse_lines, quote_at, quote_within, SourceText};
use crate::check::Role;
use crate::check::{ClaimBuilder, ClaimResult, Power, ResultBuilder, Value, Verdict};
use crate::claims::source_errata::{
    Balance, Configuration, Decision, Finding, FindingKind, SourceErrataCase,
};
use crate::derivations::dof;
use crate::error::Result;
use labels::labels_decision;

/// Every finding of the case as a claim result; without the paper's source (none attached
/// when the case was read) each finding is unverified.
pub(super) fn check(b: &ResultBuilder, case: &SourceErrataCase) -> Result<Vec<ClaimResult>> {
    match case.text.as_ref() {
        Some(text) => case.findings.iter().map(|f| finding(b, text, f)).collect(),
        None => Ok(case.findings.iter().map(|f| unverified(b, f)).collect()),
    }
}

/// A finding without the source: its quote is the transcription's, and nothing was checked
/// that could have failed, so the finding is not established (`inconclusive`).
fn unverified(b: &ResultBuilder, f: &Finding) -> ClaimResult {
    b.claim(&f.claim)
        .suffix(&f.id)
        .printed("source text", Value::quote(f.claim.quote.clone()))
        .computed(
            "quote at the stated lines",
            Value::label("not checked: the paper's source was not given (--paper FILE)"),
        )
        .correction(f.corrected.clone())
        .detail_as("defect", Value::label(f.defect.clone()), Role::Defect)
        .method("the quote as transcribed; its place in the source not checked")
        .power(Power::mutant(
            false,
            "none without the paper's source: the quote's place is checked only against it",
        ))
        .verdict(Verdict::Inconclusive)
}

/// Where a quote is looked for: its own lines, then the mutant ranges that must miss it.
struct Located {
    at_lines: bool,
    mutants_missed: usize,
    mutants: usize,
}

/// The quote at `lines`, and the same search over the range shifted by its own length (both
/// ways) and widened by one line at each end: a check that found the quote there too would
/// not have tested the line numbers.
fn locate(text: &SourceText, lines: &str, quote: &str) -> Located {
    let Some((a, b)) = parse_lines(lines) else {
        return Located {
            at_lines: false,
            mutants_missed: 0,
            mutants: 0,
        };
    };
    let len = b - a + 1;
    let mut ranges = vec![(a + len, b + len), (a.saturating_sub(1), b + 1)];
    if a > len {
        ranges.push((a - len, b - len));
    }
    let missed = ranges
        .iter()
        .filter(|(x, y)| !quote_at(text, *x, *y, quote))
        .count();
    Located {
        at_lines: quote_at(text, a, b, quote),
        mutants_missed: missed,
        mutants: ranges.len(),
    }
}

fn balances(cs: &[Configuration]) -> Vec<(Configuration, i64)> {
    cs.iter()
        .map(|c| (*c, dof::count(c.points, c.frames).balance))
        .collect()
}

fn has(balance: Balance, n: i64) -> bool {
    match balance {
        Balance::Surplus => n > 0,
        Balance::Enough => n >= 0,
    }
}

/// The correction is decided when every configuration it names has the balance and the
/// printed text names other configurations.
pub(super) fn count_confirms(
    balance: Balance,
    corrected: &[(Configuration, i64)],
    printed: &[Configuration],
) -> bool {
    let names: Vec<Configuration> = corrected.iter().map(|(c, _)| *c).collect();
    !corrected.is_empty()
        && corrected.iter().all(|(_, n)| has(balance, *n))
        && names.as_slice() != printed
}

fn name(c: &Configuration) -> String {
    format!("{} points, {} frames", c.points, c.frames)
}

/// What a decision found: whether it decides the correction, whether its mutant was
/// rejected, and how.
struct Decided {
    ok: bool,
    mutant_rejected: bool,
    method: &'static str,
    mutant: &'static str,
}

fn decide<'b>(
    r: ClaimBuilder<'b>,
    d: &Decision,
    text: &SourceText,
    quote: &str,
) -> (ClaimBuilder<'b>, Decided) {
    match d {
        Decision::DofCount {
            balance,
            printed,
            corrected,
        } => dof_decision(r, *balance, printed, corrected),
        Decision::FigureLabels {
            half_side,
            origin,
            points,
            pictures,
        } => labels_decision(r, half_side, origin, points, pictures),
        Decision::NotInSource { strings } => absence_decision(r, text, strings, quote),
    }
}

/// The strings are nowhere in the source; the same search must find the finding's own quote.
fn absence_decision<'b>(
    r: ClaimBuilder<'b>,
    text: &SourceText,
    strings: &[String],
    quote: &str,
) -> (ClaimBuilder<'b>, Decided) {
    let n = text.lines.len();
    let found = strings
        .iter()
        .filter(|s| quote_within(text, 1, n, s))
        .count();
    let d = Decided {
        ok: found == 0 && !strings.is_empty(),
        mutant_rejected: quote_within(text, 1, n, quote),
        method: "; the strings searched for in the whole source",
        mutant: "; the same search must find the finding's own quote",
    };
    (
        r.computed(
            "strings found in the source",
            Value::count_of(found, strings.len()),
        ),
        d,
    )
}

fn dof_decision<'b>(
    mut r: ClaimBuilder<'b>,
    balance: Balance,
    printed: &[Configuration],
    corrected: &[Configuration],
) -> (ClaimBuilder<'b>, Decided) {
    let one_fewer: Vec<Configuration> = corrected
        .iter()
        .map(|c| Configuration {
            points: c.points.saturating_sub(1),
            frames: c.frames,
        })
        .collect();
    let (corr, prin) = (balances(corrected), balances(printed));
    let ok = count_confirms(balance, &corr, printed);
    for (label, set) in [("corrected", &corr), ("printed", &prin)] {
        for (c, n) in set {
            r = r.computed(&format!("balance, {} ({label})", name(c)), Value::exact(*n));
        }
    }
    let d = Decided {
        ok,
        mutant_rejected: !count_confirms(balance, &balances(&one_fewer), printed),
        method: "; the correction decided by §2.1's count, 2kp − (−1 + 3p + 5(k − 1))",
        mutant: "; the count for one point fewer must not decide it",
    };
    (
        r.computed("the count decides the correction", Value::flag(ok)),
        d,
    )
}

fn finding(b: &ResultBuilder, text: &SourceText, f: &Finding) -> Result<ClaimResult> {
    let own = locate(text, &f.claim.lines, &f.claim.quote);
    let also_found = f
        .also
        .iter()
        .filter(|p| locate(text, &p.lines, &p.quote).at_lines)
        .count();
    let mut r = b
        .claim(&f.claim)
        .suffix(&f.id)
        .printed("source text", Value::quote(f.claim.quote.clone()))
        .computed("quote at the stated lines", Value::flag(own.at_lines))
        .correction(f.corrected.clone())
        .detail_as("defect", Value::label(f.defect.clone()), Role::Defect);
    if !f.also.is_empty() {
        r = r.computed(
            "other places quoted at their lines",
            Value::count_of(also_found, f.also.len()),
        );
        for p in &f.also {
            r = r.detail(
                // no ": " in the name: the evidence layout reads "model: statistic" names
                // as a table
                &format!("lines {} ({})", p.lines, p.shows.replace(": ", ", ")),
                Value::quote(p.quote.clone()),
            );
        }
    }
    let decided = match &f.decide {
        Some(d) => {
            let (r2, x) = decide(r, d, text, &f.claim.quote);
            r = r2;
            x
        }
        None => Decided {
            ok: true,
            mutant_rejected: true,
            method: "",
            mutant: "",
        },
    };
    let confirmed = own.at_lines && also_found == f.also.len() && decided.ok;
    let power = Power::mutant(
        own.mutants_missed == own.mutants && decided.mutant_rejected,
        &format!(
            "the same search over {} shifted or widened line ranges must miss the quote (missed {}){}",
            own.mutants, own.mutants_missed, decided.mutant
        ),
    );
    let method = format!(
        "the quote located in the LaTeX source (white space collapsed){}",
        decided.method
    );
    Ok(r.method(&method)
        .power(power)
        .verdict(finding_verdict(f.kind, confirmed)))
}

/// An erratum or a note when its quote stands at its lines and its computation (if any)
/// decides the correction; otherwise the finding is not established.
pub(super) fn finding_verdict(kind: FindingKind, confirmed: bool) -> Verdict {
    match (confirmed, kind) {
        (false, _) => Verdict::Inconclusive,
        (true, FindingKind::Erratum) => Verdict::Erratum,
        (true, FindingKind::Note) => Verdict::Note,
    }
}

mod labels;

#[cfg(test)]
mod tests {
    use super::*;

    fn conf(points: usize, frames: usize) -> Configuration {
        Configuration { points, frames }
    }

    #[test]
    fn the_count_judge_on_both_sides() {
        let both = balances(&[conf(4, 3), conf(3, 4)]);
        assert!(count_confirms(Balance::Surplus, &both, &[conf(3, 4)]));
        // the printed reading the same as the corrected: nothing to correct
        assert!(!count_confirms(
            Balance::Surplus,
            &both,
            &[conf(4, 3), conf(3, 4)]
        ));
        // a configuration without surplus (3 points, 3 frames: balance 0)
        let exact = balances(&[conf(3, 3)]);
        assert!(!count_confirms(Balance::Surplus, &exact, &[]));
        assert!(count_confirms(Balance::Enough, &exact, &[]));
        let short = balances(&[conf(3, 2)]);
        assert!(!count_confirms(Balance::Enough, &short, &[]));
        assert!(!count_confirms(Balance::Enough, &[], &[conf(3, 2)]));
    }

    #[test]
    fn the_verdict_judge_on_both_sides() {
        assert_eq!(
            finding_verdict(FindingKind::Erratum, true),
            Verdict::Erratum
        );
        assert_eq!(finding_verdict(FindingKind::Note, true), Verdict::Note);
        assert_eq!(
            finding_verdict(FindingKind::Erratum, false),
            Verdict::Inconclusive
        );
        assert_eq!(
            finding_verdict(FindingKind::Note, false),
            Verdict::Inconclusive
        );
    }

    #[test]
    fn wrong_lines_are_rejected_and_the_mutant_ranges_miss() {
        let t = SourceText {
            lines: ["a b", "c d", "e f", "g h", "i j"]
                .iter()
                .map(|s| s.to_string())
                .collect(),
        };
        let l = locate(&t, "2-3", "c d e f");
        assert!(l.at_lines);
        assert_eq!(l.mutants_missed, l.mutants);
        assert!(!locate(&t, "3-4", "c d e f").at_lines);
        assert!(!locate(&t, "2-3", "c d e g").at_lines);
        assert!(!locate(&t, "x", "c d").at_lines);
    }
}
