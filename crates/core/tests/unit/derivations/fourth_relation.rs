//! Tests of `orthocheck_core::derivations::fourth_relation`.

use num_rational::BigRational;
use num_traits::Zero;
use orthocheck_core::derivations::fourth_relation::*;

#[test]
fn the_fourth_relation_is_independent() {
    let r = fourth_relation(3);
    assert!(!r.linear, "{:?}", r.obstruction);
    let z = BigRational::zero();
    assert_eq!(
        &r.counterexample_values[..3],
        &[z.clone(), z.clone(), z.clone()]
    );
    assert_ne!(r.counterexample_values[3], z);
    assert_eq!((r.rank_three, r.rank_four), (3, 4));
}
