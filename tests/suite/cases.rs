//! The paper-reproduction check: every `paper_cases/*.yaml` is a test (`paper_case::<stem>`)
//! whose claim results are snapshotted under `snapshots/`; every `tests/bad_cases/*.yaml`
//! (`bad_case::<stem>`) must fail with the error its first line (`# expect: …`) names (a
//! trailing `…` there matches any rest). `build.rs` writes one test per file; the paper runs
//! once for the whole suite (`common::report`) and each case's test snapshots its share.
//!
//! The errata of the text are decided against the paper's LaTeX source (`ORTHOCHECK_PAPER`):
//! with it their snapshot is `case__source_errata`, without it `case__source_errata__unverified`
//! (each finding inconclusive), and likewise the restatements, which inherit their verdicts. Bad cases that start `# needs: the paper's source` are skipped,
//! with one line, without it.

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
    let case = cases::load_case::<orthocheck::claims::Check>(path)?;
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
    let verified = common::inputs()?.verification.is_some();
    let name = match case.check {
        // the restatements inherit the errata's verdicts
        orthocheck::claims::Check::SourceErrata(_) | orthocheck::claims::Check::Restatements(_)
            if !verified =>
        {
            format!("case__{stem}__unverified")
        }
        _ => format!("case__{stem}"),
    };
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
    let latex = if text.lines().nth(1) == Some("# needs: the paper's source") {
        let Some(source) = common::paper_source() else {
            common::skipped_without_source(&path.display().to_string());
            return Ok(());
        };
        let paper = cases::paper_of(&cases::CaseOrigin::Embedded)?;
        let record = paper.source.ok_or("paper.yml records no source")?;
        Some(cases::LatexSource::read(&source, &record)?)
    } else {
        None
    };
    match cases::load_case_with::<orthocheck::claims::Check>(path, latex.as_ref()) {
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
