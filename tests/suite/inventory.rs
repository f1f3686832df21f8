use std::collections::BTreeSet;
use std::path::Path;

use orthocheck::{cases, report::Report};

/// Every claim of the paper's inventory (CLAIMS.md ids; the ids stay stable).
const CLAIMS: &[&str] = &[
    "abstract-minimum",
    "abstract-linear",
    "abstract-two-frames",
    "dof-formula",
    "dof-k3p3",
    "dof-k2p4",
    "twofold-relations",
    "p3f3sqr",
    "p3f3-differences",
    "p3f3-a2-b2",
    "p3f3-quadratic",
    "p3f3-solution-count",
    "p3f3-feasibility",
    "ex2-body",
    "ex2-figure",
    "ex2-two-solutions",
    "ex2-noise-0.1",
    "ex2-noise-1",
    "ex2-noise-10",
    "p3f4-linear",
    "p3f4-unique",
    "ex3-body",
    "ex3-noise",
    "p4f3-relations",
    "p4f3-linear",
    "p4f3-unique",
    "ex4-body",
    "ex4-figure",
    "ex4-matrix",
    "ex4-solution",
    "ex4-noise-0.1",
    "ex4-noise-1",
    "fourth-relation",
    "two-frames-construction",
    "two-frames-coordinates",
    "two-frames-fourth-point",
    "identity-line",
    "identity-count",
    "identity-procedure",
    "ex5-frames",
    "ex5-hidden-table",
    "ex5-correct",
    "ex5-debug",
    "ex5-figure-panels",
    "identity5",
    "curves",
    "discussion",
    "conclusions",
    "appA-coefficients",
    "appA-quartic",
];

#[test]
fn every_claim_has_a_verdict() {
    let all = cases::load_all(Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/paper_cases"
    )))
    .unwrap();
    let report = Report::from_cases(&all).unwrap();
    let ids: BTreeSet<&str> = report.claims.iter().map(|c| c.claim.as_str()).collect();
    for id in CLAIMS {
        assert!(ids.contains(id), "no result for claim {id}");
    }
    assert!(all.len() >= 15, "only {} paper cases", all.len());
    let unique: BTreeSet<&str> = report.claims.iter().map(|c| c.id.as_str()).collect();
    assert_eq!(
        unique.len(),
        report.claims.len(),
        "result ids must be unique"
    );
}

/// A positive verdict rests on a check that could have failed: every claim states its power,
/// and none of the positive ones is weak.
#[test]
fn no_positive_verdict_is_weak() {
    let all = cases::load_all(Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/paper_cases"
    )))
    .unwrap();
    let report = Report::from_cases(&all).unwrap();
    let weak: Vec<&str> = report
        .claims
        .iter()
        .filter(|c| c.verdict.is_positive() && c.power.weak)
        .map(|c| c.id.as_str())
        .collect();
    assert!(
        weak.is_empty(),
        "positive verdicts with weak power: {weak:?}"
    );
}
