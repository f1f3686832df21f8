//! Noise studies as the paper reports them: the printed levels and their statements, and
//! the judge of a level against its seeded distributions.

use serde::Deserialize;

use crate::cases::{ClaimRef, Printed, Validator};
use crate::check::noise::Claim;
use crate::error::Result;

pub use crate::check::noise::Direction;
use crate::limits;

mod figure;
mod judge;

pub(crate) use judge::{setting, Context};

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
    /// The sentence's words that name no bound ("which seems to be quite satisfactory"):
    /// shown as not judged.
    #[serde(default)]
    pub unjudged: Option<String>,
}

/// "error below 0.2 %", "deviates more than 15 %", "average performance within 20 %"
/// (how each is read: `docs/verdicts.md`).
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Statement {
    /// Whether it is about the printed example or about the mean over trials: one, or each
    /// reading the words leave open (`[example, typical_trial]`).
    pub about: Subjects,
    /// Which reading the words name and which they leave open, argued from the sentence: the
    /// evidence shows it beside each reading's value.
    pub argued: String,
    /// The bound is an upper one ("below") or a lower one ("above").
    pub direction: Direction,
    /// The bound as a fraction ("0.002" for 0.2 %).
    pub bound: Printed,
    /// How the edges' errors combine, when the sentence names it: the worst edge or their
    /// mean ("on average"); absent: both readings.
    #[serde(default)]
    pub over_edges: Option<OverEdges>,
    /// What the error is measured in, when the sentence names it ("errors for edge
    /// lengths"); absent: both squares and lengths.
    #[serde(default)]
    pub quantity: Option<Quantity>,
}

/// One subject, or several readings of it.
#[derive(Clone, Debug, Deserialize, PartialEq, Eq)]
#[serde(untagged)]
pub enum Subjects {
    /// The one the sentence names.
    One(StatementSubject),
    /// The readings the sentence leaves open, the first the one drawn.
    Many(Vec<StatementSubject>),
}

impl Subjects {
    /// Every subject, the first the one drawn.
    pub fn list(&self) -> Vec<StatementSubject> {
        match self {
            Subjects::One(s) => vec![*s],
            Subjects::Many(v) => v.clone(),
        }
    }
}

/// How a statement combines the errors of the edges.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum OverEdges {
    /// The largest error over the edges.
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

/// A case's noise study within [`limits::CASE_NOISE_WORK`]: trials × levels × frames, the
/// measure its time grows with.
pub fn noise_work(v: &Validator, trials: usize, levels: usize, frames: usize) -> Result<()> {
    v.limit(
        "trials",
        "trials × levels × frames",
        trials.saturating_mul(levels).saturating_mul(frames),
        limits::CASE_NOISE_WORK,
    )
}

/// ε of each level in [0, 1] (a negative ε empties the sampler's range).
pub fn levels(v: &Validator, at: &str, levels: &[NoiseLevel]) -> Result<()> {
    v.list(at, levels.len())?;
    if levels.len() > limits::NOISE_LEVELS {
        return v.err(
            at,
            format!(
                "more than {} noise levels (see docs/limits.md)",
                limits::NOISE_LEVELS
            ),
        );
    }
    for (i, l) in levels.iter().enumerate() {
        if let Err(m) = limits::noise_level("level", l.level.to_f64()) {
            return v.err(&format!("{at}[{i}].level"), m);
        }
    }
    Ok(())
}

/// The claim of a level under each subject its sentence may have, the first the one drawn.
pub(crate) fn claims_of(lv: &NoiseLevel) -> Vec<Claim> {
    match &lv.statement {
        None => vec![Claim::Typical],
        Some(st) => st
            .about
            .list()
            .into_iter()
            .map(|s| match s {
                StatementSubject::Example => Claim::Example(st.bound.to_f64(), st.direction),
                StatementSubject::TypicalTrial => Claim::Median(st.bound.to_f64(), st.direction),
            })
            .collect(),
    }
}

/// The claim of a level under the subject drawn.
pub(crate) fn claim_of(lv: &NoiseLevel) -> Claim {
    claims_of(lv)[0]
}

/// The readings of a level's sentence, as metrics: what it names is fixed, what it leaves
/// open takes both values. The first is the quantity the printed values are (`read_as`) and
/// the largest error, where the sentence leaves them open: the reading the figure shows.
pub(crate) fn readings(st: Option<&Statement>, read_as: Quantity) -> Vec<usize> {
    let other = match read_as {
        Quantity::Squares => Quantity::Lengths,
        Quantity::Lengths => Quantity::Squares,
    };
    let quantities = st
        .and_then(|s| s.quantity)
        .map_or(vec![read_as, other], |q| vec![q]);
    let edges = st
        .and_then(|s| s.over_edges)
        .map_or(vec![OverEdges::Max, OverEdges::Mean], |e| vec![e]);
    quantities
        .iter()
        .flat_map(|&q| edges.iter().map(move |&e| metric_of(q, e)))
        .collect()
}

/// The metric of a reading: the quantity (squares or lengths) and how the edges combine.
pub(crate) fn metric_of(quantity: Quantity, edges: OverEdges) -> usize {
    let q = if quantity == Quantity::Lengths { 2 } else { 0 };
    q + usize::from(edges == OverEdges::Mean)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn readings_map_to_metrics() {
        assert_eq!(metric_of(Quantity::Squares, OverEdges::Max), 0);
        assert_eq!(metric_of(Quantity::Squares, OverEdges::Mean), 1);
        assert_eq!(metric_of(Quantity::Lengths, OverEdges::Max), 2);
        assert_eq!(metric_of(Quantity::Lengths, OverEdges::Mean), 3);
    }

    #[test]
    fn a_sentence_fixes_what_it_names_and_leaves_the_rest_open() {
        use crate::check::noise::Direction;
        let st = |quantity, over_edges| Statement {
            about: Subjects::One(StatementSubject::Example),
            argued: String::new(),
            direction: Direction::Below,
            bound: Printed::parse("0.2").unwrap(),
            over_edges,
            quantity,
        };
        // nothing named: the printed values' quantity first, both combinations of each
        assert_eq!(readings(None, Quantity::Squares), vec![0, 1, 2, 3]);
        assert_eq!(readings(None, Quantity::Lengths), vec![2, 3, 0, 1]);
        // §4: "on average, errors for edge lengths": one reading
        let named = st(Some(Quantity::Lengths), Some(OverEdges::Mean));
        assert_eq!(readings(Some(&named), Quantity::Squares), vec![3]);
        let lengths = st(Some(Quantity::Lengths), None);
        assert_eq!(readings(Some(&lengths), Quantity::Squares), vec![2, 3]);
    }
}
