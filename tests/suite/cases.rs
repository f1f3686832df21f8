//! The paper-reproduction check: every `paper_cases/*.yaml` is a test (`paper_case::<stem>`)
//! whose claim results are snapshotted under `snapshots/`; every `tests/bad_cases/*.yaml`
//! (`bad_case::<stem>`) must fail with the error its first line (`# expect: …`) names (a
//! trailing `…` there matches any rest). `build.rs` writes one test per file; the paper runs
//! once for the whole suite (`common::report`) and each case's test snapshots its share.
//!
//! The verdicts do not depend on the paper's LaTeX source: a run with it and one without
//! give the same snapshots (`transcription.rs` compares them).

use std::path::Path;

use orthocheck::{cases, check, Error};

use crate::common;

include!(concat!(env!("OUT_DIR"), "/case_tests.rs"));

/// What a case test returns: its failure, if any, as an error.
type TestResult = Result<(), Box<dyn std::error::Error>>;

fn snapshot_settings() -> insta::Settings {
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path(concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"));
    s.set_prepend_module_to_snapshot(false);
    s.set_omit_expression(true);
    s
}

/// One generated test: `test` of the case file `path`, its failure a panic naming the file.
fn passes(path: &str, test: fn(&Path) -> TestResult) {
    if let Err(e) = test(Path::new(path)) {
        panic!("{path}: {e}");
    }
}

fn paper_case(path: &Path) -> TestResult {
    let case = cases::load_case::<orthocheck::claims::CaseCheck>(path)?;
    // one run of the whole paper serves every case (the restatements need all the others)
    let results: Vec<&check::ClaimResult> = common::report()?
        .claims
        .iter()
        .filter(|r| r.case == case.id)
        .collect();
    assert!(!results.is_empty(), "{} produced no claim results", case.id);
    let stem = path
        .file_stem()
        .and_then(|s| s.to_str())
        .ok_or("case file name is not UTF-8")?;
    let json = serde_json::to_string_pretty(&results)?;
    let name = format!("case__{stem}");
    snapshot_settings().bind(|| insta::assert_snapshot!(name, json));
    Ok(())
}

fn bad_case(path: &Path) -> TestResult {
    let text = std::fs::read_to_string(path)?;
    let expected = text
        .lines()
        .next()
        .and_then(|l| l.strip_prefix("# expect: "))
        .ok_or("a bad case must start with '# expect: …'")?;
    match cases::load_case::<orthocheck::claims::CaseCheck>(path) {
        Ok(_) => Err(format!("{} loaded, but it must fail", path.display()).into()),
        Err(e @ Error::Input { .. }) => {
            let shown = e.to_string();
            let after_file = shown
                .strip_prefix(&path.display().to_string())
                .ok_or("the error does not start with the file name")?;
            // a trailing "…" makes the expectation a prefix (lists that grow with the format)
            match expected.strip_suffix('…') {
                Some(prefix) => assert!(
                    after_file.starts_with(prefix),
                    "error for {}: {after_file}",
                    path.display()
                ),
                None => assert_eq!(after_file, expected, "error for {}", path.display()),
            }
            Ok(())
        }
        Err(e) => Err(format!("{}: wrong kind of error: {e}", path.display()).into()),
    }
}
