//! The `orthocheck` command line: parses arguments, dispatches to one subcommand of [`cli`],
//! maps errors to exit codes.
//!
//! Exit codes: 0 the command ran (whatever the verdicts); 1 a check could not be carried out
//! (a numerical failure, a write that failed), or a result was printed with warnings that it
//! may be wrong (`reconstruct`); 2 bad input or usage (clap exits with 2 on usage errors
//! itself); 130 interrupted by Ctrl-C (`cli::progress`).

mod cli;

use std::io::Write as _;
use std::process::ExitCode;

use clap::Parser;
use orthocheck::Error;

#[derive(Parser)]
#[command(
    name = "orthocheck",
    version,
    about = "Machine-checked reproduction of Kłopotek's orthographic structure-from-motion paper"
)]
struct Cli {
    #[command(subcommand)]
    command: cli::Command,
}

/// The exit code of a failed command.
fn exit_code(e: &Error) -> u8 {
    match e {
        Error::Numerical(_) | Error::Write { .. } | Error::Unverified(_) | Error::Warned(_) => 1,
        _ => 2,
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    cli::progress::on_interrupt_stop();
    match cli.command.run() {
        // a reader that stopped reading is the Unix way of saying "enough"
        Ok(()) | Err(Error::ClosedOutput) => ExitCode::SUCCESS,
        Err(e) => {
            // a closed standard error leaves the exit code to say it
            let _ = writeln!(std::io::stderr(), "error: {e}");
            ExitCode::from(exit_code(&e))
        }
    }
}
