//! `orthocheck membership`: which points belong to one rigid body (two frames).

use std::path::PathBuf;

use crate::derivations::identity;
use crate::input::PointOrder;
use std::fmt::Write as _;

use crate::Error;
use serde::Serialize;

use super::{emit, in_file, two_frames};

/// Arguments of `membership`.
#[derive(clap::Args)]
pub struct Args {
    /// Tracks file with two frames.
    #[arg(long)]
    input: PathBuf,
    /// Largest epipolar distance of a member, relative to the image size. Default: from the
    /// data's noise, with the fit's degrees of freedom accounted for: least median of squares
    /// finds the body, the epipolar geometry is refitted to its points, and the tolerance is
    /// the residual standard deviation times Student's t at 99 % two-sided with m − 4 degrees
    /// of freedom (m members), so that about 1 % of true members are rejected at most
    /// (docs/limits.md, "Membership's tolerance").
    #[arg(long, allow_negative_numbers = true)]
    tolerance: Option<f64>,
    /// JSON output.
    #[arg(long)]
    json: bool,
}

/// Decide each point's membership and print one row per point.
pub fn run(a: Args) -> Result<(), Error> {
    if let Some(t) = a.tolerance.filter(|t| !(t.is_finite() && *t >= 0.0)) {
        return Err(Error::InvalidInput(format!(
            "--tolerance {t}: must be a finite number ≥ 0"
        )));
    }
    let t = two_frames(&a.input, PointOrder::ByName)?;
    crate::limits::at_most(
        "the number of points per frame of membership",
        t.names.len(),
        crate::limits::MEMBERSHIP_POINTS,
    )
    .map_err(|m| in_file(&a.input, Error::InvalidInput(m)))?;
    if let Some(d) = identity::degeneracy(&t.frames[0], &t.frames[1]) {
        return Err(in_file(&a.input, Error::InvalidInput(d.to_string())));
    }
    let from_data = a.tolerance.is_none();
    let tolerance = a
        .tolerance
        .unwrap_or_else(|| identity::robust_tolerance(&t.frames[0], &t.frames[1]));
    let m = identity::membership(&t.frames[0], &t.frames[1], tolerance);
    let inside: Vec<bool> = m.iter().map(|(i, _)| *i).collect();
    if let Some(d) = identity::members_rigid(&t.frames[0], &t.frames[1], &inside, tolerance) {
        let hint = if from_data {
            "; the tolerance came from the data's own noise: a larger --tolerance admits more points, a smaller one fewer"
        } else {
            "; a larger --tolerance admits noisier members, a smaller one sets more points apart"
        };
        return Err(in_file(
            &a.input,
            Error::InvalidInput(format!(
                "{d} (tolerance {}){hint}",
                crate::numfmt::sig(tolerance)
            )),
        ));
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
    emit(a.json, &rows, |r| membership_text(r, tolerance, from_data))?;
    Ok(())
}

/// One point of `orthocheck membership`.
#[derive(Clone, Debug, Serialize)]
struct MemberRow {
    /// The point's name.
    pub point: String,
    /// Whether it belongs to the body.
    pub member: bool,
    /// Its epipolar distance, relative to the image size.
    pub distance: f64,
}

/// `orthocheck membership` as text.
fn membership_text(rows: &[MemberRow], tolerance: f64, from_data: bool) -> String {
    use crate::numfmt::sig;
    let mut s = format!(
        "members: epipolar distance at most {} of the image size{}\n",
        sig(tolerance),
        if from_data {
            " (from the data: the members' residual scale times Student's t at 99 %; --tolerance sets it)"
        } else {
            ""
        }
    );
    for r in rows {
        let _ = writeln!(
            s,
            "{:<6} {:<9} {}",
            r.point,
            if r.member { "member" } else { "outside" },
            sig(r.distance)
        );
    }
    s
}
