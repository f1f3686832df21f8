//! Claims the paper gives no data for: what is printed and what a reproduction lacks.

mod case;
mod judge;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for NotReproducibleCase {
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
        Ok(judge::results(b, self))
    }
}
