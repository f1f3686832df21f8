//! The case schema of eq. p3f3sqr and its signed relations.

use serde::Deserialize;

use crate::cases::{ClaimRef, Validator};
use crate::error::Result;
use crate::limits;

/// Eq. p3f3sqr.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct TwofoldSquaredCase {
    /// The three signed relations.
    pub relations: RelationsClaim,
    /// The printed polynomial.
    pub polynomial: PolynomialClaim,
    /// Random points (modulo word primes) for the independent evaluation check.
    pub evaluation_points: usize,
    /// Seed of those points.
    pub seed: u64,
}

/// The printed sign patterns.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct RelationsClaim {
    /// The claim.
    pub claim: ClaimRef,
    /// Patterns such as `"+ + -"` for √A + √B − √C = 0.
    pub patterns: Vec<String>,
    /// Random triangles to test.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
}

/// A printed polynomial.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PolynomialClaim {
    /// The claim.
    pub claim: ClaimRef,
    /// The transcription.
    pub printed: String,
}

/// The sizes of a `TwofoldSquared` case.
pub(super) fn sizes(c: &TwofoldSquaredCase, v: &Validator) -> Result<()> {
    v.limit(
        "evaluation_points",
        "evaluation_points",
        c.evaluation_points,
        limits::EVALUATION_POINTS,
    )?;
    v.limit(
        "relations.trials",
        "trials",
        c.relations.trials,
        limits::CASE_TRIALS,
    )?;
    v.list("relations.patterns", c.relations.patterns.len())
}

pub(super) fn checks(c: &TwofoldSquaredCase, v: &Validator) -> Result<()> {
    for (i, p) in c.relations.patterns.iter().enumerate() {
        if parse_signs(p).is_none() {
            return v.err(
                &format!("relations.patterns[{i}]"),
                format!("'{p}' is not three signs such as \"+ + -\""),
            );
        }
    }
    v.formula("polynomial.printed", &c.polynomial.printed)
}

/// Parse a sign pattern `"+ + -"`.
pub fn parse_signs(text: &str) -> Option<[i64; 3]> {
    let signs: Vec<i64> = text
        .split_whitespace()
        .map(|t| match t {
            "+" => Some(1),
            "-" => Some(-1),
            _ => None,
        })
        .collect::<Option<_>>()?;
    signs.try_into().ok()
}
