//! The judge of restatements: a restatement holds as the results it restates hold.

use super::{Restatement, RestatementsCase};
use crate::check::{restated_verdict, ClaimResult, Power, ResultBuilder, Value, Verdict};

/// A restatement is contradicted when a result of a claim it restates is; it holds (with the
/// weakest verdict among them) when all of them hold; not reproducible when one is missing or
/// it lies outside the paper's scope.
pub(super) fn results(
    b: &ResultBuilder,
    case: &RestatementsCase,
    results: &[ClaimResult],
) -> Vec<ClaimResult> {
    case.items
        .iter()
        .map(|item| restatement(b, item, results))
        .collect()
}

fn restatement(b: &ResultBuilder, item: &Restatement, results: &[ClaimResult]) -> ClaimResult {
    let r = b
        .claim(&item.claim)
        .suffix(&item.id)
        .printed("statement", Value::label(item.claim.quote.clone()));
    if let Some(why) = &item.out_of_scope {
        return r
            .computed("outside the paper's scope", Value::label(why.clone()))
            .method("no computation: the statement concerns another model")
            .power(Power::none("outside the paper's model"))
            .verdict(Verdict::NotReproducible);
    }
    let mapped: Vec<&ClaimResult> = results
        .iter()
        .filter(|r| item.restates.contains(&r.claim) && !item.except.contains(&r.id))
        .collect();
    let missing = item
        .restates
        .iter()
        .any(|id| !mapped.iter().any(|r| &r.claim == id));
    let verdict = restated_verdict(mapped.iter().map(|r| r.verdict), missing);
    let mut r = r
        .method("the verdicts of the results of the claims restated")
        .power(Power::mutant(
            true,
            "any restated result that is contradicted, fails or is missing turns this one",
        ));
    for m in &mapped {
        r = r.computed(&m.id, Value::label(m.verdict.name()));
    }
    r.verdict(verdict)
}
