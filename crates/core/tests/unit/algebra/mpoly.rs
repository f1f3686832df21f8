//! Tests of `orthocheck_core::algebra::mpoly`.

use orthocheck_core::algebra::mpoly::coeff::Coef;
use orthocheck_core::algebra::mpoly::mul::{mul_array, mul_heap};
use orthocheck_core::algebra::mpoly::ring::Ring;
mod coeff;
mod monomial;

use orthocheck_core::algebra::mpoly::*;

fn fateman(n: u32) -> MPoly {
    let r = Ring::new(&["x", "y", "z", "t"]);
    let one = MPoly::constant(4, Coef::Small(1));
    let s = r
        .names()
        .iter()
        .fold(one, |acc, v| &acc + &r.var(v).unwrap_or(MPoly::zero(4)));
    s.pow(n)
}

#[test]
fn heap_and_array_products_agree() {
    let p = fateman(6);
    let q = &p + &MPoly::constant(4, Coef::Small(1));
    let heap = mul_heap(&p, &q);
    let array = mul_array(&p, &q).unwrap();
    assert_eq!(heap, array);
    assert_eq!(heap.len(), 1820); // the monomials of degree ≤ 12 in four variables
    assert_eq!(heap.div_exact(&p), Some(q.clone()));
    assert_eq!(
        (&heap + &MPoly::constant(4, Coef::Small(1))).div_exact(&p),
        None
    );
}

#[test]
fn big_coefficients_multiply_and_divide() {
    let r = Ring::new(&["x", "y"]);
    let x = r.var("x").unwrap();
    let big = MPoly::constant(2, Coef::Small(i64::MAX));
    let p = &(&x * &big) + &r.var("y").unwrap();
    let p3 = p.pow(3);
    assert!(p3.coefs().iter().any(|c| matches!(c, Coef::Big(_))));
    assert_eq!(p3.div_exact(&p), Some(p.pow(2)));
    assert_eq!(mul_heap(&p.pow(2), &p), p3);
}

#[test]
fn gcd_recovers_a_common_factor() {
    let r = Ring::new(&["a", "b", "c"]);
    let v = |n: &str| r.var(n).unwrap();
    let two = MPoly::constant(3, Coef::Small(2));
    let g = &(&v("a") * &v("b")) - &(&two * &v("c"));
    let a = &g.pow(2) * &(&v("a") + &two);
    let b = &g * &(&v("b") - &v("c")).pow(2);
    assert_eq!(a.gcd(&b), g.clone());
    assert_eq!(a.gcd_prs(&b), g.clone());
    let six = MPoly::constant(3, Coef::Small(6));
    assert_eq!((&a * &six).gcd(&(&b * &(&two * &two))), &g * &two);
    assert_eq!((&a * &six).gcd_prs(&(&b * &(&two * &two))), &g * &two);
    assert_eq!(v("a").gcd(&v("b")), MPoly::constant(3, Coef::Small(1)));
    assert_eq!(v("a").gcd_prs(&v("b")), MPoly::constant(3, Coef::Small(1)));
}

/// Degree 300 with 64-bit coefficients: the first image would pass the heuristic's size
/// limit, so it gives up at once, and the answer comes from the remainder sequence.
#[test]
fn gcd_falls_back_when_the_heuristic_gives_up() {
    let r = Ring::new(&["x", "y"]);
    let (x, y) = (r.var("x").unwrap(), r.var("y").unwrap());
    let one = MPoly::constant(2, Coef::Small(1));
    let k = MPoly::constant(2, Coef::Small(1 << 62));
    let g = &(&x + &y) + &one;
    let a = &g * &(&(&k * &x.pow(300)) + &y);
    let b = &g * &(&x.pow(300) - &(&k * &y));
    assert_eq!(a.gcd_heuristic(&b), None);
    assert_eq!(a.gcd(&b), g.clone());
    assert_eq!(a.gcd(&(&b * &y)), g.clone());
    assert_eq!((&a * &y.pow(2)).gcd(&(&b * &y)), &g * &y);
    // coprime after the planted factor is removed
    assert_eq!(a.gcd(&(&b + &one)), one);
}

#[test]
fn substitution_and_evaluation() {
    let r = Ring::new(&["x", "y"]);
    let (x, y) = (r.var("x").unwrap(), r.var("y").unwrap());
    let p = &x.pow(3) + &y;
    let q = p.substitute(0, &(&y + &MPoly::constant(2, Coef::Small(1))));
    let at = [num_bigint::BigInt::from(5), num_bigint::BigInt::from(7)];
    assert_eq!(q.eval(&at), num_bigint::BigInt::from(8 * 8 * 8 + 7));
    assert_eq!(r.display(&q), "y^3 + 3*y^2 + 4*y + 1");
}
