//! The case schema of identifiability decided by Jacobian rank (§2.1, the abstract).

use serde::Deserialize;

use crate::cases::{ClaimRef, Validator};
use crate::error::Result;
use crate::limits;

/// Identifiability claims over a grid.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DofIdentifiabilityCase {
    /// Seed of the generic scenes.
    pub seed: u64,
    /// Largest p of the grid.
    pub max_points: usize,
    /// Largest k of the grid.
    pub max_frames: usize,
    /// The printed count formula.
    pub formula: FormulaClaim,
    /// The printed minimum.
    pub minimum: MinimumClaim,
    /// "two frames never suffice".
    pub two_frames: ClaimRef,
}

/// The count formula as printed.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct FormulaClaim {
    /// The claim.
    pub claim: ClaimRef,
    /// Unknowns, in p and k, as printed.
    pub unknowns: String,
    /// Measurements, in p and k, as printed.
    pub measurements: String,
}

/// A claimed minimal configuration.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct MinimumClaim {
    /// The claim.
    pub claim: ClaimRef,
    /// Claimed minimal number of points.
    pub points: usize,
    /// Claimed minimal number of frames.
    pub frames: usize,
}

/// The sizes of a `DofIdentifiability` case.
pub(super) fn sizes(c: &DofIdentifiabilityCase, v: &Validator) -> Result<()> {
    v.limit("max_points", "max_points", c.max_points, limits::DOF_GRID)?;
    v.limit("max_frames", "max_frames", c.max_frames, limits::DOF_GRID)?;
    v.dof("minimum.points", c.minimum.points, c.minimum.frames)
}

pub(super) fn checks(c: &DofIdentifiabilityCase, v: &Validator) -> Result<()> {
    if c.max_points < 3 || c.max_frames < 3 {
        return v.err(
            "max_points",
            "the grid must reach at least 3 points and 3 frames".into(),
        );
    }
    v.formula("formula.unknowns", &c.formula.unknowns)?;
    v.formula("formula.measurements", &c.formula.measurements)
}
