//! `report`: the files it writes (the same as the in-process run), and what it refuses: bad
//! cases, symbolic links, non-finite numbers, paths as figure ids, a source of another hash.

use std::path::Path;
use std::process::Command;

use orthocheck::report::{Provenance, Report};

use super::orthocheck;

/// The binary runs the paper once, from a folder that holds nothing (the paper's cases are
/// built into it); its files must be byte for byte what the in-process run of the same cases
/// renders (with the binary's revision and date): the report is deterministic across
/// processes and thread schedules. (One run: the paper is the suite's longest computation.)
#[test]
fn report_writes_both_files_deterministically() {
    let empty = tempfile::tempdir().unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_orthocheck"))
        .args(["report", "--out", "out"])
        .current_dir(empty.path())
        .output()
        .expect("the binary runs");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let dir = empty.path().join("out");
    let ja = std::fs::read_to_string(dir.join("report.json")).unwrap();
    let v: serde_json::Value = serde_json::from_str(&ja).unwrap();
    let same = in_process_twin(&v);
    assert!(
        ja == same.to_json(),
        "report.json differs from the in-process run"
    );
    let html = std::fs::read_to_string(dir.join("report.html")).unwrap();
    assert!(
        html == orthocheck::report::html::render(&same),
        "report.html differs from the in-process run"
    );
    check_html(&html, &v);
    // every figure beside the report as <figure id>.svg, the same as the in-process one
    let files = orthocheck::report::svg::figure_files(&same.figures).unwrap();
    assert_eq!(files.len(), same.figures.len());
    for (name, text) in &files {
        let written = std::fs::read_to_string(dir.join(name)).unwrap();
        assert!(written == *text, "{name} differs from the in-process run");
        roxmltree::Document::parse(&written).expect("a figure file is well-formed SVG");
    }
    assert!(
        std::fs::read_to_string(dir.join("report.md")).unwrap() == same.to_markdown(),
        "report.md differs from the in-process run"
    );
    check_claims(&v);
}

/// The in-process run of the same cases, with the provenance the binary wrote (its revision,
/// date and command).
fn in_process_twin(v: &serde_json::Value) -> Report {
    let here = crate::common::report().unwrap();
    let field = |k: &str| v["provenance"][k].as_str().map(str::to_string);
    Report::with(
        here.claims.clone(),
        here.figures.clone(),
        Provenance {
            revision: field("revision"),
            date: field("date"),
            command: field("command").unwrap_or_default(),
            transcription: field("transcription").unwrap_or_default(),
            seeds: here.provenance.seeds.clone(),
        },
    )
    .with_paper(orthocheck::cases::load_paper(Path::new(crate::common::CASES_DIR)).unwrap())
}

/// Every claim of report.json has its fields and its power's, and the summary counts every
/// claim once.
fn check_claims(v: &serde_json::Value) {
    let claims = v["claims"].as_array().unwrap();
    assert!(!claims.is_empty());
    for c in claims {
        for key in [
            "id",
            "section",
            "verdict",
            "printed",
            "computed",
            "tolerance",
            "power",
            "evidence",
        ] {
            assert!(c.get(key).is_some(), "claim lacks {key}");
        }
        let power = &c["power"];
        for key in ["kind", "detail", "weak"] {
            assert!(power.get(key).is_some(), "power lacks {key}");
        }
    }
    let total: u64 = v["summary"]
        .as_object()
        .unwrap()
        .values()
        .filter_map(|n| n.as_u64())
        .sum();
    assert_eq!(total as usize, claims.len());
}

/// The page a reviewer opens: every claim of report.json is on it, every figure is a
/// well-formed SVG, and nothing is fetched from anywhere.
fn check_html(html: &str, report: &serde_json::Value) {
    for c in report["claims"].as_array().unwrap() {
        let id = c["id"].as_str().unwrap();
        let anchor = orthocheck::report::html::anchor(id);
        assert!(
            html.contains(&format!("id=\"{anchor}\"")),
            "claim {id} is not on the page"
        );
    }
    let mut svgs = 0;
    let mut rest = html;
    let mut maps = 0;
    while let Some(start) = rest.find("<svg") {
        let end =
            rest[start..].find("</svg>").expect("an <svg> is closed") + start + "</svg>".len();
        roxmltree::Document::parse(&rest[start..end]).expect("a figure is well-formed SVG");
        // the argument map is drawn beside the figures
        if rest[start..end].starts_with("<svg id=\"argument-map\"") {
            maps += 1;
        } else {
            svgs += 1;
        }
        rest = &rest[end..];
    }
    let figures = report["figures"].as_array().unwrap().len();
    assert_eq!(svgs, figures, "one SVG per figure of report.json");
    assert_eq!(maps, 1, "the argument map");
    assert!(svgs >= 10, "{svgs} figures");
    for external in ["http://", "https://", "src=", "@import", "url("] {
        assert!(!html.contains(external), "the page refers to {external}");
    }
}

/// `report --cases DIR --out DIR/out`.
pub(crate) fn report_of_cases(dir: &Path) -> std::process::Output {
    orthocheck(&[
        "report",
        "--cases",
        dir.to_str().unwrap(),
        "--out",
        dir.join("out").to_str().unwrap(),
    ])
}

#[test]
fn a_bad_case_file_exits_2_and_names_file_line_and_field() {
    let dir = tempfile::tempdir().unwrap();
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_cases/wrong_type.yaml");
    std::fs::copy(&src, dir.path().join("wrong_type.yaml")).unwrap();
    let out = report_of_cases(dir.path());
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("wrong_type.yaml:16:17: field `check.dof_count.examples[0].points`"),
        "{err}"
    );
    // nothing was written, nothing of the user's was touched
    assert!(!dir.path().join("out").exists());
    assert!(dir.path().join("wrong_type.yaml").exists());
}

#[test]
fn a_missing_cases_folder_exits_2() {
    let out = orthocheck(&["report", "--cases", "no-such-folder"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("no-such-folder"));
}

/// `report --out` never follows a symbolic link named like one of its files, and leaves
/// the link's target untouched.
#[cfg(unix)]
#[test]
fn report_refuses_a_symlinked_output_file() {
    let dir = tempfile::tempdir().unwrap();
    let outside = dir.path().join("outside.html");
    std::fs::write(&outside, "keep me").unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    std::os::unix::fs::symlink(&outside, out.join("report.html")).unwrap();
    let r = orthocheck::report::Report::new(Vec::new());
    let e = r.write(&out).unwrap_err().to_string();
    assert!(
        e.contains("cannot write") && e.contains("symbolic link"),
        "{e}"
    );
    assert_eq!(std::fs::read_to_string(&outside).unwrap(), "keep me");
    assert!(
        !out.join("report.md").exists(),
        "nothing is written when one name is refused"
    );
    // the same for a figure's file
    std::fs::remove_file(out.join("report.html")).unwrap();
    std::os::unix::fs::symlink(&outside, out.join("fig-one.svg")).unwrap();
    let figure = orthocheck::check::figure::Figure {
        id: "fig-one".into(),
        claim: "c".into(),
        title: "t".into(),
        caption: "c".into(),
        panels: Vec::new(),
    };
    let r = orthocheck::report::Report::with(Vec::new(), vec![figure], Default::default());
    let e = r.write(&out).unwrap_err().to_string();
    assert!(e.contains("symbolic link"), "{e}");
    assert_eq!(std::fs::read_to_string(&outside).unwrap(), "keep me");
    assert!(!out.join("report.md").exists());
}

/// The output guard: serde_json would write a NaN as `null`, so a report holding one is
/// refused (a numerical failure, exit 1) before any file is written.
#[test]
fn report_refuses_a_non_finite_number_before_writing() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let plot = orthocheck::check::figure::Plot {
        title: "t".into(),
        x_label: "x".into(),
        y_label: "y".into(),
        equal_aspect: false,
        log_x: false,
        log_y: false,
        layers: Vec::new(),
        window: Some(([0.0, f64::NAN], [1.0, 1.0])),
    };
    let figure = orthocheck::check::figure::Figure {
        id: "fig-nan".into(),
        claim: "c".into(),
        title: "t".into(),
        caption: "c".into(),
        panels: vec![plot],
    };
    let r = orthocheck::report::Report::with(Vec::new(), vec![figure], Default::default());
    let e = r.write(&out).unwrap_err();
    assert!(matches!(e, orthocheck::Error::Numerical(_)), "{e}");
    let e = e.to_string();
    assert!(e.contains("NaN at `figures[0].panels[0].window"), "{e}");
    assert!(!out.join("report.json").exists());
}

/// A figure whose id is not a plain file name is refused, never written outside the folder.
#[test]
fn report_refuses_a_figure_id_that_is_a_path() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let figure = orthocheck::check::figure::Figure {
        id: "../escaped".into(),
        claim: "c".into(),
        title: "t".into(),
        caption: "c".into(),
        panels: Vec::new(),
    };
    let r = orthocheck::report::Report::with(Vec::new(), vec![figure], Default::default());
    assert!(r.write(&out).is_err());
    assert!(!dir.path().join("escaped.svg").exists());
    assert!(!out.join("report.md").exists());
}

/// A `--paper` file of another hash is refused (exit 2) before anything is written.
#[test]
fn report_refuses_a_source_of_another_hash() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("other.tex"), "\\section{Introduction}\n").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_orthocheck"))
        .args(["report", "--out", "out2", "--paper", "other.tex"])
        .current_dir(dir.path())
        .output()
        .expect("the binary runs");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("other.tex") && err.contains("SHA-256"),
        "{err}"
    );
    assert!(
        !dir.path().join("out2").exists(),
        "nothing written for a refused source"
    );
}
