//! Errata of the text, judged from the transcription: each finding's quote with the words at
//! fault in it, the other places it cites, and the computation that decides the correction
//! where one exists. Whether the quotes stand at their lines of the LaTeX source is the
//! transcription's verification (`cases::verify`), not part of a verdict: a run without the
//! source gives the same verdicts. An `erratum` changes what the text says; a `note` does not
//! (the rule is in `docs/verdicts.md`).

use crate::check::Role;
use crate::check::{ClaimBuilder, ClaimResult, Power, ResultBuilder, Value, Verdict};
use crate::claims::source_errata::{
    Balance, Configuration, Decision, Finding, FindingKind, SourceErrataCase,
};
use crate::derivations::dof;
use crate::error::Result;
use labels::labels_decision;

/// Every finding of the case as a claim result.
pub(super) fn results(b: &ResultBuilder, case: &SourceErrataCase) -> Result<Vec<ClaimResult>> {
    case.findings.iter().map(|f| finding(b, f)).collect()
}

/// Which words at fault stand in a text (white space collapsed).
fn words_in(text: &str, words: &[String]) -> usize {
    let text = collapse(text);
    words.iter().filter(|w| text.contains(&collapse(w))).count()
}

fn collapse(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// The words at fault, as the transcription shows them: every one in the quote, none in the
/// corrected text (the same search over the correction is the mutant that must find nothing).
struct AtFault {
    in_quote: usize,
    in_correction: usize,
    of: usize,
}

impl AtFault {
    fn of(f: &Finding) -> AtFault {
        AtFault {
            in_quote: words_in(&f.claim.quote, &f.at_fault),
            in_correction: words_in(&f.corrected, &f.at_fault),
            of: f.at_fault.len(),
        }
    }

    fn shown(&self) -> bool {
        self.of > 0 && self.in_quote == self.of
    }

    fn mutant_rejected(&self) -> bool {
        self.in_correction == 0
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

fn decide<'b>(r: ClaimBuilder<'b>, d: &Decision) -> (ClaimBuilder<'b>, Decided) {
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
        Decision::NotInSource { strings } => absence_decision(r, strings),
    }
}

/// The strings the transcription records as absent from the source (the verification,
/// given the source, searches the whole of it for each): the finding rests on that record,
/// and on its words at fault.
fn absence_decision<'b>(r: ClaimBuilder<'b>, strings: &[String]) -> (ClaimBuilder<'b>, Decided) {
    let d = Decided {
        ok: !strings.is_empty(),
        // the record decides nothing a run could refute without the source: it adds no power
        mutant_rejected: true,
        method: "; the strings recorded as absent from the source (searched for in the whole source whenever it is given)",
        mutant: "; the recorded absence adds no power of its own (the source verifies it)",
    };
    (
        r.computed(
            "strings recorded as absent from the source",
            Value::count_of(strings.len(), strings.len()),
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

fn finding(b: &ResultBuilder, f: &Finding) -> Result<ClaimResult> {
    let fault = AtFault::of(f);
    let mut r = b
        .claim(&f.claim)
        .suffix(&f.id)
        .printed("source text", Value::quote(f.claim.quote.clone()))
        .detail("words at fault", Value::quote(f.at_fault.join(" · ")))
        .detail_as("defect", Value::label(f.defect.clone()), Role::Defect)
        .computed(
            "words at fault in the quote",
            Value::count_of(fault.in_quote, fault.of),
        )
        .correction(f.corrected.clone());
    for p in &f.also {
        r = r.detail(
            // no ": " in the name: the evidence layout reads "model: statistic" names
            // as a table
            &format!("lines {} ({})", p.lines, p.shows.replace(": ", ", ")),
            Value::quote(p.quote.clone()),
        );
    }
    let decided = match &f.decide {
        Some(d) => {
            let (r2, x) = decide(r, d);
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
    let confirmed = fault.shown() && decided.ok;
    let power = Power::mutant(
        fault.mutant_rejected() && decided.mutant_rejected,
        &format!(
            "the same search over the corrected text must find none of the words at fault (found {} of {}){}",
            fault.in_correction, fault.of, decided.mutant
        ),
    );
    let method = format!(
        "the words at fault found in the transcribed quote (white space collapsed){}",
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
    fn words_at_fault_are_found_in_the_quote_only() {
        let words = vec!["Q_I".to_string(), "four  images".to_string()];
        assert_eq!(words_in("P_i, Q_I and\n four images", &words), 2);
        assert_eq!(words_in("P_i, Q_i and four points", &words), 0);
        // case matters: Q_i is not the defect Q_I
        assert_eq!(words_in("Q_i", &words[..1]), 0);
    }
}
