//! Errata of the text, each quoted at its lines of the LaTeX source.

mod case;
pub mod figure_labels;
mod judge;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for SourceErrataCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        Vec::new()
    }

    fn validate(&self, v: &Validator) -> Result<()> {
        case::checks(self, v)
    }

    fn seeds(&self) -> Vec<u64> {
        Vec::new()
    }

    fn run(&self, b: &ResultBuilder, _earlier: &[ClaimResult]) -> Result<Vec<ClaimResult>> {
        judge::results(b, self)
    }

    fn source_checks(&self) -> Vec<crate::cases::SourceCheck> {
        SourceErrataCase::source_checks(self)
    }

    fn audited() -> bool {
        true
    }

    fn audit_items(
        &self,
        b: &ResultBuilder,
        _source: &crate::cases::Source,
        wanted: crate::claims::audit::Wanted,
    ) -> Result<Vec<(ClaimResult, crate::claims::audit::Shown)>> {
        let asked = SourceErrataCase {
            findings: self
                .findings
                .iter()
                .filter(|f| wanted.item(&format!("{}/{}", f.claim.claim, f.id), &f.claim.claim))
                .cloned()
                .collect(),
        };
        let results = judge::results(b, &asked)?;
        Ok(asked
            .findings
            .iter()
            .zip(&results)
            .map(|(f, r)| {
                let shown = crate::claims::audit::Shown {
                    place: crate::claims::shared::Place {
                        section: r.section.clone(),
                        label: None,
                        macros: Vec::new(),
                    },
                    printed: f.claim.quote.clone(),
                    defect: Some(f.defect.clone()),
                    should_be: f.corrected.clone(),
                };
                (r.clone(), shown)
            })
            .collect())
    }
}
