//! `dof`: one count and the grid.

use super::{json, orthocheck};

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
