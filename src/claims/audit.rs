//! `orthocheck audit`: the items of every kind that audits the paper's formulas and text,
//! each a claim result with what it shows beside it.

use super::Case;
use crate::check::ClaimResult;
use crate::check::ResultBuilder;
use crate::claims::formula_audit::Place;
use crate::error::Result;

/// What an audit item shows beside its claim result.
pub struct Shown {
    /// Where the item stands.
    pub place: Place,
    /// As printed.
    pub printed: String,
    /// The defect, if any.
    pub defect: Option<String>,
    /// What it should be.
    pub should_be: String,
}

/// Every audit item of the given cases, in case order, each a claim result and what it
/// shows: each kind gives its own ([`super::ClaimKind::audit_items`]).
pub fn audit_all(cases: &[Case]) -> Result<Vec<(ClaimResult, Shown)>> {
    let mut out = Vec::new();
    for case in cases {
        let b = ResultBuilder::new(case);
        out.extend(case.check.kind().audit_items(&b, &case.source)?);
    }
    Ok(out)
}
