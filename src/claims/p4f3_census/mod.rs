//! §4's uniqueness over generic and degenerate scenes.

mod judge;

use serde::Deserialize;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::shared::census as census_checks;
use crate::claims::shared::CensusDesign;
use crate::claims::ClaimKind;
use crate::error::Result;

/// The census case (its schema shared with the other censuses).
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(transparent)]
pub struct P4f3CensusCase(pub CensusDesign);

impl ClaimKind for P4f3CensusCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        vec![("trials", self.0.trials)]
    }

    fn validate(&self, v: &Validator) -> Result<()> {
        census_checks::sizes(&self.0, v)?;
        census_checks::p4f3_checks(&self.0, v)
    }

    fn seeds(&self) -> Vec<u64> {
        vec![self.0.seed]
    }

    fn run(&self, b: &ResultBuilder, _earlier: &[ClaimResult]) -> Result<Vec<ClaimResult>> {
        judge::results(b, &self.0)
    }
}
