//! Tests of `orthocheck_core::algebra::modp`.

use orthocheck_core::algebra::modp::*;
use orthocheck_core::algebra::mpoly::{Coef, Scalar};
use orthocheck_core::algebra::RatFn;

#[test]
fn field_arithmetic_is_exact() {
    let a: Fp = Residue(PRIME - 1);
    assert_eq!(a.mul(&a), Residue(1));
    assert_eq!(a.add(&Residue(1)), Residue(0));
    let x: Fp = Residue(12345);
    assert_eq!(x.inv().map(|i| i.mul(&x)), Some(Residue(1)));
    // the largest offset: (p − 1)² ≡ 1 and an inverse through the two folds
    let b: Residue<819> = Residue(prime(15) - 1);
    assert_eq!(b.mul(&b), Residue(1));
    let y: Residue<819> = Residue(prime(15) - 12345);
    assert_eq!(y.inv().map(|i| i.mul(&y)), Some(Residue(1)));
    assert_eq!(Fp::from_coef(&Coef::Small(-1)), a);
}

#[test]
fn a_changed_coefficient_is_rejected() {
    let l = RatFn::parse("(x + y)^3 / (x - 2 z)").unwrap();
    let same = RatFn::parse("(x^3 + 3x^2 y + 3x y^2 + y^3) / (x - 2z)").unwrap();
    let mutant = RatFn::parse("(x^3 + 3x^2 y + 4x y^2 + y^3) / (x - 2z)").unwrap();
    let one = orthocheck_core::algebra::rat(1, 1);
    assert_eq!(agree_mod_p(&l, &same, &one, 16, 5).agreeing, 16);
    assert_eq!(agree_mod_p(&l, &mutant, &one, 16, 5).agreeing, 0);
    assert_eq!(agree_mod_p(&l, &same, &one, 1, 5).degree, 4);
}

/// A difference that the first prime divides (its coefficient is 2⁶¹ − 1) vanishes modulo that
/// prime at every point; its height asks for a second prime, which rejects it.
#[test]
fn a_difference_the_first_prime_divides_is_rejected_by_the_second() {
    let one = orthocheck_core::algebra::rat(1, 1);
    let l = RatFn::parse(&format!("{PRIME} x + y")).unwrap();
    let r = RatFn::parse("y").unwrap();
    let s = agree_mod_p(&l, &r, &one, 8, 3);
    assert_eq!(s.primes, vec![prime(0), prime(1)]);
    assert_eq!(s.agreeing, 0);
    assert!(s.height_bits > 60);
    // a smaller coefficient: one prime suffices
    let small = RatFn::parse("(2^50) x + y").unwrap();
    assert_eq!(agree_mod_p(&small, &r, &one, 8, 3).primes.len(), 1);
}

/// Constants (degree 0): the bound is finite, never −∞ (which no output may hold).
#[test]
fn a_constant_difference_has_a_finite_bound() {
    let one = orthocheck_core::algebra::rat(1, 1);
    let s = agree_mod_p(
        &RatFn::parse("2").unwrap(),
        &RatFn::parse("3").unwrap(),
        &one,
        4,
        1,
    );
    assert_eq!((s.agreeing, s.degree), (0, 0));
    assert!(s.log10_false_pass().is_finite() && s.log10_false_pass() < -300.0);
}
