//! `orthocheck membership`: which points belong to one rigid body (two frames).

use std::path::PathBuf;

use orthocheck::derivations::identity;
use orthocheck::input::PointOrder;
use orthocheck::report::MemberRow;
use orthocheck::{report, Error};

use super::{emit, in_file, two_frames};

/// Arguments of `membership`.
#[derive(clap::Args)]
pub struct Args {
    /// Tracks file with two frames.
    #[arg(long)]
    input: PathBuf,
    /// Largest epipolar distance of a member, relative to the image size.
    #[arg(long, default_value_t = 1e-6)]
    tolerance: f64,
    /// JSON output.
    #[arg(long)]
    json: bool,
}

/// Decide each point's membership and print one row per point.
pub fn run(a: Args) -> Result<(), Error> {
    let tolerance = a.tolerance;
    if !(tolerance.is_finite() && tolerance >= 0.0) {
        return Err(Error::InvalidInput(format!(
            "--tolerance {tolerance}: must be a finite number ≥ 0"
        )));
    }
    let t = two_frames(&a.input, PointOrder::ByName)?;
    if let Some(d) = identity::degeneracy(&t.frames[0], &t.frames[1]) {
        return Err(in_file(&a.input, Error::InvalidInput(d.to_string())));
    }
    let m = identity::membership(&t.frames[0], &t.frames[1], tolerance);
    let inside: Vec<bool> = m.iter().map(|(i, _)| *i).collect();
    if let Some(d) = identity::members_rigid(&t.frames[0], &t.frames[1], &inside, tolerance) {
        return Err(in_file(&a.input, Error::InvalidInput(d.to_string())));
    }
    let rows: Vec<MemberRow> = t
        .names
        .iter()
        .zip(&m)
        .map(|(n, (inside, d))| MemberRow {
            point: n.clone(),
            member: *inside,
            distance: *d,
        })
        .collect();
    emit(a.json, &rows, |r| report::membership_text(r, tolerance))?;
    Ok(())
}
