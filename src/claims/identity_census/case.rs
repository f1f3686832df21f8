//! The case schema of the identity tests over seeded scenes (§5.2, §5.3).

use serde::Deserialize;

use crate::cases::{ClaimRef, Validator};
use crate::error::Result;

/// The identity tests over seeded random scenes.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct IdentityCensusCase {
    /// "Three traced points ensure that … we can identify the line".
    pub line: ClaimRef,
    /// The procedure (c, b, a, T_a, T_b) and its c.
    pub procedure: ClaimRef,
    /// §5.3: five points.
    pub five_points: ClaimRef,
    /// The abstract's and the conclusions' identification claim.
    pub tracing: ClaimRef,
    /// Random scenes.
    pub trials: usize,
    /// Values of c per scene, as multiples of the smallest allowed c.
    pub c_factors: Vec<f64>,
    /// The control: how far T₂ (and S₂) is moved off the body (fraction of the image size),
    /// which the same tests must then reject.
    pub control_shift: f64,
    /// Seed.
    pub seed: u64,
}

pub(super) fn checks(c: &IdentityCensusCase, v: &Validator) -> Result<()> {
    if c.trials == 0
        || c.c_factors.is_empty()
        || c.c_factors.iter().any(|f| f.is_nan() || *f < 1.0)
        || c.control_shift.is_nan()
        || c.control_shift <= 0.0
    {
        return v.err(
            "c_factors",
            "needs trials, factors of at least 1 and a positive control shift".into(),
        );
    }
    Ok(())
}
