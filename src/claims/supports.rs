//! What each result rests on, and the paper's main results with their standing: the
//! argument as the cases record it (`rests_on`, a restatement's `restates`).

use std::collections::{BTreeMap, BTreeSet};

use super::PaperCase;
use crate::check::standing::{standing, MainResult};
use crate::check::ClaimResult;

/// Give every result its supports: its own (a restatement's) when it has them, else those the
/// cases record for its claim (the union over the cases naming it).
pub fn attach(results: &mut [ClaimResult], cases: &[PaperCase]) {
    let mut by_claim: BTreeMap<&str, BTreeSet<&str>> = BTreeMap::new();
    for c in cases {
        for (claim, supports) in &c.rests_on {
            by_claim
                .entry(claim)
                .or_default()
                .extend(supports.iter().map(String::as_str));
        }
    }
    let by_result: BTreeMap<String, Vec<String>> = cases
        .iter()
        .flat_map(|c| c.check.kind().result_supports())
        .collect();
    for r in results.iter_mut() {
        r.rests_on = match by_result.get(&r.id) {
            Some(own) => own.clone(),
            None => by_claim
                .get(r.claim.as_str())
                .map(|s| s.iter().map(|x| x.to_string()).collect())
                .unwrap_or_default(),
        };
    }
}

/// Every claim the claims `start` rest on, transitively (`start` not included unless a cycle
/// leads back to it, which the loader refuses).
pub fn closure(start: &[String], results: &[ClaimResult]) -> BTreeSet<String> {
    let mut supports: BTreeMap<&str, BTreeSet<&str>> = BTreeMap::new();
    for r in results {
        supports
            .entry(&r.claim)
            .or_default()
            .extend(r.rests_on.iter().map(String::as_str));
    }
    let mut seen: BTreeSet<String> = BTreeSet::new();
    let mut todo: Vec<&str> = start.iter().map(String::as_str).collect();
    while let Some(c) = todo.pop() {
        if seen.insert(c.to_string()) {
            todo.extend(supports.get(c).into_iter().flatten().copied());
        }
    }
    seen
}

/// The main results: each claim of `ids` in that order, one entry for the claim when its
/// results rest on the same claims, one per result when they do not (the conclusions'
/// restatements, each a sentence of its own). A note on a claim's wording is not one of its
/// results here: it changes no meaning; a claim the run did not check is left out.
pub fn main_results(ids: &[String], results: &[ClaimResult]) -> Vec<MainResult> {
    let mut out = Vec::new();
    for id in ids {
        let own: Vec<&ClaimResult> = results
            .iter()
            .filter(|r| &r.claim == id && r.verdict != crate::check::Verdict::Note)
            .collect();
        // a run of some cases only says nothing of the claims it did not check
        if own.is_empty() {
            continue;
        }
        let alike = own.windows(2).all(|w| w[0].rests_on == w[1].rests_on);
        let groups: Vec<(String, Vec<&ClaimResult>)> = if alike {
            vec![(id.clone(), own)]
        } else {
            own.into_iter().map(|r| (r.id.clone(), vec![r])).collect()
        };
        for (gid, group) in groups {
            out.push(main_result(gid, &group, results));
        }
    }
    out
}

fn main_result(id: String, own: &[&ClaimResult], results: &[ClaimResult]) -> MainResult {
    let direct: Vec<String> = own.first().map(|r| r.rests_on.clone()).unwrap_or_default();
    let support = closure(&direct, results);
    let counted: Vec<&ClaimResult> = own
        .iter()
        .copied()
        .chain(results.iter().filter(|r| support.contains(&r.claim)))
        .collect();
    let missing: Vec<String> = support
        .iter()
        .filter(|c| !results.iter().any(|r| &r.claim == *c))
        .cloned()
        .collect();
    let decided = standing(&counted, &missing);
    let first = own.first();
    MainResult {
        id,
        claim: first.map(|r| r.claim.clone()).unwrap_or_default(),
        section: first.map(|r| r.section.clone()).unwrap_or_default(),
        lines: first.map(|r| r.lines.clone()).unwrap_or_default(),
        quote: first.map(|r| r.quote.clone()).unwrap_or_default(),
        standing: decided.standing,
        deciding: decided.deciding,
        rests_on: direct,
        support_claims: support.len(),
        support_results: counted.len(),
    }
}
