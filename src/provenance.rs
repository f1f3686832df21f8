//! Where a report comes from: the source revision and its date, asked of git, so that the
//! report says how to make it again. Nothing here prints.

use serde::Serialize;

/// The command that makes the whole report.
pub const REPORT_COMMAND: &str = "cargo run -- report";

/// The provenance of a report made now from this source tree (the seeds are filled in by
/// [`crate::report::Report::from_run`]).
pub fn report_provenance() -> Provenance {
    Provenance {
        revision: revision(),
        date: date(),
        command: REPORT_COMMAND.into(),
        transcription: String::new(),
        seeds: Vec::new(),
    }
}

/// The source revision (12 hex digits), with "+changes" when tracked files have uncommitted
/// edits; none outside a git checkout.
pub fn revision() -> Option<String> {
    let r = git(&["rev-parse", "--short=12", "HEAD"])?;
    let dirty =
        git(&["status", "--porcelain", "--untracked-files=no"]).is_some_and(|s| !s.is_empty());
    Some(if dirty { format!("{r}+changes") } else { r })
}

/// The date to print: `SOURCE_DATE_EPOCH` when set (reproducible builds), else the commit
/// date of the revision; never today's date, so the report is the same on every day.
pub fn date() -> Option<String> {
    std::env::var("SOURCE_DATE_EPOCH")
        .ok()
        .map(|e| format!("{e} (SOURCE_DATE_EPOCH)"))
        .or_else(|| git(&["show", "-s", "--format=%cs", "HEAD"]))
}

/// A git query's trimmed output in the source tree, when git answers.
fn git(args: &[&str]) -> Option<String> {
    let out = std::process::Command::new("git")
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// Where a report comes from, so that it can be made again.
#[derive(Clone, Debug, Default, Serialize)]
pub struct Provenance {
    /// The source revision (git), when known, with "+changes" for uncommitted edits.
    pub revision: Option<String>,
    /// The date of that revision (or `SOURCE_DATE_EPOCH`), when known: the report itself is
    /// the same on every day.
    pub date: Option<String>,
    /// The command that makes this report.
    pub command: String,
    /// Whether the transcription was verified against the paper's LaTeX source, in one
    /// sentence (empty when the caller says nothing).
    #[serde(skip_serializing_if = "String::is_empty")]
    pub transcription: String,
    /// The seeds each case sets.
    pub seeds: Vec<CaseSeeds>,
}

/// One case's seeds.
#[derive(Clone, Debug, Serialize)]
pub struct CaseSeeds {
    /// The case id.
    pub case: String,
    /// Its file.
    pub file: String,
    /// Its seeds.
    pub seeds: Vec<u64>,
}
