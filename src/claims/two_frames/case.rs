//! The case schema of §5.1 and §5.4: the printed construction and the two-frame claims.

use serde::Deserialize;

use crate::cases::{ClaimRef, Printed, Validator};
use crate::error::Result;
use crate::limits;

/// §5.1's printed construction and the general two-frame claims.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct TwoFramesCase {
    /// The printed points P, Q, R, Q′, R′.
    pub counterexample: PrintedPoints,
    /// The construction as the text describes it.
    pub construction: ClaimRef,
    /// "no possibility of recovery … from two images" (the family, at random scenes).
    pub family: ClaimRef,
    /// "the forth point T2 does carry only one piece of information".
    pub fourth_point: ClaimRef,
    /// §5.4: curves.
    pub curves: ClaimRef,
    /// Points of the random scenes (≥ 4).
    pub points: usize,
    /// Random scenes.
    pub trials: usize,
    /// Samples of the curve.
    pub curve_samples: usize,
    /// The angles β of the family members compared (each in (0, π)).
    pub betas: Vec<f64>,
    /// The control: how far one point of frame 2 is moved off the body (fraction of the
    /// image size), which the family's reprojection must then reject.
    pub control_shift: f64,
    /// The counterexample's mutant: Q′'s second coordinate moved by this many half units.
    pub mutant_half_units: f64,
    /// The member of the family the figures draw, when judged.
    #[serde(default)]
    pub drawn_member: Option<DrawnMember>,
    /// Seed.
    pub seed: u64,
}

/// §5.1's figures as drawn, against the printed points.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DrawnMember {
    /// The claim.
    pub claim: ClaimRef,
    /// The figure label the text says shows the rotated body (the other shows the original).
    pub rotated_figure: String,
    /// The pictures.
    pub drawings: Vec<Drawing>,
}

/// One picture: drawing coordinates as printed in its `\put` commands.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Drawing {
    /// Line range.
    pub lines: String,
    /// The figure label it belongs to.
    pub figure: String,
    /// The hidden corner of the cube, where its three thin edges start.
    pub corner: [Printed; 2],
    /// The other ends of the three thin edges.
    pub edges: Vec<[Printed; 2]>,
    /// The names of the three body points labelled (P first).
    pub label_names: Vec<String>,
    /// Their label positions.
    pub labels: Vec<[Printed; 2]>,
    /// The line n (two ends).
    pub n: [[Printed; 2]; 2],
    /// One frame-1 ray (two ends).
    pub frame1_ray: [[Printed; 2]; 2],
    /// The frame-2 rays (two ends each).
    pub frame2_rays: Vec<[[Printed; 2]; 2]>,
}

/// Printed 3-D points.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PrintedPoints {
    /// The claim.
    pub claim: ClaimRef,
    /// Names, as printed.
    pub names: Vec<String>,
    /// Coordinates, as printed.
    pub points: Vec<[Printed; 3]>,
}

pub(super) fn sizes(c: &TwoFramesCase, v: &Validator) -> Result<()> {
    v.limit("points", "points", c.points, limits::CASE_POINTS)?;
    v.limit("trials", "trials", c.trials, limits::CASE_TRIALS)?;
    v.limit(
        "curve_samples",
        "curve_samples",
        c.curve_samples,
        limits::CURVE_SAMPLES,
    )?;
    v.list("betas", c.betas.len())?;
    if c.betas
        .iter()
        .chain([&c.control_shift, &c.mutant_half_units])
        .any(|x| !x.is_finite())
    {
        return v.err("betas", "angles and shifts must be finite numbers".into());
    }
    v.names("counterexample.names", &c.counterexample.names)
}

pub(super) fn checks(c: &TwoFramesCase, v: &Validator) -> Result<()> {
    if c.counterexample.points.len() != 5 || c.counterexample.names.len() != 5 {
        return v.err(
            "counterexample.points",
            "needs the five points P, Q, R, Q′, R′".into(),
        );
    }
    if c.points < 4 || c.trials == 0 || c.curve_samples < 4 {
        return v.err(
            "points",
            "needs at least 4 points, 1 trial and 4 curve samples".into(),
        );
    }
    let in_range = |b: &f64| *b > 0.0 && *b < std::f64::consts::PI;
    if c.betas.len() < 2 || !c.betas.iter().all(in_range) {
        return v.err("betas", "needs at least two angles in (0, π)".into());
    }
    if !(c.control_shift > 0.0 && c.mutant_half_units > 1.0) {
        return v.err(
            "control_shift",
            "the control shift must be positive and the mutant more than one half unit".into(),
        );
    }
    Ok(())
}
