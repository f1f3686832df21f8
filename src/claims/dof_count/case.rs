//! The case schema of §2.1's worked counts, with its limits.

use serde::Deserialize;

use crate::cases::{ClaimRef, Printed, Validator};
use crate::error::Result;

/// §2.1 worked examples.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DofCountCase {
    /// Seed of the generic scene for the rank evidence.
    pub seed: u64,
    /// The printed examples.
    pub examples: Vec<DofExample>,
}

/// One printed count.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DofExample {
    /// The claim.
    pub claim: ClaimRef,
    /// p.
    pub points: usize,
    /// k.
    pub frames: usize,
    /// The printed −1+3p+5(k−1).
    pub unknowns: Printed,
    /// The printed 2kp.
    pub measurements: Printed,
}

/// The sizes of a `DofCount` case.
pub(super) fn sizes(c: &DofCountCase, v: &Validator) -> Result<()> {
    for (i, e) in c.examples.iter().enumerate() {
        v.dof(&format!("examples[{i}].points"), e.points, e.frames)?;
    }
    Ok(())
}

pub(super) fn checks(c: &DofCountCase, v: &Validator) -> Result<()> {
    for (i, e) in c.examples.iter().enumerate() {
        if e.points == 0 || e.frames == 0 {
            return v.err(
                &format!("examples[{i}].points"),
                "points and frames must be at least 1".into(),
            );
        }
    }
    Ok(())
}
