//! Tests of `orthocheck_core::algebra::modp`.

use orthocheck_core::algebra::modp::*;
use orthocheck_core::algebra::mpoly::{Coef, Scalar};
use orthocheck_core::algebra::RatFn;

#[test]
fn field_arithmetic_is_exact() {
    let a = Fp(PRIME - 1);
    assert_eq!(a.mul(&a), Fp(1));
    assert_eq!(a.add(&Fp(1)), Fp(0));
    assert_eq!(Fp(12345).inv().map(|i| i.mul(&Fp(12345))), Some(Fp(1)));
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
