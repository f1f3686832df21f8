//! Eq. p3f3sqr: the signed relations and their twofold squaring.

mod case;
mod judge;
pub mod study;

pub use judge::{audit, TwofoldAudit};

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for TwofoldSquaredCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        vec![
            ("relations.trials", self.relations.trials),
            ("evaluation_points", self.evaluation_points),
        ]
    }

    fn validate(&self, v: &Validator) -> Result<()> {
        case::sizes(self, v)?;
        case::checks(self, v)
    }

    fn seeds(&self) -> Vec<u64> {
        vec![self.relations.seed, self.seed]
    }

    fn run(&self, b: &ResultBuilder, _earlier: &[ClaimResult]) -> Result<Vec<ClaimResult>> {
        judge::results(b, self)
    }

    fn audited() -> bool {
        true
    }

    fn audit_in_full(&self) -> Option<Result<crate::claims::audit::InFull>> {
        Some(judge::audit(self).map(crate::claims::audit::InFull::TwofoldSquared))
    }

    fn audit_items(
        &self,
        b: &ResultBuilder,
        source: &crate::cases::Source,
        wanted: crate::claims::audit::Wanted,
    ) -> Result<Vec<(ClaimResult, crate::claims::audit::Shown)>> {
        let id = &self.polynomial.claim.claim;
        if !wanted.item(id, id) {
            return Ok(Vec::new());
        }
        let (r, derived) = judge::audit_item(b, self)?;
        let shown = crate::claims::audit::Shown {
            place: crate::claims::shared::Place {
                section: source.section.clone(),
                label: source.label.clone(),
                macros: Vec::new(),
            },
            printed: format!("{} = 0", self.polynomial.printed),
            defect: None,
            should_be: format!(
                "±√(a²−aᵢ²) ± √(b²−bᵢ²) ± √(c²−cᵢ²) = 0 squared twice: {} = 0",
                derived
            ),
        };
        Ok(vec![(r, shown)])
    }
}
