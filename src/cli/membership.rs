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
    /// Largest epipolar distance of a member, relative to the image size, the same for every
    /// point. Default: from the data's noise, point by point, with the fit's degrees of
    /// freedom accounted for: least median of squares over fits of equal scale finds the
    /// body, the epipolar geometry is refitted to its points, the noise's mix of one scale
    /// and a scale growing with the coordinates is estimated (from 10 members), and each
    /// point's tolerance is its own standard deviation times Student's t at 99 % two-sided,
    /// so that at most about 1 % of true members are rejected (0.3–0.6 % measured from 6
    /// members on; docs/limits.md, "Membership's tolerance").
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
    let tolerance = a.tolerance.map_or_else(
        || identity::robust_tolerance(&t.frames[0], &t.frames[1]),
        identity::Tolerance::uniform,
    );
    let m = identity::membership(&t.frames[0], &t.frames[1], &tolerance);
    let inside: Vec<bool> = m.iter().map(|j| j.member).collect();
    let largest = tolerance.largest(&m);
    if let Some(d) = identity::members_rigid(&t.frames[0], &t.frames[1], &inside, largest) {
        let hint = if from_data {
            "; the tolerance came from the data's own noise: a larger --tolerance admits more points, a smaller one fewer"
        } else {
            "; a larger --tolerance admits noisier members, a smaller one sets more points apart"
        };
        return Err(in_file(
            &a.input,
            Error::InvalidInput(format!(
                "{d} (beyond the noise of tolerance {}, or of the members' own residuals at level {}){hint}",
                crate::numfmt::sig(largest),
                crate::numfmt::sig(identity::RIGID_LEVEL)
            )),
        ));
    }
    let rows: Vec<MemberRow> = t
        .names
        .iter()
        .zip(&m)
        .map(|(n, j)| MemberRow {
            point: n.clone(),
            member: j.member,
            distance: j.distance,
            tolerance: j.tolerance,
        })
        .collect();
    emit(a.json, &rows, |r| membership_text(r, &tolerance, from_data))?;
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
    /// The largest distance it could have had as a member (its own when the noise grows
    /// with the coordinates).
    pub tolerance: f64,
}

/// `orthocheck membership` as text.
fn membership_text(rows: &[MemberRow], tolerance: &identity::Tolerance, from_data: bool) -> String {
    use crate::numfmt::sig;
    let per_point = tolerance.relative > 0.0;
    let mut s = format!(
        "members: epipolar distance at most {}{} of the image size{}\n",
        sig(tolerance.base),
        if per_point {
            format!(
                " × the point's noise weight ({} % of the noise variance grows with the coordinates; each point's tolerance in the last column)",
                sig(100.0 * tolerance.relative)
            )
        } else {
            String::new()
        },
        if from_data {
            " (from the data: the members' residual scale times Student's t at 99 %; --tolerance sets one for every point)"
        } else {
            ""
        }
    );
    for r in rows {
        let _ = write!(
            s,
            "{:<6} {:<9} {}",
            r.point,
            if r.member { "member" } else { "outside" },
            sig(r.distance)
        );
        if per_point {
            let _ = write!(s, "  (at most {})", sig(r.tolerance));
        }
        s.push('\n');
    }
    s
}
