//! The command line end to end, one module per command: exit codes, JSON shapes, text,
//! determinism, and what each refuses.

use std::path::Path;
use std::process::{Command, Output};

mod audit;
mod dof;
mod identify;
mod noise;
mod process;
mod report;
mod solve;
mod synth;

pub(crate) use report::report_of_cases;

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
