//! `synth`: scenes that `solve` and `identify` read back, and files it never overwrites.

use super::{json, orthocheck};

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
        let listed = synth_shuffled(f, format);
        let out = orthocheck(&["identify", "--input", f, "--json"]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let (names, truth) = identify_finds_the_listing(&json(&out), &listed, format);
        let text = String::from_utf8(orthocheck(&["identify", "--input", f]).stdout).unwrap();
        let pairs: Vec<String> = names
            .iter()
            .zip(&truth)
            .map(|(n, &k)| format!("{n}→{}", label(format, k)))
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

/// `synth --shuffle` of six points in two frames into `f`: the order frame 2 lists its points
/// in, as the file's header names it.
fn synth_shuffled(f: &str, format: &str) -> Vec<String> {
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
    let written = std::fs::read_to_string(f).unwrap();
    assert!(
        written.lines().next().unwrap().ends_with(" --shuffle"),
        "{written}"
    );
    written
        .lines()
        .find_map(|l| l.strip_prefix("# frame 2 lists: "))
        .unwrap()
        .split_whitespace()
        .map(str::to_string)
        .collect()
}

/// How identify names the frame-2 point listed k-th: `#k` in YAML, the CSV rows' labels.
fn label(format: &str, k: usize) -> String {
    match format {
        "csv" => format!("X{}", k + 1),
        _ => format!("#{}", k + 1),
    }
}

/// identify's JSON against the listing: the same points, the truth found, every match named;
/// the frame-1 names and, for each, the position its point is listed at in frame 2.
fn identify_finds_the_listing(
    v: &serde_json::Value,
    listed: &[String],
    format: &str,
) -> (Vec<String>, Vec<usize>) {
    let names: Vec<String> = v["frame1_points"]
        .as_array()
        .unwrap()
        .iter()
        .map(|n| n.as_str().unwrap().to_string())
        .collect();
    let mut sorted = (names.clone(), listed.to_vec());
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
    let matches = v["matches"].as_array().unwrap();
    assert_eq!(matches.len(), names.len());
    for (m, (n, &k)) in matches.iter().zip(names.iter().zip(&truth)) {
        assert_eq!(m["frame1"], *n);
        assert_eq!(m["frame2"], label(format, k).as_str());
    }
    (names, truth)
}
