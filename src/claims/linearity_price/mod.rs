//! §4's price of linearity: the paper's solvers against the standard method.

mod case;
mod judge;
pub mod study;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for LinearityPriceCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        vec![("trials", self.trials)]
    }

    fn validate(&self, v: &Validator) -> Result<()> {
        case::validate(self, v)
    }

    fn seeds(&self) -> Vec<u64> {
        vec![self.seed]
    }

    fn run(&self, b: &ResultBuilder, _earlier: &[ClaimResult]) -> Result<Vec<ClaimResult>> {
        judge::results(b, self)
    }
}
