//! What the benchmarks share: where the paper's cases are.

use std::path::PathBuf;

/// The folder of the paper's cases, `paper_cases/` of the repository.
pub fn paper_cases() -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../paper_cases"))
}
