//! Tests of `orthocheck_core::algebra::poly`.

use num_rational::BigRational;
use orthocheck_core::algebra::poly::*;

#[test]
fn parse_and_print_round_trip() {
    let p = Poly::parse("2(a_i^2 - b^2)c^2 - 1/2").unwrap();
    assert_eq!(p.to_string(), "2*a_i^2*c^2 - 2*b^2*c^2 - 1/2");
    assert_eq!(Poly::parse(&p.to_string()).unwrap(), p);
}

#[test]
fn substitution_and_coefficients() {
    let p = Poly::parse("x^2 + y").unwrap();
    let q = p.substitute("x", &Poly::parse("y + 1").unwrap());
    assert_eq!(q, Poly::parse("y^2 + 3y + 1").unwrap());
    let c = q.coefficients_in("y");
    assert_eq!(c.len(), 3);
    assert_eq!(c[1], Poly::int(3));
}

#[test]
fn ratio_detects_scalar_multiples() {
    let p = Poly::parse("a - b").unwrap();
    let q = Poly::parse("3b - 3a").unwrap();
    assert_eq!(q.ratio_to(&p), Some(BigRational::from_integer((-3).into())));
    assert_eq!(Poly::parse("a + b").unwrap().ratio_to(&p), None);
}

#[test]
fn parse_errors_name_the_position() {
    let e = Poly::parse("a + * b").unwrap_err();
    assert_eq!(e.position, 4);
    assert!(Poly::parse("a^b").is_err());
    assert!(Poly::parse("(a").is_err());
    assert!(Poly::parse("a / b").is_err());
}
