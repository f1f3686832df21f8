//! The command line: the subcommands, one file each (its argument struct and one `run`), and
//! [`run_command_line`], the whole of `main`.
//!
//! It is a private module of the library, on the top floor: no other module names it, the
//! library's public items carry no clap types, and only this module prints. It lives here, not
//! in the binary, because a release build compiles the generic code a crate instantiates in
//! that crate (case loading, serialisation, the claim runner): in the binary all of it was
//! compiled a second time, the longest step of a cold build. A `run` only validates its
//! arguments, calls the library and prints through the `report` renderers (`solve`,
//! `identify` and `noise` lay out their own text tables); it computes nothing itself.

mod audit;
mod dof;
mod family;
mod identify;
mod membership;
mod noise;
mod progress;
mod reconstruct;
mod report;
mod solve;
mod synth;

use std::path::Path;

use std::io::Write as _;
use std::process::ExitCode;

use crate::error::InputLocation;
use crate::input::{load_tracks, PointOrder};
use crate::model::Tracks;
use crate::Error;
use clap::{Parser, Subcommand};

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

/// The exit code of a failed command.
fn exit_code(e: &Error) -> u8 {
    match e {
        Error::Numerical(_) | Error::Write { .. } | Error::Unverified(_) | Error::Warned(_) => 1,
        _ => 2,
    }
}

/// The `orthocheck` command: parse the process's arguments, run the subcommand, say what
/// failed on standard error and return the exit code (0 ran, 1 a check could not be carried
/// out or a result came with warnings, 2 bad input or usage, 130 interrupted).
pub fn run_command_line() -> ExitCode {
    let cli = Cli::parse();
    progress::on_interrupt_stop();
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

/// Every subcommand.
#[derive(Subcommand)]
pub enum Command {
    /// Reproduce the paper: run every case and write report.md, report.json and report.html.
    Report(report::Args),
    /// Count degrees of freedom (§2.1) and decide identifiability by Jacobian rank.
    Dof(dof::Args),
    /// Machine-check the paper's printed formulas: one item, a claim's items, or all.
    Audit(audit::Args),
    /// Recover the squared edges (and the body) from a tracks file.
    Solve(solve::Args),
    /// Run a noise study of a paper case with your own levels, trials and seed.
    Noise(noise::Args),
    /// Find which frame-2 point is which frame-1 point (two frames; frame 2's order unknown).
    Identify(identify::Args),
    /// Decide which points belong to one rigid body (two frames, correspondences known).
    Membership(membership::Args),
    /// Print members of the one-parameter family of bodies two frames allow.
    Family(family::Args),
    /// Write a tracks file of a seeded random scene, to try the solvers on.
    Synth(synth::Args),
    /// Reconstruct the body and every camera from many points in many frames (Tomasi–Kanade,
    /// bundle adjustment, gaps, RANSAC over the four-point solver).
    ///
    /// Points seen in fewer than 2 frames and frames that keep fewer than 4 points are
    /// dropped and listed; frames that split into groups (no frame of one sharing 4 points
    /// with a frame of another) are reconstructed group by group, each in its own frame of
    /// reference. Exit codes: 0 done; 1 the whole result was printed, but with warnings
    /// that it may be wrong (a search stopped at its limit, the metric upgrade clipped,
    /// bundle adjustment skipped or stopped at its limit, points implausibly deep); 2 bad
    /// input, or nothing can be reconstructed.
    Reconstruct(reconstruct::Args),
}

impl Command {
    /// Run the subcommand.
    pub fn run(self) -> Result<(), Error> {
        let _ = COMMAND.set(self.name());
        match self {
            Command::Report(a) => report::run(a),
            Command::Dof(a) => dof::run(a),
            Command::Audit(a) => audit::run(a),
            Command::Solve(a) => solve::run(a),
            Command::Noise(a) => noise::run(a),
            Command::Identify(a) => identify::run(a),
            Command::Membership(a) => membership::run(a),
            Command::Family(a) => family::run(a),
            Command::Synth(a) => synth::run(a),
            Command::Reconstruct(a) => reconstruct::run(a),
        }
    }
}

/// The running subcommand's name, for the output guard's message.
static COMMAND: std::sync::OnceLock<&'static str> = std::sync::OnceLock::new();

/// The running subcommand's name (`orthocheck` before one runs).
/// A seed argument: a whole number, and a value that is not UTF-8 named by its argument
/// (clap's own check says only that some argument is not).
#[derive(Clone, Copy, Debug)]
pub(crate) struct SeedParser;

impl clap::builder::TypedValueParser for SeedParser {
    type Value = u64;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &std::ffi::OsStr,
    ) -> Result<u64, clap::Error> {
        let name = arg.map_or_else(|| "the seed".to_string(), |a| format!("'--{}'", a.get_id()));
        let text = value.to_str().ok_or_else(|| {
            clap::Error::raw(
                clap::error::ErrorKind::InvalidValue,
                format!(
                    "invalid value for {name}: not valid UTF-8 (a whole number from 0 to {})\n",
                    u64::MAX
                ),
            )
            .with_cmd(cmd)
        })?;
        text.parse().map_err(|_| {
            clap::Error::raw(
                clap::error::ErrorKind::InvalidValue,
                format!(
                    "invalid value '{text}' for {name}: a whole number from 0 to {}\n",
                    u64::MAX
                ),
            )
            .with_cmd(cmd)
        })
    }
}

fn command_name() -> &'static str {
    COMMAND.get().copied().unwrap_or("orthocheck")
}

impl Command {
    /// The subcommand's name as typed.
    fn name(&self) -> &'static str {
        match self {
            Command::Report(_) => "report",
            Command::Dof(_) => "dof",
            Command::Audit(_) => "audit",
            Command::Solve(_) => "solve",
            Command::Noise(_) => "noise",
            Command::Identify(_) => "identify",
            Command::Membership(_) => "membership",
            Command::Family(_) => "family",
            Command::Synth(_) => "synth",
            Command::Reconstruct(_) => "reconstruct",
        }
    }
}

/// Print `value` as pretty JSON when `json`, else as `text` renders it.
fn emit<T: serde::Serialize>(
    json: bool,
    value: &T,
    text: impl FnOnce(&T) -> String,
) -> Result<(), Error> {
    if json {
        json_out(value)
    } else {
        out(&text(value))
    }
}

/// Print `value` as pretty JSON through the output guard: serde_json writes a non-finite
/// number as `null`, which the text guard cannot tell from an honest `null`, so the value is
/// walked first ([`crate::report::finite`]) and a NaN or inf is an error (exit 1).
fn json_out<T: serde::Serialize>(value: &T) -> Result<(), Error> {
    if let Some(bad) = crate::report::finite::first_non_finite(value) {
        return Err(non_finite(&bad.to_string()));
    }
    out(&format!("{}\n", to_json(value)))
}

/// The output guard's error: which command, which value.
fn non_finite(what: &str) -> Error {
    Error::Numerical(format!(
        "{}: a non-finite number ({what}) reached the output; nothing was printed",
        command_name()
    ))
}

/// The output guard on text: if any formatter turned a non-finite number into text during
/// this command, nothing is printed or written (exit 1). It counts numbers as they are
/// formatted, so a point named `inf` or `NaN` passes.
fn guard_formatted() -> Result<(), Error> {
    match crate::numfmt::non_finite_formatted() {
        0 => Ok(()),
        1 => Err(non_finite("one was formatted")),
        n => Err(non_finite(&format!("{n} were formatted"))),
    }
}

/// Write to standard output through the output guard: a non-finite number in the text is an
/// error (exit 1) rather than output; a closed pipe ends the command quietly; any other
/// write failure (a full disk) is an error.
fn out(text: &str) -> Result<(), Error> {
    use std::io::Write as _;
    guard_formatted()?;
    let mut stdout = std::io::stdout().lock();
    match stdout
        .write_all(text.as_bytes())
        .and_then(|()| stdout.flush())
    {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Err(Error::ClosedOutput),
        Err(e) => Err(Error::Write {
            path: "standard output".into(),
            message: e.to_string(),
        }),
    }
}

/// Pretty JSON (an error object in the impossible case that serialising fails).
fn to_json<T: serde::Serialize>(v: &T) -> String {
    serde_json::to_string_pretty(v).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
}

/// A tracks file that must hold exactly two frames.
fn two_frames(path: &Path, order: PointOrder) -> Result<Tracks, Error> {
    let t = load_tracks(path, order)?;
    if t.frames.len() != 2 {
        return Err(in_file(
            path,
            Error::InvalidInput(format!(
                "{} frames: this command takes exactly two",
                t.frames.len()
            )),
        ));
    }
    Ok(t)
}

/// An input that parsed but cannot be used is still the user's file's fault: name it.
fn in_file(path: &Path, e: Error) -> Error {
    match e {
        Error::InvalidInput(message) => Error::Input {
            location: InputLocation::file(path),
            message,
        },
        e => e,
    }
}

/// Write a file that must not exist yet: a user's file is never overwritten (an existing
/// name is refused with [`would_overwrite`], exit 2; a failed write is exit 1).
fn write_new(path: &Path, text: &str) -> Result<(), Error> {
    guard_formatted()?;
    crate::files::write_new(path, text, would_overwrite)
}

/// The refusal to write over an existing file: usage, not a failure (exit 2).
fn would_overwrite(path: &Path) -> Error {
    Error::Input {
        location: InputLocation::file(path),
        message: format!(
            "the file exists and `{} --out` would overwrite it; nothing was written (choose another name, or remove the file first)",
            command_name()
        ),
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_output_guard_refuses_once_a_non_finite_number_was_formatted() {
        let before = crate::numfmt::non_finite_formatted();
        let text = crate::numfmt::sig(f64::NAN);
        assert!(crate::numfmt::non_finite_formatted() > before);
        let refused = super::guard_formatted().unwrap_err().to_string();
        assert!(refused.contains("non-finite"), "{text}: {refused}");
    }
}
