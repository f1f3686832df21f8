//! The case schema of claims the paper gives no data for.

use serde::Deserialize;

use crate::cases::{ClaimRef, Validator};
use crate::error::Result;

/// Claims without data.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct NotReproducibleCase {
    /// One entry per claim.
    pub claims: Vec<MissingData>,
}

/// One claim the paper gives no data for.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct MissingData {
    /// The claim.
    pub claim: ClaimRef,
    /// What the paper does print about it.
    pub printed: String,
    /// What a reproduction would need and the paper does not give.
    pub missing: Vec<String>,
}

pub(super) fn checks(c: &NotReproducibleCase, v: &Validator) -> Result<()> {
    if let Some(i) = c.claims.iter().position(|m| m.missing.is_empty()) {
        return v.err(
            &format!("claims[{i}].missing"),
            "say what is missing".into(),
        );
    }
    Ok(())
}
