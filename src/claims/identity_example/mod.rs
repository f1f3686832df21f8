//! §5.2's example: the frames, the hidden table, the debug printouts, the panels.

pub mod author_program;
mod case;
mod judge;
pub mod panels;
pub mod ranking;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for IdentityExampleCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        vec![("census_trials", self.census_trials)]
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
