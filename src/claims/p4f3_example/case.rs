//! The case schema of §4's worked example.

use serde::Deserialize;

use crate::cases::{ClaimRef, Printed, Validator};
use crate::claims::shared::{body_digits, levels, noise_work};
use crate::claims::shared::{BodyTable, FigureFrames, NoiseLevel, PrintedSolutions};
use crate::error::Result;
use crate::limits;

/// §4's example: the edge table, the figure, the printed coefficient matrix and solution.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct P4f3ExampleCase {
    /// The edge table (PQ, QR, RP, TP, TQ, TR).
    pub body: BodyTable,
    /// The figure: three frames of P, Q, R, T.
    pub figure: FigureFrames,
    /// The printed coefficient matrix.
    pub matrix: PrintedMatrix,
    /// The printed solution x1 … x6.
    pub solution: PrintedSolutions,
    /// The claim the conditioning result answers.
    pub conditioning: ClaimRef,
    /// The claim of the system solved from the figure's printed digits, when judged.
    #[serde(default)]
    pub figure_system: Option<ClaimRef>,
    /// The printed noise runs: each level is judged against random motions of the body and
    /// against the figure's own scene.
    pub noise: Vec<NoiseLevel>,
    /// Shifts of the single-entry mutants of the printed matrix, in half units of the entry:
    /// the same witness search must fail for every mutant at the largest shift; the counts
    /// at each shift are reported.
    pub matrix_mutant_half_units: Vec<f64>,
    /// Monte Carlo trials per level, noise model and scene.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
}

/// A printed matrix: rows of printed numbers, the last column the constant.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PrintedMatrix {
    /// The claim.
    pub claim: ClaimRef,
    /// Significant digits the program printed with.
    pub significant_digits: u32,
    /// The rows as printed.
    pub rows: Vec<Vec<Printed>>,
}

pub(super) fn sizes(c: &P4f3ExampleCase, v: &Validator) -> Result<()> {
    v.limit("trials", "trials", c.trials, limits::NOISE_TRIALS)?;
    levels(v, "noise", &c.noise)?;
    noise_work(v, c.trials, c.noise.len(), 3)?;
    v.list("matrix_mutant_half_units", c.matrix_mutant_half_units.len())?;
    v.digits("matrix.significant_digits", c.matrix.significant_digits)?;
    v.digits("solution.significant_digits", c.solution.significant_digits)?;
    body_digits(v, "body.significant_digits", &c.body)
}

pub(super) fn checks(c: &P4f3ExampleCase, v: &Validator) -> Result<()> {
    let f = &c.figure.frames;
    if f.len() != 3 || f.iter().any(|fr| fr.len() != 4) {
        return v.err("figure.frames", "needs 3 frames of 4 points".into());
    }
    if c.body.lengths.len() != 6 || c.body.squares.len() != 6 {
        return v.err("body.lengths", "needs 6 lengths and 6 squares".into());
    }
    if c.matrix.rows.len() != 6 || c.matrix.rows.iter().any(|r| r.len() != 7) {
        return v.err(
            "matrix.rows",
            "needs 6 rows of 7 numbers (x1 … x6 and the constant)".into(),
        );
    }
    if let Some(i) = c
        .noise
        .iter()
        .position(|l| l.printed.is_empty() || l.printed.iter().any(|p| p.len() != 6))
    {
        return v.err(
            &format!("noise[{i}].printed"),
            "needs solutions of 6 values".into(),
        );
    }
    if c.matrix_mutant_half_units.is_empty()
        || c.matrix_mutant_half_units
            .iter()
            .any(|m| !(*m > 1.0 && m.is_finite()))
    {
        return v.err(
            "matrix_mutant_half_units",
            "needs shifts of more than one half unit".into(),
        );
    }
    if c.solution.values.len() != 1 || c.solution.values[0].len() != 6 {
        return v.err("solution.values", "needs one solution of 6 values".into());
    }
    Ok(())
}
