//! `orthocheck synth`: a tracks file of a seeded random scene, to try the solvers on.

use std::path::PathBuf;

use clap::ValueEnum;
use orthocheck::input::{tracks_to_csv, tracks_to_yaml};
use orthocheck::seeds::synthetic;
use orthocheck::{report, Error};

use super::{out, write_new};

/// Arguments of `synth`.
#[derive(clap::Args)]
pub struct Args {
    /// Number of points.
    #[arg(long)]
    points: usize,
    /// Number of frames.
    #[arg(long)]
    frames: usize,
    /// Seed.
    #[arg(long)]
    seed: u64,
    /// Relative error up to ε on every image coordinate.
    #[arg(long)]
    noise: Option<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value = "yaml")]
    format: FormatArg,
    /// Write to this file (refused if it exists); standard output otherwise.
    #[arg(long)]
    out: Option<PathBuf>,
}

/// The tracks file formats.
#[derive(Clone, Copy, ValueEnum)]
enum FormatArg {
    Yaml,
    Csv,
}

/// Make the scene, write its tracks with a header naming the truth.
pub fn run(a: Args) -> Result<(), Error> {
    check_limits(&a).map_err(Error::InvalidInput)?;
    let s = synthetic(a.points, a.frames, a.seed, a.noise);
    let header = report::synth_header(&s.scene, a.seed, a.noise);
    let body = match a.format {
        FormatArg::Yaml => tracks_to_yaml(&s.tracks),
        FormatArg::Csv => tracks_to_csv(&s.tracks),
    };
    let text = format!("{header}{body}");
    match a.out {
        Some(path) => write_new(&path, &text),
        None => {
            out(&text)?;
            Ok(())
        }
    }
}

/// The sizes within `docs/limits.md`, and ε in range, before the scene is made.
fn check_limits(a: &Args) -> Result<(), String> {
    use orthocheck::limits::{count, SYNTH_FRAMES, SYNTH_POINTS, SYNTH_POINTS_TIMES_FRAMES};
    count("--points", a.points, SYNTH_POINTS)?;
    count("--frames", a.frames, SYNTH_FRAMES)?;
    count(
        "--points × --frames",
        a.points.saturating_mul(a.frames),
        SYNTH_POINTS_TIMES_FRAMES,
    )?;
    a.noise
        .map_or(Ok(()), |e| orthocheck::limits::noise_level("--noise", e))
}
