//! Embeds the paper's cases (`paper_cases/*.yaml` and `paper.yml`) in the crate, so that the
//! binary reproduces the paper from any folder; `--cases DIR` reads another folder instead.
//! Also writes one test per case file and per malformed case (`tests/bad_cases/*.yaml`) for
//! the suite (`tests/suite/cases.rs`), so that adding a case file adds its test.

use std::fmt::Write as _;
use std::path::Path;

fn main() {
    let root = std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR");
    let out_dir = std::env::var("OUT_DIR").expect("cargo sets OUT_DIR");
    embed_cases(Path::new(&root), Path::new(&out_dir));
    let mut tests = case_tests(Path::new(&root), "paper_cases", "paper_case");
    tests.push_str(&case_tests(Path::new(&root), "tests/bad_cases", "bad_case"));
    std::fs::write(Path::new(&out_dir).join("case_tests.rs"), tests).expect("OUT_DIR is writable");
}

/// `EMBEDDED_CASES`: every file of `paper_cases/`, its name and its text.
fn embed_cases(root: &Path, out_dir: &Path) {
    let dir = root.join("paper_cases");
    println!("cargo:rerun-if-changed={}", dir.display());
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .expect("paper_cases/ is part of the crate")
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".yaml") || n.ends_with(".yml") || n.ends_with(".md"))
        .collect();
    names.sort();
    let mut out = String::from("/// Every file of `paper_cases/`: its name and its text.\n");
    out.push_str("pub(crate) static EMBEDDED_CASES: &[(&str, &str)] = &[\n");
    for n in &names {
        let path = dir.join(n);
        println!("cargo:rerun-if-changed={}", path.display());
        writeln!(
            out,
            "    ({n:?}, include_str!({:?})),",
            path.display().to_string()
        )
        .expect("writing to a String");
    }
    out.push_str("];\n");
    std::fs::write(out_dir.join("embedded_cases.rs"), out).expect("OUT_DIR is writable");
}

/// A module `module` of tests, one per `*.yaml` of `folder`, each calling the function of the
/// same name with the file's path relative to the crate (as the errors name it).
fn case_tests(root: &Path, folder: &str, module: &str) -> String {
    let dir = root.join(folder);
    println!("cargo:rerun-if-changed={}", dir.display());
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .expect("the case folders are part of the crate")
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".yaml"))
        .collect();
    names.sort();
    let mut out = format!("/// One test per file of `{folder}/`.\nmod {module} {{\n");
    for n in &names {
        let stem = n.trim_end_matches(".yaml");
        let ident: String = stem
            .chars()
            .map(|c| {
                if c.is_ascii_alphanumeric() {
                    c.to_ascii_lowercase()
                } else {
                    '_'
                }
            })
            .collect();
        writeln!(
            out,
            "    #[test]\n    fn {ident}() {{\n        super::{module}(\"{folder}/{n}\");\n    }}"
        )
        .expect("writing to a String");
    }
    out.push_str("}\n");
    out
}
