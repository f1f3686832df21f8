//! Where in the paper a case or claim comes from.

use serde::Deserialize;

/// Where in the paper a case or claim comes from.
#[derive(Clone, Debug, Deserialize, serde::Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Source {
    /// Section number as in the paper ("2.1", "A" for the appendix).
    pub section: String,
    /// Equation, table or figure label, if any.
    #[serde(default)]
    pub label: Option<String>,
    /// Line range in the LaTeX source.
    pub lines: String,
    /// A short quote.
    pub quote: String,
}

/// Another place of the source a claim cites: its lines and its exact words.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ClaimPlace {
    /// Line range, the tightest that holds the quote.
    pub lines: String,
    /// The source's words there.
    pub quote: String,
}

/// One claim of the inventory (paper_cases/claims.md) as a case refers to it.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ClaimRef {
    /// The claim id (paper_cases/claims.md).
    pub claim: String,
    /// The paper section, when it differs from the case's (a case may span sections).
    #[serde(default)]
    pub section: Option<String>,
    /// Line range.
    pub lines: String,
    /// A short quote.
    pub quote: String,
}
