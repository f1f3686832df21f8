//! The paper's data: the YAML files of `paper_cases/` (format in `docs/case-format.md`).
//!
//! The paper's numbers live only here. A printed number keeps its printed digits, which give
//! both its exact value and its precision.

mod corrections;
mod formula_size;
mod inventory;
mod latex;
mod load;
mod normalise;
mod origin;
mod paper;
mod plain_numbers;
mod printed;
mod quote;
mod source;
mod supports;
mod validate;
mod verify;

pub use corrections::{corrections_of, Correction, CORRECTIONS_FILE};
pub use formula_size::Size as FormulaSize;
pub use inventory::{inventory_ids, refers_to_inventory, INVENTORY_FILES};
pub use latex::{sha256_hex, source_path, LatexSource, SourceRecord, PAPER_ENV};
pub(crate) use load::line_of;
pub use load::{
    case_files, load_all, load_case, load_cases, load_cases_of, parse_case, parse_yaml,
    parse_yaml_limited, Kinds,
};
pub use normalise::Canonical;
pub use origin::CaseOrigin;
pub use paper::{
    load_paper, paper_of, parse_paper, section_depth, section_key, Paper, SectionTitle, PAPER_FILE,
};
pub use printed::{contradicting_square, Printed};
pub use quote::{parse_lines, quote_at, quote_within, SourceText};
pub use source::{ClaimPlace, ClaimRef, Source};
pub use validate::Validator;
pub use verify::{
    load_inputs, load_inputs_of, unverified_sentence, verify, Disagreement, PaperInputs,
    SourceCheck, SourceFact, Verification,
};

use std::path::PathBuf;

use serde::Deserialize;

/// A case file: its id, title and place in the paper, and its check `C`, one of the kinds
/// of the claims module.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Case<C> {
    /// Unique case id (also the snapshot name).
    pub id: String,
    /// Human title.
    pub title: String,
    /// Where the case sits in the paper.
    pub source: Source,
    /// What each claim of the case rests on in the paper's argument: claim id → the claim
    /// ids it uses (checked at load: the case's own claims, known supports, no cycle).
    #[serde(default)]
    pub rests_on: std::collections::BTreeMap<String, Vec<String>>,
    /// What to check, by kind.
    pub check: C,
    /// The file it was read from (set by [`load_case`]).
    #[serde(skip)]
    pub file: Option<PathBuf>,
}

/// What the loader asks of a case's check: the checks serde cannot express, and the two
/// things only the whole folder or the source can tell.
pub trait Schema: serde::de::DeserializeOwned + Send {
    /// Counts, limits, formulas that parse; `v` names fields from the case's top level.
    fn validate(&self, v: &Validator) -> crate::error::Result<()>;

    /// The facts of the source the case records beyond its quotes (every quote is verified
    /// anyway), checked whenever the source is given.
    fn source_checks(&self) -> Vec<SourceCheck>;

    /// Claim ids the case restates, each with its field: every one must be a claim some case
    /// of the folder refers to.
    fn restated_ids(&self) -> Vec<(String, String)>;
}
