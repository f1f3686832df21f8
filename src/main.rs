//! The `orthocheck` command line: parses arguments, calls the library, maps errors to exit codes.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};
use orthocheck::{cases, check, derivations, report, Error};

#[derive(Parser)]
#[command(
    name = "orthocheck",
    version,
    about = "Machine-checked reproduction of Kłopotek's orthographic structure-from-motion paper"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Reproduce the paper: run every case and write report.md and report.json.
    Report {
        /// Output folder.
        #[arg(long, default_value = "target/orthocheck-report")]
        out: PathBuf,
        /// Folder of case files.
        #[arg(long, default_value = "paper_cases")]
        cases: PathBuf,
    },
    /// Count degrees of freedom (§2.1) and decide identifiability by Jacobian rank.
    Dof {
        /// Number of points p.
        #[arg(long, required_unless_present = "table")]
        points: Option<usize>,
        /// Number of frames k.
        #[arg(long, required_unless_present = "table")]
        frames: Option<usize>,
        /// The whole grid p = 1..max-points, k = 1..max-frames.
        #[arg(long, conflicts_with_all = ["points", "frames"])]
        table: bool,
        /// Largest p of the grid.
        #[arg(long, default_value_t = 8, requires = "table")]
        max_points: usize,
        /// Largest k of the grid.
        #[arg(long, default_value_t = 6, requires = "table")]
        max_frames: usize,
        /// Seed of the generic scene.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// JSON output.
        #[arg(long)]
        json: bool,
    },
    /// Machine-check a printed formula of the paper.
    Audit {
        /// Which formula.
        id: AuditId,
        /// Folder of case files (the printed formula is read from there).
        #[arg(long, default_value = "paper_cases")]
        cases: PathBuf,
        /// JSON output.
        #[arg(long)]
        json: bool,
    },
}

#[derive(Clone, Copy, ValueEnum)]
enum AuditId {
    /// Eq. p3f3sqr: the twofold squaring of the signed relations.
    TwofoldSquared,
}

fn exit_code(e: &Error) -> u8 {
    match e {
        Error::Numerical(_) => 1,
        _ => 2,
    }
}

fn run(cli: Cli) -> Result<(), Error> {
    match cli.command {
        Command::Report { out, cases } => {
            let all = cases::load_all(&cases)?;
            let r = report::Report::from_cases(&all)?;
            r.write(&out)?;
            println!(
                "wrote {} and {} ({} claims)",
                out.join("report.md").display(),
                out.join("report.json").display(),
                r.claims.len()
            );
            for (verdict, n) in &r.summary {
                if *n > 0 {
                    println!("  {verdict}: {n}");
                }
            }
        }
        Command::Dof {
            points,
            frames,
            table,
            max_points,
            max_frames,
            seed,
            json,
        } => {
            if table {
                let rows = derivations::dof::table(max_points, max_frames, seed)?;
                if json {
                    println!("{}", to_json(&rows));
                } else {
                    print!("{}", report::dof_table_text(&rows));
                }
            } else {
                let (p, k) = (points.unwrap_or(0), frames.unwrap_or(0));
                let r = derivations::dof::identifiability(p, k, seed)?;
                if json {
                    println!("{}", to_json(&r));
                } else {
                    print!("{}", report::dof_text(&r));
                }
            }
        }
        Command::Audit { id, cases, json } => match id {
            AuditId::TwofoldSquared => {
                let case = cases::load_all(&cases)?
                    .into_iter()
                    .find_map(|c| match c.check {
                        cases::CaseCheck::TwofoldSquared(t) => Some(t),
                        _ => None,
                    })
                    .ok_or_else(|| {
                        Error::InvalidInput(format!(
                            "no twofold_squared case in {}",
                            cases.display()
                        ))
                    })?;
                let a = check::audit_twofold(&case)?;
                if json {
                    println!("{}", to_json(&a));
                } else {
                    print!("{}", report::twofold_text(&a));
                }
            }
        },
    }
    Ok(())
}

fn to_json<T: serde::Serialize>(v: &T) -> String {
    serde_json::to_string_pretty(v).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(exit_code(&e))
        }
    }
}
