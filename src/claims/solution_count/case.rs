//! The case schema of exact solution counts: what the paper says about the number of
//! solutions of three and four points in three frames, and what the literature prints.

use serde::Deserialize;

use crate::cases::{ClaimRef, Printed, Validator};
use crate::error::Result;

/// A count the paper states in words, with the number those words bound.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PaperCount {
    /// The claim decided.
    pub claim: ClaimRef,
    /// The paper's words for the count ("at most two").
    pub words: String,
    /// The largest number of edge-length solutions those words allow.
    pub at_most: Printed,
}

/// A count printed in another publication, with its source.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct LiteratureCount {
    /// The claim decided (an id of `additional-claims.md`).
    pub claim: ClaimRef,
    /// The publication: authors, title, year, where it was read.
    pub publication: String,
    /// Its words.
    pub quote: String,
    /// The printed ratio for three cameras and three points (the "64" of "64:1").
    pub three_points: Printed,
    /// The printed ratio for three cameras and four points.
    pub four_points: Printed,
}

/// Exact counts at seeded rational instances, against the paper's words and the literature.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct SolutionCountCase {
    /// §2.2: three points, three frames.
    pub three_points: PaperCount,
    /// §4: four points, three frames.
    pub four_points: PaperCount,
    /// Knill & Ramirez-Herran's ratios.
    pub literature: LiteratureCount,
    /// Rational instances per configuration.
    pub instances: usize,
    /// Seed of the first instance (the others follow it).
    pub seed: u64,
}

/// The printed counts must be whole numbers (they are counts of solutions).
pub(super) fn checks(c: &SolutionCountCase, v: &Validator) -> Result<()> {
    let fields = [
        ("three_points.at_most", &c.three_points.at_most),
        ("four_points.at_most", &c.four_points.at_most),
        ("literature.three_points", &c.literature.three_points),
        ("literature.four_points", &c.literature.four_points),
    ];
    for (field, p) in fields {
        if p.to_integer().is_none() || p.value < num_rational::BigRational::from_integer(0.into()) {
            return v.err(
                field,
                format!("`{}` is not a whole number of solutions", p.text),
            );
        }
    }
    Ok(())
}
