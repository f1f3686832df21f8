//! Tests of `orthocheck_core::studies::rounding`.

use orthocheck_core::derivations::rounding::RoundingBox;
use orthocheck_core::studies::rounding::*;

#[test]
fn the_ladder_stops_at_the_first_failure() {
    let a = acceptance(&|s| s.abs() < 20.0);
    assert_eq!(a.accepted, [10.0, 10.0]);
    assert_eq!(a.rejected, [Some(30.0), Some(30.0)]);
    assert_eq!(a.interval(5.0, 0.5), (-10.0, 20.0));
    assert_eq!(a.outer(), 30.0);
    let never = acceptance(&|_| true);
    assert!(never.outer().is_infinite());
}

#[test]
fn a_witness_is_found_only_inside_the_box() {
    let b = RoundingBox {
        center: vec![0.0],
        half: vec![0.5],
    };
    // x = 0.3 is inside, x = 3 is not
    let near = |x: &[f64]| Some(vec![(x[0] - 0.3) / 1e-9]);
    let far = |x: &[f64]| Some(vec![(x[0] - 3.0) / 1e-9]);
    assert!(reproduce(&b, &near).is_some());
    assert!(reproduce(&b, &far).is_none());
}
