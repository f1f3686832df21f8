//! Tests of `orthocheck_core::algebra::Multiquad`: signs decided exactly on both sides of a
//! close rational, and zero found through a dependent basis.

use std::cmp::Ordering::*;

use orthocheck_core::algebra::{rat, Multiquad};

#[test]
fn the_sign_of_a_close_approximation_of_a_root() {
    let f = Multiquad::field(vec![rat(2, 1)]);
    let r2 = Multiquad::root(&f, 0);
    // 140/99 < √2 < 99/70, within 1e-4 of it on either side
    let above = &Multiquad::constant(&f, rat(99, 70)) - &r2;
    let below = &Multiquad::constant(&f, rat(140, 99)) - &r2;
    assert_eq!(above.sign(), Greater);
    assert_eq!(below.sign(), Less);
    assert_eq!((&r2 * &r2).sign(), Greater);
    assert!((&(&r2 * &r2) - &Multiquad::constant(&f, rat(2, 1))).is_zero());
}

#[test]
fn three_generators_on_both_sides_of_a_rational() {
    // √2 + √3 − √5 = 0.910196…
    let f = Multiquad::field(vec![rat(2, 1), rat(3, 1), rat(5, 1)]);
    let [a, b, c] = [0, 1, 2].map(|i| Multiquad::root(&f, i));
    let x = &(&a + &b) - &c;
    let at = |n, d| &x - &Multiquad::constant(&f, rat(n, d));
    assert_eq!(at(91, 100).sign(), Greater);
    assert_eq!(at(9102, 10000).sign(), Less);
    assert_eq!((-&at(9102, 10000)).sign(), Greater);
}

#[test]
fn a_dependent_basis_still_finds_zero() {
    // √6 is √2·√3: the coefficients differ, the value is zero
    let f = Multiquad::field(vec![rat(2, 1), rat(3, 1), rat(6, 1)]);
    let [a, b, c] = [0, 1, 2].map(|i| Multiquad::root(&f, i));
    let x = &(&a * &b) - &c;
    assert!(x.is_zero());
    assert_eq!(
        (&x + &Multiquad::constant(&f, rat(1, 1_000_000))).sign(),
        Greater
    );
    assert_eq!(x.scale(&rat(3, 1)).sign(), Equal);
}

#[test]
fn a_rational_generator_and_a_sum_over_unequal_denominators() {
    // √(2/3) = 0.816496…, kept as √6 / 3; its square is 2/3 exactly
    let f = Multiquad::field(vec![rat(2, 3)]);
    let r = Multiquad::root(&f, 0);
    assert!((&(&r * &r) - &Multiquad::constant(&f, rat(2, 3))).is_zero());
    assert_eq!(
        (&r - &Multiquad::constant(&f, rat(8164, 10000))).sign(),
        Greater
    );
    assert_eq!(
        (&r - &Multiquad::constant(&f, rat(8165, 10000))).sign(),
        Less
    );
    // 1/6 + √(2/3)/4 − (1/6 + √(2/3)/4) over denominators 6 and 12
    let x = &Multiquad::constant(&f, rat(1, 6)) + &r.scale(&rat(1, 4));
    assert_eq!(
        x,
        &r.scale(&rat(3, 12)) + &Multiquad::constant(&f, rat(2, 12))
    );
}
