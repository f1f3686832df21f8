//! Tests of `orthocheck_core::algebra::perm`.

use orthocheck_core::algebra::perm::*;

#[test]
fn counts_and_order() {
    assert_eq!(permutations(0), vec![Vec::<usize>::new()]);
    assert_eq!(permutations(5).len(), 120);
    let p4 = permutations4();
    assert_eq!(p4.len(), 24);
    assert_eq!(p4[0], [0, 1, 2, 3]);
    assert_eq!(p4[23], [3, 2, 1, 0]);
    assert!(p4.windows(2).all(|w| w[0] < w[1]));
}
