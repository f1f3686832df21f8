//! What the report says in words, the same in every output: the findings' sentences and
//! why each claim is listed, which claims are statistical, an erratum's printed side, and the
//! verdicts the glance lists.

use super::layout::GROUPS;
use super::values::value_text;
use crate::check::Role;
use crate::check::{ClaimResult, ToleranceSource, Value, Verdict};

/// One paragraph of the summary: a sentence and the claims it names, each with a phrase.
pub(crate) struct Finding<'a> {
    /// The group's name ("wrong in the paper (errata)").
    pub(crate) group: &'static str,
    /// The sentence.
    pub(crate) sentence: String,
    /// The claims it lists, each with why.
    pub(crate) items: Vec<(&'a ClaimResult, Why)>,
}

/// Why a claim is listed: a phrase, or the formula it should read as.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Why {
    /// Words (claim ids in it are linked).
    Text(String),
    /// "should read:" and a formula in the paper's notation.
    ShouldRead(String),
}

/// "1 place", "2 places".
fn plural(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// The claims of `ordered` with one of `verdicts`.
fn with<'a>(ordered: &[&'a ClaimResult], verdicts: &[Verdict]) -> Vec<&'a ClaimResult> {
    ordered
        .iter()
        .copied()
        .filter(|c| verdicts.contains(&c.verdict))
        .collect()
}

/// An erratum's defect in one sentence: the defect its check names, else its correction.
pub(crate) fn defect_sentence(c: &ClaimResult) -> Why {
    let named = c
        .evidence
        .details
        .iter()
        .find(|d| d.role == Role::Defect)
        .map(|d| Why::Text(value_text(&d.value)));
    named.unwrap_or_else(|| Why::ShouldRead(c.correction.clone().unwrap_or_default()))
}

/// Why a claim was not decided: the judge's own reason, else what its power says could not
/// be told apart.
fn why(c: &ClaimResult) -> Why {
    Why::Text(
        c.undecided
            .clone()
            .unwrap_or_else(|| c.power.detail.clone()),
    )
}

/// Counts of the verdicts in `claims` as "12 reproduced, 3 identity-verified".
fn counted(claims: &[&ClaimResult], verdicts: &[Verdict]) -> String {
    verdicts
        .iter()
        .map(|v| (v, claims.iter().filter(|c| c.verdict == *v).count()))
        .filter(|(_, n)| *n > 0)
        .map(|(v, n)| format!("{n} {}", v.name()))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The summary's paragraphs, in the order of the verdict groups; empty groups are left out.
pub(crate) fn findings<'a>(ordered: &[&'a ClaimResult]) -> Vec<Finding<'a>> {
    let mut out = Vec::new();
    for (group, verdicts) in GROUPS {
        let claims = with(ordered, verdicts);
        if claims.is_empty() {
            continue;
        }
        let n = claims.len();
        let (sentence, items) = match verdicts[0] {
            Verdict::Reproduced => (
                format!(
                    "{} of the paper's claims hold, each by a check that could have failed: {}.",
                    n,
                    counted(&claims, verdicts)
                ),
                Vec::new(),
            ),
            Verdict::Erratum => (
                format!(
                    "{} where the paper prints something wrong, each with its correction checked:",
                    plural(n, "place", "places")
                ),
                claims.iter().map(|c| (*c, defect_sentence(c))).collect(),
            ),
            Verdict::Contradicted => (
                format!(
                    "{} ({}):",
                    plural(n, "claim does not hold", "claims do not hold"),
                    counted(&claims, verdicts)
                ),
                claims
                    .iter()
                    .map(|c| (*c, Why::Text(format!("“{}”", c.quote))))
                    .collect(),
            ),
            Verdict::Note => (
                format!(
                    "{} with one possible reading (a subscript, a header, a spelling); listed with their claims, not counted as errata.",
                    plural(n, "slip of form", "slips of form")
                ),
                Vec::new(),
            ),
            Verdict::NotReproducible => (
                format!(
                    "{} decided, because the paper lacks the data needed:",
                    plural(n, "claim cannot be", "claims cannot be")
                ),
                claims.iter().map(|c| (*c, why(c))).collect(),
            ),
            _ => (
                format!(
                    "{}, each for the reason given (a check that could not have failed on values the paper would call wrong, or whose readings or parts disagree):",
                    plural(n, "check is inconclusive", "checks are inconclusive")
                ),
                claims.iter().map(|c| (*c, why(c))).collect(),
            ),
        };
        out.push(Finding {
            group,
            sentence,
            items,
        });
    }
    out
}

/// "wrong in the paper" → "Wrong in the paper".
pub(crate) fn capitalised(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|f| f.to_uppercase().collect::<String>() + c.as_str())
        .unwrap_or_default()
}

/// Whether a claim rests on a noise study (its verdict is statistical, or its tolerance is a
/// Monte Carlo percentile).
pub fn is_statistical(c: &ClaimResult) -> bool {
    matches!(
        c.verdict,
        Verdict::StatisticalHolds | Verdict::StatisticalFails
    ) || c
        .tolerance
        .as_ref()
        .is_some_and(|t| matches!(t.source, ToleranceSource::MonteCarlo { .. }))
}

/// What an erratum's printed side shows: the LaTeX as printed when the check kept it, else
/// every printed value.
pub fn printed_side(c: &ClaimResult) -> Vec<&crate::check::Quantity> {
    let latex: Vec<_> = c
        .printed
        .iter()
        .filter(|q| q.role == Role::AsPrinted)
        .collect();
    if latex.is_empty() {
        c.printed.iter().collect()
    } else {
        latex
    }
}

/// Whether a claim's correction is words rather than a formula: none of what it printed is
/// a formula.
pub(crate) fn correction_is_prose(c: &ClaimResult) -> bool {
    !c.printed
        .iter()
        .any(|q| matches!(q.value, Value::Formula { .. }))
}

/// Whether a statistical claim holds, in one word.
pub fn holds_word(v: Verdict) -> &'static str {
    match v {
        Verdict::StatisticalHolds => "holds",
        Verdict::StatisticalFails => "fails",
        Verdict::Inconclusive | Verdict::NotReproducible => "undecided",
        v if v.is_positive() => "holds",
        _ => "fails",
    }
}

/// The verdicts listed one by one at a glance, with their headings.
pub const LISTS: [(&str, Verdict); 4] = [
    ("Contradicted", Verdict::Contradicted),
    (
        "Cannot be decided (the paper lacks the data)",
        Verdict::NotReproducible,
    ),
    (
        "Inconclusive (the check cannot discriminate)",
        Verdict::Inconclusive,
    ),
    (
        "Holds except on a case the paper never names",
        Verdict::HoldsGenerically,
    ),
];

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::{Evidence, Power, Value};

    fn claim_with(id: &str, verdict: Verdict) -> ClaimResult {
        ClaimResult {
            id: id.into(),
            claim: id.into(),
            case: "c".into(),
            section: "2".into(),
            lines: "1".into(),
            quote: "q".into(),
            verdict,
            printed: Vec::new(),
            computed: Vec::new(),
            tolerance: None,
            power: Power::exact_value("d"),
            correction: None,
            undecided: None,
            rests_on: Vec::new(),
            evidence: Evidence::new("m"),
        }
    }

    #[test]
    fn errata_stand_apart_from_failures() {
        let e = claim_with("a-1", Verdict::Erratum);
        let f = claim_with("b-1", Verdict::StatisticalFails);
        let ordered = vec![&e, &f];
        let fs = findings(&ordered);
        assert_eq!(fs.len(), 2);
        assert!(fs[0].sentence.starts_with("1 place where the paper prints"));
        assert_eq!(fs[0].items[0].0.id, "a-1");
        assert!(fs[1].sentence.contains("1 statistical-fails"));
    }

    #[test]
    fn an_erratum_s_defect_is_its_named_defect_else_its_correction() {
        let mut e = claim_with("a-1", Verdict::Erratum);
        e.correction = Some("x = 2".into());
        assert_eq!(defect_sentence(&e), Why::ShouldRead("x = 2".into()));
        // a detail is the defect by its role, whatever its name says
        e.evidence.details.push(crate::check::Quantity::new(
            "defect",
            Value::label("not the defect"),
        ));
        assert_eq!(defect_sentence(&e), Why::ShouldRead("x = 2".into()));
        e.evidence.details.push(crate::check::Quantity::with_role(
            "what is wrong",
            Value::label("a sign is wrong"),
            Role::Defect,
        ));
        assert_eq!(defect_sentence(&e), Why::Text("a sign is wrong".into()));
    }

    #[test]
    fn an_undecided_claim_says_the_judge_s_reason_else_its_control() {
        let mut c = claim_with("a-1", Verdict::Inconclusive);
        assert_eq!(why(&c), Why::Text("d".into()));
        c.undecided = Some("the readings disagree".into());
        assert_eq!(why(&c), Why::Text("the readings disagree".into()));
    }
}
