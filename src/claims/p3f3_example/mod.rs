//! §2's worked example: three points in three frames.

mod case;
mod judge;
pub mod restricted;
pub mod study;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for P3f3ExampleCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        vec![("rounding_trials", self.rounding_trials)]
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
