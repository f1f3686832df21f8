//! Tests of `orthocheck_core::derivations::appendix_a`.

use num_rational::BigRational;
use num_traits::{Signed, Zero};
use orthocheck_core::algebra::Poly;
use orthocheck_core::derivations::appendix_a::*;
use std::collections::BTreeMap;

#[test]
fn exact_delta_b_matches_the_float_quadratic() {
    // projections (4, 8, 4) and (4, 5, 1) of the scene below; at c² = 5 the true b² = 9
    // is a root, so Δ_b ≥ 0 there
    let q = |v: [i64; 3]| v.map(|x| BigRational::from_integer(x.into()));
    let d = exact_delta_b(eliminate_symbolic(), &q([4, 8, 4]), &q([4, 5, 1])).unwrap();
    let at5 = d.eval(&BigRational::from_integer(5.into()));
    assert!(!at5.is_negative());
    assert!(d.f_cb_over_f_b2.is_some());
    let flat = ExactDeltaB {
        coefficients: [
            BigRational::zero(),
            -BigRational::from_integer(1.into()),
            BigRational::zero(),
        ],
        f_cb_over_f_b2: None,
    };
    assert_eq!(flat.sign_above(&BigRational::zero()), -1);
    assert!(flat.negative_beyond(&BigRational::zero()));
}

#[test]
fn an_exact_scene_satisfies_the_eliminated_equation() {
    // P = (0,0,0), Q = (2,0,0), R = (0,2,1): a² = 4, b² = 9, c² = 5; frame 1 the
    // identity, frame 2 turned 90° about x: projected squares (4, 8, 4) and (4, 5, 1)
    let e = eliminate();
    let squares = |p: &Poly| {
        ["a_1", "b_1", "c_1", "a_2", "b_2", "c_2", "b", "c"]
            .iter()
            .try_fold(p.clone(), |q, v| in_squares(&q, v, &format!("{v}_sq")))
            .unwrap()
    };
    let vals: BTreeMap<String, BigRational> = [
        ("a_1", 4),
        ("b_1", 8),
        ("c_1", 4),
        ("a_2", 4),
        ("b_2", 5),
        ("c_2", 1),
        ("b", 9),
        ("c", 5),
    ]
    .into_iter()
    .map(|(k, v)| (format!("{k}_sq"), BigRational::from_integer(v.into())))
    .collect();
    let num = squares(&e.equation.num).eval(&vals).unwrap();
    let den = squares(&e.equation.den).eval(&vals).unwrap();
    assert_eq!(num, BigRational::from_integer(0.into()));
    assert_ne!(den, BigRational::from_integer(0.into()));
}
