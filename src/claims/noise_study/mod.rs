//! A noise study (§2, §3): the paper's statements about errors under noise.

mod case;
mod judge;
pub mod request;

pub(crate) use judge::check_runs_of_body;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for NoiseStudyCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        vec![("trials", self.trials)]
    }

    fn validate(&self, v: &Validator) -> Result<()> {
        case::sizes(self, v)?;
        case::checks(self, v)
    }

    fn seeds(&self) -> Vec<u64> {
        vec![self.seed]
    }

    fn run(&self, b: &ResultBuilder, _earlier: &[ClaimResult]) -> Result<Vec<ClaimResult>> {
        judge::check(b, self)
    }
}
