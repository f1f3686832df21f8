//! `solve`: bad tracks files, the method chosen, complex roots, gaps and degenerate input.

use std::path::Path;

use super::{json, orthocheck, solve_text_and_json};

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
