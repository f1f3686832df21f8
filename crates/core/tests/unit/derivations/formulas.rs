//! Tests of `orthocheck_core::derivations::formulas`.

use orthocheck_core::derivations::formulas::*;

#[test]
fn ordered_choices_agree_with_enumeration() {
    for n in 0..7 {
        for r in 0..4 {
            assert_eq!(ordered_choices(n, r), ordered_choices_enumerated(n, r));
        }
    }
}
