use std::collections::BTreeSet;
use std::path::Path;

use orthocheck::{cases, report::Report};

/// Claims of the paper (CLAIMS.md ids) that the cases decide so far; each must appear.
const REQUIRED: &[&str] = &[
    "abstract-minimum",
    "abstract-two-frames",
    "dof-formula",
    "dof-k3p3",
    "dof-k2p4",
    "twofold-relations",
    "p3f3sqr",
];

#[test]
fn every_required_claim_has_a_verdict() {
    let all = cases::load_all(Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/paper_cases"
    )))
    .unwrap();
    assert!(all.len() >= 3, "only {} paper cases", all.len());
    let report = Report::from_cases(&all).unwrap();
    let ids: BTreeSet<&str> = report.claims.iter().map(|c| c.claim.as_str()).collect();
    for id in REQUIRED {
        assert!(ids.contains(id), "no result for claim {id}");
    }
    let unique: BTreeSet<&str> = report.claims.iter().map(|c| c.id.as_str()).collect();
    assert_eq!(
        unique.len(),
        report.claims.len(),
        "result ids must be unique"
    );
}
