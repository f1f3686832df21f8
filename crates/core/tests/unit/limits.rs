//! Tests of `orthocheck_core::limits`.

use orthocheck_core::limits::*;

#[test]
fn docs_list_every_limit() {
    let doc = include_str!("../../../../docs/limits.md");
    let me = include_str!("limits.rs");
    for line in me.lines() {
        if let Some(rest) = line.strip_prefix("pub const ") {
            let name = rest.split(':').next().unwrap_or("");
            assert!(doc.contains(name), "docs/limits.md does not list {name}");
        }
    }
}

#[test]
fn limits_accept_up_to_and_refuse_beyond() {
    assert!(at_most("n", 10, 10).is_ok());
    assert!(at_most("n", 11, 10).unwrap_err().contains("limit of 10"));
    assert!(count("n", 0, 10).is_err());
    assert!(count("n", 1, 10).is_ok());
    assert!(noise_level("ε", 0.0).is_ok());
    assert!(noise_level("ε", NOISE_LEVEL).is_ok());
    assert!(noise_level("ε", -0.1).is_err());
    assert!(noise_level("ε", 1e308).unwrap_err().starts_with("ε 1e308:"));
    assert!(noise_level("ε", f64::NAN).is_err());
}
