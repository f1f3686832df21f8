//! Tests of `orthocheck_core::algebra::sturm`.

use num_rational::BigRational;
use orthocheck_core::algebra::sturm::*;

fn r(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

#[test]
fn square_free_factors_of_repeated_roots() {
    // (x-1)^3 (x+2)^2 x
    let p = UPoly::from_roots(&[r(1, 1), r(1, 1), r(1, 1), r(-2, 1), r(-2, 1), r(0, 1)]);
    let f = p.square_free_factors();
    let mults: Vec<u32> = f.iter().map(|(m, _)| *m).collect();
    assert_eq!(mults, vec![1, 2, 3]);
}

#[test]
fn isolates_close_and_exact_roots() {
    let p = UPoly::from_roots(&[r(1, 3), r(1, 3) + r(1, 1_000_000), r(-5, 2), r(0, 1)]);
    let roots = p.real_roots_within(&r(1, 1_000_000_000));
    assert_eq!(roots.len(), 4);
    let want = [-2.5, 0.0, 1.0 / 3.0, 1.0 / 3.0 + 1e-6];
    for (root, w) in roots.iter().zip(want) {
        assert!((root.to_f64() - w).abs() < 1e-9, "{} vs {w}", root.to_f64());
        assert!(root.lo() <= root.hi());
    }
}

#[test]
fn no_real_roots() {
    assert!(UPoly::from_i64(&[1, 0, 1]).real_roots().is_empty());
}
