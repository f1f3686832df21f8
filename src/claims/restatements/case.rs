//! The case schema of restatements (discussion, conclusions).

use serde::Deserialize;

use crate::cases::{ClaimRef, Validator};
use crate::error::Result;

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

pub(super) fn checks(c: &RestatementsCase, v: &Validator) -> Result<()> {
    if let Some(i) = c
        .items
        .iter()
        .position(|r| r.restates.is_empty() == r.out_of_scope.is_none())
    {
        return v.err(
            &format!("items[{i}].restates"),
            "give either the claims it restates or why it is out of scope".into(),
        );
    }
    // an exception names a result of a restated claim: `claim` or `claim/suffix`
    if let Some(i) = c.items.iter().position(|r| {
        r.except.iter().any(|e| {
            let claim = e.split('/').next().unwrap_or(e);
            !r.restates.iter().any(|x| x == claim)
        })
    }) {
        return v.err(
            &format!("items[{i}].except"),
            "an exception must be a result of a claim the item restates".into(),
        );
    }
    Ok(())
}
