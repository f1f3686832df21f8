//! Eq. p3f3sqr: the signed relations and their twofold squaring.

mod case;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for TwofoldCase {
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
        crate::check::twofold::check(b, self)
    }
}
