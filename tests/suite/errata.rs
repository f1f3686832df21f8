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
    let items = orthocheck::claims::audit::audit_all(all).unwrap();
    assert!(
        items
            .iter()
            .filter(|(r, _)| r.verdict == check::Verdict::Erratum)
            .count()
            >= 11
    );
}
