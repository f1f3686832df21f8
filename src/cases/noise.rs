//! Noise studies as the paper reports them.

use serde::Deserialize;

use super::{ClaimRef, Printed};

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

/// What the paper's symbols say the printed values are.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// a², b², c².
    Squares,
    /// a, b, c.
    Lengths,
}

/// One noise level as reported.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct NoiseLevel {
    /// The claim.
    pub claim: ClaimRef,
    /// ε as printed ("up to 0.1 %" is "0.001").
    pub level: Printed,
    /// What the printed symbols say the values are.
    pub labelled_as: Quantity,
    /// The printed run's solutions; the first is the one compared with the truth.
    pub printed: Vec<Vec<Printed>>,
    /// A numeric statement about the errors, if the paper makes one.
    #[serde(default)]
    pub statement: Option<Statement>,
}

/// "error below 0.2 %", "deviates more than 15 %", "average performance within 20 %"
/// (how each is read: `docs/verdicts.md`).
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Statement {
    /// Whether it is about the printed example or about the mean over trials.
    pub about: StatementSubject,
    /// The bound is an upper one ("below") or a lower one ("above").
    pub direction: Direction,
    /// The bound as a fraction ("0.002" for 0.2 %).
    pub bound: Printed,
    /// How the edges' errors combine: the worst edge (default) or their mean ("on average").
    #[serde(default)]
    pub over_edges: OverEdges,
    /// What the error is measured in when the paper names it ("errors for edge lengths");
    /// absent: the quantity the printed values are.
    #[serde(default)]
    pub quantity: Option<Quantity>,
}

/// How a statement combines the errors of the edges.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum OverEdges {
    /// The largest error over the edges.
    #[default]
    Max,
    /// The mean error over the edges.
    Mean,
}

/// The subject of a statement.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum StatementSubject {
    /// The printed run.
    Example,
    /// The trials as a whole ("the average performance"): judged by the median trial.
    TypicalTrial,
}

/// Below or above.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum Direction {
    /// The error is below the bound.
    Below,
    /// The error is above the bound.
    Above,
}
