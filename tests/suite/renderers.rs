//! The Markdown and HTML renderers on a small fixed set of claims, and the properties every
//! page of the whole paper must have: links that resolve, headings in order, no raw LaTeX,
//! colours that pass WCAG AA, the paper file true to the LaTeX source.

use orthocheck::check::figure::{Figure, Layer, Plot, Shape, Style};
use orthocheck::check::{
    ClaimResult, Evidence, Power, Quantity, Role, Tolerance, ToleranceSource, Value, Verdict,
};
use orthocheck::report::{claim_markdown, html, Provenance, Report};

use std::collections::BTreeSet;

use orthocheck::report::style::{
    badge_background, contrast_ratio, parse_colour, BADGE_TEXT, GRAPHIC_CONTRAST, TEXT_CONTRAST,
};

fn claims() -> Vec<ClaimResult> {
    let claim = |id: &str, section: &str, verdict: Verdict, computed: &str| ClaimResult {
        id: id.into(),
        claim: id.split('/').next().unwrap_or(id).into(),
        case: "fixture".into(),
        section: section.into(),
        lines: "1-2".into(),
        quote: "a quote with <markup> & \"quotes\"".into(),
        verdict,
        printed: vec![Quantity::new("squares", Value::reals(&[4.0, 9.0, 16.0]))],
        computed: vec![Quantity::with_role("computed", computed, Role::ValueOnly)],
        tolerance: Some(Tolerance::bound(
            0.005,
            ToleranceSource::PrintedPrecision,
            "half a unit of the second decimal",
        )),
        power: Power::interval(3.995, 4.005, 4.0, 0.005, "printed 4 ± 0.005"),
        correction: None,
        undecided: None,
        rests_on: Vec::new(),
        evidence: Evidence::new("a method").with("a detail", "a value"),
    };
    vec![
        claim("ex2-body", "2", Verdict::Reproduced, "4, 9, 16"),
        claim(
            "p3f3-differences/equation-1",
            "2.2",
            Verdict::Erratum,
            "the corrected formula holds",
        ),
        claim(
            "appA-quartic/equation",
            "A",
            Verdict::IdentityVerified,
            "exact over ℚ",
        ),
        claim(
            "p4f3-unique/planar-body",
            "4",
            Verdict::Contradicted,
            "rank 5 of 6",
        ),
    ]
    .into_iter()
    .map(|mut c| {
        if c.id == "p3f3-differences/equation-1" {
            c.lines = "208-214".into();
            c.printed = vec![Quantity::with_role(
                "as printed (LaTeX)",
                Value::formula("\\diffCst{1} = (\\facCst{1},$$ $$-\\facCst{3})"),
                Role::AsPrinted,
            )];
            c.correction = Some("d_Cst1 = facCst1 - facCst3".into());
        }
        if c.id == "ex2-body" {
            c.evidence = Evidence::new("contradicted by p4f3-unique/planar-body")
                .with_role("trials per model", Value::count(10_000), Role::Trials)
                .with_quantiles(
                    "A",
                    "5/50/95 % quantiles",
                    &[0.05, 0.5, 0.95],
                    &[0.0123456, 0.5, 1.23456],
                )
                .with_cell("A", "mean over the trials", 0.2345678)
                .with_quantiles(
                    "B",
                    "5/50/95 % quantiles",
                    &[0.05, 0.5, 0.95],
                    &[0.01, 0.6, 2.0],
                )
                .with_cell("B", "mean over the trials", 0.3);
        }
        c
    })
    .collect()
}

fn paper() -> orthocheck::cases::Paper {
    orthocheck::cases::load_paper(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/paper_cases"
    )))
    .unwrap()
}

fn fixture_report() -> Report {
    let provenance = Provenance {
        revision: Some("0123456789ab".into()),
        date: Some("2026-11-22".into()),
        command: "cargo run --release -- report".into(),
        transcription: orthocheck::cases::unverified_sentence(),
        seeds: Vec::new(),
    };
    Report::with(claims(), vec![fixture_figure()], provenance).with_paper(paper())
}

fn settings() -> insta::Settings {
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path(concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"));
    s.set_prepend_module_to_snapshot(false);
    s.set_omit_expression(true);
    s
}

#[test]
fn markdown_renderer() {
    let md: String = claims().iter().map(claim_markdown).collect();
    settings().bind(|| insta::assert_snapshot!("render__markdown", md));
}

fn fixture_figure() -> Figure {
    Figure {
        id: "fig-fixture".into(),
        claim: "ex2-body".into(),
        title: "a triangle".into(),
        caption: "printed and computed".into(),
        panels: vec![Plot::image(
            "frame 1",
            vec![
                Layer::new(
                    "printed",
                    Shape::Polygon,
                    Style::Printed,
                    vec![[0.0, 0.0], [2.0, 0.0], [0.5, 1.5]],
                )
                .labelled(&["P", "Q", "R"]),
                Layer::new(
                    "computed",
                    Shape::Polygon,
                    Style::Computed,
                    vec![[0.0, 0.0], [2.01, 0.0], [0.5, 1.49]],
                ),
            ],
        )],
    }
}

#[test]
fn html_renderer() {
    let page = html::render(&fixture_report());
    settings().bind(|| insta::assert_snapshot!("render__html", page));
}

#[test]
fn markdown_report_renderer() {
    let md = fixture_report().to_markdown();
    settings().bind(|| insta::assert_snapshot!("render__markdown_report", md));
}

/// Every `attr="#x"` of `page` and whether an `id="x"` exists for it.
fn dangling_fragments(page: &str, attr: &str, id: &str) -> Vec<String> {
    let ids: BTreeSet<&str> = page
        .split(id)
        .skip(1)
        .filter_map(|r| r.split('"').next())
        .collect();
    page.split(attr)
        .skip(1)
        .filter_map(|r| r.split(['"', ')']).next())
        .filter(|x| !ids.contains(x))
        .map(str::to_string)
        .collect()
}

/// `\name` commands outside `<script>` and `<style>`.
fn raw_latex(page: &str) -> Vec<String> {
    let mut text = String::new();
    let mut rest = page;
    while let Some(at) = rest.find("<s") {
        text.push_str(&rest[..at]);
        let after = &rest[at..];
        let close = if after.starts_with("<script") {
            "</script>"
        } else if after.starts_with("<style") {
            "</style>"
        } else {
            text.push_str("<s");
            rest = &after[2..];
            continue;
        };
        rest = after.find(close).map_or("", |e| &after[e + close.len()..]);
    }
    text.push_str(rest);
    orthocheck::report::math::raw_macros(&text)
        .into_iter()
        .map(str::to_string)
        .collect()
}

/// Heading levels never skip one on the way down.
fn heading_jumps(page: &str) -> Vec<(usize, usize)> {
    let mut last = 0usize;
    let mut jumps = Vec::new();
    for part in page.split("<h").skip(1) {
        let Some(level) = part.chars().next().and_then(|c| c.to_digit(10)) else {
            continue;
        };
        let level = level as usize;
        if !part[1..].starts_with([' ', '>']) {
            continue;
        }
        if level > last + 1 {
            jumps.push((last, level));
        }
        last = level;
    }
    jumps
}

#[test]
fn the_fixture_page_links_resolve_and_shows_no_latex() {
    let page = html::render(&fixture_report());
    assert_eq!(
        dangling_fragments(&page, "href=\"#", "id=\""),
        Vec::<String>::new()
    );
    assert_eq!(raw_latex(&page), Vec::<String>::new());
    assert_eq!(heading_jumps(&page), Vec::<(usize, usize)>::new());
    // the id in the method is a link; the erratum shows both sides readably
    assert!(page.contains(
        "<a href=\"#claim-p4f3-unique-planar-body\"><code>p4f3-unique/planar-body</code></a>"
    ));
    assert!(page.contains("d<sub>Cst,1</sub> = ((a₁⁴+b₁⁴+c₁⁴"), "{page}");
    assert!(page.contains("<meta name=\"viewport\""));
    assert!(page.contains("@media print"));
}

/// The page of the whole paper: every in-page link lands on an id, the headings descend one
/// level at a time, no LaTeX command is left, the sections are in the paper's order with
/// their titles, and the Markdown links its figures' SVG files and its own anchors.
#[test]
fn the_paper_report_navigates() {
    let r = crate::common::report().unwrap();
    let r = r.clone().with_paper(paper());
    let page = html::render(&r);
    assert_eq!(
        dangling_fragments(&page, "href=\"#", "id=\""),
        Vec::<String>::new()
    );
    assert_eq!(raw_latex(&page), Vec::<String>::new());
    assert_eq!(heading_jumps(&page), Vec::<(usize, usize)>::new());
    let titles: Vec<usize> = paper()
        .sections
        .iter()
        .map(|s| {
            page.find(&format!("id=\"section-{}\"", s.number.replace('.', "-")))
                .unwrap_or_else(|| panic!("section {} missing", s.number))
        })
        .collect();
    assert!(
        titles.windows(2).all(|w| w[0] < w[1]),
        "sections out of order"
    );
    assert!(page.contains("§2.2 Structure and motion for 3 point correspondences"));
    let md = r.to_markdown();
    assert_eq!(
        dangling_fragments(&md, "](#", "<a id=\""),
        Vec::<String>::new()
    );
    for f in &r.figures {
        assert!(
            md.contains(&format!("]({}.svg)", f.id)),
            "{} not linked",
            f.id
        );
    }
    assert!(md.contains("revision") && md.contains("Seeds of every case"));
    assert!(md.contains("### Errata: printed → what is wrong → corrected"));
    assert!(!md.contains("\\facCst") && !md.contains("\\diffCst"));
}

#[test]
fn every_badge_and_series_colour_passes_wcag_aa() {
    use orthocheck::check::figure::Style;
    let white = [255, 255, 255];
    let text = parse_colour(BADGE_TEXT).unwrap();
    for v in Verdict::ALL {
        let bg = parse_colour(badge_background(v)).unwrap();
        let ratio = contrast_ratio(bg, text);
        assert!(ratio >= TEXT_CONTRAST, "badge {}: {ratio:.2}:1", v.name());
    }
    // every style a figure can draw
    for st in Style::ALL {
        let css = orthocheck::report::svg::css_colour(st);
        let c = parse_colour(&css).unwrap_or_else(|| panic!("{css} does not parse"));
        let ratio = contrast_ratio(c, white);
        assert!(
            ratio >= GRAPHIC_CONTRAST,
            "series {st:?} ({css}): {ratio:.2}:1"
        );
    }
}

/// The section titles and macro definitions of `paper_cases/paper.yml` are the LaTeX
/// source's own, and every quote's lines lie within it (`cases::verify`, run by the shared
/// inputs when the source is given).
#[test]
fn the_paper_file_is_true_to_the_source() {
    let inputs = crate::common::inputs().unwrap();
    let Some(v) = &inputs.verification else {
        crate::common::skipped_without_source("the_paper_file_is_true_to_the_source");
        return;
    };
    assert!(v.sections >= 14, "{} sections", v.sections);
    assert!(v.macros >= 20, "{} macros", v.macros);
    // every erratum's quote is verbatim (the loader refuses it otherwise); most others too
    assert!(v.quotes >= 150 && v.verbatim * 2 > v.quotes, "{v:?}");
    let macros = orthocheck::report::math::Macros::parse(&inputs.paper.macros);
    assert_eq!(macros.len(), v.macros);
}

/// A source with another hash is refused, naming both hashes.
#[test]
fn another_source_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let fake = dir.path().join("paper.tex");
    std::fs::write(&fake, "\\section{Introduction}\n").unwrap();
    let origin = orthocheck::cases::CaseOrigin::Embedded;
    let e = orthocheck::cases::load_inputs::<orthocheck::claims::CaseCheck>(&origin, Some(&fake))
        .unwrap_err()
        .to_string();
    assert!(
        e.contains("not the paper's source") && e.contains("SHA-256"),
        "{e}"
    );
}

/// What a reader sees of a page: the text outside tags, `<style>` and `<script>`, entities
/// decoded.
fn visible_text(page: &str) -> String {
    let mut text = String::new();
    let mut rest = page;
    while let Some(at) = rest.find('<') {
        text.push_str(&rest[..at]);
        let after = &rest[at..];
        let skip_to = if after.starts_with("<style") {
            "</style>"
        } else if after.starts_with("<script") {
            "</script>"
        } else {
            ">"
        };
        text.push(' ');
        rest = after
            .find(skip_to)
            .map_or("", |e| &after[e + skip_to.len()..]);
    }
    text.push_str(rest);
    text.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&#39;", "'")
        .replace("&amp;", "&")
}

/// Every raw piece of TeX or non-finite number a reader could meet in `text`.
fn unreadable(text: &str, labels: &[&String]) -> Vec<String> {
    let mut found = Vec::new();
    for bad in ["$", "\\", "20\\%"] {
        if text.contains(bad) {
            let at = text.find(bad).unwrap_or(0);
            let from = text[..at].char_indices().rev().nth(40).map_or(0, |c| c.0);
            found.push(format!(
                "{bad:?} in …{}…",
                &text[from..(at + 1).min(text.len())]
            ));
        }
    }
    for word in text.split(|c: char| !c.is_alphanumeric()) {
        if matches!(word, "inf" | "NaN") || labels.iter().any(|l| l.as_str() == word) {
            found.push(word.to_string());
        }
    }
    found
}

/// The paper's page and its Markdown show no raw TeX (no `$`, no backslash, no `\label` name
/// of the paper) and no non-finite number.
#[test]
fn the_paper_report_has_no_raw_tex_and_no_non_finite_number() {
    let r = crate::common::report().unwrap();
    let paper = r.paper.clone().unwrap_or_else(paper);
    let labels: Vec<&String> = paper.labels.keys().collect();
    assert!(labels.len() >= 10, "{} label names", labels.len());
    let page = visible_text(&html::render(r));
    assert_eq!(
        unreadable(&page, &labels),
        Vec::<String>::new(),
        "in report.html"
    );
    // the Markdown: outside its code spans and link targets
    let md = r.to_markdown();
    let prose: String = md.split('`').step_by(2).collect::<Vec<_>>().join(" ");
    let prose = visible_text(&prose.replace("\\|", "|").replace("\\*", "*"));
    let without_links: String = prose
        .split("](")
        .enumerate()
        .map(|(i, p)| match p.split_once(')') {
            Some((_, after)) if i > 0 => after,
            _ => p,
        })
        .collect();
    assert_eq!(
        unreadable(&without_links, &labels),
        Vec::<String>::new(),
        "in report.md"
    );
    // the guard catches numbers already turned into text: a non-finite Real is a number
    let nan = orthocheck::check::Value::real(f64::NAN);
    assert!(orthocheck::report::finite::first_non_finite(&nan).is_some());
}

/// The page's shape: every block tag (tables, rows, cells, lists, sections) with its class;
/// no text and no inline markup (a name may carry a link or mathematics of its own).
fn skeleton(html: &str) -> Vec<String> {
    const BLOCKS: [&str; 22] = [
        "table",
        "tr",
        "th",
        "td",
        "caption",
        "dl",
        "dt",
        "dd",
        "ul",
        "li",
        "details",
        "summary",
        "div",
        "section",
        "article",
        "figure",
        "h2",
        "h3",
        "h4",
        "p",
        "blockquote",
        "svg",
    ];
    html.split('<')
        .skip(1)
        .filter_map(|t| {
            let tag = t.split('>').next().unwrap_or("");
            let name = tag.split_whitespace().next().unwrap_or("");
            let bare = name.trim_start_matches('/');
            BLOCKS.contains(&bare).then(|| {
                let class = tag
                    .split("class=\"")
                    .nth(1)
                    .and_then(|c| c.split('"').next())
                    .unwrap_or("");
                format!("{name}.{class}")
            })
        })
        .collect()
}

/// Rename every printed, computed and evidence quantity of `c` ("quantity 1", …); how many.
fn rename_quantities(c: &mut orthocheck::check::ClaimResult) -> usize {
    let mut n = 0;
    for q in c
        .printed
        .iter_mut()
        .chain(c.computed.iter_mut())
        .chain(c.evidence.details.iter_mut())
    {
        n += 1;
        q.name = format!("quantity {n}");
    }
    n
}

/// Renaming every printed, computed and evidence quantity of the paper's report changes
/// words only: the renderers read roles, never names, so the page keeps its shape (tables,
/// rows, the printed side of each erratum, the digits each value is shown with).
#[test]
fn relabelling_the_evidence_changes_words_not_layout() {
    let report = crate::common::report().expect("the paper runs");
    let mut renamed = report.clone();
    let n = renamed
        .claims
        .iter_mut()
        .map(rename_quantities)
        .sum::<usize>();
    assert!(n > 1000, "the report has its quantities ({n})");
    let (before, after) = (html::render(report), html::render(&renamed));
    assert_ne!(before, after, "the names are on the page");
    assert_eq!(skeleton(&before), skeleton(&after));
    // Markdown: the same lines, each of the same kind (heading, list item, table row, text)
    let kind = |l: &str| -> String {
        l.chars()
            .take_while(|c| matches!(c, ' ' | '-' | '|' | '#' | '>'))
            .collect()
    };
    let (mb, ma) = (report.to_markdown(), renamed.to_markdown());
    let kinds = |md: &str| md.lines().map(kind).collect::<Vec<_>>();
    assert_eq!(kinds(&mb), kinds(&ma));
}

/// The judges that read other claims (the restatements of the discussion and the
/// conclusions) read their ids and verdicts, never their words: with every quantity, method
/// and power statement of the earlier results renamed, each restatement keeps its verdict.
#[test]
fn restated_verdicts_are_stable_under_relabelling() {
    let report = crate::common::report().expect("the paper runs");
    let cases = crate::common::cases().expect("the cases load");
    let restating: Vec<_> = cases.iter().filter(|c| c.check.kind().restates()).collect();
    assert!(!restating.is_empty(), "the paper has restatements");
    let restated_ids: std::collections::BTreeSet<&str> = restating
        .iter()
        .flat_map(|c| report.claims.iter().filter(move |r| r.case == c.id))
        .map(|r| r.id.as_str())
        .collect();
    let mut earlier: Vec<_> = report
        .claims
        .iter()
        .filter(|r| !restated_ids.contains(r.id.as_str()))
        .cloned()
        .collect();
    for (n, c) in earlier.iter_mut().enumerate() {
        rename_quantities(c);
        c.power.detail = format!("control {n}");
        c.evidence.method = format!("method {n}");
    }
    let mut checked = 0;
    for case in restating {
        for r in orthocheck::claims::run_case_full(case, &earlier).unwrap().0 {
            let before = report.claims.iter().find(|c| c.id == r.id).unwrap();
            assert_eq!(r.verdict, before.verdict, "{}", r.id);
            checked += 1;
        }
    }
    assert_eq!(checked, restated_ids.len());
}
