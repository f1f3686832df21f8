//! Tests of `orthocheck_core::algebra::ratfn`.

use orthocheck_core::algebra::ratfn::*;
use orthocheck_core::algebra::Poly;

#[test]
fn substitution_and_linear_solve() {
    let f = RatFn::parse("x^2 / (y + 1)").unwrap();
    let g = f.substitute("x", &RatFn::parse("1/(y - 1)").unwrap());
    assert!(g.equals(&RatFn::parse("1 / ((y - 1)^2 (y + 1))").unwrap()));
    // [u 1; 1 v] x = [1; 0]
    let m = vec![
        vec![RatFn::var("u"), RatFn::int(1)],
        vec![RatFn::int(1), RatFn::var("v")],
    ];
    let x = solve_linear(&m, &[RatFn::int(1), RatFn::int(0)]).unwrap();
    assert!(x[0].equals(&RatFn::parse("v / (u v - 1)").unwrap()));
    assert!(RatFn::parse("1/(a - a)").is_err());
    let y = solve_linear_fraction_free(&m, &[RatFn::int(1), RatFn::int(0)]).unwrap();
    assert!(x.iter().zip(&y).all(|(a, b)| a.equals(b)));
}

#[test]
fn reduction_cancels_and_normalises() {
    let f = RatFn::parse("(x^2 - y^2)(z + 1) / (3(x - y)(z + 1)^2)").unwrap();
    let r = f.reduced();
    assert!(r.equals(&f));
    assert_eq!(r.num.to_string(), "1/3*x + 1/3*y");
    assert_eq!(r.den.to_string(), "z + 1");
    assert_eq!(RatFn::parse("0 / x").unwrap().reduced().den, Poly::int(1));
}
