//! `audit`: eq. p3f3sqr in full, every item with its verdict, the SymPy export.

use std::process::Command;

use super::{json, orthocheck};

#[test]
fn audit_twofold_squared_verifies_the_identity() {
    let out = orthocheck(&["audit", "twofold-squared"]);
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains("verdict:  identity-verified"), "{text}");
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
