//! Every displayed formula and derivation step, machine-checked against its derivation.

mod case;
mod judge;
pub mod study;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for FormulaAuditCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        vec![("evaluation_points", self.evaluation_points)]
    }

    fn validate(&self, v: &Validator) -> Result<()> {
        v.limit(
            "evaluation_points",
            "evaluation_points",
            self.evaluation_points,
            crate::limits::EVALUATION_POINTS,
        )?;
        case::checks(self, v)
    }

    fn seeds(&self) -> Vec<u64> {
        vec![self.seed]
    }

    fn run(&self, b: &ResultBuilder, _earlier: &[ClaimResult]) -> Result<Vec<ClaimResult>> {
        judge::results(b, self)
    }

    fn audited() -> bool {
        true
    }

    fn audit_items(
        &self,
        b: &ResultBuilder,
        // each item names its own place
        _source: &crate::cases::Source,
        wanted: crate::claims::audit::Wanted,
    ) -> Result<Vec<(ClaimResult, crate::claims::audit::Shown)>> {
        let judged = |f: &FormulaItem| case::is_asked(&f.claim, &f.id, wanted);
        let items = judge::judged(b, &case::asked(self, wanted), &judged)?;
        Ok(items
            .into_iter()
            .filter(|(r, _)| wanted.shows(&r.id, &r.claim))
            .collect())
    }

    fn sympy_scripts(&self) -> Result<Vec<crate::claims::audit::Script>> {
        study::sympy_scripts(self)
    }
}
