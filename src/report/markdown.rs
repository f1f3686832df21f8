//! The report as Markdown, in the same order as the HTML page: provenance, the verdict counts
//! (linked to their lists), the contents in the paper's order, the claims at a glance (the
//! statistical claims and the errata printed → what is wrong → corrected), the claims by verdict, then every
//! section's claims in line order with links to the figures' SVG files (`<figure id>.svg`,
//! written beside `report.md`).

use std::collections::BTreeSet;
use std::fmt::Write as _;

use super::layout::{self, anchor, section_anchor, verdict_anchor, GROUPS};
use super::model::Report;
use super::values::{
    computed_text, power_phrase, printed_text, quantities_line, shown_text, tolerance_text,
    trials_of, value_text,
};
use super::words::{
    capitalised, correction_is_prose, defect_sentence, findings, holds_word, is_statistical,
    printed_side, Why, LISTS,
};
use super::{
    evidence,
    math::{math_text, prose_text_in, quote_text, Macros},
};
use crate::check::{ClaimResult, Quantity, Role, Value, Verdict};

/// What the Markdown renderer needs beside a claim: the ids to link, the claims in order, the
/// paper's macros.
struct Ctx<'a> {
    ordered: Vec<&'a ClaimResult>,
    ids: BTreeSet<String>,
    macros: Macros,
    labels: std::collections::BTreeMap<String, String>,
}

impl Ctx<'_> {
    fn empty() -> Ctx<'static> {
        Ctx {
            ordered: Vec::new(),
            ids: BTreeSet::new(),
            macros: Macros::default(),
            labels: Default::default(),
        }
    }

    /// Text with every claim id it mentions a link, and backslash macro names without their
    /// backslash.
    fn linked(&self, text: &str) -> String {
        layout::split_ids(text, &self.ids)
            .into_iter()
            .map(
                |(part, is_id)| match layout::target_of(&self.ordered, part) {
                    Some(c) if is_id => format!("[`{part}`](#{})", anchor(&c.id)),
                    _ => md_escape(&strip_backslashes(&layout::readable_labels(
                        part,
                        &self.labels,
                    ))),
                },
            )
            .collect()
    }

    /// A quote of the paper: running text or mathematics, label names readable.
    fn quote(&self, text: &str) -> String {
        md_escape(&layout::readable_labels(
            &quote_text(text, &self.macros),
            &self.labels,
        ))
    }

    fn value(&self, role: &Role, v: &Value, trials: Option<u64>) -> String {
        match v {
            Value::Formula { text } => md_escape(&math_text(text, &self.macros, true)),
            Value::Label { text } => self.linked(text),
            Value::Quote { text } => self.quote(text),
            v => md_escape(&shown_text(role, v, trials)),
        }
    }

    fn quantities(&self, qs: &[Quantity], trials: Option<u64>) -> String {
        quantities_line(qs, md_escape, |q| self.value(&q.role, &q.value, trials))
    }
}

/// `\faca` → `faca`: no raw LaTeX command reaches the reader.
fn strip_backslashes(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    let mut chars = s.chars().peekable();
    while let Some(c) = chars.next() {
        if c == '\\' && chars.peek().is_some_and(|n| n.is_ascii_alphabetic()) {
            continue;
        }
        out.push(c);
    }
    out
}

/// A claim's correction: words as running text, a formula as mathematics.
fn correction_md(ctx: &Ctx, c: &ClaimResult) -> String {
    let corr = c.correction.as_deref().unwrap_or("");
    if correction_is_prose(c) {
        md_escape(&layout::readable_labels(
            &prose_text_in(corr, &ctx.macros),
            &ctx.labels,
        ))
    } else {
        md_escape(&math_text(corr, &ctx.macros, true))
    }
}

/// Text for a Markdown line: no backslash command, no markup.
pub(crate) fn plain_text(s: &str) -> String {
    md_escape(&strip_backslashes(s))
}

/// Characters Markdown would read as markup inside a table cell or a line.
fn md_escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '|' => out.push_str("\\|"),
            '*' => out.push_str("\\*"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '\n' => out.push(' '),
            c => out.push(c),
        }
    }
    out
}

/// One claim as Markdown (on its own: no links to other claims, macros unexpanded).
pub fn claim_markdown(c: &ClaimResult) -> String {
    claim_in(&Ctx::empty(), c, 3, &[])
}

fn claim_in(
    ctx: &Ctx,
    c: &ClaimResult,
    level: usize,
    figures: &[&crate::check::figure::Figure],
) -> String {
    let trials = trials_of(c);
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<a id=\"{a}\"></a>\n\n{} [`{}`](#{a}) — **{}**\n",
        "#".repeat(level),
        c.id,
        c.verdict.name(),
        a = anchor(&c.id)
    );
    let _ = writeln!(
        s,
        "> {} (lines {}, §{})\n",
        ctx.quote(&c.quote),
        c.lines,
        c.section
    );
    if matches!(c.verdict, Verdict::Erratum | Verdict::Note)
        && let Why::Text(d) = defect_sentence(c)
    {
        let _ = writeln!(s, "- **defect:** {}", ctx.linked(&d));
    }
    let _ = writeln!(s, "- paper: {}", ctx.quantities(&c.printed, trials));
    let _ = writeln!(s, "- computed: {}", ctx.quantities(&c.computed, trials));
    if let Some(t) = &c.tolerance {
        let _ = writeln!(s, "- tolerance: {}", ctx.linked(&tolerance_text(t)));
    }
    let _ = writeln!(
        s,
        "- power: **{}**: {}",
        power_phrase(&c.power),
        ctx.linked(&c.power.detail)
    );
    if let Some(u) = &c.undecided {
        let _ = writeln!(s, "- undecided: {}", ctx.linked(u));
    }
    if c.correction.is_some() {
        let _ = writeln!(s, "- corrected: {}", correction_md(ctx, c));
    }
    let _ = writeln!(s, "- method: {}", ctx.linked(&c.evidence.method));
    let ev = evidence::layout(c);
    for d in &ev.rows {
        let _ = writeln!(
            s,
            "  - {}: {}",
            ctx.linked(&d.name),
            ctx.value(&d.role, &d.value, trials)
        );
    }
    for t in &ev.tables {
        let _ = writeln!(s, "\n  {}:\n", md_escape(&t.caption));
        let _ = writeln!(
            s,
            "  | {} | {} |",
            md_escape(&t.corner),
            t.columns
                .iter()
                .map(|c| md_escape(c))
                .collect::<Vec<_>>()
                .join(" | ")
        );
        let _ = writeln!(s, "  |---|{}", "---:|".repeat(t.columns.len()));
        for (head, cells) in &t.rows {
            let _ = writeln!(s, "  | {} | {} |", md_escape(head), cells.join(" | "));
        }
    }
    for f in figures {
        s.push_str(&figure_md(f));
    }
    s.push('\n');
    s
}

/// A figure: a link to its SVG file beside the report, and its caption.
fn figure_md(f: &crate::check::figure::Figure) -> String {
    format!(
        "\n![{}]({}.svg)\n\n*{}* — {}\n",
        md_escape(&strip_backslashes(&f.title)),
        f.id,
        md_escape(&strip_backslashes(&f.title)),
        md_escape(&strip_backslashes(&f.caption))
    )
}

fn count(r: &Report, v: Verdict) -> usize {
    r.summary.get(v.name()).copied().unwrap_or(0)
}

/// The first screen: each main result in one line, its standing and what carries it.
fn push_main_results(s: &mut String, r: &Report) {
    if r.main_results.is_empty() {
        return;
    }
    s.push_str(
        "## Do the main results stand?\n\nThe abstract's and the conclusions' claims, each with its standing: what the verdicts of everything it rests on, transitively, make of it (the rule: `docs/verdicts.md`; the argument map is in `report.html`).\n\n",
    );
    for (i, m) in r.main_results.iter().enumerate() {
        let c = crate::report::argument::carries(m);
        let ids: Vec<String> = c
            .ids
            .iter()
            .map(|id| format!("[`{id}`](#{})", anchor(id)))
            .collect();
        let _ = writeln!(
            s,
            "{}. **{}** “{}” (`{}`, §{}). {}{}{}",
            i + 1,
            m.standing.name(),
            m.quote,
            m.id,
            m.section,
            c.lead,
            ids.join(", "),
            c.tail
        );
    }
    s.push('\n');
}

/// The whole report as Markdown.
pub fn render(r: &Report) -> String {
    let ctx = Ctx {
        ordered: layout::ordered(r),
        ids: layout::linkable_ids(r),
        macros: Macros::parse(r.paper.as_ref().map_or("", |p| p.macros.as_str())),
        labels: r
            .paper
            .as_ref()
            .map(|p| p.labels.clone())
            .unwrap_or_default(),
    };
    let mut s = String::from("# Reproducibility report\n\n");
    if let Some(p) = &r.paper {
        let _ = writeln!(s, "*{}* — {}\n", p.title, p.author);
    }
    let p = &r.provenance;
    let _ = writeln!(
        s,
        "Produced by {}; revision {}; date {}; reproduce with `{}`.\n",
        r.tool,
        p.revision.as_deref().unwrap_or("unknown"),
        p.date.as_deref().unwrap_or("unknown"),
        p.command
    );
    if !p.transcription.is_empty() {
        let _ = writeln!(s, "{}\n", p.transcription);
    }
    push_main_results(&mut s, r);
    push_findings(&mut s, &ctx.ordered, &ctx.macros, &ctx.labels);
    push_summary(&mut s, r);
    push_contents(&mut s, r);
    push_glance(&mut s, &ctx);
    push_by_verdict(&mut s, &ctx);
    for sec in layout::sections(r) {
        let level = sec.depth + 1;
        let _ = writeln!(
            s,
            "<a id=\"{}\"></a>\n\n{} {}\n",
            sec.anchor(),
            "#".repeat(level),
            sec.heading()
        );
        for c in &sec.claims {
            let figs: Vec<_> = r.figures.iter().filter(|f| f.claim == c.id).collect();
            s.push_str(&claim_in(&ctx, c, level + 1, &figs));
        }
    }
    let shown: Vec<&str> = r.claims.iter().map(|c| c.id.as_str()).collect();
    let rest: Vec<_> = r
        .figures
        .iter()
        .filter(|f| !shown.contains(&f.claim.as_str()))
        .collect();
    if !rest.is_empty() {
        s.push_str("## Further figures\n");
        for f in rest {
            s.push_str(&figure_md(f));
        }
    }
    push_seeds(&mut s, r);
    s
}

fn push_summary(s: &mut String, r: &Report) {
    s.push_str("## Verdicts\n\n| | verdict | claims |\n|---|---|---:|\n");
    for (group, verdicts) in GROUPS {
        for (i, v) in verdicts.iter().enumerate() {
            let _ = writeln!(
                s,
                "| {} | [{}](#{}) | {} |",
                if i == 0 { group } else { "" },
                v.name(),
                verdict_anchor(*v),
                count(r, *v)
            );
        }
    }
    s.push('\n');
}

fn push_contents(s: &mut String, r: &Report) {
    s.push_str("## Contents\n\n- [At a glance](#glance)\n- [Claims by verdict](#by-verdict)\n");
    for sec in layout::sections(r) {
        let _ = writeln!(
            s,
            "{}- [{}](#{}) ({} claim{})",
            if sec.depth > 1 { "  " } else { "" },
            sec.heading(),
            sec.anchor(),
            sec.claims.len(),
            if sec.claims.len() == 1 { "" } else { "s" }
        );
    }
    s.push_str("- [Seeds of every case](#seeds)\n\n");
}

fn push_glance(s: &mut String, ctx: &Ctx) {
    s.push_str("<a id=\"glance\"></a>\n\n## At a glance\n\n");
    let stats: Vec<&&ClaimResult> = ctx.ordered.iter().filter(|c| is_statistical(c)).collect();
    if !stats.is_empty() {
        s.push_str(
            "### Statistical claims\n\n| claim | § | holds? | verdict | power |\n|---|---|---|---|---|\n",
        );
        for c in stats {
            let _ = writeln!(
                s,
                "| [`{}`](#{}) | {} | **{}** | {} | {} |",
                c.id,
                anchor(&c.id),
                c.section,
                holds_word(c.verdict),
                c.verdict.name(),
                md_escape(&power_phrase(&c.power))
            );
        }
        s.push('\n');
    }
    s.push_str(
        "### Errata: printed → what is wrong → corrected\n\n| claim | printed | what is wrong | corrected |\n|---|---|---|---|\n",
    );
    for c in ctx.ordered.iter().filter(|c| c.verdict == Verdict::Erratum) {
        let printed: Vec<String> = printed_side(c)
            .iter()
            .map(|q| match &q.value {
                Value::Formula { text } | Value::Label { text } => {
                    md_escape(&math_text(text, &ctx.macros, true))
                }
                Value::Quote { text } => ctx.quote(text),
                v => md_escape(&value_text(v)),
            })
            .collect();
        let corrected = if c.correction.is_some() {
            correction_md(ctx, c)
        } else {
            ctx.quantities(&c.computed, None)
        };
        let wrong = match defect_sentence(c) {
            Why::Text(d) => ctx.linked(&d),
            Why::ShouldRead(_) => String::new(),
        };
        let _ = writeln!(
            s,
            "| [`{}`](#{}) (§{}, line {}) | {} | {} | {} |",
            c.id,
            anchor(&c.id),
            c.section,
            c.lines,
            printed.join("; "),
            wrong,
            corrected
        );
    }
    s.push('\n');
    for (title, v) in LISTS {
        let claims: Vec<&&ClaimResult> = ctx.ordered.iter().filter(|c| c.verdict == v).collect();
        if claims.is_empty() {
            continue;
        }
        let _ = writeln!(s, "### {title}\n");
        for c in claims {
            let _ = writeln!(
                s,
                "- [`{}`](#{}) (§{}): {} — *{}*",
                c.id,
                anchor(&c.id),
                c.section,
                ctx.quantities(&c.computed, trials_of(c)),
                md_escape(&power_phrase(&c.power))
            );
        }
        s.push('\n');
    }
}

fn push_by_verdict(s: &mut String, ctx: &Ctx) {
    s.push_str("<a id=\"by-verdict\"></a>\n\n## Claims by verdict\n\n");
    for v in Verdict::ALL {
        let claims: Vec<&&ClaimResult> = ctx.ordered.iter().filter(|c| c.verdict == v).collect();
        let _ = writeln!(
            s,
            "<a id=\"{}\"></a>\n\n### {} ({})\n",
            verdict_anchor(v),
            v.name(),
            claims.len()
        );
        if claims.is_empty() {
            s.push_str("(none)\n");
        }
        for c in claims {
            let _ = writeln!(
                s,
                "- [`{}`](#{}) [§{}](#{}), line {}",
                c.id,
                anchor(&c.id),
                c.section,
                section_anchor(&c.section),
                c.lines
            );
        }
        s.push('\n');
    }
}

fn push_seeds(s: &mut String, r: &Report) {
    s.push_str("<a id=\"seeds\"></a>\n\n## Seeds of every case\n\n| case | file | seeds |\n|---|---|---|\n");
    for cs in &r.provenance.seeds {
        let _ = writeln!(
            s,
            "| {} | `{}` | {} |",
            cs.case,
            cs.file,
            cs.seeds
                .iter()
                .map(|x| x.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
}

/// The summary as Markdown.
fn push_findings(
    s: &mut String,
    ordered: &[&ClaimResult],
    macros: &Macros,
    labels: &std::collections::BTreeMap<String, String>,
) {
    let plain = |t: &str| plain_text(&layout::readable_labels(t, labels));
    s.push_str("## What was found\n\n");
    for f in findings(ordered) {
        let _ = writeln!(s, "**{}.** {}\n", capitalised(f.group), f.sentence);
        for (c, why) in &f.items {
            let text = match why {
                Why::Text(t) => plain(t),
                Why::ShouldRead(t) if correction_is_prose(c) => {
                    format!("should read: {}", plain_text(&prose_text_in(t, macros)))
                }
                Why::ShouldRead(t) => {
                    format!("should read {}", plain_text(&math_text(t, macros, true)))
                }
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

/// The errata list (Markdown): every claim result whose verdict is `erratum`, `contradicted`
/// or `holds-generically` (an exception the paper never names), in report order — what
/// `docs/errata.md` holds.
pub fn errata_markdown(claims: &[ClaimResult]) -> String {
    let mut s = String::from(
        "# Errata\n\nGenerated by `orthocheck audit --all --markdown` from `paper_cases/`; do not edit.\n\
         Every entry is decided by computation; the report gives the method and the evidence.\n",
    );
    for c in claims.iter().filter(|c| {
        matches!(
            c.verdict,
            Verdict::Erratum | Verdict::Contradicted | Verdict::HoldsGenerically
        )
    }) {
        let _ = write!(
            s,
            "\n## `{}` — {} (§{}, lines {})\n\n- printed: {}\n",
            c.id,
            c.verdict.name(),
            c.section,
            c.lines,
            printed_text(c)
        );
        for d in c
            .evidence
            .details
            .iter()
            .filter(|d| matches!(d.role, Role::Defect | Role::ShouldBe))
        {
            let _ = writeln!(s, "- {}: {}", d.name, value_text(&d.value));
        }
        if let Some(corr) = &c.correction {
            let _ = writeln!(s, "- corrected: {corr}");
        }
        let _ = writeln!(s, "- found: {}", computed_text(c));
    }
    s
}
