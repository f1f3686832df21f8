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
