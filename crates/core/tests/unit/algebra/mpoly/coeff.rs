//! Tests of `orthocheck_core::algebra::mpoly::coeff`.

use num_bigint::BigInt;
use orthocheck_core::algebra::mpoly::coeff::*;

#[test]
fn small_values_promote_and_demote() {
    let m = Coef::Small(i64::MAX);
    let sq = m.mul(&m);
    assert!(matches!(sq, Coef::Big(_)));
    assert_eq!(sq.div_exact(&m), Some(m.clone()));
    assert_eq!(
        Coef::Small(i64::MIN).neg().to_big(),
        -BigInt::from(i64::MIN)
    );
    let mut acc = Acc::default();
    for _ in 0..4 {
        acc.add_mul(&sq.clone(), &Coef::Small(1));
        acc.add_mul(&m, &m);
    }
    assert_eq!(acc.take().to_big(), BigInt::from(8) * sq.to_big());
    assert_eq!(content(&[Coef::Small(6), Coef::Small(-4)]), Coef::Small(2));
}
