use std::path::Path;
use std::process::{Command, Output};

use orthocheck::report::{Provenance, Report};

pub(crate) fn orthocheck(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_orthocheck"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs")
}

/// `solve --input file` as text, then with `--json`.
pub(crate) fn solve_text_and_json(file: &Path) -> [Output; 2] {
    let input = file.to_str().unwrap();
    [
        orthocheck(&["solve", "--input", input]),
        orthocheck(&["solve", "--input", input, "--json"]),
    ]
}

fn json(out: &Output) -> serde_json::Value {
    serde_json::from_slice(&out.stdout).expect("stdout is JSON")
}

#[test]
fn dof_reports_the_two_frame_deficiency() {
    let out = orthocheck(&["dof", "--points", "4", "--frames", "2", "--json"]);
    assert_eq!(out.status.code(), Some(0));
    let v = json(&out);
    for key in [
        "points",
        "frames",
        "unknowns",
        "measurements",
        "balance",
        "jacobian_rank",
        "exact_rank",
        "deficiency",
    ] {
        assert!(v.get(key).is_some(), "missing {key}");
    }
    assert_eq!(v["balance"], 0);
    assert_eq!(v["deficiency"], 1);
    assert_eq!(v["jacobian_rank"], v["exact_rank"]);
}

#[test]
fn dof_table_lists_the_grid() {
    let out = orthocheck(&[
        "dof",
        "--table",
        "--max-points",
        "4",
        "--max-frames",
        "3",
        "--json",
    ]);
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(json(&out).as_array().map(Vec::len), Some(12));
}

#[test]
fn usage_errors_exit_2() {
    assert_eq!(
        orthocheck(&["dof", "--points", "0", "--frames", "3"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        orthocheck(&["dof", "--points", "x", "--frames", "3"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(orthocheck(&["nonsense"]).status.code(), Some(2));
    assert_eq!(orthocheck(&["dof"]).status.code(), Some(2));
}

#[test]
fn audit_twofold_squared_verifies_the_identity() {
    let out = orthocheck(&["audit", "twofold-squared"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("verdict:  identity-verified"), "{text}");
}

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
    let here = crate::common::report().unwrap();
    let field = |k: &str| v["provenance"][k].as_str().map(str::to_string);
    let same = Report::with(
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
    .with_paper(
        orthocheck::cases::load_paper(std::path::Path::new(crate::common::CASES_DIR)).unwrap(),
    );
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

/// What `solve` adds to the error of a tracks file that would read as tracks with gaps.
const GAPS_POINTER: &str =
    "; solve needs every point in every frame; `orthocheck reconstruct` reads tracks with gaps";

#[test]
fn every_bad_tracks_file_exits_2_with_its_error() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_tracks");
    let mut checked = 0;
    for entry in std::fs::read_dir(&dir).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        let expected = text
            .lines()
            .next()
            .unwrap()
            .strip_prefix("# expect: ")
            .unwrap();
        let rel = format!(
            "tests/bad_tracks/{}",
            path.file_name().unwrap().to_str().unwrap()
        );
        let out = orthocheck(&["solve", "--input", &rel]);
        assert_eq!(out.status.code(), Some(2), "{rel}");
        let err = String::from_utf8_lossy(&out.stderr);
        // a file that would read as tracks with gaps also points to `reconstruct`
        let err = err.trim_end();
        let err = err.strip_suffix(GAPS_POINTER).unwrap_or(err);
        assert_eq!(err, format!("error: {rel}{expected}"), "{rel}");
        checked += 1;
    }
    assert!(checked >= 10, "only {checked} bad tracks files");
}

#[test]
fn synth_then_solve_recovers_the_truth_in_both_formats() {
    let dir = tempfile::tempdir().unwrap();
    for (points, frames, format, method) in [
        (3, 3, "yaml", "p3f3"),
        (3, 6, "csv", "p3f4"),
        (4, 3, "yaml", "p4f3"),
        (7, 4, "csv", "lsq"),
    ] {
        let file = dir.path().join(format!("t{points}{frames}.{format}"));
        let out = orthocheck(&[
            "synth",
            "--points",
            &points.to_string(),
            "--frames",
            &frames.to_string(),
            "--seed",
            "4",
            "--format",
            format,
            "--out",
            file.to_str().unwrap(),
        ]);
        assert_eq!(out.status.code(), Some(0));
        let text = std::fs::read_to_string(&file).unwrap();
        // the truth is in the header: "# true squared edges: PQ=… QR=… RP=…"
        let truth: Vec<f64> = text
            .lines()
            .find_map(|l| l.strip_prefix("# true squared edges: "))
            .unwrap()
            .split_whitespace()
            .map(|kv| kv.split_once('=').unwrap().1.parse().unwrap())
            .collect();
        let out = orthocheck(&["solve", "--input", file.to_str().unwrap(), "--json"]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v = json(&out);
        assert_eq!(v["method"], method);
        assert!(v["degenerate"].is_null());
        let names = orthocheck::derivations::solver::default_edge_names(truth.len());
        let found = v["solutions"].as_array().unwrap().iter().any(|s| {
            s["feasible"] == true
                && s["squared_edges"].as_object().unwrap().len() == truth.len()
                && names.iter().zip(&truth).all(|(e, t)| {
                    // the header prints six significant digits
                    (s["squared_edges"][e.as_str()].as_f64().unwrap() - t).abs() <= 5e-6 * t
                })
        });
        assert!(found, "{v}");
        for key in ["residual", "reason", "squared_edges", "feasible"] {
            assert!(v["solutions"][0].get(key).is_some(), "missing {key}");
        }
    }
    // an existing file is never overwritten
    let file = dir.path().join("t33.yaml");
    let before = std::fs::read(&file).unwrap();
    let out = orthocheck(&[
        "synth",
        "--points",
        "3",
        "--frames",
        "3",
        "--seed",
        "9",
        "--out",
        file.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(std::fs::read(&file).unwrap(), before);
}

#[test]
fn solve_auto_says_why_and_refuses_what_it_cannot_do() {
    let out = orthocheck(&["solve", "--input", "tests/bad_tracks/two_frames.yaml"]);
    assert_eq!(out.status.code(), Some(2));
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("t.yaml");
    orthocheck(&[
        "synth",
        "--points",
        "3",
        "--frames",
        "3",
        "--seed",
        "1",
        "--out",
        file.to_str().unwrap(),
    ]);
    let out = orthocheck(&[
        "solve",
        "--input",
        file.to_str().unwrap(),
        "--method",
        "p3f4",
    ]);
    assert_eq!(out.status.code(), Some(2));
    let out = orthocheck(&["solve", "--input", file.to_str().unwrap()]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.starts_with("method: p3f3 (3 points in 3 frames"),
        "{text}"
    );
}

/// A complex root prints with the sign of its imaginary part (`re+imi`, `re-imi`, the minus
/// the numbers print), and the text says what the JSON says: a conjugate pair shows both.
#[test]
fn solve_prints_complex_roots_with_their_sign() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("noisy.yaml");
    let f = file.to_str().unwrap();
    // seeded noisy views that no rigid body gives: no real root, a conjugate pair
    let out = orthocheck(&[
        "synth", "--points", "3", "--frames", "3", "--seed", "3", "--noise", "0.05", "--out", f,
    ]);
    assert_eq!(out.status.code(), Some(0));
    let v = json(&orthocheck(&["solve", "--input", f, "--json"]));
    let text = String::from_utf8(orthocheck(&["solve", "--input", f]).stdout).unwrap();
    let lines: Vec<&str> = text
        .lines()
        .filter(|l| l.starts_with("solution "))
        .collect();
    let solutions = v["solutions"].as_array().unwrap();
    assert_eq!(lines.len(), solutions.len(), "{text}");
    // "3.07053+0.169191i" → (3.07053, 0.169191); the sign is the last + or - not of an exponent
    let complex = |s: &str| -> (f64, f64) {
        let body = s
            .strip_suffix('i')
            .unwrap_or_else(|| panic!("{s} is not complex"));
        let at = body
            .char_indices()
            .rev()
            .find(|&(k, c)| k > 0 && (c == '+' || c == '-') && !body[..k].ends_with('e'))
            .map(|(k, _)| k)
            .unwrap_or_else(|| panic!("{s} has no sign between its parts"));
        (body[..at].parse().unwrap(), body[at..].parse().unwrap())
    };
    let close = |a: f64, b: f64| (a - b).abs() <= 1e-5 * b.abs().max(1e-12);
    let (mut plus, mut minus) = (0, 0);
    for (line, sol) in lines.iter().zip(solutions) {
        let edges = line
            .split_once(": ")
            .unwrap()
            .1
            .split("  [")
            .next()
            .unwrap();
        for token in edges.split_whitespace() {
            let (name, value) = token.split_once("²=").unwrap();
            let re = sol["squared_edges"][name].as_f64().unwrap();
            match sol["imaginary"][name].as_f64().filter(|im| *im != 0.0) {
                Some(im) => {
                    let (tr, ti) = complex(value);
                    assert!(
                        close(tr, re) && close(ti, im),
                        "{token} against {re}{im:+}i"
                    );
                    if im > 0.0 {
                        plus += 1;
                    } else {
                        minus += 1;
                    }
                }
                None => assert!(close(value.parse().unwrap(), re), "{token}"),
            }
        }
    }
    assert!(
        plus > 0 && minus > 0,
        "a conjugate pair has both signs: {text}"
    );
}

/// `solve` needs every point in every frame: a file with a gap (`null` in YAML, a missing
/// row in CSV) is refused (exit 2) with the reader's location and a pointer to
/// `reconstruct`, which reads gaps; a file that is simply wrong gets no such pointer.
#[test]
fn solve_points_tracks_with_gaps_to_reconstruct() {
    let dir = tempfile::tempdir().unwrap();
    let yaml = dir.path().join("gap.yaml");
    std::fs::write(
        &yaml,
        "frames:\n  - [[0, 0], [1, 0], [0, 1]]\n  - [[0, 0], null, [0, 1]]\n  - [[0.5, 0], [1, 0.25], [0, 1]]\n",
    )
    .unwrap();
    let csv = dir.path().join("gap.csv");
    std::fs::write(
        &csv,
        "frame,point,x,y\n1,P,0,0\n1,Q,1,0\n1,R,0,1\n2,P,0,0\n2,Q,1,0.5\n3,P,0,0\n3,Q,1,0\n3,R,0.3,1\n",
    )
    .unwrap();
    let missing = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/bad_tracks/missing_point.csv");
    for (file, what) in [
        (
            yaml,
            "gap.yaml:3:14: field `frames[1][1]`: point `Q` is missing from frame 2 (`null`)",
        ),
        (
            csv,
            "gap.csv:6: field `point`: frame `2` has 2 points, but frame `1` has 3",
        ),
        (
            missing,
            "missing_point.csv:8: field `point`: frame `2` lacks point `R`",
        ),
    ] {
        let out = orthocheck(&["solve", "--input", file.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(2));
        assert!(out.stdout.is_empty());
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.trim_end().ends_with(&format!("{what}{GAPS_POINTER}")),
            "{err}"
        );
    }
    // too few entries is a mistake, not a gap (a gap is written `null`)
    let out = orthocheck(&["solve", "--input", "tests/bad_tracks/ragged.yaml"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(!String::from_utf8_lossy(&out.stderr).contains("reconstruct"));
}

/// Collinear points (three or four, in every frame) are one degenerate answer: exit 2, a
/// message naming the degeneracy, nothing on standard output, in text and JSON alike.
#[test]
fn collinear_input_is_one_degenerate_error() {
    let dir = tempfile::tempdir().unwrap();
    for (name, frames) in [
        (
            "three.yaml",
            "  - [[0, 0], [1, 1], [3, 3]]\n  - [[0, 0], [2, 0.5], [5, 1.25]]\n  - [[1, 1], [1, 2], [1, 4.5]]\n",
        ),
        (
            "four.yaml",
            "  - [[0, 0], [1, 1], [3, 3], [4, 4]]\n  - [[0, 0], [2, 0.5], [5, 1.25], [7, 1.75]]\n  - [[1, 1], [1, 2], [1, 4.5], [1, 7]]\n",
        ),
    ] {
        let file = dir.path().join(name);
        std::fs::write(&file, format!("frames:\n{frames}")).unwrap();
        for out in solve_text_and_json(&file) {
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(out.status.code(), Some(2), "{name}: {err}");
            assert!(out.stdout.is_empty(), "{name}: nothing is printed");
            assert!(
                err.contains(name)
                    && err.contains("degenerate input, not solved: collinear points")
                    && err.lines().count() == 1,
                "{err}"
            );
        }
    }
}

/// `synth --out` onto an existing file refuses (exit 2), says it would overwrite the file,
/// and leaves it and its folder as they were.
#[test]
fn synth_refuses_to_overwrite_and_says_so() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("mine.yaml");
    std::fs::write(&file, "my own notes\n").unwrap();
    let out = orthocheck(&[
        "synth",
        "--points",
        "3",
        "--frames",
        "3",
        "--seed",
        "1",
        "--out",
        file.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("mine.yaml")
            && err.contains("would overwrite")
            && !err.contains("cannot read"),
        "{err}"
    );
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "my own notes\n");
    // no temporary file left beside it
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 1);
}

/// `synth --shuffle` lists the points of frame 2 in a seeded random order and names that order
/// in its header; `identify` reads the file (YAML and CSV), finds the truth, and names the
/// points it matches (`#k` for the k-th listed in YAML, the CSV rows' labels otherwise).
#[test]
fn synth_shuffle_feeds_identify_which_names_the_points() {
    let dir = tempfile::tempdir().unwrap();
    for format in ["yaml", "csv"] {
        let file = dir.path().join(format!("shuffled.{format}"));
        let f = file.to_str().unwrap();
        let args = [
            "synth",
            "--points",
            "6",
            "--frames",
            "2",
            "--seed",
            "5",
            "--shuffle",
            "--format",
            format,
            "--out",
            f,
        ];
        let out = orthocheck(&args);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let written = std::fs::read_to_string(&file).unwrap();
        assert!(
            written.lines().next().unwrap().ends_with(" --shuffle"),
            "{written}"
        );
        let listed: Vec<&str> = written
            .lines()
            .find_map(|l| l.strip_prefix("# frame 2 lists: "))
            .unwrap()
            .split_whitespace()
            .collect();
        let out = orthocheck(&["identify", "--input", f, "--json"]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let v = json(&out);
        let names: Vec<&str> = v["frame1_points"]
            .as_array()
            .unwrap()
            .iter()
            .map(|n| n.as_str().unwrap())
            .collect();
        let mut sorted = (names.clone(), listed.clone());
        sorted.0.sort_unstable();
        sorted.1.sort_unstable();
        assert_eq!(sorted.0, sorted.1, "frame 2 lists the same points");
        assert_ne!(names, listed, "seed 5 moves some point");
        // frame-1 point i is the frame-2 point listed at the position of its name
        let truth: Vec<usize> = names
            .iter()
            .map(|n| listed.iter().position(|m| m == n).unwrap())
            .collect();
        let full: Vec<usize> = v["full"]["frame2_indices"]
            .as_array()
            .unwrap()
            .iter()
            .map(|x| x.as_u64().unwrap() as usize)
            .collect();
        assert_eq!(full, truth);
        let label = |k: usize| match format {
            "csv" => format!("X{}", k + 1),
            _ => format!("#{}", k + 1),
        };
        let matches = v["matches"].as_array().unwrap();
        assert_eq!(matches.len(), names.len());
        for (m, (n, &k)) in matches.iter().zip(names.iter().zip(&truth)) {
            assert_eq!(m["frame1"], *n);
            assert_eq!(m["frame2"], label(k).as_str());
        }
        let text = String::from_utf8(orthocheck(&["identify", "--input", f]).stdout).unwrap();
        let pairs: Vec<String> = names
            .iter()
            .zip(&truth)
            .map(|(n, &k)| format!("{n}→{}", label(k)))
            .collect();
        assert!(text.contains(&pairs.join(" ")), "{text}");
        assert!(text.contains("residual"), "{text}");
    }
    // nothing to shuffle in one frame
    let out = orthocheck(&[
        "synth",
        "--points",
        "4",
        "--frames",
        "1",
        "--seed",
        "1",
        "--shuffle",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--shuffle"));
}

/// `noise` prints its tables in fixed-width columns two spaces apart, and an id it does not
/// take (unknown, or a case that is no noise study) lists the ids it does take.
#[test]
fn noise_columns_stand_apart_and_bad_ids_list_the_good_ones() {
    let out = orthocheck(&[
        "noise",
        "--case",
        "ex2-noise",
        "--levels",
        "0.01",
        "--trials",
        "300",
        "--seed",
        "3",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines().peekable();
    let mut tables = 0;
    while let Some(header) = lines.next() {
        if !header.trim_start().starts_with("metric") {
            continue;
        }
        tables += 1;
        let width = header.chars().count();
        let cells = header.split_whitespace().count();
        assert_eq!(cells, 8, "metric, six quantiles, mean: {header}");
        let mut rows = vec![header];
        while let Some(r) = lines.next_if(|r| !r.trim().is_empty()) {
            rows.push(r);
        }
        assert_eq!(rows.len(), 5, "a header and four metrics: {text}");
        for r in rows {
            assert_eq!(r.chars().count(), width, "fixed-width columns: {text}");
            assert_eq!(r.split_whitespace().count(), cells, "{r}");
            let apart = r.split("  ").filter(|c| !c.trim().is_empty()).count();
            assert_eq!(apart, cells, "every cell two spaces from the next: {r}");
        }
    }
    assert_eq!(tables, 2, "one table per noise model: {text}");
    for (id, also) in [
        ("no-such-study", "no case `no-such-study`"),
        ("twofold-squared", "has no noise runs"),
    ] {
        let out = orthocheck(&["noise", "--case", id]);
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains(also)
                && err.contains("ex2-noise")
                && err.contains("ex3-noise")
                && err.contains("ex4-four-points"),
            "{err}"
        );
    }
    // §4's printed runs are rerun too
    let out = orthocheck(&[
        "noise",
        "--case",
        "ex4-four-points",
        "--levels",
        "0.001",
        "--trials",
        "50",
    ]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(String::from_utf8_lossy(&out.stdout).contains("ε = 0.001"));
}

#[test]
fn noise_is_seeded_and_agrees_with_itself() {
    let args = [
        "noise",
        "--case",
        "ex2-noise",
        "--levels",
        "0.01",
        "--trials",
        "500",
        "--seed",
        "3",
        "--model",
        "relative-length",
        "--json",
    ];
    let a = orthocheck(&args);
    assert_eq!(
        a.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&a.stderr)
    );
    assert_eq!(a.stdout, orthocheck(&args).stdout);
    // the progress bar is drawn only on a terminal: piped, standard error stays empty
    assert!(
        a.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&a.stderr)
    );
    let v = json(&a);
    let rows = v.as_array().unwrap();
    assert_eq!(rows.len(), 1);
    assert_eq!(rows[0]["model"], "relative-length");
    assert_eq!(rows[0]["trials"], 500);
    assert_eq!(rows[0]["metrics"].as_array().unwrap().len(), 4);
    assert_eq!(
        orthocheck(&["noise", "--case", "dof-counts"]).status.code(),
        Some(2)
    );
    assert_eq!(
        orthocheck(&["noise", "--case", "ex2-noise", "--levels", "-1"])
            .status
            .code(),
        Some(2)
    );
}

/// Ctrl-C stops a long run cleanly: one line "interrupted", exit 130, nothing on standard
/// output and no output file under its name (files are written whole, then renamed).
#[cfg(unix)]
#[test]
fn an_interrupted_run_exits_130_and_writes_nothing() {
    use std::process::Stdio;
    use std::time::{Duration, Instant};
    let interrupt = |args: &[&str], after: Duration| {
        let child = Command::new(env!("CARGO_BIN_EXE_orthocheck"))
            .args(args)
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        std::thread::sleep(after);
        let start = Instant::now();
        let killed = Command::new("kill")
            .args(["-INT", &child.id().to_string()])
            .status()
            .unwrap();
        assert!(killed.success());
        let out = child.wait_with_output().unwrap();
        assert!(
            start.elapsed() < Duration::from_secs(5),
            "it stops promptly"
        );
        out
    };
    // a noise study of 10⁶ trials per level and model runs for minutes
    let out = interrupt(
        &[
            "noise",
            "--case",
            "ex2-noise",
            "--trials",
            "1000000",
            "--json",
        ],
        Duration::from_millis(1500),
    );
    assert_eq!(
        out.status.code(),
        Some(130),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.stdout.is_empty());
    assert!(String::from_utf8_lossy(&out.stderr).contains("interrupted"));
    // the report: either it had finished (every file whole) or nothing is there
    let dir = tempfile::tempdir().unwrap();
    let folder = dir.path().join("out");
    let out = interrupt(
        &["report", "--out", folder.to_str().unwrap()],
        Duration::from_millis(1000),
    );
    match out.status.code() {
        Some(130) => {
            assert!(!folder.join("report.md").exists() && !folder.join("report.json").exists())
        }
        Some(0) => assert!(folder.join("report.json").exists()),
        c => panic!("exit {c:?}: {}", String::from_utf8_lossy(&out.stderr)),
    }
}

#[test]
fn audit_lists_every_item_and_finds_the_errata() {
    let out = orthocheck(&["audit", "--all", "--json"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json(&out);
    let items = v.as_array().unwrap();
    assert!(items.len() >= 40, "{} items", items.len());
    for it in items {
        for key in [
            "id",
            "where",
            "printed",
            "should_be",
            "method",
            "finding",
            "verdict",
        ] {
            assert!(it.get(key).is_some(), "missing {key}");
        }
    }
    let verdict = |id: &str| {
        items
            .iter()
            .find(|i| i["id"] == id)
            .map(|i| i["verdict"].as_str().unwrap().to_string())
    };
    assert_eq!(verdict("p3f3sqr").as_deref(), Some("identity-verified"));
    assert_eq!(
        verdict("p3f3-differences/equation-2").as_deref(),
        Some("erratum")
    );
    assert_eq!(
        verdict("appA-coefficients/f_cb").as_deref(),
        Some("identity-verified")
    );
    let one = orthocheck(&["audit", "appA-quartic"]);
    let text = String::from_utf8_lossy(&one.stdout);
    assert!(
        text.contains("appA-quartic/b-formula — identity-verified"),
        "{text}"
    );
    assert_eq!(
        orthocheck(&["audit", "no-such-item"]).status.code(),
        Some(2)
    );
    assert_eq!(orthocheck(&["audit"]).status.code(), Some(2));
}

#[test]
fn identify_membership_and_family_on_two_frames() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("two.csv");
    // five points in two frames; frame 2 listed in another order
    let t = orthocheck::model::Scene::random(5, 2, 21).tracks();
    let order = [3, 0, 4, 2, 1];
    let mut csv = String::from("frame,point,x,y\n");
    for (i, p) in t.frames[0].iter().enumerate() {
        csv.push_str(&format!("1,{},{:?},{:?}\n", t.names[i], p.x, p.y));
    }
    for (k, &j) in order.iter().enumerate() {
        let p = t.frames[1][j];
        csv.push_str(&format!("2,X{k},{:?},{:?}\n", p.x, p.y));
    }
    std::fs::write(&file, csv).unwrap();
    let out = orthocheck(&["identify", "--input", file.to_str().unwrap(), "--json"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json(&out);
    let best: Vec<usize> = v["assignments"][0]["frame2_indices"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_u64().unwrap() as usize)
        .collect();
    // frame-1 point i is frame-2 index k with order[k] == i
    let truth: Vec<usize> = (0..4)
        .map(|i| order.iter().position(|j| *j == i).unwrap())
        .collect();
    assert_eq!(best, truth);
    assert!(v["full"]["frame2_indices"].as_array().unwrap().len() == 5);

    let same = dir.path().join("same.yaml");
    std::fs::write(&same, orthocheck::input::tracks_to_yaml(&t)).unwrap();
    let out = orthocheck(&["membership", "--input", same.to_str().unwrap(), "--json"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(json(&out)
        .as_array()
        .unwrap()
        .iter()
        .all(|r| r["member"] == true));
    let out = orthocheck(&[
        "family",
        "--input",
        same.to_str().unwrap(),
        "--samples",
        "3",
        "--json",
    ]);
    assert_eq!(json(&out).as_array().unwrap().len(), 3);
    // three points are too few; three frames are not two
    let three = dir.path().join("three.yaml");
    let t3 = orthocheck::model::Scene::random(3, 2, 1).tracks();
    std::fs::write(&three, orthocheck::input::tracks_to_yaml(&t3)).unwrap();
    assert_eq!(
        orthocheck(&["identify", "--input", three.to_str().unwrap()])
            .status
            .code(),
        Some(2)
    );
    let out = orthocheck(&["family", "--input", "tests/bad_tracks/two_frames.yaml"]);
    assert_eq!(out.status.code(), Some(2));
}

/// identify's time grows as n⁴ (n⁵ for five): beyond the method's limit it refuses before any
/// work (exit 2), naming the limit and the override; `--max-points` moves the limit.
#[test]
fn identify_refuses_more_points_than_its_limit() {
    let dir = tempfile::tempdir().unwrap();
    let big = dir.path().join("big.yaml");
    let n = orthocheck::limits::IDENTIFY_POINTS_EPIPOLAR + 1;
    let t = orthocheck::model::Scene::random(n, 2, 5).tracks();
    std::fs::write(&big, orthocheck::input::tracks_to_yaml(&t)).unwrap();
    let start = std::time::Instant::now();
    let out = orthocheck(&["identify", "--input", big.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let e = String::from_utf8_lossy(&out.stderr);
    assert!(
        e.contains(&format!("is {n}, more than the limit of {}", n - 1))
            && e.contains("--max-points"),
        "{e}"
    );
    assert!(e.contains("big.yaml"), "the message names the file: {e}");
    assert!(start.elapsed() < std::time::Duration::from_secs(5));
    for (method, limit) in [
        ("four", orthocheck::limits::IDENTIFY_POINTS_FOUR),
        ("five", orthocheck::limits::IDENTIFY_POINTS_FIVE),
    ] {
        let e = orthocheck(&[
            "identify",
            "--input",
            big.to_str().unwrap(),
            "--method",
            method,
        ]);
        assert_eq!(e.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&e.stderr).contains(&format!("limit of {limit}")));
    }
    // the override lowers it as well as raising it
    let small = dir.path().join("small.yaml");
    let t = orthocheck::model::Scene::random(5, 2, 5).tracks();
    std::fs::write(&small, orthocheck::input::tracks_to_yaml(&t)).unwrap();
    let s = small.to_str().unwrap();
    assert_eq!(
        orthocheck(&["identify", "--input", s, "--max-points", "4"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        orthocheck(&["identify", "--input", s, "--max-points", "5"])
            .status
            .code(),
        Some(0)
    );
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
    while let Some(start) = rest.find("<svg") {
        let end =
            rest[start..].find("</svg>").expect("an <svg> is closed") + start + "</svg>".len();
        roxmltree::Document::parse(&rest[start..end]).expect("a figure is well-formed SVG");
        svgs += 1;
        rest = &rest[end..];
    }
    let figures = report["figures"].as_array().unwrap().len();
    assert_eq!(svgs, figures, "one SVG per figure of report.json");
    assert!(svgs >= 10, "{svgs} figures");
    for external in ["http://", "https://", "src=", "@import", "url("] {
        assert!(!html.contains(external), "the page refers to {external}");
    }
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

/// A reader that stops reading ends the command quietly (exit 0, as Unix tools do); a full
/// disk is an error (exit 1) that says it could not write, never a panic.
#[cfg(target_os = "linux")]
#[test]
fn closed_pipes_end_quietly_and_full_disks_are_errors() {
    use std::io::Read as _;
    use std::process::Stdio;
    let mut child = Command::new(env!("CARGO_BIN_EXE_orthocheck"))
        .args(["dof", "--table", "--json"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut first = [0u8; 16];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    // the pipe's reader is gone now
    let out = child.wait_with_output().unwrap();
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(!String::from_utf8_lossy(&out.stderr).contains("panicked"));
    let full = std::fs::File::create("/dev/full").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_orthocheck"))
        .args(["dof", "--table"])
        .stdout(full)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(err.contains("cannot write"), "{err}");
}

/// `audit --export sympy` writes one script per identity, refuses to overwrite, and the
/// scripts re-verify in SymPy when python3 with sympy is on the machine (the test says so
/// plainly when it is not).
#[test]
fn exported_sympy_scripts_verify_and_never_overwrite() {
    let dir = tempfile::tempdir().unwrap();
    let to = dir.path().join("sympy");
    let to_s = to.to_str().unwrap();
    let args = [
        "audit",
        "appA-coefficients",
        "--export",
        "sympy",
        "--out",
        to_s,
    ];
    let out = orthocheck(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut files: Vec<_> = std::fs::read_dir(&to)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    files.sort();
    // each macro-level identity beside its expansion
    assert!(files.len() >= 4 && files.len() % 2 == 0, "{files:?}");
    assert!(files.iter().any(|f| f
        .to_string_lossy()
        .ends_with("appA-coefficients__f_cb__expanded.py")));
    // a second export into the same folder refuses and leaves the files alone
    let before = std::fs::read(&files[0]).unwrap();
    let again = orthocheck(&args);
    assert!(!again.status.success());
    assert!(String::from_utf8_lossy(&again.stderr).contains("not overwritten"));
    assert_eq!(std::fs::read(&files[0]).unwrap(), before);
    let has_sympy = Command::new("python3")
        .args(["-c", "import sympy"])
        .output()
        .is_ok_and(|o| o.status.success());
    if !has_sympy {
        eprintln!("SKIPPED: python3 with sympy not found; the exported scripts were not run");
        println!("SKIPPED: python3 with sympy not found; the exported scripts were not run");
        return;
    }
    // the first script as a reader runs it, then all of them in one interpreter (SymPy's
    // import is most of a script's second), each in its own namespace, one line per script
    let run = Command::new("python3").arg(&files[0]).output().unwrap();
    let text = String::from_utf8_lossy(&run.stdout);
    assert!(run.status.success() && text.starts_with("OK "), "{text}");
    let each = "import contextlib, io, runpy, sys\n\
        for f in sys.argv[1:]:\n\
        \x20   out, code = io.StringIO(), 0\n\
        \x20   with contextlib.redirect_stdout(out):\n\
        \x20       try:\n\
        \x20           runpy.run_path(f, run_name='__main__')\n\
        \x20       except SystemExit as e:\n\
        \x20           code = e.code or 0\n\
        \x20   print(code, out.getvalue().strip().replace('\\n', ' '), '|', f)\n";
    let run = Command::new("python3")
        .arg("-c")
        .arg(each)
        .args(&files)
        .output()
        .unwrap();
    let stdout = String::from_utf8_lossy(&run.stdout);
    assert!(
        run.status.success(),
        "{stdout}{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let lines: Vec<&str> = stdout.lines().collect();
    assert_eq!(lines.len(), files.len(), "{stdout}");
    for line in lines {
        assert!(line.starts_with("0 OK "), "{line}");
    }
}

/// `membership` without `--tolerance` takes it from the data's noise: a foreign point among
/// six points of one body at 0.1 % noise is set apart, the five others kept, in every scene.
#[test]
fn membership_finds_a_foreign_point_at_its_default_tolerance() {
    use rand::{Rng, SeedableRng};
    let dir = tempfile::tempdir().unwrap();
    for seed in 1..=10u64 {
        let mut t = orthocheck::model::Scene::random(6, 2, seed).tracks();
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        for f in &mut t.frames {
            for p in f.iter_mut() {
                p.x *= 1.0 + 1e-3 * rng.random_range(-1.0..1.0);
                p.y *= 1.0 + 1e-3 * rng.random_range(-1.0..1.0);
            }
        }
        // the last point of frame 2 belongs to another body: moved by a third of the image
        let size = t.frames[1].iter().map(|p| p.norm()).fold(0.0f64, f64::max);
        t.frames[1][5].x += size / 3.0;
        t.frames[1][5].y -= size / 4.0;
        let file = dir.path().join(format!("six-{seed}.yaml"));
        std::fs::write(&file, orthocheck::input::tracks_to_yaml(&t)).unwrap();
        let out = orthocheck(&["membership", "--input", file.to_str().unwrap(), "--json"]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "seed {seed}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let members: Vec<bool> = json(&out)
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r["member"] == true)
            .collect();
        assert_eq!(
            members,
            [true, true, true, true, true, false],
            "seed {seed}"
        );
    }
    let out = orthocheck(&["membership", "--input", "tests/bad_tracks/two_frames.yaml"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.code() != Some(0) || text.contains("from the data"),
        "{text}"
    );
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
