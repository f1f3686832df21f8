//! Identifiability decided by Jacobian rank (§2.1, the abstract).

mod case;
mod judge;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for DofIdentifiabilityCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        Vec::new()
    }

    fn validate(&self, v: &Validator) -> Result<()> {
        case::sizes(self, v)?;
        case::checks(self, v)
    }

    fn seeds(&self) -> Vec<u64> {
        vec![self.seed]
    }

    fn run(&self, b: &ResultBuilder, _earlier: &[ClaimResult]) -> Result<Vec<ClaimResult>> {
        judge::results(b, self)
    }
}
