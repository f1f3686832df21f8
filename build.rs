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

/// The names of the files of `dir` ending in one of `endings`, in name order; the build
/// script reruns when the folder changes.
fn listed(dir: &Path, endings: &[&str]) -> Vec<String> {
    println!("cargo:rerun-if-changed={}", dir.display());
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .expect("the case folders are part of the crate")
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| endings.iter().any(|e| n.ends_with(e)))
        .collect();
    names.sort();
    names
}

/// `EMBEDDED_CASES`: every file of `paper_cases/`, its name and its text.
fn embed_cases(root: &Path, out_dir: &Path) {
    let dir = root.join("paper_cases");
    let names = listed(&dir, &[".yaml", ".yml", ".md"]);
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

/// A module `module` of tests, one per `*.yaml` of `folder`, each passing the file's path
/// relative to the crate (as the errors name it) to the function of the same name.
fn case_tests(root: &Path, folder: &str, module: &str) -> String {
    let names = listed(&root.join(folder), &[".yaml"]);
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
            "    #[test]\n    fn {ident}() {{\n        super::passes(\"{folder}/{n}\", super::{module});\n    }}"
        )
        .expect("writing to a String");
    }
    out.push_str("}\n");
    out
}
