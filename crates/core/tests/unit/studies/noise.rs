//! Tests of `orthocheck_core::studies::noise`.

use orthocheck_core::studies::noise::*;

#[test]
fn squares_and_lengths_are_told_apart() {
    let truth = [9.0, 16.0, 25.0];
    assert!(SymbolDistances::of(&[9.1, 16.1, 24.9], &truth).are_squares());
    assert!(!SymbolDistances::of(&[3.1, 4.1, 4.9], &truth).are_squares());
}

#[test]
fn run_errors_carry_the_rounding() {
    let truth = [9.0, 16.0, 25.0];
    let e = run_errors(&[9.9, 16.0, 25.0], &[0.09; 3], true, &truth).unwrap();
    assert!((e.metrics[0] - 0.1).abs() < 1e-12);
    let (lo, hi) = e.ranges[0];
    assert!((lo - 0.09).abs() < 1e-12 && (hi - 0.11).abs() < 1e-12);
    // an exact edge's error range starts at 0
    assert!((e.ranges[1].0 - 0.09 / 3.0).abs() < 1e-12);
    // lengths squared first
    let l = run_errors(&[3.3, 4.0, 5.0], &[0.0; 3], false, &truth).unwrap();
    assert!((l.metrics[2] - 0.1).abs() < 1e-12);
}
