use std::collections::BTreeSet;

use orthocheck::cases::{inventory_ids, refers_to_inventory};
use orthocheck::check::Verdict;

use crate::common;

/// The claim inventory: its table's first column lists every claim id the report must decide.
const CLAIMS_MD: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/paper_cases/claims.md");

/// Claims the report decides beyond the inventory, in the same table form.
const ADDITIONAL_MD: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/paper_cases/additional-claims.md"
);

/// The ids of the inventory (claims.md) and of the additional claims, read from the files themselves so that
/// a new claim cannot slip past. A missing file fails: the inventory is never passed
/// without being read.
fn claim_ids() -> BTreeSet<String> {
    let mut ids = inventory_claim_ids();
    let extra = std::fs::read_to_string(ADDITIONAL_MD)
        .unwrap_or_else(|e| panic!("cannot read {ADDITIONAL_MD} ({e})"));
    ids.extend(inventory_ids(&extra));
    ids
}

/// The ids of the inventory alone.
fn inventory_claim_ids() -> BTreeSet<String> {
    let text = std::fs::read_to_string(CLAIMS_MD)
        .unwrap_or_else(|e| panic!("cannot read the claim inventory {CLAIMS_MD} ({e})"));
    let ids = inventory_ids(&text);
    assert!(
        ids.len() >= 40,
        "{CLAIMS_MD}: only {} ids in its table (is the table still `| id | … |`?)",
        ids.len()
    );
    ids
}

/// Every claim id a case file names: the `claim` of each claim reference and each id a
/// restatement `restates`.
fn claim_references(value: &serde_json::Value, out: &mut Vec<String>) {
    match value {
        serde_json::Value::Object(map) => {
            for (key, v) in map {
                match (key.as_str(), v) {
                    ("claim", serde_json::Value::String(s)) => out.push(s.clone()),
                    ("restates", serde_json::Value::Array(list)) => out.extend(
                        list.iter()
                            .map(|x| x.as_str().map_or_else(|| x.to_string(), str::to_string)),
                    ),
                    _ => claim_references(v, out),
                }
            }
        }
        serde_json::Value::Array(list) => list.iter().for_each(|v| claim_references(v, out)),
        _ => {}
    }
}

#[test]
fn the_inventory_parser_reads_the_table() {
    let md = "# t\n\n| id | where | claim |\n|---|---|---|\n| a-1 | 1 | x |\n| `b` | 2 | y |\n\nafter\n| not | a | row |\n";
    let ids = inventory_ids(md);
    assert_eq!(ids.into_iter().collect::<Vec<_>>(), ["a-1", "b"]);
}

#[test]
fn every_claim_has_a_verdict() {
    let inventory = inventory_claim_ids();
    let claims = claim_ids();
    let all = common::cases().unwrap();
    let report = common::report().unwrap();
    let decided: BTreeSet<&str> = report.claims.iter().map(|c| c.claim.as_str()).collect();
    let undecided: Vec<&String> = inventory
        .iter()
        .filter(|id| !decided.contains(id.as_str()))
        .collect();
    assert!(
        undecided.is_empty(),
        "claims of {CLAIMS_MD} without a result: {undecided:?}"
    );
    let unknown: Vec<&str> = report
        .claims
        .iter()
        .filter(|c| !refers_to_inventory(&c.claim, &claims))
        .map(|c| c.id.as_str())
        .collect();
    assert!(
        unknown.is_empty(),
        "results whose claim is not in {CLAIMS_MD}: {unknown:?}"
    );
    assert!(all.len() >= 15, "only {} paper cases", all.len());
    let unique: BTreeSet<&str> = report.claims.iter().map(|c| c.id.as_str()).collect();
    assert_eq!(
        unique.len(),
        report.claims.len(),
        "result ids must be unique"
    );
}

/// A case can only name claims of the inventory (a typo would leave a claim undecided and a
/// result without a place in the paper).
#[test]
fn every_case_refers_to_inventory_claims() {
    let claims = claim_ids();
    let mut files = 0;
    for entry in std::fs::read_dir(common::CASES_DIR).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("yaml") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let value: serde_json::Value =
            serde_saphyr::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let mut refs = Vec::new();
        claim_references(&value, &mut refs);
        assert!(!refs.is_empty(), "{} names no claim", path.display());
        let unknown: Vec<&String> = refs
            .iter()
            .filter(|r| !refers_to_inventory(r, &claims))
            .collect();
        assert!(
            unknown.is_empty(),
            "{}: claims not in {CLAIMS_MD}: {unknown:?}",
            path.display()
        );
        files += 1;
    }
    assert!(files >= 15, "only {files} case files");
}

/// A positive verdict rests on a check that could have failed: every claim states its power,
/// and none of the positive ones is weak.
#[test]
fn no_positive_verdict_is_weak() {
    let report = common::report().unwrap();
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

/// The resolution rule on both sides (docs/verdicts.md, "Power"): a check whose acceptance
/// interval resolves some but not all of the printed digits agrees within rounding, with its
/// resolution stated; one that resolves none (§4's system from the figure's digits accepts x4
/// anywhere in about [−10, 93]) decides nothing; a restatement of such a claim is judged by
/// what it restates.
#[test]
fn verdicts_follow_the_resolution_of_their_checks() {
    let report = common::report().expect("the paper runs");
    let claim = |id: &str| {
        report
            .claims
            .iter()
            .find(|c| c.id == id)
            .unwrap_or_else(|| panic!("{id} is a claim of the report"))
    };
    for id in [
        "ex2-two-solutions",
        "ex4-solution",
        "ex4-figure",
        "ex2-rounding-restricted",
    ] {
        let c = claim(id);
        let r = c
            .power
            .resolution
            .expect("an interval control states its resolution");
        assert_eq!(c.verdict, Verdict::ReproducedWithinRounding, "{id}");
        assert!(r.digits >= 1 && r.digits < r.printed, "{id}: {r:?}");
    }
    let system = claim("ex4-figure-system");
    assert_eq!(system.verdict, Verdict::Inconclusive);
    assert_eq!(system.power.resolution.map(|r| r.digits), Some(0));
    assert_eq!(claim("conclusions/quadratic").verdict, Verdict::Reproduced);
}

/// What a reader computes from §4's printed squares stays in `ex4-body`'s evidence (it was
/// once dropped): the Cayley–Menger determinant, the volume it gives, and the four faces.
#[test]
fn the_body_of_section_4_keeps_its_volume_and_faces() {
    let report = common::report().expect("the paper runs");
    let body = report
        .claims
        .iter()
        .find(|c| c.id == "ex4-body")
        .expect("ex4-body is a claim of the report");
    let real = |name: &str| {
        body.evidence
            .details
            .iter()
            .find(|q| q.name == name)
            .and_then(|q| match &q.value {
                orthocheck::check::Value::Real { value } => Some(value.0),
                _ => None,
            })
            .unwrap_or_else(|| panic!("ex4-body's evidence lacks {name}"))
    };
    let cm = real("Cayley–Menger determinant of the printed squares (288 V²)");
    let volume = real("volume of the tetrahedron");
    // V = √(cm/288) and back: four roundings, each half an ulp
    assert!(cm > 0.0 && (volume * volume * 288.0 - cm).abs() <= 4.0 * f64::EPSILON * cm);
    for face in ["PQR", "PQT", "QRT", "RPT"] {
        assert!(real(&format!("area of face {face}")) > 0.0);
    }
}

/// One defect, one erratum: a formula's expansion to the end is evidence of the formula's
/// claim, never a claim of its own (the audit still lists it), and the §5.2 copy of the
/// Appendix's constant symbols is not a second erratum.
#[test]
fn every_defect_is_one_erratum() {
    let report = common::report().expect("the paper runs");
    let twins: Vec<&str> = report
        .claims
        .iter()
        .map(|c| c.id.as_str())
        .filter(|id| id.ends_with("/expanded"))
        .collect();
    assert!(
        twins.is_empty(),
        "expanded twins counted as claims: {twins:?}"
    );
    let errata: Vec<&str> = report
        .claims
        .iter()
        .filter(|c| c.verdict == Verdict::Erratum)
        .map(|c| c.id.as_str())
        .collect();
    let symbols = errata
        .iter()
        .filter(|id| id.ends_with("/constant-symbols"))
        .count();
    assert_eq!(symbols, 1, "{errata:?}");
    // the two levels still agree for every formula erratum
    for id in errata
        .iter()
        .filter(|id| id.starts_with("p3f3-differences/"))
    {
        let c = report.claims.iter().find(|c| c.id == *id).unwrap();
        let cell = c
            .evidence
            .details
            .iter()
            .chain(&c.computed)
            .find(|q| {
                matches!(&q.role, orthocheck::check::Role::Cell { model, statistic, .. }
                    if model == "every macro expanded" && statistic == "verdict")
            })
            .unwrap_or_else(|| panic!("{id} lacks its expanded check"));
        assert_eq!(
            cell.value,
            orthocheck::check::Value::label("erratum"),
            "{id}"
        );
    }
}

/// One reading rule for the noise sentences: a sentence that leaves its reading open decides
/// only where every reading agrees (§3's "average performance within 20 %" fails only as the
/// largest error in squares; §4's "errors of well above 20 %" holds only as the largest error
/// in squares; §4's "on average … did not exceed 1 %" holds over the printed run's edges and
/// fails over the trials at the paper's scene), and each reading is a row of a table.
#[test]
fn noise_claims_follow_one_reading_rule() {
    use orthocheck::check::{Role, Value};
    let report = common::report().expect("the paper runs");
    let decisions = |id: &str| -> (Verdict, Vec<String>) {
        let c = report
            .claims
            .iter()
            .find(|c| c.id == id)
            .unwrap_or_else(|| panic!("{id} is a claim of the report"));
        let ds = c
            .evidence
            .details
            .iter()
            .filter(|q| matches!(&q.role, Role::Entry { table, column, .. } if table == "readings" && column == "decision"))
            .map(|q| match &q.value {
                Value::Label { text } => text.clone(),
                v => panic!("{id}: a decision is a label, not {v:?}"),
            })
            .collect();
        (c.verdict, ds)
    };
    let (v, ds) = decisions("ex3-noise/eps-0.1");
    assert_eq!(v, Verdict::Inconclusive);
    assert_eq!(ds, ["fails", "holds", "holds", "holds"]);
    let (v, ds) = decisions("ex4-noise-1");
    assert_eq!(v, Verdict::Inconclusive);
    assert_eq!(ds, ["holds", "fails", "fails", "fails"]);
    let (v, ds) = decisions("ex4-noise-0.1");
    assert_eq!(v, Verdict::Inconclusive);
    assert_eq!(ds.iter().filter(|d| d.starts_with("not read")).count(), 3);
    assert_eq!(
        ds.iter()
            .filter(|d| !d.starts_with("not read"))
            .collect::<Vec<_>>(),
        ["holds", "fails"]
    );
    let (v, ds) = decisions("ex2-noise-0.1");
    assert_eq!(v, Verdict::StatisticalHolds);
    assert!(ds.iter().all(|d| d == "holds"), "{ds:?}");
}
