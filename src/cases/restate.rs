//! Restatements (discussion, conclusions) and claims the paper gives no data for.

use serde::Deserialize;

use super::ClaimRef;

/// Restatements of earlier claims.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct RestatementsCase {
    /// One per restated sentence or bullet.
    pub items: Vec<Restatement>,
}

/// One restatement.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Restatement {
    /// The claim.
    pub claim: ClaimRef,
    /// The result id's suffix.
    pub id: String,
    /// The claim id (paper_cases/claims.md)s it restates (every result of each counts); empty for a statement
    /// outside the paper's scope.
    #[serde(default)]
    pub restates: Vec<String>,
    /// Result ids of those claims the statement does not rest on (the reason in the case).
    #[serde(default)]
    pub except: Vec<String>,
    /// Why it is outside the scope, when `restates` is empty.
    #[serde(default)]
    pub out_of_scope: Option<String>,
}

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
