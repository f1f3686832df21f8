//! The report as one self-contained HTML page (inline CSS and SVG, nothing fetched), drawn
//! from the same claim results and figure data as `report.json`.

use std::collections::BTreeMap;
use std::fmt::Write as _;

use super::values::{computed_text, power_text, printed_text, tolerance_text, value_text};
use super::Report;
use crate::check::figure::Figure;
use crate::check::{ClaimResult, Verdict};

/// HTML-escape text.
pub fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// An anchor id from a result id (`appA-coefficients/f_cb` → `claim-appA-coefficients-f_cb`).
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

fn section_anchor(s: &str) -> String {
    format!("section-{}", s.replace('.', "-"))
}

/// Paper sections in reading order: numbers numerically, then the appendix.
fn section_key(s: &str) -> (u32, Vec<u32>) {
    if s.chars().next().is_some_and(|c| c.is_ascii_digit()) {
        (
            0,
            s.split(['.', '-']).filter_map(|p| p.parse().ok()).collect(),
        )
    } else {
        (1, Vec::new())
    }
}

const CSS: &str = "
body { font-family: system-ui, sans-serif; margin: 0 auto; max-width: 72rem; padding: 1rem 2rem; color: #222; line-height: 1.45; }
h1 { font-size: 1.6rem; margin-bottom: .2rem; } h2 { border-bottom: 1px solid #ccc; margin-top: 2.2rem; }
.meta { color: #555; font-size: .9rem; } .meta code, code { background: #f3f3f3; padding: 0 .25rem; border-radius: 3px; }
table { border-collapse: collapse; margin: .6rem 0; } td, th { border: 1px solid #ddd; padding: .25rem .55rem; text-align: left; vertical-align: top; }
article { border: 1px solid #e2e2e2; border-radius: 6px; padding: .6rem 1rem; margin: .9rem 0; }
article h3 { font-size: 1.02rem; margin: .2rem 0 .4rem; font-family: ui-monospace, monospace; }
blockquote { margin: .3rem 0; padding-left: .8rem; border-left: 3px solid #bbb; color: #444; font-style: italic; }
.badge { display: inline-block; padding: .05rem .5rem; border-radius: 1rem; font-size: .8rem; font-family: system-ui, sans-serif; color: #fff; vertical-align: middle; }
.v-reproduced { background: #2e7d32; } .v-reproduced-within-rounding { background: #33691e; } .v-identity-verified { background: #1565c0; }
.v-holds-generically { background: #00695c; } .v-statistical-holds { background: #4a148c; } .v-statistical-fails { background: #ad1457; }
.v-erratum { background: #a84300; } .v-note { background: #455a64; } .v-inconclusive { background: #5d4037; } .v-not-reproducible { background: #616161; } .v-contradicted { background: #c62828; }
dl { display: grid; grid-template-columns: 9rem 1fr; gap: .15rem .8rem; margin: .3rem 0; } dt { color: #666; } dd { margin: 0; }
details { margin-top: .4rem; } summary { cursor: pointer; color: #1565c0; }
figure { margin: .8rem 0; } figcaption { color: #555; font-size: .88rem; margin-top: .2rem; }
.panels { display: flex; flex-wrap: wrap; gap: .5rem; } .panels svg { border: 1px solid #eee; }
";

fn badge(v: Verdict) -> String {
    format!("<span class=\"badge v-{0}\">{0}</span>", v.name())
}

fn figure_html(f: &Figure) -> String {
    let mut s = format!("<figure id=\"{}\"><div class=\"panels\">", escape(&f.id));
    s.push_str(&super::svg::figure_svg(f, false));
    // the key: every layer name once, in its colour
    let mut key: Vec<(String, crate::check::figure::Style)> = Vec::new();
    for l in f.panels.iter().flat_map(|p| &p.layers) {
        if !l.name.is_empty() && !key.iter().any(|(n, _)| n == &l.name) {
            key.push((l.name.clone(), l.style));
        }
    }
    let key: Vec<String> = key
        .iter()
        .map(|(n, st)| {
            format!(
                "<span style=\"color: {}\">■ {}</span>",
                super::svg::css_colour(*st),
                escape(n)
            )
        })
        .collect();
    let _ = write!(
        s,
        "</div><figcaption><strong>{}</strong> — {}<br>{}</figcaption></figure>",
        escape(&f.title),
        escape(&f.caption),
        key.join(" · ")
    );
    s
}

fn claim_html(c: &ClaimResult, figures: &[&Figure]) -> String {
    let mut s = format!(
        "<article id=\"{}\"><h3>{} {}</h3>",
        anchor(&c.id),
        escape(&c.id),
        badge(c.verdict)
    );
    let _ = write!(
        s,
        "<blockquote>{} <span class=\"meta\">(lines {})</span></blockquote>",
        escape(&c.quote),
        escape(&c.lines)
    );
    s.push_str("<dl>");
    let _ = write!(s, "<dt>paper</dt><dd>{}</dd>", escape(&printed_text(c)));
    let _ = write!(s, "<dt>computed</dt><dd>{}</dd>", escape(&computed_text(c)));
    if let Some(t) = &c.tolerance {
        let _ = write!(
            s,
            "<dt>tolerance</dt><dd>{}</dd>",
            escape(&tolerance_text(t))
        );
    }
    let _ = write!(
        s,
        "<dt>power</dt><dd>{}</dd>",
        escape(&power_text(&c.power))
    );
    if let Some(corr) = &c.correction {
        let _ = write!(s, "<dt>corrected</dt><dd>{}</dd>", escape(corr));
    }
    s.push_str("</dl>");
    let _ = write!(
        s,
        "<details><summary>evidence</summary><p><strong>method:</strong> {}</p>",
        escape(&c.evidence.method)
    );
    if !c.evidence.details.is_empty() {
        s.push_str("<table>");
        for d in &c.evidence.details {
            let _ = write!(
                s,
                "<tr><th>{}</th><td>{}</td></tr>",
                escape(&d.name),
                escape(&value_text(&d.value))
            );
        }
        s.push_str("</table>");
    }
    s.push_str("</details>");
    for f in figures {
        s.push_str(&figure_html(f));
    }
    s.push_str("</article>");
    s
}

/// The whole page.
pub fn render(r: &Report) -> String {
    let mut s = String::from("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">");
    push_header(&mut s, r);
    push_seeds(&mut s, r);
    push_summary(&mut s, r);
    push_errata(&mut s, r);
    push_sections(&mut s, r);
    push_further_figures(&mut s, r);
    s.push_str("</body></html>\n");
    s
}

/// The page title, the stylesheet and the header with the provenance.
fn push_header(s: &mut String, r: &Report) {
    let title = r.paper.as_ref().map_or("", |p| p.title.as_str());
    let author = r.paper.as_ref().map_or("", |p| p.author.as_str());
    let _ = write!(
        s,
        "<title>Reproducibility report — {}</title><style>{CSS}</style></head><body>",
        escape(title)
    );
    let p = &r.provenance;
    let _ = write!(
        s,
        "<h1>Reproducibility report</h1><p><em>{}</em> — {}</p><p class=\"meta\">{}; revision {}; date {}; \
         reproduce with <code>{}</code></p>",
        escape(title),
        escape(author),
        escape(&r.tool),
        escape(p.revision.as_deref().unwrap_or("unknown")),
        escape(p.date.as_deref().unwrap_or("unknown")),
        escape(&p.command)
    );
}

/// The collapsed table of the seeds of every case.
fn push_seeds(s: &mut String, r: &Report) {
    s.push_str("<details><summary>seeds of every case</summary><table><tr><th>case</th><th>file</th><th>seeds</th></tr>");
    for cs in &r.provenance.seeds {
        let _ = write!(
            s,
            "<tr><td>{}</td><td><code>{}</code></td><td>{}</td></tr>",
            escape(&cs.case),
            escape(&cs.file),
            cs.seeds
                .iter()
                .map(|x| x.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    s.push_str("</table></details>");
}

/// The count of claims per verdict.
fn push_summary(s: &mut String, r: &Report) {
    s.push_str("<h2 id=\"summary\">Summary</h2><table><tr><th>verdict</th><th>claims</th></tr>");
    for v in Verdict::ALL {
        let _ = write!(
            s,
            "<tr><td>{}</td><td>{}</td></tr>",
            badge(v),
            r.summary.get(v.name()).copied().unwrap_or(0)
        );
    }
    s.push_str("</table>");
}

/// The list of errata, contradicted claims and exceptions the paper never names.
fn push_errata(s: &mut String, r: &Report) {
    s.push_str("<h3>Errata, contradicted claims and unnamed exceptions</h3><ul>");
    for c in r.claims.iter().filter(|c| {
        matches!(
            c.verdict,
            Verdict::Erratum | Verdict::Contradicted | Verdict::HoldsGenerically
        )
    }) {
        let _ = write!(
            s,
            "<li>{} <a href=\"#{}\"><code>{}</code></a> (<a href=\"#{}\">§{}</a>): {}</li>",
            badge(c.verdict),
            anchor(&c.id),
            escape(&c.id),
            section_anchor(&c.section),
            escape(&c.section),
            escape(&computed_text(c))
        );
    }
    s.push_str("</ul>");
}

/// The claims grouped by paper section, in reading order, each with its figures.
fn push_sections(s: &mut String, r: &Report) {
    let mut sections: BTreeMap<(u32, Vec<u32>, String), Vec<&ClaimResult>> = BTreeMap::new();
    for c in &r.claims {
        let (a, b) = section_key(&c.section);
        sections
            .entry((a, b, c.section.clone()))
            .or_default()
            .push(c);
    }
    for ((_, _, name), claims) in &sections {
        let _ = write!(
            s,
            "<h2 id=\"{}\">Section {}</h2>",
            section_anchor(name),
            escape(name)
        );
        for c in claims {
            let figs: Vec<&Figure> = r.figures.iter().filter(|f| f.claim == c.id).collect();
            s.push_str(&claim_html(c, &figs));
        }
    }
}

/// Figures whose claim id has no result of its own.
fn push_further_figures(s: &mut String, r: &Report) {
    // figures whose claim has several results are shown with the first of them
    let shown: Vec<&str> = r.claims.iter().map(|c| c.id.as_str()).collect();
    let rest: Vec<&Figure> = r
        .figures
        .iter()
        .filter(|f| !shown.contains(&f.claim.as_str()))
        .collect();
    if !rest.is_empty() {
        s.push_str("<h2 id=\"figures\">Further figures</h2>");
        for f in rest {
            s.push_str(&figure_html(f));
        }
    }
}
