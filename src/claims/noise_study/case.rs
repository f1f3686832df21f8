//! The case schema of a noise study (§2, §3) as the paper reports it.

use serde::Deserialize;

use crate::cases::{ClaimRef, Printed, Validator};
use crate::claims::shared::NoiseLevel;
use crate::claims::shared::{levels, noise_work};
use crate::error::Result;
use crate::limits;

/// A noise study as the paper reports it.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct NoiseStudyCase {
    /// The solver the paper used.
    pub solver: crate::model::StudySolver,
    /// The body.
    pub body: NoiseBody,
    /// Frames per trial.
    pub frames: usize,
    /// Trials per level and noise model.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
    /// The levels the paper reports.
    pub levels: Vec<NoiseLevel>,
}

/// The body of a noise study: printed lengths (and squares, when printed).
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct NoiseBody {
    /// The claim about the printed body, if any.
    #[serde(default)]
    pub claim: Option<ClaimRef>,
    /// Printed lengths in edge order (PQ, QR, RP, then TP, TQ, TR for four points).
    pub lengths: Vec<Printed>,
    /// Printed squares, if printed.
    #[serde(default)]
    pub squares: Vec<Printed>,
    /// Significant digits the program printed the squares with.
    #[serde(default)]
    pub significant_digits: Option<u32>,
}

pub(super) fn sizes(c: &NoiseStudyCase, v: &Validator) -> Result<()> {
    v.limit("trials", "trials", c.trials, limits::NOISE_TRIALS)?;
    v.limit("frames", "frames", c.frames, limits::DOF_FRAMES)?;
    levels(v, "levels", &c.levels)?;
    noise_work(v, c.trials, c.levels.len(), c.frames)?;
    c.body
        .significant_digits
        .map_or(Ok(()), |d| v.digits("body.significant_digits", d))
}

pub(super) fn checks(c: &NoiseStudyCase, v: &Validator) -> Result<()> {
    use crate::model::StudySolver;
    let edges = match c.solver {
        StudySolver::P3f3 | StudySolver::P3f4 => 3,
        StudySolver::P4f3 => 6,
    };
    if c.body.lengths.len() != edges
        || !(c.body.squares.is_empty() || c.body.squares.len() == edges)
    {
        return v.err(
            "body.lengths",
            format!("the solver needs {edges} lengths (and {edges} squares if any)"),
        );
    }
    if let Some((i, words)) = crate::cases::contradicting_square(&c.body.lengths, &c.body.squares) {
        return v.err(&format!("body.squares[{i}]"), words);
    }
    // the body must exist: a triangle (or, for more points, realizable in 3-D), refused here
    // with the field rather than when the study runs
    let lengths: Vec<f64> = c.body.lengths.iter().map(|p| p.to_f64()).collect();
    let squares: Vec<f64> = c.body.squares.iter().map(|p| p.to_f64()).collect();
    if let Err(e) = crate::studies::noise::body_of(&lengths, &squares) {
        return v.err(
            "body.lengths",
            e.to_string().trim_start_matches("invalid input: ").into(),
        );
    }
    let frames_ok = match c.solver {
        StudySolver::P3f3 | StudySolver::P4f3 => c.frames == 3,
        StudySolver::P3f4 => c.frames >= 4,
    };
    if !frames_ok {
        return v.err(
            "frames",
            "p3f3 and p4f3 need 3 frames, p3f4 at least 4".into(),
        );
    }
    for (i, l) in c.levels.iter().enumerate() {
        if l.printed.is_empty() || l.printed.iter().any(|p| p.len() != edges) {
            return v.err(
                &format!("levels[{i}].printed"),
                format!("needs solutions of {edges} values"),
            );
        }
    }
    Ok(())
}
