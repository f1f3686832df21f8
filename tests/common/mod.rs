//! The paper, run once per test binary: every test that needs claim results reads them from
//! here, so one `cargo test` reproduces the paper once per binary instead of once per test.
//!
//! The paper's LaTeX source is optional: `ORTHOCHECK_PAPER` names it. Tests that need it run
//! when it is named and print one line when they skip; with `ORTHOCHECK_REQUIRE_PAPER=1`
//! (as `.ci/run` sets) a missing source fails them instead.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use orthocheck::cases::{self, CaseOrigin};
use orthocheck::claims::PaperCase;
use orthocheck::claims::PaperInputs;
use orthocheck::report::{Provenance, Report};

/// The folder of the paper's cases.
pub const CASES_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/paper_cases");

/// The paper's LaTeX source, when `ORTHOCHECK_PAPER` names one.
pub fn paper_source() -> Option<PathBuf> {
    let path = cases::source_path(None);
    let required = std::env::var("ORTHOCHECK_REQUIRE_PAPER").is_ok_and(|v| v == "1");
    assert!(
        path.is_some() || !required,
        "ORTHOCHECK_REQUIRE_PAPER=1 but {} names no LaTeX source",
        cases::PAPER_ENV
    );
    path
}

/// Say that `test` was skipped for want of the source: one line, straight to standard error
/// (the test harness hides what a passing test prints through `eprintln!`).
pub fn skipped_without_source(test: &str) {
    use std::io::Write as _;
    let _ = writeln!(
        std::io::stderr(),
        "SKIPPED {test}: the paper's LaTeX source is not given ({} names none)",
        cases::PAPER_ENV
    );
}

/// The cases, the paper file and the verification, read once (with the source when given).
pub fn inputs() -> Result<&'static PaperInputs, String> {
    static INPUTS: OnceLock<Result<PaperInputs, String>> = OnceLock::new();
    INPUTS
        .get_or_init(|| {
            let origin = CaseOrigin::Folder(Path::new(CASES_DIR).to_path_buf());
            cases::load_inputs::<orthocheck::claims::CaseCheck>(&origin, paper_source().as_deref())
                .map_err(|e| e.to_string())
        })
        .as_ref()
        .map_err(Clone::clone)
}

/// Every paper case, loaded once.
pub fn cases() -> Result<&'static [PaperCase], String> {
    inputs().map(|i| i.cases.as_slice())
}

/// The whole report (every case's claim results and figures), computed once; a failure says
/// how far the run came.
pub fn report() -> Result<&'static Report, String> {
    static REPORT: OnceLock<Result<Report, String>> = OnceLock::new();
    REPORT
        .get_or_init(|| {
            let inputs = inputs()?;
            let all = cases()?;
            // the run reports each finished case (they run at once, in no fixed order)
            let done = std::sync::Mutex::new(0usize);
            let progress = |i: usize, _: &str| {
                if let Ok(mut d) = done.lock() {
                    *d = (*d).max(i + 1);
                }
            };
            let provenance = Provenance {
                transcription: inputs.transcription_sentence(),
                ..Provenance::default()
            };
            orthocheck::claims::run_paper(inputs, &progress)
                .map(|run| Report::from_run(run, provenance).with_paper(inputs.paper.clone()))
                .map_err(|e| {
                    let at = done.lock().map(|d| *d).unwrap_or(0);
                    format!(
                        "the paper run failed ({at} of {} cases finished): {e}",
                        all.len()
                    )
                })
        })
        .as_ref()
        .map_err(Clone::clone)
}
