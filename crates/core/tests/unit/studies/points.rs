//! Tests of `orthocheck_core::studies::points`.

use orthocheck_core::algebra::modp::prime;
use orthocheck_core::algebra::rat;
use orthocheck_core::algebra::RatFn;
use orthocheck_core::studies::points::*;

#[test]
fn a_false_identity_fails_and_the_bound_is_small() {
    let l = RatFn::parse("x^2 + y").unwrap();
    let r = RatFn::parse("x^2 - y").unwrap();
    let c = agree_at_points(&l, &r, &rat(1, 1), 8, 1);
    assert_eq!(c.agreeing, 0);
    assert_eq!(c.primes, vec![prime(0)]);
    assert!((c.log10_false_pass() - 8.0 * (2.0 / prime(0) as f64).log10()).abs() < 1e-9);
}

#[test]
fn a_flipped_term_is_rejected() {
    let e = RatFn::parse("(x^2 - y)/(x + 1)").unwrap();
    let (_, m) = flip_one_term(&e).unwrap();
    assert!(!m.equals(&e) && m.ratio_to(&e).is_none());
    // a single term cannot be flipped in sign alone: a proportional check would absorb it
    let one = RatFn::parse("3x^2").unwrap();
    let (_, m) = flip_one_term(&one).unwrap();
    assert!(m.ratio_to(&one).is_none());
}
