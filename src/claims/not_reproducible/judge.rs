//! The judge of claims without data: what the paper prints, and what a reproduction lacks.

use super::NotReproducibleCase;
use crate::check::Role;
use crate::check::{ClaimResult, Power, ResultBuilder, Value, Verdict};

/// One `not-reproducible` result per claim, naming what is missing.
pub(super) fn results(b: &ResultBuilder, c: &NotReproducibleCase) -> Vec<ClaimResult> {
    c.claims
        .iter()
        .map(|m| {
            let mut r = b
                .claim(&m.claim)
                .printed_as("paper", Value::label(m.printed.clone()), Role::ValueOnly)
                .method("nothing to compute: the paper does not print the data")
                .power(Power::none("no computation to control"));
            for missing in &m.missing {
                r = r.detail("missing", Value::label(missing.clone()));
            }
            r.verdict(Verdict::NotReproducible)
        })
        .collect()
}
