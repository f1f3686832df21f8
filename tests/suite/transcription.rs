//! One verdict set with or without the paper's source: the source only verifies the
//! transcription, quote by quote at the tightest lines, and a disagreement makes the claims
//! concerned `inconclusive`.

use std::path::Path;

use orthocheck::cases::{self, CaseOrigin};
use orthocheck::check::Verdict;
use orthocheck::claims::CaseCheck;

use crate::common;

fn paper_cases() -> CaseOrigin {
    CaseOrigin::Folder(Path::new(common::CASES_DIR).to_path_buf())
}

/// Without the source the cases read are the same, and so are the claims of the kinds that
/// once read it (the errata of the text): a run without the source judges alike.
#[test]
fn the_source_changes_no_claim() {
    let Some(_) = common::paper_source() else {
        common::skipped_without_source("transcription::the_source_changes_no_claim");
        return;
    };
    let without = cases::load_cases::<CaseCheck>(&paper_cases()).unwrap();
    assert_eq!(without.as_slice(), common::cases().unwrap());
    let errata: Vec<_> = without
        .iter()
        .filter(|c| matches!(c.check, CaseCheck::SourceErrata(_)))
        .cloned()
        .collect();
    assert_eq!(errata.len(), 1);
    let mut run = orthocheck::claims::run_cases(&errata, &[], &|_, _| {}).unwrap();
    // what each claim rests on is gathered from every case of the folder
    orthocheck::claims::supports::attach(&mut run.results, &without);
    let with: Vec<_> = common::report()
        .unwrap()
        .claims
        .iter()
        .filter(|r| r.case == errata[0].id)
        .cloned()
        .collect();
    assert!(with.len() >= 24);
    assert_eq!(run.results, with);
}

/// With the source, every quote of every case stands at the tightest range of lines that
/// holds it, and every other fact the cases record holds: nothing disagrees.
#[test]
fn every_quote_stands_at_its_tightest_lines() {
    let Some(_) = common::paper_source() else {
        common::skipped_without_source("transcription::every_quote_stands_at_its_tightest_lines");
        return;
    };
    let v = common::inputs().unwrap().verification.as_ref().unwrap();
    let listed: Vec<String> = v.disagreements.iter().map(|d| d.to_string()).collect();
    assert!(listed.is_empty(), "{}", listed.join("\n"));
    assert_eq!(v.verbatim + v.normalised, v.quotes);
    assert!(v.quotes >= 190, "{} quotes", v.quotes);
    assert!(
        v.normalised >= 60,
        "{} formulas in plain notation",
        v.normalised
    );
    assert!(v.facts >= 30, "{} facts", v.facts);
}

/// One quote's range shifted by a line, one widened, one recorded absence that is present:
/// each is listed, naming its file and field, and makes its claims `inconclusive`.
#[test]
fn a_shifted_range_is_a_disagreement() {
    let Some(source) = common::paper_source() else {
        common::skipped_without_source("transcription::a_shifted_range_is_a_disagreement");
        return;
    };
    let dir = tempfile::tempdir().unwrap();
    for e in std::fs::read_dir(common::CASES_DIR).unwrap() {
        let p = e.unwrap().path();
        std::fs::copy(&p, dir.path().join(p.file_name().unwrap())).unwrap();
    }
    let edit = |file: &str, from: &str, to: &str| {
        let p = dir.path().join(file);
        let t = std::fs::read_to_string(&p).unwrap();
        assert_eq!(t.matches(from).count(), 1, "{from} in {file}");
        std::fs::write(&p, t.replacen(from, to, 1)).unwrap();
    };
    // d_{a,1} is at 225; 226 is the line after it
    edit("formula_audit.yaml", "lines: \"225\"", "lines: \"226\"");
    // the subscript's note, one line wider
    edit("source_errata.yaml", "lines: \"157\"", "lines: \"156-157\"");
    edit(
        "source_errata.yaml",
        "strings: ['\\begin{thebibliography}',",
        "strings: ['\\begin{document}',",
    );
    let origin = CaseOrigin::Folder(dir.path().to_path_buf());
    let inputs = cases::load_inputs::<CaseCheck>(&origin, Some(&source)).unwrap();
    let found: Vec<String> = inputs
        .disagreements()
        .iter()
        .map(|d| format!("{}: {}", d.claim.clone().unwrap_or_default(), d.field))
        .collect();
    assert_eq!(
        found,
        [
            "p3f3-differences: check.formula_audit.formulas[2].claim.quote",
            "twofold-relations: check.source_errata.findings[6].claim.quote",
            "source-text: check.source_errata.findings[20].decide.not_in_source.strings[0]",
        ],
        "{:#?}",
        inputs.disagreements()
    );
    let mut results = common::report().unwrap().claims.clone();
    orthocheck::claims::mark_disagreements(&mut results, inputs.disagreements());
    for claim in ["p3f3-differences", "twofold-relations", "source-text"] {
        let of: Vec<_> = results.iter().filter(|r| r.claim == claim).collect();
        assert!(!of.is_empty(), "{claim}");
        for r in of {
            assert_eq!(r.verdict, Verdict::Inconclusive, "{}", r.id);
            assert!(r
                .undecided
                .as_deref()
                .unwrap()
                .contains("disagrees with the paper's source"));
        }
    }
}
