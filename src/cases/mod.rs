//! The paper's data: the YAML files of `paper_cases/` (format in `docs/case-format.md`).
//!
//! The paper's numbers live only here. A printed number keeps its printed digits, which give
//! both its exact value and its precision.

mod audit;
mod counts;
mod errata;
mod examples;
mod formula_size;
mod identity;
mod latex;
mod linearity;
mod load;
mod noise;
mod origin;
mod paper;
mod printed;
mod restate;
mod sizes;
mod source;
mod validate;
mod verify;

pub use audit::*;
pub use counts::{LiteratureCount, PaperCount, SolutionCountCase};
pub use errata::{
    parse_lines, quote_at, quote_within, Balance, Configuration, Decision, Finding, FindingKind,
    LabelPicture, NamedPoint, Place as SourcePlace, PrintedLabel, SourceErrataCase, SourceText,
};
pub use examples::*;
pub use identity::*;
pub use latex::{sha256_hex, source_path, LatexSource, SourceRecord, PAPER_ENV};
pub use linearity::{LinearityBody, LinearityCase, PrintedRun, MAX_RANDOM_POINTS};
pub(crate) use load::line_of;
pub use load::{
    case_files, load_all, load_case, load_case_with, load_cases, parse_case, parse_yaml,
    parse_yaml_limited,
};
pub use noise::*;
pub use origin::CaseOrigin;
pub use paper::{load_paper, paper_of, parse_paper, Paper, SectionTitle, PAPER_FILE};
pub use printed::Printed;
pub use restate::*;
pub use source::{ClaimRef, Source};
pub use validate::parse_signs;
pub use verify::{load_inputs, unverified_sentence, verify, PaperInputs, Verification};

use std::path::PathBuf;

use serde::Deserialize;

/// A case file.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Case {
    /// Unique case id (also the snapshot name).
    pub id: String,
    /// Human title.
    pub title: String,
    /// Where the case sits in the paper.
    pub source: Source,
    /// What to check, by kind.
    pub check: CaseCheck,
    /// The file it was read from (set by [`load_case`]).
    #[serde(skip)]
    pub file: Option<PathBuf>,
}

/// The kinds of case; each kind has its runner in `check`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum CaseCheck {
    /// §2.1's worked counts.
    DofCount(DofCountCase),
    /// §2.1 and the abstract: identifiability decided by Jacobian rank.
    DofIdentifiability(DofIdentifiabilityCase),
    /// Eq. p3f3sqr and the signed relations.
    TwofoldSquared(TwofoldCase),
    /// §2's worked example.
    P3f3Example(P3f3ExampleCase),
    /// §4's worked example.
    P4f3Example(P4f3ExampleCase),
    /// §4's uniqueness over generic and degenerate scenes.
    P4f3Census(CensusCase),
    /// §2.2's solution count over generic and degenerate scenes.
    P3f3Census(CensusCase),
    /// §3's uniqueness over generic and special motions.
    P3f4Census(CensusCase),
    /// Claims the paper gives no data for: what is printed and what a reproduction lacks.
    NotReproducible(NotReproducibleCase),
    /// Every displayed formula and derivation step, machine-checked.
    FormulaAudit(FormulaAuditCase),
    /// §5.1 and §5.4: two frames are not enough; the counterexample; curves.
    TwoFrames(TwoFramesCase),
    /// §5.2 and §5.3 over seeded random scenes: the identity tests.
    IdentityCensus(IdentityCensusCase),
    /// §5.2's example: the frames, the hidden table, the debug printouts, the panels.
    IdentityExample(IdentityExampleCase),
    /// Restatements (discussion, conclusions): each decided by the claims it restates.
    Restatements(RestatementsCase),
    /// A noise study (§2, §3).
    NoiseStudy(NoiseStudyCase),
    /// Errata of the text, each quoted at its lines of the LaTeX source.
    SourceErrata(SourceErrataCase),
    /// Exact solution counts of three and four points in three frames, and the literature's.
    SolutionCount(SolutionCountCase),
    /// §4's price of linearity: the paper's solvers against the standard method.
    LinearityPrice(LinearityCase),
}

impl Case {
    /// Every seed the case sets (the report lists them, so that a run can be repeated).
    pub fn seeds(&self) -> Vec<u64> {
        match &self.check {
            CaseCheck::DofCount(c) => vec![c.seed],
            CaseCheck::DofIdentifiability(c) => vec![c.seed],
            CaseCheck::TwofoldSquared(c) => vec![c.relations.seed, c.seed],
            CaseCheck::P3f3Example(c) => vec![c.seed],
            CaseCheck::P4f3Example(c) => vec![c.seed],
            CaseCheck::P4f3Census(c) | CaseCheck::P3f3Census(c) | CaseCheck::P3f4Census(c) => {
                vec![c.seed]
            }
            CaseCheck::FormulaAudit(c) => vec![c.seed],
            CaseCheck::TwoFrames(c) => vec![c.seed],
            CaseCheck::IdentityCensus(c) => vec![c.seed],
            CaseCheck::IdentityExample(c) => vec![c.seed],
            CaseCheck::NoiseStudy(c) => vec![c.seed],
            CaseCheck::SolutionCount(c) => vec![c.seed],
            CaseCheck::LinearityPrice(c) => vec![c.seed],
            CaseCheck::NotReproducible(_)
            | CaseCheck::Restatements(_)
            | CaseCheck::SourceErrata(_) => Vec::new(),
        }
    }
}
