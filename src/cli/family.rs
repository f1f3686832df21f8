//! `orthocheck family`: members of the one-parameter family of bodies two frames allow.

use std::path::PathBuf;

use crate::input::PointOrder;
use crate::studies::family_samples::sample_family;
use std::fmt::Write as _;

use crate::Error;
use serde::Serialize;

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
    crate::limits::count("--samples", a.samples, crate::limits::FAMILY_SAMPLES)
        .map_err(Error::InvalidInput)?;
    let t = two_frames(&a.input, PointOrder::ByName)?;
    crate::limits::at_most(
        "the points × --samples of family",
        t.names.len().saturating_mul(a.samples),
        crate::limits::FAMILY_POINTS_TIMES_SAMPLES,
    )
    .map_err(|m| {
        in_file(
            &a.input,
            Error::InvalidInput(format!("{m}: fewer --samples fit")),
        )
    })?;
    let members =
        sample_family(&t.frames[0], &t.frames[1], a.samples).map_err(|e| in_file(&a.input, e))?;
    let view = family_view(&t.names, &members);
    emit(a.json, &view, |v| family_text(v))?;
    Ok(())
}

/// One member of the two-frame family, for display.
#[derive(Clone, Debug, Serialize)]
struct FamilyMember {
    /// The angle between the views.
    pub beta: f64,
    /// The points, named.
    pub points: Vec<(String, [f64; 3])>,
    /// Largest reprojection error (relative).
    pub reprojection: f64,
}

/// The family as shown: names with coordinates.
fn family_view(
    names: &[String],
    members: &[crate::derivations::two_frames::Member],
) -> Vec<FamilyMember> {
    members
        .iter()
        .map(|m| FamilyMember {
            beta: m.beta,
            points: names
                .iter()
                .zip(&m.points)
                .map(|(n, p)| (n.clone(), [p.x, p.y, p.z]))
                .collect(),
            reprojection: m.reprojection,
        })
        .collect()
}

/// `orthocheck family` as text.
fn family_text(members: &[FamilyMember]) -> String {
    use crate::numfmt::{below, sig, sig_list};
    let mut s = String::from(
        "members of the family of bodies both frames allow (frame 1's camera coordinates; the depth is fixed up to a shift)\n",
    );
    for m in members {
        let _ = writeln!(
            s,
            "β = {} rad (reprojection {}):",
            sig(m.beta),
            below(m.reprojection)
        );
        for (n, p) in &m.points {
            let _ = writeln!(s, "  {n:<6} {}", sig_list(p));
        }
    }
    s
}
