//! The order both report renderers follow: the paper's sections in reading order with their
//! titles, the claims of each section in line order, the verdicts grouped for a reader, and
//! the claim ids a text may mention.

use std::collections::BTreeSet;

use super::model::Report;
use crate::check::{ClaimResult, Verdict};

/// One section of the paper and the claims it holds.
#[derive(Clone, Debug)]
pub struct Section<'a> {
    /// The number as the cases write it ("2.2", "A").
    pub number: String,
    /// The paper's title of it, when known.
    pub title: Option<String>,
    /// 1 for a section, 2 for a subsection.
    pub depth: usize,
    /// Its claims, in line order.
    pub claims: Vec<&'a ClaimResult>,
}

/// The paper numbers its appendices by letters, its sections by digits.
fn is_appendix(number: &str) -> bool {
    number.chars().all(|c| c.is_ascii_alphabetic())
}

impl Section<'_> {
    /// "§2.2 Structure and motion …" (the appendix by its title alone).
    pub fn heading(&self) -> String {
        match &self.title {
            // an appendix is named by its title alone ("Appendix A")
            Some(t) if is_appendix(&self.number) => t.clone(),
            Some(t) => format!("§{} {t}", self.number),
            None if is_appendix(&self.number) => {
                format!("Appendix {}", self.number)
            }
            None => format!("§{}", self.number),
        }
    }

    /// The anchor of the section (`section-2-2`).
    pub fn anchor(&self) -> String {
        section_anchor(&self.number)
    }
}

/// The anchor of section `number`.
pub fn section_anchor(number: &str) -> String {
    format!("section-{}", number.replace('.', "-"))
}

/// The anchor of the list of claims with verdict `v` (`verdict-erratum`).
pub fn verdict_anchor(v: Verdict) -> String {
    format!("verdict-{}", v.name())
}

/// A claim's anchor (`appA-coefficients/f_cb` → `claim-appA-coefficients-f_cb`).
pub fn anchor(id: &str) -> String {
    let clean: String = id
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' || c == '.' {
                c
            } else {
                '-'
            }
        })
        .collect();
    format!("claim-{clean}")
}

/// The first line number a claim cites (claims without one sort last).
pub fn first_line(c: &ClaimResult) -> u32 {
    let digits: String = c
        .lines
        .chars()
        .skip_while(|ch| !ch.is_ascii_digit())
        .take_while(char::is_ascii_digit)
        .collect();
    digits.parse().unwrap_or(u32::MAX)
}

/// Every section in the paper's order, with its claims in line order: the sections the paper
/// file names (even those without claims), then any other section a claim cites.
pub fn sections(r: &Report) -> Vec<Section<'_>> {
    let mut numbers: Vec<(String, Option<String>)> = r
        .paper
        .as_ref()
        .map(|p| {
            p.sections
                .iter()
                .map(|s| (s.number.clone(), Some(s.title.clone())))
                .collect()
        })
        .unwrap_or_default();
    for c in &r.claims {
        if !numbers.iter().any(|(n, _)| n == &c.section) {
            numbers.push((c.section.clone(), None));
        }
    }
    numbers.sort_by_key(|(n, _)| crate::cases::section_key(n));
    numbers
        .into_iter()
        .map(|(number, title)| {
            let mut claims: Vec<&ClaimResult> =
                r.claims.iter().filter(|c| c.section == number).collect();
            // stable: claims on the same line keep the cases' order
            claims.sort_by_key(|c| first_line(c));
            Section {
                depth: crate::cases::section_depth(&number),
                number,
                title,
                claims,
            }
        })
        .collect()
}

/// The claims in report order: section by section, each in line order.
pub fn ordered(r: &Report) -> Vec<&ClaimResult> {
    sections(r).into_iter().flat_map(|s| s.claims).collect()
}

/// How a reader groups the verdicts at a glance. Errata stand apart from failures: an
/// erratum is a finding about the paper, a failure a claim that does not hold.
pub const GROUPS: [(&str, &[Verdict]); 6] = [
    (
        "holds",
        &[
            Verdict::Reproduced,
            Verdict::ReproducedWithinRounding,
            Verdict::IdentityVerified,
            Verdict::HoldsGenerically,
            Verdict::StatisticalHolds,
        ],
    ),
    ("wrong in the paper (errata)", &[Verdict::Erratum]),
    ("fails", &[Verdict::Contradicted, Verdict::StatisticalFails]),
    ("form only (notes)", &[Verdict::Note]),
    ("cannot be decided", &[Verdict::NotReproducible]),
    ("inconclusive", &[Verdict::Inconclusive]),
];

/// `text` with every label name of the paper (`zweiframeseins`) in the words the report
/// names it by (`Fig. 3`); a kind word before it is not said twice ("Fig. zweiframeseins",
/// "fig. zweiframeseins" → "Fig. 3").
pub fn readable_labels(text: &str, labels: &std::collections::BTreeMap<String, String>) -> String {
    if labels.is_empty() {
        return text.to_string();
    }
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(c) = rest.chars().next() {
        if !c.is_ascii_alphanumeric() {
            out.push(c);
            rest = &rest[c.len_utf8()..];
            continue;
        }
        let n = rest
            .find(|ch: char| !ch.is_ascii_alphanumeric())
            .unwrap_or(rest.len());
        let (word, after) = rest.split_at(n);
        let boundary = !out.ends_with(['_', '/', '-']);
        match labels.get(word).filter(|_| boundary) {
            Some(name) => {
                let kind = name.split(' ').next().unwrap_or("").to_lowercase();
                let said = out.len() > kind.len()
                    && out[..out.len() - 1].to_lowercase().ends_with(&kind)
                    && out.ends_with(' ');
                if said {
                    out.truncate(out.len() - kind.len() - 1);
                }
                out.push_str(name);
            }
            None => out.push_str(word),
        }
        rest = after;
    }
    out
}

/// The ids a text may mention and a renderer links: every result id, and every claim id that
/// cannot be an ordinary word (it holds a digit, a dash or a slash).
pub fn linkable_ids(r: &Report) -> BTreeSet<String> {
    let mut ids = BTreeSet::new();
    for c in &r.claims {
        ids.insert(c.id.clone());
        if c.claim
            .contains(|ch: char| ch.is_ascii_digit() || ch == '-' || ch == '/')
        {
            ids.insert(c.claim.clone());
        }
    }
    ids
}

/// The result an id names: the result itself, or the first result (in report order) of the
/// claim it names.
pub fn target_of<'a>(ordered: &[&'a ClaimResult], id: &str) -> Option<&'a ClaimResult> {
    ordered
        .iter()
        .find(|c| c.id == id)
        .or_else(|| ordered.iter().find(|c| c.claim == id))
        .copied()
}

/// Split `text` into pieces, each either plain text or an id of `ids` (a whole token of id
/// characters, trailing punctuation excluded).
pub fn split_ids<'t>(text: &'t str, ids: &BTreeSet<String>) -> Vec<(&'t str, bool)> {
    let is_id_char = |c: char| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.' | '/');
    let mut out = Vec::new();
    let mut plain_from = 0;
    let mut i = 0;
    let bytes = text.as_bytes();
    while i < text.len() {
        let c = text[i..].chars().next().unwrap_or(' ');
        if !is_id_char(c) {
            i += c.len_utf8();
            continue;
        }
        let start = i;
        while i < text.len() && is_id_char(bytes[i] as char) && bytes[i].is_ascii() {
            i += 1;
        }
        let token = text[start..i].trim_end_matches(['.', '/', '-']);
        let end = start + token.len();
        if ids.contains(token) {
            if plain_from < start {
                out.push((&text[plain_from..start], false));
            }
            out.push((&text[start..end], true));
            plain_from = end;
        }
    }
    if plain_from < text.len() {
        out.push((&text[plain_from..], false));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ids_are_found_as_whole_tokens() {
        let ids: BTreeSet<String> = ["p4f3-unique/planar-body", "ex2-body"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        let parts = split_ids(
            "contradicted by p4f3-unique/planar-body. not ex2-body2",
            &ids,
        );
        assert_eq!(
            parts,
            vec![
                ("contradicted by ", false),
                ("p4f3-unique/planar-body", true),
                (". not ex2-body2", false)
            ]
        );
        assert_eq!(split_ids("ex2-body", &ids), vec![("ex2-body", true)]);
        assert_eq!(split_ids("a², b²", &ids), vec![("a², b²", false)]);
    }

    #[test]
    fn sections_sort_in_reading_order() {
        let mut v = vec!["A", "5.2", "2.2", "10", "2", "5"];
        v.sort_by_key(|s| crate::cases::section_key(s));
        assert_eq!(v, vec!["2", "2.2", "5", "5.2", "10", "A"]);
    }
}

#[cfg(test)]
mod label_tests {
    use super::readable_labels;

    #[test]
    fn label_names_become_the_report_s_names() {
        let labels = [("zweiframeseins", "Fig. 3"), ("p4f2", "eq. (2)")]
            .map(|(a, b)| (a.to_string(), b.to_string()))
            .into_iter()
            .collect();
        assert_eq!(
            readable_labels(
                "see Fig. zweiframeseins and fig. zweiframeseins, (p4f2)",
                &labels
            ),
            "see Fig. 3 and Fig. 3, (eq. (2))"
        );
        // inside an id or a longer word nothing changes
        assert_eq!(readable_labels("x-p4f2 p4f2x", &labels), "x-p4f2 p4f2x");
    }
}
