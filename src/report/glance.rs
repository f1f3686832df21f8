//! The claims at a glance (HTML): every statistical claim and whether it holds, every
//! erratum as printed → corrected in readable mathematics, and the claims that fail, cannot be
//! decided or are inconclusive, each with its power in one short phrase.

use std::fmt::Write as _;

use super::html::{anchor, badge, escape, Page};
use super::math::math_html;
use super::values::power_phrase;
use crate::check::{ClaimResult, ToleranceSource, Value, Verdict};

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
        .filter(|q| q.name.contains("LaTeX"))
        .collect();
    if latex.is_empty() {
        c.printed.iter().collect()
    } else {
        latex
    }
}

fn side(page: &Page, qs: &[&crate::check::Quantity]) -> String {
    qs.iter()
        .map(|q| match &q.value {
            Value::Formula { text } | Value::Label { text } => {
                format!(
                    "<span class=\"math\">{}</span>",
                    math_html(text, &page.macros, true)
                )
            }
            v => escape(&super::values::value_text(v)),
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// An erratum's printed and corrected forms side by side.
pub(crate) fn fix_html(page: &Page, c: &ClaimResult) -> String {
    let corrected = c.correction.as_deref().unwrap_or("");
    format!(
        "<div class=\"fix\"><div><span class=\"label\">printed</span>{}</div><div class=\"arrow\" aria-label=\"corrected to\">→</div>\
         <div><span class=\"label\">corrected</span><span class=\"math\">{}</span></div></div>",
        side(page, &printed_side(c)),
        math_html(corrected, &page.macros, true)
    )
}

fn claim_link(c: &ClaimResult) -> String {
    format!(
        "<a href=\"#{}\"><code>{}</code></a>",
        anchor(&c.id),
        escape(&c.id)
    )
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

/// The at-a-glance part of the page.
pub(crate) fn push_glance(s: &mut String, page: &Page) {
    s.push_str("<section aria-labelledby=\"glance\"><h2 id=\"glance\">At a glance</h2>");
    push_statistical(s, page);
    push_errata(s, page);
    for (title, v) in LISTS {
        let claims: Vec<&&ClaimResult> = page.ordered.iter().filter(|c| c.verdict == v).collect();
        if claims.is_empty() {
            continue;
        }
        let _ = write!(s, "<h3>{title}</h3><ul>");
        for c in claims {
            let _ = write!(
                s,
                "<li>{} {} (§{}): {} <span class=\"meta\">— {}</span></li>",
                badge(c.verdict),
                claim_link(c),
                escape(&c.section),
                page.quantities(&c.computed, super::values::trials_of(c)),
                escape(&power_phrase(&c.power))
            );
        }
        s.push_str("</ul>");
    }
    s.push_str("</section>");
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

fn push_statistical(s: &mut String, page: &Page) {
    let stats: Vec<&&ClaimResult> = page.ordered.iter().filter(|c| is_statistical(c)).collect();
    if stats.is_empty() {
        return;
    }
    s.push_str(
        "<h3>Statistical claims</h3><div class=\"scroll\"><table><tr><th scope=\"col\">claim</th>\
         <th scope=\"col\">§</th><th scope=\"col\">holds?</th><th scope=\"col\">verdict</th><th scope=\"col\">power</th></tr>",
    );
    for c in stats {
        let holds = holds_word(c.verdict);
        let _ = write!(
            s,
            "<tr><td>{}</td><td>{}</td><td><strong>{holds}</strong></td><td>{}</td><td>{}</td></tr>",
            claim_link(c),
            escape(&c.section),
            badge(c.verdict),
            escape(&power_phrase(&c.power))
        );
    }
    s.push_str("</table></div>");
}

fn push_errata(s: &mut String, page: &Page) {
    let errata: Vec<&&ClaimResult> = page
        .ordered
        .iter()
        .filter(|c| c.verdict == Verdict::Erratum)
        .collect();
    if errata.is_empty() {
        return;
    }
    s.push_str("<h3>Errata: printed → corrected</h3>");
    for c in errata {
        let _ = write!(
            s,
            "<div class=\"erratum\"><p>{} (§{}, line {})</p>{}</div>",
            claim_link(c),
            escape(&c.section),
            escape(&c.lines),
            if c.correction.is_some() {
                fix_html(page, c)
            } else {
                format!(
                    "<p>printed: {}; found: {}</p>",
                    page.quantities(&c.printed, None),
                    page.quantities(&c.computed, None)
                )
            }
        );
    }
}
