//! The report as data: the claim results, figures and provenance of a run, what `report.json`
//! holds and every renderer reads.

use std::collections::BTreeMap;

use serde::Serialize;

use crate::cases::Paper;
use crate::check::{ClaimResult, Verdict};
use crate::provenance::Provenance;

/// The whole report: what `report.json` holds.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// The paper, as its cases folder names it ([`crate::cases::load_paper`]); none for a
    /// report built from claims alone.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub paper: Option<Paper>,
    /// Tool name and version.
    pub tool: String,
    /// Revision, date, command, seeds.
    pub provenance: Provenance,
    /// Every claim result, in case order.
    pub claims: Vec<ClaimResult>,
    /// The figures the checks drew, as data.
    pub figures: Vec<crate::check::figure::Figure>,
    /// Count per verdict (every verdict listed, zeros included).
    pub summary: BTreeMap<String, usize>,
    /// The paper's main results with their standing (docs/verdicts.md, "Main results"):
    /// those its paper file names.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub main_results: Vec<crate::check::standing::MainResult>,
}

impl Report {
    /// Build a report from claim results.
    pub fn new(claims: Vec<ClaimResult>) -> Report {
        Report::with(claims, Vec::new(), Provenance::default())
    }

    /// Build a report from claim results, figures and provenance.
    pub fn with(
        claims: Vec<ClaimResult>,
        figures: Vec<crate::check::figure::Figure>,
        provenance: Provenance,
    ) -> Report {
        let mut summary: BTreeMap<String, usize> = Verdict::ALL
            .iter()
            .map(|v| (v.name().to_string(), 0))
            .collect();
        for c in &claims {
            *summary.entry(c.verdict.name().to_string()).or_default() += 1;
        }
        Report {
            paper: None,
            tool: format!("orthocheck {}", env!("CARGO_PKG_VERSION")),
            provenance,
            claims,
            figures,
            summary,
            main_results: Vec::new(),
        }
    }

    /// The report of the paper's run, with `provenance` completed by the run's seeds (and
    /// the report command, when it names none).
    pub fn from_run(run: crate::claims::PaperRun, mut provenance: Provenance) -> Report {
        if provenance.command.is_empty() {
            provenance.command = crate::provenance::REPORT_COMMAND.into();
        }
        provenance.seeds = run.seeds;
        Report::with(run.results, run.figures, provenance)
    }

    /// The same report, naming its paper, with the main results the paper file names.
    pub fn with_paper(self, paper: Paper) -> Report {
        let main_results = crate::claims::supports::main_results(&paper.main_results, &self.claims);
        Report {
            paper: Some(paper),
            main_results,
            ..self
        }
    }

    /// Pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }
}
