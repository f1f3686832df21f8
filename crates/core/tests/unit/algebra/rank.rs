//! Tests of `orthocheck_core::algebra::rank`.

use num_rational::BigRational;
use orthocheck_core::algebra::rank::*;

fn r(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

#[test]
fn bareiss_and_modular_agree() {
    let m = vec![
        vec![r(1, 2), r(1, 3), r(1, 4)],
        vec![r(1, 3), r(1, 4), r(1, 5)],
        vec![r(5, 6), r(7, 12), r(9, 20)],
    ];
    // third row = first + second
    assert_eq!(bareiss_rank(&m), 2);
    assert_eq!(modular_rank(&m), Some(2));
    assert_eq!(exact_rank(&m), (2, ExactRankMethod::FractionFree));
    let full = vec![vec![r(1, 1), r(0, 1)], vec![r(0, 1), r(3, 7)]];
    assert_eq!(exact_rank(&full), (2, ExactRankMethod::ModularFull));
}

#[test]
fn skipped_columns_keep_divisions_exact() {
    let m = vec![
        vec![r(0, 1), r(2, 1), r(4, 1), r(1, 1)],
        vec![r(0, 1), r(1, 1), r(2, 1), r(3, 1)],
        vec![r(0, 1), r(3, 1), r(6, 1), r(4, 1)],
    ];
    assert_eq!(bareiss_rank(&m), 2);
}
