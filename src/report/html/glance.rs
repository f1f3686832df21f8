//! The claims at a glance (HTML): every statistical claim and whether it holds, every
//! erratum as printed → what is wrong → corrected in readable mathematics, and the claims that fail, cannot be
//! decided or are inconclusive, each with its power in one short phrase.

use std::fmt::Write as _;

use super::page::{badge, Page};
use crate::check::{ClaimResult, Value, Verdict};
use crate::mathtext::{escape, math_html, prose_html};
use crate::report::layout::anchor;
use crate::report::values::{power_phrase, trials_of, value_text};
use crate::report::words::{
    correction_is_prose, defect_sentence, holds_word, is_statistical, printed_side, Why, LISTS,
};

fn side(page: &Page, qs: &[&crate::check::Quantity]) -> String {
    qs.iter()
        .map(|q| match &q.value {
            Value::Quote { text } => page.quote(text),
            Value::Formula { text } | Value::Label { text } => {
                format!(
                    "<span class=\"math\">{}</span>",
                    math_html(text, &page.macros, true)
                )
            }
            v => escape(&value_text(v)),
        })
        .collect::<Vec<_>>()
        .join("; ")
}

/// A claim's correction as HTML: words as running text, a formula as mathematics.
pub(crate) fn correction_html(page: &Page, c: &ClaimResult) -> String {
    let corrected = c.correction.as_deref().unwrap_or("");
    if correction_is_prose(c) {
        page.readable(&prose_html(corrected, &page.macros))
    } else {
        format!(
            "<span class=\"math\">{}</span>",
            math_html(corrected, &page.macros, true)
        )
    }
}

/// An erratum's printed and corrected forms side by side, what changed marked on both sides.
pub(crate) fn fix_html(page: &Page, c: &ClaimResult) -> String {
    let (printed, corrected) =
        mark_change(&side(page, &printed_side(c)), &correction_html(page, c));
    format!(
        "<div class=\"fix\"><div><span class=\"label\">printed</span>{printed}</div><div class=\"arrow\" role=\"img\" aria-label=\"corrected to\">→</div>\
         <div><span class=\"label\">corrected</span>{corrected}</div></div>"
    )
}

/// The visible characters of an HTML fragment (outside tags, entities as one), with their
/// byte offsets, spaces left out: what a reader compares.
fn visible(html: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < html.len() {
        let rest = &html[i..];
        let c = rest.chars().next().unwrap_or(' ');
        let len = match c {
            '<' => {
                i += rest.find('>').map_or(rest.len(), |e| e + 1);
                continue;
            }
            '&' => rest.find(';').map_or(1, |e| e + 1),
            c => c.len_utf8(),
        };
        if !c.is_whitespace() {
            out.push((i, &rest[..len]));
        }
        i += len;
    }
    out
}

/// Scripts (`<sub>`, `<sup>`) open at byte `at` of `html`.
fn open_scripts(html: &str, at: usize) -> usize {
    let h = &html[..at];
    let open = h.matches("<sub>").count() + h.matches("<sup>").count();
    open.saturating_sub(h.matches("</sub>").count() + h.matches("</sup>").count())
}

/// Byte offset in `html` of a cut before visible character `k` (`back`), or just after it,
/// moved out of any script: back before it, or forward past its end.
fn cut(html: &str, vis: &[(usize, &str)], k: usize, back: bool) -> usize {
    let mut at = match (back, vis.get(k)) {
        (true, Some(v)) => v.0,
        (false, Some(v)) => v.0 + v.1.len(),
        (_, None) => html.len(),
    };
    while open_scripts(html, at) > 0 {
        at = if back {
            html[..at].rfind("<su").unwrap_or(0)
        } else {
            html[at..]
                .find("</su")
                .map_or(html.len(), |e| at + e + "</sub>".len())
        };
    }
    at
}

/// `a` and `b` with the part between their common beginning and common end (in visible
/// characters) wrapped in `<mark>`; unchanged when they are the same or share nothing.
pub(crate) fn mark_change(a: &str, b: &str) -> (String, String) {
    let (va, vb) = (visible(a), visible(b));
    let same = |x: &(usize, &str), y: &(usize, &str)| x.1 == y.1;
    let pre = va.iter().zip(&vb).take_while(|(x, y)| same(x, y)).count();
    let max_suf = va.len().min(vb.len()) - pre;
    let suf = va
        .iter()
        .rev()
        .zip(vb.iter().rev())
        .take(max_suf)
        .take_while(|(x, y)| same(x, y))
        .count();
    if pre + suf == va.len() && pre + suf == vb.len() || pre + suf == 0 {
        return (a.to_string(), b.to_string());
    }
    let wrap = |h: &str, v: &[(usize, &str)]| {
        let start = cut(h, v, pre, true);
        let changed = v.len() - suf;
        let end = if changed > pre {
            cut(h, v, changed - 1, false)
        } else {
            start
        };
        if end > start {
            format!(
                "{}<mark>{}</mark>{}",
                &h[..start],
                &h[start..end],
                &h[end..]
            )
        } else {
            h.to_string()
        }
    };
    (wrap(a, &va), wrap(b, &vb))
}

fn claim_link(c: &ClaimResult) -> String {
    format!(
        "<a href=\"#{}\"><code>{}</code></a>",
        anchor(&c.id),
        escape(&c.id)
    )
}

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
                page.quantities(&c.computed, trials_of(c)),
                escape(&power_phrase(&c.power))
            );
        }
        s.push_str("</ul>");
    }
    s.push_str("</section>");
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
    s.push_str("<h3>Errata: printed → what is wrong → corrected</h3>");
    for c in errata {
        let wrong = match defect_sentence(c) {
            Why::Text(d) => format!(
                "<p class=\"defect\"><strong>what is wrong:</strong> {}</p>",
                page.linked(&d)
            ),
            Why::ShouldRead(_) => String::new(),
        };
        let _ = write!(
            s,
            "<div class=\"erratum\"><p>{} (§{}, line {})</p>{wrong}{}</div>",
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_change_is_marked_on_both_sides_outside_scripts() {
        let (a, b) = mark_change("<span>x + 2y</span>", "x + 3y");
        assert_eq!(a, "<span>x + <mark>2</mark>y</span>");
        assert_eq!(b, "x + <mark>3</mark>y");
        // a change inside a script marks the whole script
        let (a, b) = mark_change("d<sub>Cst,1</sub> = 1", "d<sub>Cst,2</sub> = 1");
        assert_eq!(a, "d<mark><sub>Cst,1</sub></mark> = 1");
        assert_eq!(b, "d<mark><sub>Cst,2</sub></mark> = 1");
        // spaces do not count; equal sides are left alone
        assert_eq!(mark_change("a + b", "a+b"), ("a + b".into(), "a+b".into()));
    }
}
