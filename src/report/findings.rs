//! What was found, in sentences: the first thing the report says. What holds (by kind), what is
//! wrong in the paper (each erratum with its defect), what fails, what cannot be decided and
//! why, what is inconclusive and why; then what each verdict word means.

use std::fmt::Write as _;

use super::html::{anchor, escape, Page};
use super::layout::GROUPS;
use super::math::{math_text, prose_text_in, Macros};
use super::values::value_text;
use crate::check::Role;
use crate::check::{ClaimResult, Verdict};

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

/// The summary as HTML, with every claim linked, and the verdict words explained.
pub(crate) fn push_findings_html(s: &mut String, page: &Page) {
    s.push_str("<section id=\"findings\" aria-labelledby=\"findings-h\"><h2 id=\"findings-h\">What was found</h2>");
    for f in findings(&page.ordered) {
        let _ = write!(
            s,
            "<p><strong>{}.</strong> {}</p>",
            escape(&capitalised(f.group)),
            escape(&f.sentence)
        );
        if f.items.is_empty() {
            continue;
        }
        s.push_str("<ul class=\"findings\">");
        for (c, why) in &f.items {
            let text = match why {
                Why::Text(t) => page.linked(t),
                Why::ShouldRead(_) => {
                    format!("should read {}", super::glance::correction_html(page, c))
                }
            };
            let _ = write!(
                s,
                "<li><a href=\"#{}\"><code>{}</code></a> (§{}): {text}</li>",
                anchor(&c.id),
                escape(&c.id),
                escape(&c.section),
            );
        }
        s.push_str("</ul>");
    }
    s.push_str("<details><summary>what the verdict words mean</summary><dl class=\"verdicts\">");
    for v in Verdict::ALL {
        let _ = write!(
            s,
            "<dt>{}</dt><dd>{}</dd>",
            super::html::badge(v),
            escape(v.meaning())
        );
    }
    s.push_str("</dl></details></section>");
}

/// The summary as Markdown.
pub(crate) fn push_findings_markdown(
    s: &mut String,
    ordered: &[&ClaimResult],
    macros: &Macros,
    labels: &std::collections::BTreeMap<String, String>,
) {
    let plain = |t: &str| super::markdown::plain_text(&super::layout::readable_labels(t, labels));
    s.push_str("## What was found\n\n");
    for f in findings(ordered) {
        let _ = writeln!(s, "**{}.** {}\n", capitalised(f.group), f.sentence);
        for (c, why) in &f.items {
            let text = match why {
                Why::Text(t) => plain(t),
                Why::ShouldRead(t) if super::glance::correction_is_prose(c) => {
                    format!(
                        "should read: {}",
                        super::markdown::plain_text(&prose_text_in(t, macros))
                    )
                }
                Why::ShouldRead(t) => format!(
                    "should read {}",
                    super::markdown::plain_text(&math_text(t, macros, true))
                ),
            };
            let _ = writeln!(
                s,
                "- [`{}`](#{}) (§{}): {text}",
                c.id,
                anchor(&c.id),
                c.section,
            );
        }
        if !f.items.is_empty() {
            s.push('\n');
        }
    }
    s.push_str("What the verdict words mean:\n\n");
    for v in Verdict::ALL {
        let _ = writeln!(s, "- `{}`: {}", v.name(), v.meaning());
    }
    s.push('\n');
}

/// "wrong in the paper" → "Wrong in the paper".
fn capitalised(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|f| f.to_uppercase().collect::<String>() + c.as_str())
        .unwrap_or_default()
}

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
