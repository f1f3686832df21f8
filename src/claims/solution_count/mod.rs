//! Exact solution counts of three and four points in three frames, and the literature's.

mod case;
mod judge;
pub mod study;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for SolutionCountCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        vec![("instances", self.instances)]
    }

    fn validate(&self, v: &Validator) -> Result<()> {
        v.limit(
            "instances",
            "instances",
            self.instances,
            crate::limits::COUNT_INSTANCES,
        )?;
        case::checks(self, v)
    }

    fn seeds(&self) -> Vec<u64> {
        vec![self.seed]
    }

    fn run(&self, b: &ResultBuilder, _earlier: &[ClaimResult]) -> Result<Vec<ClaimResult>> {
        judge::results(b, self)
    }
}
