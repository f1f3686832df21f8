//! `orthocheck report`: reproduce the whole paper and write the report files.

use super::out;
use std::io::{IsTerminal, Write as _};
use std::path::PathBuf;
use std::time::Instant;

use orthocheck::report::Report;
use orthocheck::{cases, provenance, Error};

/// Arguments of `report`.
#[derive(clap::Args)]
pub struct Args {
    /// Output folder.
    #[arg(long, default_value = "target/orthocheck-report")]
    out: PathBuf,
    /// Folder of case files.
    #[arg(long, default_value = "paper_cases")]
    cases: PathBuf,
}

/// Run every case, write report.md, report.json, report.html and one SVG file per figure,
/// print the verdict counts.
pub fn run(args: Args) -> Result<(), Error> {
    let all = cases::load_all(&args.cases)?;
    let paper = cases::load_paper(&args.cases)?;
    // an unwritable folder is found before the report is computed
    orthocheck::report::prepare_output_dir(&args.out)?;
    let started = Instant::now();
    // only for a run that takes long enough to wonder about
    let show = || std::io::stderr().is_terminal() && started.elapsed().as_secs_f64() > 1.0;
    let progress = |i: usize, id: &str| {
        if show() {
            eprint!("\r{}/{} cases ({id})            ", i + 1, all.len());
            let _ = std::io::stderr().flush();
        }
    };
    let r = Report::run(&all, provenance::report_provenance(), &progress)?.with_paper(paper);
    if show() {
        eprintln!();
    }
    r.write(&args.out)?;
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
    Ok(())
}
