//! What was found (HTML): the findings' sentences, every claim they list linked, and what
//! each verdict word means.

use std::fmt::Write as _;

use super::glance::correction_html;
use super::page::{badge, Page};
use crate::check::Verdict;
use crate::mathtext::escape;
use crate::report::layout::anchor;
use crate::report::words::{capitalised, findings, Why};

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
                    format!("should read {}", correction_html(page, c))
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
        let _ = write!(s, "<dt>{}</dt><dd>{}</dd>", badge(v), escape(v.meaning()));
    }
    s.push_str("</dl></details></section>");
}
