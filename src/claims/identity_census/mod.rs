//! §5.2 and §5.3 over seeded scenes: the identity tests.

mod case;
mod judge;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for IdentityCensusCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        vec![("trials", self.trials)]
    }

    fn validate(&self, v: &Validator) -> Result<()> {
        v.limit(
            "trials",
            "trials",
            self.trials,
            crate::limits::IDENTITY_CENSUS_TRIALS,
        )?;
        v.list("c_factors", self.c_factors.len())?;
        case::checks(self, v)
    }

    fn seeds(&self) -> Vec<u64> {
        vec![self.seed]
    }

    fn run(&self, b: &ResultBuilder, _earlier: &[ClaimResult]) -> Result<Vec<ClaimResult>> {
        judge::results(b, self)
    }
}
