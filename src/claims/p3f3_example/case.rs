//! The case schema of §2's worked example.

use serde::Deserialize;

use crate::cases::{ClaimRef, Validator};
use crate::claims::shared::body_digits;
use crate::claims::shared::{BodyTable, FigureFrames, PrintedSolutions};
use crate::error::Result;
use crate::limits;

/// §2's example.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct P3f3ExampleCase {
    /// The body table.
    pub body: BodyTable,
    /// The figure.
    pub figure: FigureFrames,
    /// The printed solutions.
    pub solutions: PrintedSolutions,
    /// The feasibility rules, applied to the printed solutions.
    pub feasibility: ClaimRef,
    /// The claim of the rounding analysis restricted to exact views of the body, when judged.
    #[serde(default)]
    pub restricted: Option<ClaimRef>,
    /// The claim of the quadratic's discriminant at the printed data, when judged.
    #[serde(default)]
    pub discriminant: Option<ClaimRef>,
    /// Monte Carlo samples of the rounding box.
    pub rounding_trials: usize,
    /// Seed.
    pub seed: u64,
}

/// The sizes of a `P3f3Example` case.
pub(super) fn sizes(c: &P3f3ExampleCase, v: &Validator) -> Result<()> {
    v.limit(
        "rounding_trials",
        "rounding_trials",
        c.rounding_trials,
        limits::ROUNDING_TRIALS,
    )?;
    v.digits(
        "solutions.significant_digits",
        c.solutions.significant_digits,
    )?;
    body_digits(v, "body.significant_digits", &c.body)
}

pub(super) fn checks(c: &P3f3ExampleCase, v: &Validator) -> Result<()> {
    let f = &c.figure.frames;
    if f.len() != 3 || f.iter().any(|fr| fr.len() != 3) {
        return v.err("figure.frames", "needs 3 frames of 3 points".into());
    }
    if c.body.lengths.len() != 3 || c.body.squares.len() != 3 {
        return v.err("body.lengths", "needs 3 lengths and 3 squares".into());
    }
    if c.solutions.values.len() > 2 || c.solutions.values.iter().any(|s| s.len() != 3) {
        return v.err(
            "solutions.values",
            "at most 2 solutions of 3 squared edges".into(),
        );
    }
    Ok(())
}
