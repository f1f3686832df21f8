//! The process: usage errors, Ctrl-C, closed pipes and full disks.

use std::process::Command;

use super::orthocheck;

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
