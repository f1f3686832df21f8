use std::path::Path;

use orthocheck::check;

use crate::common;

#[test]
fn docs_errata_is_up_to_date() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let all = common::cases().unwrap();
    if common::inputs().unwrap().verification.is_none() {
        // the errata of the text are decided only against the source
        common::skipped_without_source("docs_errata_is_up_to_date");
        return;
    }
    let report = common::report().unwrap();
    let fresh = orthocheck::report::errata_markdown(&report.claims);
    let committed = std::fs::read_to_string(root.join("docs/errata.md")).unwrap_or_default();
    assert!(
        fresh == committed,
        "docs/errata.md is out of date: run `cargo run --release -- audit --all --markdown > docs/errata.md`"
    );
    // the audit's errata stay found
    let items =
        orthocheck::claims::audit::audit_all(all, orthocheck::claims::audit::Wanted::All).unwrap();
    assert!(
        items
            .iter()
            .filter(|(r, _)| r.verdict == check::Verdict::Erratum)
            .count()
            >= 11
    );
}

/// The audit computes what is asked: one item (or one claim's items) alone gives exactly
/// what the whole audit gives for it, the names earlier formulas define (A_c for the
/// substitution, f_b for Δ_b) read but those formulas not judged.
#[test]
fn one_item_of_the_audit_is_its_line_in_the_whole() {
    use orthocheck::claims::audit::{audit_all, Wanted};
    let all = common::cases().unwrap();
    let whole = audit_all(all, Wanted::All).unwrap();
    for id in [
        "p3f3-differences/equation-1",
        "p3f3-a2-b2/a-squared/expanded",
        "p3f3-quadratic/substitution",
        "appA-coefficients/f_b/expanded",
        "appA-quartic/delta_b",
        "appA-quartic/constant-symbols",
        "p3f3-a2-b2",
    ] {
        let one: Vec<_> = audit_all(all, Wanted::Id(id))
            .unwrap()
            .into_iter()
            .map(|(r, _)| r)
            .collect();
        let expected: Vec<_> = whole
            .iter()
            .filter(|(r, _)| r.id == id || r.claim == id)
            .map(|(r, _)| r.clone())
            .collect();
        assert!(!expected.is_empty(), "{id} is an audit item or claim");
        assert_eq!(one, expected, "{id}");
    }
}

/// `orthocheck audit` reads the case files of the audited kinds alone: their items are
/// those of every case (no other kind has audit items).
#[test]
fn the_audit_reads_the_audited_kinds_alone() {
    use orthocheck::cases::{load_cases_of, CaseOrigin, Kinds};
    use orthocheck::claims::audit::{audit_all, Wanted};
    let kinds = orthocheck::claims::audited_kinds();
    assert_eq!(kinds, ["twofold_squared", "formula_audit", "source_errata"]);
    let origin = CaseOrigin::Folder(Path::new(env!("CARGO_MANIFEST_DIR")).join("paper_cases"));
    let some =
        load_cases_of::<orthocheck::claims::CaseCheck>(&origin, Kinds::Only(&kinds)).unwrap();
    assert_eq!(some.len(), kinds.len());
    let ids = |cases: &[orthocheck::claims::PaperCase]| -> Vec<String> {
        let items = audit_all(cases, Wanted::All).unwrap();
        items.into_iter().map(|(r, _)| r.id).collect()
    };
    assert_eq!(ids(&some), ids(common::cases().unwrap()));
}

/// `errata.patch` applies to the source with `patch`; the patched source then holds the
/// corrected formulas where the errata stood (read by the normaliser that verifies every
/// quote), the audit verifies each of them as printed, and every other quote of the
/// transcription still stands at its lines.
#[test]
fn the_paper_corrected_applies_and_its_formulas_verify() {
    use orthocheck::cases::{self, Canonical, LatexSource, SourceText};
    let inputs = common::inputs().unwrap();
    let Some(src) = &inputs.source else {
        common::skipped_without_source("the_paper_corrected_applies_and_its_formulas_verify");
        return;
    };
    let report = common::report().unwrap();
    let errata: Vec<&check::ClaimResult> = report
        .claims
        .iter()
        .filter(|r| r.verdict == check::Verdict::Erratum)
        .collect();
    for e in &errata {
        assert!(
            inputs.corrections.iter().any(|c| c.result == e.id),
            "{}: no correction in corrections.yml",
            e.id
        );
    }
    let patch = orthocheck::report::errata_patch(
        &src.text,
        "paper.tex",
        &inputs.corrections,
        &report.claims,
    )
    .unwrap();
    assert_eq!(patch.matches("\n@@ ").count(), 20, "{patch}");
    let dir = tempfile::tempdir().unwrap();
    let tex = dir.path().join("paper.tex");
    std::fs::copy(&src.path, &tex).unwrap();
    std::fs::write(dir.path().join("errata.patch"), &patch).unwrap();
    let out = std::process::Command::new("patch")
        .current_dir(dir.path())
        .args(["paper.tex", "errata.patch"])
        .output()
        .expect("`patch` runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stdout)
    );
    let lines: Vec<String> = std::fs::read_to_string(&tex)
        .unwrap()
        .lines()
        .map(str::to_string)
        .collect();
    assert_eq!(lines.len(), src.text.lines.len());
    let patched = SourceText { lines };
    // nothing else changes: only the errata's own quotes move out of place
    let latex = LatexSource {
        path: tex.clone(),
        sha256: src.sha256.clone(),
        text: patched.clone(),
    };
    let v = cases::verify(
        &cases::CaseOrigin::Embedded,
        &inputs.paper,
        &latex,
        &inputs.cases,
    )
    .unwrap();
    let changed: Vec<usize> = (0..patched.lines.len())
        .filter(|&i| patched.lines[i] != src.text.lines[i])
        .map(|i| i + 1)
        .collect();
    // a quote that moves is one whose lines the patch changed (an erratum's own quote, or a
    // quote of another claim that holds the words corrected)
    for d in &v.disagreements {
        let claim = d.claim.as_deref().unwrap_or("");
        let touched = report.claims.iter().filter(|r| r.claim == claim).any(|r| {
            cases::parse_lines(&r.lines)
                .is_some_and(|(a, b)| changed.iter().any(|l| (a..=b).contains(l)))
        });
        assert!(touched, "{d}");
    }
    assert!(v.disagreements.len() >= errata.len() / 2);
    // the corrected formulas stand in the patched source at the errata's lines, the printed
    // ones no longer do
    let canon = Canonical::of_source(&patched);
    let before = Canonical::of_source(&src.text);
    let formulas = formula_errata(&inputs.cases);
    assert_eq!(formulas.len(), 4);
    for (id, _, printed, corrected) in &formulas {
        // near a line its correction changed (a display's breaks spread one formula)
        let hunks: Vec<(usize, usize)> = inputs
            .corrections
            .iter()
            .filter(|c| &c.result == id)
            .filter_map(|c| c.lines.as_deref().and_then(cases::parse_lines))
            .collect();
        assert!(!hunks.is_empty(), "{id}");
        let within = |r: &(usize, usize)| hunks.iter().any(|h| r.0 <= h.1 + 3 && r.1 + 3 >= h.0);
        assert!(
            canon.ranges_of(corrected).iter().any(within),
            "{id}: {corrected}"
        );
        if let Some(p) = printed {
            assert!(before.ranges_of(p).iter().any(within), "{id}: {p}");
            assert!(
                !canon.ranges_of(p).iter().any(within),
                "{id}: {p} still stands"
            );
        }
    }
    audit_as_printed(&formulas, &report.claims);
}

/// The formula errata of the audit: id, lines, printed form (when transcribed), corrected.
type FormulaErratum = (String, String, Option<String>, String);

fn formula_errata(all: &[orthocheck::claims::PaperCase]) -> Vec<FormulaErratum> {
    let text = all
        .iter()
        .find(|c| c.check.name() == "formula_audit")
        .and_then(|c| c.file.clone())
        .map(|f| std::fs::read_to_string(f).unwrap())
        .unwrap_or_else(|| {
            std::fs::read_to_string(
                Path::new(env!("CARGO_MANIFEST_DIR")).join("paper_cases/formula_audit.yaml"),
            )
            .unwrap()
        });
    let doc: serde_json::Value =
        orthocheck::cases::parse_yaml(&text, Path::new("formula_audit.yaml")).unwrap();
    let items = doc["check"]["formula_audit"]["formulas"]
        .as_array()
        .unwrap()
        .clone();
    items
        .iter()
        .filter(|f| f.get("corrected").is_some())
        .map(|f| {
            (
                format!(
                    "{}/{}",
                    f["claim"]["claim"].as_str().unwrap(),
                    f["id"].as_str().unwrap()
                ),
                f["claim"]["lines"].as_str().unwrap().to_string(),
                f.get("printed")
                    .and_then(|p| p.as_str())
                    .map(str::to_string),
                f["corrected"].as_str().unwrap().to_string(),
            )
        })
        .collect()
}

/// The audit's case with each erratum printed as corrected (no defect recorded): every one
/// of them is then identity-verified, and every other result of the case keeps its verdict.
fn audit_as_printed(formulas: &[FormulaErratum], before: &[check::ClaimResult]) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("paper_cases/formula_audit.yaml")).unwrap();
    let mut out: Vec<String> = Vec::new();
    let mut current: Option<&FormulaErratum> = None;
    for line in text.lines() {
        let t = line.trim_start();
        if t.starts_with("- ") {
            current = None;
        }
        if let Some(id) = t.strip_prefix("id: ") {
            current = formulas.iter().find(|f| f.0.ends_with(&format!("/{id}")));
            if let Some(f) = current {
                out.push(line.to_string());
                let indent = &line[..line.len() - t.len()];
                out.push(format!("{indent}printed: {:?}", f.3));
                continue;
            }
        }
        let dropped = ["printed: ", "printed_text: ", "defect: ", "corrected: "];
        if current.is_some() && dropped.iter().any(|d| t.starts_with(d)) {
            continue;
        }
        out.push(line.to_string());
    }
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("formula_audit.yaml");
    std::fs::write(&file, out.join("\n") + "\n").unwrap();
    let case = orthocheck::cases::load_case::<orthocheck::claims::CaseCheck>(&file).unwrap();
    let (results, _) = orthocheck::claims::run_case_full(&case, &[]).unwrap();
    for r in &results {
        let was = before.iter().find(|b| b.id == r.id).unwrap();
        if formulas.iter().any(|f| f.0 == r.id) {
            assert_eq!(r.verdict, check::Verdict::IdentityVerified, "{}", r.id);
        } else {
            assert_eq!(r.verdict, was.verdict, "{}", r.id);
        }
    }
}
