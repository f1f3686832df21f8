//! Restatements (discussion, conclusions): each decided by the results of the claims it restates.

mod case;
mod judge;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::ClaimKind;
use crate::error::Result;

impl ClaimKind for RestatementsCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        Vec::new()
    }

    fn validate(&self, v: &Validator) -> Result<()> {
        case::checks(self, v)
    }

    fn seeds(&self) -> Vec<u64> {
        Vec::new()
    }

    fn run(&self, b: &ResultBuilder, earlier: &[ClaimResult]) -> Result<Vec<ClaimResult>> {
        Ok(judge::results(b, self, earlier))
    }

    fn restates(&self) -> bool {
        true
    }

    fn result_supports(&self) -> Vec<(String, Vec<String>)> {
        self.items
            .iter()
            .map(|item| {
                (
                    format!("{}/{}", item.claim.claim, item.id),
                    item.restates.clone(),
                )
            })
            .collect()
    }

    fn restated_ids(&self) -> Vec<(String, String)> {
        self.items
            .iter()
            .enumerate()
            .flat_map(|(i, item)| {
                item.restates
                    .iter()
                    .map(move |id| (id.clone(), format!("items[{i}].restates")))
            })
            .collect()
    }
}
