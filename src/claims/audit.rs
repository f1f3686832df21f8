//! `orthocheck audit`: the items of every kind that audits the paper's formulas and text,
//! each a claim result with what it shows beside it.

use super::PaperCase;
use crate::check::ClaimResult;
use crate::check::ResultBuilder;
use crate::claims::shared::Place;
use crate::claims::twofold_squared::TwofoldAudit;
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

/// One exported SymPy script ([`super::ClaimKind::sympy_scripts`]).
#[derive(Clone, Debug)]
pub struct Script {
    /// The audit item's id (`claim/suffix`).
    pub id: String,
    /// A file name for it (the id with `/` as `__`, `.py`).
    pub file: String,
    /// The Python source.
    pub source: String,
}

/// What `orthocheck audit ID` shows of a case in full ([`super::ClaimKind::audit_in_full`]).
#[derive(Clone, Debug)]
pub enum InFull {
    /// Eq. p3f3sqr: the printed polynomial, its derivation and their comparison.
    TwofoldSquared(TwofoldAudit),
}

/// Which audit items a command asks for: every one, or those of one item id or claim id.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Wanted<'a> {
    /// Every item.
    All,
    /// The item of this id, or every item of this claim; an item's `/expanded` sibling is
    /// computed with it.
    Id(&'a str),
}

impl Wanted<'_> {
    /// Whether the item `id` of claim `claim` is asked for, as itself or as the item whose
    /// `/expanded` sibling is asked: a kind computes only those.
    pub fn item(&self, id: &str, claim: &str) -> bool {
        self.shows(id, claim)
            || matches!(self, Wanted::Id(w) if w.strip_suffix("/expanded") == Some(id))
    }

    /// Whether the item `id` of claim `claim` is one the command shows.
    pub fn shows(&self, id: &str, claim: &str) -> bool {
        match self {
            Wanted::All => true,
            Wanted::Id(w) => *w == id || *w == claim,
        }
    }
}

/// The audit items of the given cases that `wanted` asks for, in case order, each a claim
/// result and what it shows: each kind gives its own ([`super::ClaimKind::audit_items`]) and
/// computes only what is asked.
pub fn audit_all(cases: &[PaperCase], wanted: Wanted) -> Result<Vec<(ClaimResult, Shown)>> {
    let mut out = Vec::new();
    for case in cases {
        let b = ResultBuilder::new(case);
        out.extend(case.check.kind().audit_items(&b, &case.source, wanted)?);
    }
    Ok(out)
}
