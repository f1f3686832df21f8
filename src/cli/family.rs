//! `orthocheck family`: members of the one-parameter family of bodies two frames allow.

use std::path::PathBuf;

use orthocheck::input::PointOrder;
use orthocheck::studies::family_samples::sample_family;
use orthocheck::{report, Error};

use super::{emit, in_file, two_frames};

/// Arguments of `family`.
#[derive(clap::Args)]
pub struct Args {
    /// Tracks file with two frames.
    #[arg(long)]
    input: PathBuf,
    /// Members, at angles evenly spread in (0, π).
    #[arg(long, allow_negative_numbers = true, default_value_t = 5)]
    samples: usize,
    /// JSON output.
    #[arg(long)]
    json: bool,
}

/// Sample the family and print its members.
pub fn run(a: Args) -> Result<(), Error> {
    orthocheck::limits::count("--samples", a.samples, orthocheck::limits::FAMILY_SAMPLES)
        .map_err(Error::InvalidInput)?;
    let t = two_frames(&a.input, PointOrder::ByName)?;
    orthocheck::limits::at_most(
        "the points × --samples of family",
        t.names.len().saturating_mul(a.samples),
        orthocheck::limits::FAMILY_POINTS_TIMES_SAMPLES,
    )
    .map_err(|m| {
        in_file(
            &a.input,
            Error::InvalidInput(format!("{m}: fewer --samples fit")),
        )
    })?;
    let members =
        sample_family(&t.frames[0], &t.frames[1], a.samples).map_err(|e| in_file(&a.input, e))?;
    let view = report::family_view(&t.names, &members);
    emit(a.json, &view, |v| report::family_text(v))?;
    Ok(())
}
