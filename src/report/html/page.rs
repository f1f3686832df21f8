//! What every part of the page shares: the page's context (claims in order, the ids a text
//! may link, the paper's macros and labels), escaped and linked text, values as HTML, badges.

use std::collections::BTreeSet;
use std::fmt::Write as _;

use crate::check::{ClaimResult, Quantity, Role, Value, Verdict};
use crate::mathtext::{escape, math_html, quote_html, Macros};
use crate::report::layout::{self, anchor};
use crate::report::model::Report;
use crate::report::values::{quantities_line, quantities_shown, shown_text};

/// What every part of the page needs: the claims in order, the ids a text may link, the
/// paper's macros.
pub(crate) struct Page<'a> {
    pub(crate) report: &'a Report,
    pub(crate) ordered: Vec<&'a ClaimResult>,
    ids: BTreeSet<String>,
    pub(crate) macros: Macros,
    labels: std::collections::BTreeMap<String, String>,
}

impl<'a> Page<'a> {
    pub(crate) fn new(report: &'a Report) -> Page<'a> {
        Page {
            report,
            ordered: layout::ordered(report),
            ids: layout::linkable_ids(report),
            macros: Macros::parse(report.paper.as_ref().map_or("", |p| p.macros.as_str())),
            labels: report
                .paper
                .as_ref()
                .map(|p| p.labels.clone())
                .unwrap_or_default(),
        }
    }

    /// Escaped text with every claim id it mentions turned into a link.
    pub(crate) fn linked(&self, text: &str) -> String {
        let mut s = String::new();
        for (part, is_id) in layout::split_ids(text, &self.ids) {
            match layout::target_of(&self.ordered, part) {
                Some(c) if is_id => {
                    let _ = write!(
                        s,
                        "<a href=\"#{}\"><code>{}</code></a>",
                        anchor(&c.id),
                        escape(part)
                    );
                }
                _ => s.push_str(&plain_label(&self.readable(part))),
            }
        }
        s
    }

    /// `text` with the paper's label names as the report names them.
    pub(crate) fn readable(&self, text: &str) -> String {
        layout::readable_labels(text, &self.labels)
    }

    /// A quote of the paper as HTML: running text or mathematics, label names readable.
    pub(crate) fn quote(&self, text: &str) -> String {
        self.readable(&quote_html(text, &self.macros))
    }

    /// A value as HTML: formulas as mathematics, labels with their ids linked.
    pub(crate) fn value(&self, role: &Role, v: &Value, trials: Option<u64>) -> String {
        match v {
            Value::Formula { text } => format!(
                "<span class=\"math\">{}</span>",
                math_html(text, &self.macros, true)
            ),
            Value::Label { text } => self.linked(text),
            Value::Quote { text } => self.quote(text),
            v => escape(&shown_text(role, v, trials)),
        }
    }

    /// Named values on one line.
    pub(crate) fn quantities(&self, qs: &[Quantity], trials: Option<u64>) -> String {
        if qs.iter().all(|q| {
            !matches!(
                q.value,
                Value::Formula { .. } | Value::Label { .. } | Value::Quote { .. }
            )
        }) {
            return escape(&quantities_shown(qs, trials));
        }
        quantities_line(qs, escape, |q| self.value(&q.role, &q.value, trials))
    }
}

/// Escaped text in which a backslash command names a macro (`\faca` → `faca` in code), so
/// that no raw LaTeX reaches the reader.
pub(crate) fn plain_label(text: &str) -> String {
    let mut s = String::new();
    let mut rest = text;
    while let Some(at) = rest.find('\\') {
        s.push_str(&escape(&rest[..at]));
        let after = &rest[at + 1..];
        let n = after
            .find(|c: char| !c.is_ascii_alphabetic())
            .unwrap_or(after.len());
        if n == 0 {
            s.push('\\');
        } else {
            let _ = write!(s, "<code>{}</code>", &after[..n]);
        }
        rest = &after[n..];
    }
    s.push_str(&escape(rest));
    s
}

/// A verdict badge.
pub fn badge(v: Verdict) -> String {
    format!("<span class=\"badge v-{0}\">{0}</span>", v.name())
}
