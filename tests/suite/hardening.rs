//! The writes and exits of the command line: temporary files that cannot be redirected,
//! a file-size limit, SIGTERM, and bad usage (exit 2, the option named).

use std::process::Command;

use orthocheck::report::Report;

use crate::cli::orthocheck;

/// Temporary and probe files are created exclusively under unpredictable names: links planted
/// under the names they once had (`.report.md.PID.tmp`, `.orthocheck-probe-PID`) are neither
/// followed nor removed, the file they point to keeps its bytes, and no temporary is left;
/// the report's files have the mode of any new file.
#[test]
fn planted_links_under_temporary_names_are_not_followed() {
    let dir = tempfile::tempdir().unwrap();
    let outside = dir.path().join("outside.txt");
    std::fs::write(&outside, "keep me").unwrap();
    let out = dir.path().join("out");
    std::fs::create_dir(&out).unwrap();
    let pid = std::process::id();
    let mut planted = vec![format!(".orthocheck-probe-{pid}")];
    planted.extend(["report.md", "report.json", "report.html"].map(|n| format!(".{n}.{pid}.tmp")));
    for name in &planted {
        std::os::unix::fs::symlink(&outside, out.join(name)).unwrap();
    }
    orthocheck::report::prepare_output_dir(&out).unwrap();
    Report::new(Vec::new()).write(&out).unwrap();
    assert_eq!(std::fs::read_to_string(&outside).unwrap(), "keep me");
    let mut left: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    left.sort();
    let mut expected = planted.clone();
    expected.extend(["report.html", "report.json", "report.md"].map(String::from));
    expected.sort();
    assert_eq!(left, expected, "only the report and the planted links");
    assert!(std::fs::read_to_string(out.join("report.md"))
        .unwrap()
        .contains("Reproducibility"));
    // a new file's mode, as any program makes one: 0666 less the umask, not a temporary's 0600
    use std::os::unix::fs::PermissionsExt as _;
    let status = std::fs::read_to_string("/proc/self/status").unwrap();
    let umask = status
        .lines()
        .find_map(|l| l.strip_prefix("Umask:"))
        .map(|m| u32::from_str_radix(m.trim(), 8).unwrap())
        .unwrap();
    let mode = std::fs::metadata(out.join("report.md"))
        .unwrap()
        .permissions()
        .mode();
    assert_eq!(mode & 0o777, 0o666 & !umask);
}

/// A file-size limit (`ulimit -f`) makes the write fail with a message naming the file, exit
/// 1, instead of SIGXFSZ ending the process silently; nothing is left behind.
#[test]
fn a_full_file_size_limit_is_an_error_that_names_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("big.yaml");
    // 1 block of 1024 bytes: 40 points in 6 frames take far more
    let script = format!(
        "ulimit -f 1; exec \"$0\" synth --points 40 --frames 6 --seed 3 --out {}",
        file.display()
    );
    let out = Command::new("bash")
        .args(["-c", &script, env!("CARGO_BIN_EXE_orthocheck")])
        .output()
        .expect("bash runs");
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.contains("big.yaml") && err.to_lowercase().contains("too large"),
        "{err}"
    );
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        0,
        "neither the file nor a temporary is left"
    );
}

/// SIGTERM is handled like Ctrl-C: the command stops, says so, exits 130, and leaves no
/// temporary file in the output folder.
#[test]
fn sigterm_stops_the_report_cleanly() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let child = Command::new(env!("CARGO_BIN_EXE_orthocheck"))
        .args(["report", "--out", out.to_str().unwrap()])
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the binary runs");
    // the folder is prepared before the paper runs: wait for it, then signal
    let start = std::time::Instant::now();
    while !out.exists() && start.elapsed() < std::time::Duration::from_secs(20) {
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    std::thread::sleep(std::time::Duration::from_millis(200));
    let killed = Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(killed.success());
    let done = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&done.stderr);
    assert_eq!(done.status.code(), Some(130), "{err}");
    assert!(err.contains("interrupted"), "{err}");
    assert_eq!(
        std::fs::read_dir(&out).unwrap().count(),
        0,
        "nothing left in the folder"
    );
}

/// Run the binary with `args`, send `signal` after `delay`, and wait for it.
fn signalled(args: &[&str], delay_ms: u64, signal: &str) -> std::process::Output {
    let child = Command::new(env!("CARGO_BIN_EXE_orthocheck"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("the binary runs");
    std::thread::sleep(std::time::Duration::from_millis(delay_ms));
    // the process may have ended already: then the signal finds nobody, which is a moment too
    let _ = Command::new("kill")
        .args([&format!("-{signal}"), &child.id().to_string()])
        .status();
    child.wait_with_output().unwrap()
}

/// The names in `dir`, sorted.
fn names_in(dir: &std::path::Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .map(|r| {
            r.map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    names.sort();
    names
}

/// What a signalled run may leave: exit 0 and the whole output, or exit 130 and the output
/// either absent or whole; byte for byte the uninterrupted run's, and no temporary beside it.
/// A signal that lands before the handler is installed ends the process by itself, which is
/// allowed only while nothing has been written.
fn absent_or_whole(
    out: &std::process::Output,
    dir: &std::path::Path,
    whole: &[(String, Vec<u8>)],
    at: &str,
) {
    use std::os::unix::process::ExitStatusExt as _;
    let err = String::from_utf8_lossy(&out.stderr);
    let code = out.status.code();
    let before_handler = out.status.signal().is_some();
    assert!(
        before_handler || code == Some(0) || code == Some(130),
        "{at}: {:?} {err}",
        out.status
    );
    let names = names_in(dir);
    let expected: Vec<String> = whole.iter().map(|(n, _)| n.clone()).collect();
    assert!(
        names.is_empty() && code != Some(0) || names == expected && !before_handler,
        "{at}: {:?} left {names:?}",
        out.status
    );
    for (name, bytes) in whole.iter().filter(|_| !names.is_empty()) {
        assert!(
            std::fs::read(dir.join(name)).unwrap() == *bytes,
            "{at}: {name} differs"
        );
    }
}

/// `synth --out` stopped by SIGINT or SIGTERM at moments spread over its run (10 MB of
/// tracks): the file is absent or whole, never cut, and no temporary survives.
#[test]
fn signals_at_any_moment_leave_synth_output_absent_or_whole() {
    let args = [
        "synth", "--points", "1000", "--frames", "300", "--seed", "5",
    ];
    let whole = crate::cli::orthocheck(&args).stdout;
    for (i, delay) in [0, 10, 30, 60, 100, 140, 180, 250].into_iter().enumerate() {
        let dir = tempfile::tempdir().unwrap();
        let file = dir.path().join("s.yaml");
        let mut with_out = args.to_vec();
        with_out.extend(["--out", file.to_str().unwrap()]);
        let signal = ["INT", "TERM"][i % 2];
        let out = signalled(&with_out, delay, signal);
        let at = format!("SIG{signal} at {delay} ms");
        absent_or_whole(&out, dir.path(), &[("s.yaml".into(), whole.clone())], &at);
    }
}

/// `report --out` on one case with figures, stopped at moments spread over loading, the
/// case run and the writes: the report is absent or whole (every file the uninterrupted
/// run's bytes), never a mix, and no temporary survives.
#[test]
fn signals_at_any_moment_leave_the_report_absent_or_whole() {
    let cases = tempfile::tempdir().unwrap();
    for name in ["paper.yml", "ex2_three_frames.yaml"] {
        let from = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("paper_cases")
            .join(name);
        std::fs::copy(from, cases.path().join(name)).unwrap();
    }
    let run = |out: &std::path::Path| {
        vec![
            "report".to_string(),
            "--cases".into(),
            cases.path().display().to_string(),
            "--out".into(),
            out.display().to_string(),
        ]
    };
    let reference = tempfile::tempdir().unwrap();
    let args = run(reference.path());
    let done = crate::cli::orthocheck(&args.iter().map(String::as_str).collect::<Vec<_>>());
    assert!(
        done.status.success(),
        "{}",
        String::from_utf8_lossy(&done.stderr)
    );
    let whole: Vec<(String, Vec<u8>)> = names_in(reference.path())
        .into_iter()
        .map(|n| (n.clone(), std::fs::read(reference.path().join(&n)).unwrap()))
        .collect();
    for (i, delay) in [0, 5, 40, 150, 300, 450, 600, 750, 900]
        .into_iter()
        .enumerate()
    {
        let parent = tempfile::tempdir().unwrap();
        let dir = parent.path().join("out");
        let args = run(&dir);
        let signal = ["TERM", "INT"][i % 2];
        let out = signalled(
            &args.iter().map(String::as_str).collect::<Vec<_>>(),
            delay,
            signal,
        );
        absent_or_whole(&out, &dir, &whole, &format!("SIG{signal} at {delay} ms"));
    }
}

/// The output guard counts numbers as they are formatted, not words: points named `inf`,
/// `NaN`, `nan` and `-inf` (legal names) reach both the text and the JSON output.
#[test]
fn points_named_like_non_finite_numbers_pass_the_output_guard() {
    let dir = tempfile::tempdir().unwrap();
    let tracks = orthocheck(&["synth", "--points", "4", "--frames", "3", "--seed", "1"]);
    let yaml = String::from_utf8(tracks.stdout)
        .unwrap()
        .replace("points: [P, Q, R, T]", "points: [inf, NaN, nan, \"-inf\"]");
    let file = dir.path().join("names.yaml");
    std::fs::write(&file, yaml).unwrap();
    for out in crate::cli::solve_text_and_json(&file) {
        let text = String::from_utf8_lossy(&out.stdout);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(
            // the edges' names keep their points apart
            text.contains("inf–NaN") && text.contains("-inf–inf") && !text.contains("infNaN"),
            "{text}"
        );
    }
}

/// Bad usage is exit 2 and names what is wrong: a negative count or seed names its option
/// (it is not taken for an unknown flag), an output folder that is a file or cannot be
/// written is refused before any work, and an empty `dof` table is refused.
#[test]
fn bad_usage_is_exit_2_and_names_the_option() {
    let cases: [(&[&str], &str); 5] = [
        (&["dof", "--points", "-1", "--frames", "3"], "--points"),
        (
            &["dof", "--points", "3", "--frames", "3", "--seed", "-1"],
            "--seed",
        ),
        (&["noise", "--trials", "-1"], "--trials"),
        (
            &[
                "synth", "--points", "3", "--frames", "3", "--seed", "1", "--noise", "-1",
            ],
            "--noise",
        ),
        (&["dof", "--table", "--max-points", "0"], "--max-points"),
    ];
    for (args, names) in cases {
        let out = orthocheck(args);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {err}");
        assert!(
            err.contains(names) && !err.contains("unexpected argument"),
            "{args:?}: {err}"
        );
        assert!(out.stdout.is_empty(), "{args:?}");
    }
    // a seed that is not UTF-8 is named too (clap's own check names no argument)
    use std::os::unix::ffi::OsStrExt as _;
    let out = Command::new(env!("CARGO_BIN_EXE_orthocheck"))
        .args(["synth", "--points", "3", "--frames", "3", "--seed"])
        .arg(std::ffi::OsStr::from_bytes(b"\xff"))
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("'--seed'") && err.contains("UTF-8"), "{err}");
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("a-file");
    std::fs::write(&file, "mine").unwrap();
    let out = orthocheck(&["report", "--out", file.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("a-file") && err.contains("output folder"),
        "{err}"
    );
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "mine");
}

#[test]
fn a_claim_the_inventory_does_not_list_is_refused_at_its_line() {
    // a typo, and values YAML reads as a number or a boolean, not as a name
    for bad in ["no-such-claim", "12", "1.0", "yes"] {
        let dir = tempfile::tempdir().unwrap();
        let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("paper_cases");
        for e in std::fs::read_dir(&src).unwrap() {
            let p = e.unwrap().path();
            std::fs::copy(&p, dir.path().join(p.file_name().unwrap())).unwrap();
        }
        let file = dir.path().join("ex2_three_frames.yaml");
        let text = std::fs::read_to_string(&file).unwrap();
        let line = text
            .lines()
            .position(|l| l.trim() == "claim: ex2-figure")
            .unwrap()
            + 1;
        std::fs::write(
            &file,
            text.replace("claim: ex2-figure", &format!("claim: {bad}")),
        )
        .unwrap();
        let out = crate::cli::report_of_cases(dir.path());
        assert_eq!(out.status.code(), Some(2), "{bad}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(
            err.contains(&format!("ex2_three_frames.yaml:{line}"))
                && err.contains(&format!("`{bad}` is not a claim of the inventory")),
            "{err}"
        );
        // without an inventory in the folder, the paper's own, built in, decides
        for name in ["claims.md", "additional-claims.md"] {
            std::fs::remove_file(dir.path().join(name)).unwrap();
        }
        let out = crate::cli::report_of_cases(dir.path());
        assert_eq!(out.status.code(), Some(2), "{bad}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(
            err.contains(&format!("ex2_three_frames.yaml:{line}"))
                && err.contains(&format!(
                    "`{bad}` is not a claim of the paper's inventory, built in"
                )),
            "{err}"
        );
    }
}

#[test]
fn the_two_frame_commands_refuse_work_beyond_their_limits_before_doing_it() {
    let dir = tempfile::tempdir().unwrap();
    let file = |n: usize| {
        let f = dir.path().join(format!("p{n}.yaml"));
        let s = f.to_str().unwrap().to_string();
        let out = orthocheck(&[
            "synth",
            "--points",
            &n.to_string(),
            "--frames",
            "2",
            "--seed",
            "1",
            "--out",
            &s,
        ]);
        assert!(out.status.success());
        s
    };
    let small = file(600);
    let cases: [(Vec<&str>, &str); 2] = [
        (
            vec!["identify", "--input", &small, "--top", "10001"],
            "--top is 10001, more than the limit of 10000",
        ),
        (
            vec!["family", "--input", &small, "--samples", "10000"],
            "the points × --samples of family is 6000000",
        ),
    ];
    for (args, says) in cases {
        let out = orthocheck(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(err.contains(says), "{err}");
    }
    let big = file(50_001);
    let out = orthocheck(&["membership", "--input", &big]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8(out.stderr).unwrap();
    assert!(
        err.contains("p50001.yaml") && err.contains("more than the limit of 50000"),
        "{err}"
    );
}

/// Each case file's work is bounded by what its time grows with, measured at the limit
/// (`docs/limits.md`): the file is refused at the field before any trial runs, and the
/// paper's own sizes pass.
#[test]
fn case_work_beyond_its_limit_is_refused_at_the_field() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("paper_cases");
    let refused = |file: &str, from: &str, to: &str, says: &str| {
        let path = root.join(file);
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(text.contains(from), "{file}: {from}");
        orthocheck::cases::parse_case::<orthocheck::claims::CaseCheck>(&text, &path)
            .unwrap_or_else(|e| panic!("{file} as printed: {e}"));
        let err = orthocheck::cases::parse_case::<orthocheck::claims::CaseCheck>(
            &text.replacen(from, to, 1),
            &path,
        )
        .expect_err(to)
        .to_string();
        assert!(err.contains(file) && err.contains(says), "{err}");
    };
    let l = orthocheck::limits::CASE_NOISE_WORK;
    // ex2: 3 levels of 3 frames
    let over = l / 9 + 1;
    refused(
        "ex2_noise.yaml",
        "trials: 10000",
        &format!("trials: {over}"),
        &format!("trials × levels × frames is {}", over * 9),
    );
    refused(
        "linearity_price.yaml",
        "trials: 200",
        "trials: 1000",
        "trials × bodies × levels is 12000",
    );
    refused(
        "p3f4_uniqueness.yaml",
        "trials: 10000",
        "trials: 2000000",
        "trials is 2000000",
    );
    refused(
        "p3f4_uniqueness.yaml",
        "frames: 4\n    trials: 10000",
        "frames: 200\n    trials: 30000",
        "trials × frames is 6000000",
    );
    refused(
        "solution_count.yaml",
        "instances: 12",
        "instances: 25",
        "more than the limit of 24",
    );
    refused(
        "identity_census.yaml",
        "trials: 200",
        "trials: 5001",
        "more than the limit of 5000",
    );
}

/// A CSV of 20,000 rows, each a new frame and a new point, would expand into a dense table of
/// 4 × 10⁸ cells: it is refused by its cell count, naming the file, before the table is made.
#[test]
fn a_sparse_csv_is_refused_by_its_cell_count_before_the_table_is_made() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("sparse.csv");
    let mut text = String::from("frame,point,x,y\n");
    for i in 0..20_000 {
        text.push_str(&format!("{i},p{i},0.{i},1.{i}\n"));
    }
    std::fs::write(&path, text).unwrap();
    let out = orthocheck(&["reconstruct", "--input", path.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(err.contains("sparse.csv") && err.contains("cells"), "{err}");
}

/// An error printed to a closed standard error still ends with the documented exit code
/// (no panic, no 101), and so does an interrupt.
#[test]
fn a_closed_standard_error_keeps_the_exit_code() {
    let out = Command::new("bash")
        .args([
            "-c",
            "exec 2>&-; exec \"$0\" solve --input no-such-file.yaml",
            env!("CARGO_BIN_EXE_orthocheck"),
        ])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
}

#[test]
fn variable_projection_beyond_its_work_limit_is_refused_before_the_work() {
    // 2,000 points each in 30 of 100 frames: 20 steps would cost 1.07e10 multiply-adds
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("turntable.csv");
    let out = orthocheck(&[
        "synth",
        "--points",
        "2000",
        "--frames",
        "100",
        "--seed",
        "1",
        "--turntable",
        "--window",
        "30",
        "--format",
        "csv",
        "--out",
        file.to_str().unwrap(),
    ]);
    assert!(out.status.success());
    let out = orthocheck(&["reconstruct", "--input", file.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("2000 points in 100 frames") && err.contains("limit of 1.0e10"),
        "{err}"
    );
    assert!(out.stdout.is_empty());
}

/// `--robust`'s limits count the images given, not points × frames: 17,000 points each seen
/// once in 6 frames (102,000 cells, 17,000 images) pass them and are then dropped as tracks
/// seen once; 10,002 points each in 2 of the 6 (20,004 images) are refused by the limit of
/// tracks with gaps, and 25,001 points in all 4 frames (100,004 images) by that of complete
/// tracks.
#[test]
fn the_robust_limits_count_images_not_cells() {
    let dir = tempfile::tempdir().unwrap();
    let write = |name: &str, points: usize, frames: usize, seen: usize| {
        let mut text = String::from("frame,point,x,y\n");
        for j in 0..points {
            for f in 0..frames {
                if (f + frames - j % frames) % frames < seen {
                    let (x, y) = ((j % 1000) as f64, (j / 1000) as f64 + f as f64 / 8.0);
                    text.push_str(&format!("{},P{j},{x},{y}\n", f + 1));
                }
            }
        }
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        path
    };
    let robust = |path: &std::path::Path| {
        let out = orthocheck(&["reconstruct", "--robust", "--input", path.to_str().unwrap()]);
        assert_eq!(out.status.code(), Some(2));
        String::from_utf8_lossy(&out.stderr).into_owned()
    };
    let err = robust(&write("once.csv", 17_000, 6, 1));
    assert!(
        !err.contains("limit") && err.contains("all 6 frames were dropped"),
        "{err}"
    );
    let err = robust(&write("gaps.csv", 10_002, 6, 2));
    assert!(
        err.contains("observations of --robust on tracks with gaps is 20004")
            && err.contains("limit of 20000"),
        "{err}"
    );
    let err = robust(&write("complete.csv", 25_001, 4, 4));
    assert!(
        err.contains("observations of --robust is 100004") && err.contains("limit of 100000"),
        "{err}"
    );
}

#[test]
fn what_a_claim_rests_on_is_checked_at_its_line() {
    let copy = || {
        let dir = tempfile::tempdir().unwrap();
        let src = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("paper_cases");
        for e in std::fs::read_dir(&src).unwrap() {
            let p = e.unwrap().path();
            std::fs::copy(&p, dir.path().join(p.file_name().unwrap())).unwrap();
        }
        dir
    };
    // (file, the line replaced, its replacement, what the error says)
    let faults = [
        (
            "ex2_three_frames.yaml",
            "  ex2-discriminant: [",
            "  ex2-discriminant: [no-such-claim, ",
            "field `rests_on.ex2-discriminant`: `no-such-claim` is not a claim of the inventory",
        ),
        (
            "ex2_three_frames.yaml",
            "  ex2-discriminant: [",
            "  p3f3sqr: [ex2-body]\n  ex2-discriminant: [",
            "field `rests_on.p3f3sqr`: `p3f3sqr` is not a claim this case checks",
        ),
        (
            "twofold_squared.yaml",
            "  p3f3sqr: [",
            "  p3f3sqr: [p3f3-quadratic, ",
            "a cycle of supports: ",
        ),
    ];
    for (file, from, to, says) in faults {
        let dir = copy();
        let path = dir.path().join(file);
        let text = std::fs::read_to_string(&path).unwrap();
        assert_eq!(text.matches(from).count(), 1, "{from}");
        let line = text.lines().position(|l| l.starts_with(from)).unwrap() + 1;
        std::fs::write(&path, text.replacen(from, to, 1)).unwrap();
        let out = crate::cli::report_of_cases(dir.path());
        assert_eq!(out.status.code(), Some(2), "{to}");
        let err = String::from_utf8(out.stderr).unwrap();
        assert!(err.contains(says), "{err}");
        // the line of the claim whose supports are at fault
        if !says.starts_with("a cycle") {
            assert!(err.contains(&format!("{file}:{line}")), "{err}");
        }
    }
}
