//! `noise`: its tables, its seeds, the ids it takes.

use super::{json, orthocheck};

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
