//! The paper, run once per test binary: every test that needs claim results reads them from
//! here, so one `cargo test` reproduces the paper once per binary instead of once per test.

use std::path::Path;
use std::sync::OnceLock;

use orthocheck::cases::{self, Case};
use orthocheck::report::Report;

/// The folder of the paper's cases.
pub const CASES_DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/paper_cases");

/// Every paper case, loaded once.
pub fn cases() -> Result<&'static [Case], String> {
    static CASES: OnceLock<Result<Vec<Case>, String>> = OnceLock::new();
    CASES
        .get_or_init(|| cases::load_all(Path::new(CASES_DIR)).map_err(|e| e.to_string()))
        .as_deref()
        .map_err(Clone::clone)
}

/// The whole report (every case's claim results and figures), computed once; a failure names
/// the case that stopped the run.
pub fn report() -> Result<&'static Report, String> {
    static REPORT: OnceLock<Result<Report, String>> = OnceLock::new();
    REPORT
        .get_or_init(|| {
            let all = cases()?;
            // the run reports each finished case: the one after the last reported failed
            let done = std::sync::Mutex::new(0usize);
            let progress = |i: usize, _: &str| {
                if let Ok(mut d) = done.lock() {
                    *d = i + 1;
                }
            };
            Report::run(all, Default::default(), &progress).map_err(|e| {
                let at = done.lock().map(|d| *d).unwrap_or(0);
                let case = all.get(at).map_or("?", |c| c.id.as_str());
                format!("the paper run stopped at case {case}: {e}")
            })
        })
        .as_ref()
        .map_err(Clone::clone)
}
