//! The report as one self-contained HTML page (inline CSS, SVG and one small script; nothing
//! fetched), drawn from the same claim results and figure data as `report.json`: a verdict
//! strip, the contents in the paper's order, the claims at a glance, a filter by verdict that
//! works without JavaScript (`:target`), then every claim with its evidence and figures.

mod findings;
mod glance;
mod main_results;
mod page;

use std::fmt::Write as _;

use crate::check::figure::Figure;
use crate::check::{ClaimResult, Verdict};
use crate::report::layout::{self, section_anchor, verdict_anchor, Section, GROUPS};
use crate::report::model::Report;
use crate::report::values::{power_phrase, tolerance_text, trials_of};
use crate::report::words::{defect_sentence, Why};
use crate::report::{evidence, style, svg};
use page::{plain_label, Page};

pub use crate::mathtext::escape;
pub use crate::report::layout::anchor;
pub use page::badge;

/// The whole page.
pub fn render(r: &Report) -> String {
    let page = Page::new(r);
    let mut s = String::from(
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">",
    );
    push_header(&mut s, r);
    main_results::push_main_results(&mut s, &page);
    push_provenance(&mut s, r);
    findings::push_findings_html(&mut s, &page);
    push_strip(&mut s, r);
    push_contents(&mut s, &page);
    glance::push_glance(&mut s, &page);
    push_verdict_lists(&mut s, &page);
    s.push_str("<main id=\"claims\">");
    let sections = layout::sections(r);
    for (i, sec) in sections.iter().enumerate() {
        let prefix = format!("{}.", sec.number);
        let parent = sections
            .get(i + 1)
            .is_some_and(|n| n.number.starts_with(&prefix));
        push_section(&mut s, &page, sec, parent);
    }
    push_further_figures(&mut s, r);
    s.push_str("</main>");
    s.push_str(SCRIPT);
    s.push_str("</body></html>\n");
    s
}

/// The optional search: an input box the script adds (the page works without it); before
/// printing it also unfolds every evidence (the print stylesheet does so too where the
/// browser styles `::details-content`).
const SCRIPT: &str = "<script>(function(){var m=document.getElementById('claims');if(!m)return;\
var i=document.createElement('input');i.id='search';i.type='search';\
i.placeholder='search claims (id, words)';i.setAttribute('aria-label','search claims');\
var f=document.createElement('div');f.setAttribute('role','search');f.appendChild(i);\
m.parentNode.insertBefore(f,m);var a=m.querySelectorAll('article.claim');\
i.addEventListener('input',function(){var q=i.value.toLowerCase();\
for(var k=0;k<a.length;k++){a[k].style.display=(!q||a[k].textContent.toLowerCase().indexOf(q)>=0)?'':'none';}});\
window.addEventListener('beforeprint',function(){var d=document.querySelectorAll('details');for(var k=0;k<d.length;k++)d[k].open=true;});\
})();</script>";

/// The page title, the stylesheet and the header: the report's title and the paper's.
fn push_header(s: &mut String, r: &Report) {
    let title = r.paper.as_ref().map_or("", |p| p.title.as_str());
    let author = r.paper.as_ref().map_or("", |p| p.author.as_str());
    let _ = write!(
        s,
        "<title>Reproducibility report — {}</title><style>{}</style></head><body>\
         <header><h1>Reproducibility report</h1><p><em>{}</em> — {}</p></header>",
        escape(title),
        style::css(),
        escape(title),
        escape(author),
    );
}

/// Where the report comes from: tool, revision, date, command, the transcription's
/// verification and every case's seeds (after the main results, which a reader asks first).
fn push_provenance(s: &mut String, r: &Report) {
    let p = &r.provenance;
    let _ = write!(
        s,
        "<section class=\"provenance\" aria-label=\"provenance\"><p class=\"meta\">{}; revision {}; date {}; \
         reproduce with <code>{}</code></p>",
        escape(&r.tool),
        escape(p.revision.as_deref().unwrap_or("unknown")),
        escape(p.date.as_deref().unwrap_or("unknown")),
        escape(&p.command)
    );
    if !p.transcription.is_empty() {
        let _ = write!(s, "<p class=\"meta\">{}</p>", escape(&p.transcription));
    }
    s.push_str("<details><summary>seeds of every case</summary><div class=\"scroll\"><table><tr><th>case</th><th>file</th><th>seeds</th></tr>");
    for cs in &p.seeds {
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
    s.push_str("</table></div></details></section>");
}

fn count(r: &Report, v: Verdict) -> usize {
    r.summary.get(v.name()).copied().unwrap_or(0)
}

/// The verdict strip: what holds, what fails, what cannot be decided, what is inconclusive;
/// every count links to the list of its claims.
fn push_strip(s: &mut String, r: &Report) {
    s.push_str("<nav aria-label=\"verdicts\"><ul class=\"strip\">");
    for (group, verdicts) in GROUPS {
        let total: usize = verdicts.iter().map(|v| count(r, *v)).sum();
        let _ = write!(
            s,
            "<li><span class=\"group\">{group}</span><span class=\"total\">{total}</span><ul>"
        );
        for v in verdicts {
            let _ = write!(
                s,
                "<li><a href=\"#{}\">{} {}</a></li>",
                verdict_anchor(*v),
                badge(*v),
                count(r, *v)
            );
        }
        s.push_str("</ul></li>");
    }
    s.push_str("</ul></nav>");
}

/// The table of contents: the paper's sections in order with their titles, each with its
/// claims in line order (folded).
fn push_contents(s: &mut String, page: &Page) {
    s.push_str("<nav class=\"toc\" aria-labelledby=\"contents\"><h2 id=\"contents\">Contents</h2><ul class=\"sections\">");
    s.push_str("<li><a href=\"#glance\">At a glance</a></li><li><a href=\"#by-verdict\">Claims by verdict</a></li>");
    for sec in layout::sections(page.report) {
        let _ = write!(
            s,
            "<li{}><a href=\"#{}\">{}</a> <span class=\"meta\">({} claim{})</span>",
            if sec.depth > 1 { " class=\"sub\"" } else { "" },
            sec.anchor(),
            escape(&sec.heading()),
            sec.claims.len(),
            if sec.claims.len() == 1 { "" } else { "s" }
        );
        if !sec.claims.is_empty() {
            s.push_str("<details><summary>claims</summary><ul>");
            for c in &sec.claims {
                let _ = write!(
                    s,
                    "<li><a href=\"#{}\"><code>{}</code></a> {} <span class=\"meta\">line {}</span></li>",
                    anchor(&c.id),
                    escape(&c.id),
                    badge(c.verdict),
                    escape(&c.lines)
                );
            }
            s.push_str("</ul></details>");
        }
        s.push_str("</li>");
    }
    s.push_str("</ul></nav>");
}

/// The filter by verdict: one list per verdict, shown when the URL's fragment names it (which
/// also hides every claim of another verdict below); no script needed.
fn push_verdict_lists(s: &mut String, page: &Page) {
    s.push_str("<section aria-labelledby=\"by-verdict\"><h2 id=\"by-verdict\">Claims by verdict</h2><p class=\"filter\">Show only: ");
    for v in Verdict::ALL {
        let _ = write!(
            s,
            "<a href=\"#{}\">{} ({})</a>",
            verdict_anchor(v),
            escape(v.name()),
            count(page.report, v)
        );
    }
    s.push_str("<a href=\"#contents\">all</a></p>");
    for v in Verdict::ALL {
        let _ = write!(
            s,
            "<div class=\"vlist\" id=\"{}\"><h3>{} {} claim{}</h3><ul>",
            verdict_anchor(v),
            badge(v),
            count(page.report, v),
            if count(page.report, v) == 1 { "" } else { "s" }
        );
        for c in page.ordered.iter().filter(|c| c.verdict == v) {
            let _ = write!(
                s,
                "<li><a href=\"#{}\"><code>{}</code></a> <a href=\"#{}\">§{}</a>, line {}</li>",
                anchor(&c.id),
                escape(&c.id),
                section_anchor(&c.section),
                escape(&c.section),
                escape(&c.lines)
            );
        }
        s.push_str("</ul><p><a href=\"#contents\">show every verdict</a></p></div>");
    }
    s.push_str("</section>");
}

/// One section: its heading (the paper's title) and its claims.
fn push_section(s: &mut String, page: &Page, sec: &Section, parent: bool) {
    let h = sec.depth + 1;
    let _ = write!(
        s,
        "<section aria-labelledby=\"{a}\"><h{h} id=\"{a}\">{}</h{h}>",
        escape(&sec.heading()),
        a = sec.anchor()
    );
    if sec.claims.is_empty() && !parent {
        s.push_str("<p class=\"meta\">No claim of this section is checked.</p>");
    }
    for c in &sec.claims {
        let figs: Vec<&Figure> = page
            .report
            .figures
            .iter()
            .filter(|f| f.claim == c.id)
            .collect();
        s.push_str(&claim_html(page, c, &figs, h + 1));
    }
    s.push_str("</section>");
}

/// One claim: a permalink heading, the quote, printed / computed / tolerance / power, the
/// correction of an erratum side by side, the evidence (folded), the figures.
fn claim_html(page: &Page, c: &ClaimResult, figures: &[&Figure], h: usize) -> String {
    let trials = trials_of(c);
    let a = anchor(&c.id);
    let mut s = format!(
        "<article id=\"{a}\" class=\"claim v-{}\"><h{h} class=\"h\"><a class=\"permalink\" href=\"#{a}\">{}</a> {}</h{h}>",
        c.verdict.name(),
        escape(&c.id),
        badge(c.verdict)
    );
    let _ = write!(
        s,
        "<blockquote>{} <span class=\"meta\">(lines {}, <a href=\"#{}\">§{}</a>)</span></blockquote>",
        page.quote(&c.quote),
        escape(&c.lines),
        section_anchor(&c.section),
        escape(&c.section)
    );
    if matches!(c.verdict, Verdict::Erratum | Verdict::Note)
        && let Why::Text(d) = defect_sentence(c)
    {
        let _ = write!(
            s,
            "<p class=\"defect\"><strong>defect:</strong> {}</p>",
            page.linked(&d)
        );
    }
    s.push_str("<dl>");
    let _ = write!(
        s,
        "<dt>paper</dt><dd>{}</dd>",
        page.quantities(&c.printed, trials)
    );
    let _ = write!(
        s,
        "<dt>computed</dt><dd>{}</dd>",
        page.quantities(&c.computed, trials)
    );
    if let Some(t) = &c.tolerance {
        let _ = write!(
            s,
            "<dt>tolerance</dt><dd>{}</dd>",
            page.linked(&tolerance_text(t))
        );
    }
    let _ = write!(
        s,
        "<dt>power</dt><dd><strong>{}</strong>: {}</dd>",
        escape(&power_phrase(&c.power)),
        page.linked(&c.power.detail)
    );
    if let Some(u) = &c.undecided {
        let _ = write!(s, "<dt>undecided</dt><dd>{}</dd>", page.linked(u));
    }
    s.push_str("</dl>");
    if c.correction.is_some() {
        s.push_str(&glance::fix_html(page, c));
    }
    s.push_str(&evidence_html(page, c, trials));
    for f in figures {
        s.push_str(&figure_html(f));
    }
    s.push_str("</article>");
    s
}

/// The folded evidence: the method, the single details, the per-model tables.
fn evidence_html(page: &Page, c: &ClaimResult, trials: Option<u64>) -> String {
    let ev = evidence::layout(c);
    let mut s = format!(
        "<details class=\"evidence\"><summary>evidence</summary><p><strong>method:</strong> {}</p>",
        page.linked(&c.evidence.method)
    );
    if !ev.rows.is_empty() {
        s.push_str("<div class=\"scroll\"><table>");
        for d in &ev.rows {
            let _ = write!(
                s,
                "<tr><th scope=\"row\">{}</th><td>{}</td></tr>",
                page.linked(&d.name),
                page.value(&d.role, &d.value, trials)
            );
        }
        s.push_str("</table></div>");
    }
    for t in &ev.tables {
        let _ = write!(
            s,
            "<div class=\"scroll\"><table><caption>{}</caption><tr><th scope=\"col\">{}</th>",
            escape(&t.caption),
            escape(&t.corner)
        );
        for col in &t.columns {
            let _ = write!(s, "<th scope=\"col\" class=\"num\">{}</th>", escape(col));
        }
        s.push_str("</tr>");
        for (head, cells) in &t.rows {
            let _ = write!(s, "<tr><th scope=\"row\">{}</th>", escape(head));
            for cell in cells {
                let _ = write!(s, "<td class=\"num\">{}</td>", escape(cell));
            }
            s.push_str("</tr>");
        }
        s.push_str("</table></div>");
    }
    if let Some(n) = trials {
        let _ = write!(
            s,
            "<p class=\"meta\">Statistics of {n} trials are shown to {} significant digits (sampling error about 1/√{n}).</p>",
            crate::numfmt::sampled_digits(n)
        );
    }
    s.push_str("</details>");
    s
}

/// A figure: its panels and its caption. The key of its series is drawn once, inside the
/// SVG beside the plot; the caption says in words what the figure shows.
pub fn figure_html(f: &Figure) -> String {
    // a figure with a minimum width scrolls sideways in its box on a narrow screen
    // (focusable, so that a keyboard can scroll it: WCAG 2.1.1)
    let panels = if svg::min_width(f).is_some() {
        format!(
            "class=\"panels scroll\" tabindex=\"0\" role=\"group\" aria-labelledby=\"{}-title\"",
            escape(&f.id)
        )
    } else {
        "class=\"panels\"".to_string()
    };
    let mut s = format!("<figure id=\"{}\"><div {panels}>", escape(&f.id));
    s.push_str(&svg::figure_svg(f, false));
    let _ = write!(
        s,
        "</div><figcaption><strong>{}</strong> — {}</figcaption></figure>",
        plain_label(&f.title),
        plain_label(&f.caption)
    );
    s
}

/// Figures whose claim id has no result of its own.
fn push_further_figures(s: &mut String, r: &Report) {
    let shown: Vec<&str> = r.claims.iter().map(|c| c.id.as_str()).collect();
    let rest: Vec<&Figure> = r
        .figures
        .iter()
        .filter(|f| !shown.contains(&f.claim.as_str()))
        .collect();
    if !rest.is_empty() {
        s.push_str("<section aria-labelledby=\"figures\"><h2 id=\"figures\">Further figures</h2>");
        for f in rest {
            s.push_str(&figure_html(f));
        }
        s.push_str("</section>");
    }
}
