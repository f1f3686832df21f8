//! The Markdown and HTML renderers on a small fixed set of claims (not the whole report).

use orthocheck::check::figure::{Figure, Layer, Plot, Shape, Style};
use orthocheck::check::{
    ClaimResult, Evidence, Power, Quantity, Tolerance, ToleranceSource, Value, Verdict,
};
use orthocheck::report::{claim_markdown, html, Provenance, Report};

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
        computed: vec![Quantity::new("computed", computed)],
        tolerance: Some(Tolerance::bound(
            0.005,
            ToleranceSource::PrintedPrecision,
            "half a unit of the second decimal",
        )),
        power: Power::interval(3.995, 4.005, 4.0, 0.005, "printed 4 ± 0.005"),
        correction: None,
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

#[test]
fn html_renderer() {
    let figure = Figure {
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
    };
    let provenance = Provenance {
        revision: Some("0123456789ab".into()),
        date: Some("2026-11-22".into()),
        command: "cargo run --release -- report".into(),
        seeds: Vec::new(),
    };
    let paper = orthocheck::cases::load_paper(std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/paper_cases"
    )))
    .unwrap();
    let report = Report::with(claims(), vec![figure], provenance).with_paper(paper);
    let page = html::render(&report);
    settings().bind(|| insta::assert_snapshot!("render__html", page));
}
