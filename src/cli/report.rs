//! `orthocheck report`: reproduce the whole paper and write the report files.

use super::{guard_formatted, out};
use std::io::{IsTerminal, Write as _};
use std::path::PathBuf;
use std::time::Instant;

use crate::claims::CaseCheck;
use crate::{cases, provenance, Error};

/// Arguments of `report`.
#[derive(clap::Args)]
pub struct Args {
    /// Output folder.
    #[arg(long, default_value = "target/orthocheck-report")]
    out: PathBuf,
    /// Folder of case files, instead of the paper's cases built into the binary.
    #[arg(long)]
    cases: Option<PathBuf>,
    /// The paper's LaTeX source: verifies the transcription (its SHA-256 must be the one
    /// paper.yml records). Default: the file ORTHOCHECK_PAPER names, else none.
    #[arg(long, value_name = "FILE")]
    paper: Option<PathBuf>,
}

/// Run every case, write report.md, report.json, report.html and one SVG file per figure,
/// print the verdict counts.
pub fn run(args: Args) -> Result<(), Error> {
    let origin = cases::CaseOrigin::from_arg(args.cases.as_deref());
    let source = cases::source_path(args.paper.as_deref());
    let inputs = cases::load_inputs::<CaseCheck>(&origin, source.as_deref())?;
    let all = &inputs.cases;
    // an unwritable folder is found before the report is computed
    crate::report::prepare_output_dir(&args.out)?;
    let started = Instant::now();
    // only for a run that takes long enough to wonder about
    let show = || std::io::stderr().is_terminal() && started.elapsed().as_secs_f64() > 1.0;
    let progress = |i: usize, id: &str| {
        if show() {
            let _ = write!(
                std::io::stderr(),
                "\r{}/{} cases ({id})            ",
                i + 1,
                all.len()
            );
            let _ = std::io::stderr().flush();
        }
    };
    let mut prov = provenance::report_provenance();
    prov.transcription = inputs.transcription_sentence();
    let run = crate::claims::run_paper(&inputs, &progress)?;
    let r = crate::report::Report::from_run(run, prov).with_paper(inputs.paper.clone());
    if show() {
        let _ = writeln!(std::io::stderr());
    }
    let mut files = r.files()?;
    // with the source, the paper corrected
    if let Some(src) = &inputs.source {
        let name = src
            .path
            .file_name()
            .map_or_else(|| "paper.tex".into(), |n| n.to_string_lossy().into_owned());
        let patch = crate::report::errata_patch(&src.text, &name, &inputs.corrections, &r.claims)?;
        files.push(("errata.patch".to_string(), patch));
    }
    // the text guard: a number formatted as `NaN` or `inf` anywhere in the report
    guard_formatted()?;
    crate::report::write_all_atomic(&args.out, &files)?;
    let dir = &args.out;
    out(&format!(
        "wrote {}, {} and {} ({} claims), and {} figures as {}\n",
        dir.join("report.md").display(),
        dir.join("report.json").display(),
        dir.join("report.html").display(),
        r.claims.len(),
        r.figures.len(),
        dir.join("<figure id>.svg").display()
    ))?;
    for (verdict, n) in &r.summary {
        if *n > 0 {
            out(&format!("  {verdict}: {n}\n"))?;
        }
    }
    let disagreements = inputs.disagreements();
    if disagreements.is_empty() {
        Ok(())
    } else {
        Err(Error::Unverified(
            disagreements.iter().map(|d| format!("\n  {d}")).collect(),
        ))
    }
}
