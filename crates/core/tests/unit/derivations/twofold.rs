//! Tests of `orthocheck_core::derivations::twofold`.

use num_rational::BigRational;
use orthocheck_core::derivations::twofold::*;

#[test]
fn every_sign_pattern_squares_to_the_same_polynomial() {
    let p = twofold_squared([1, 1, -1]);
    assert_eq!(twofold_squared([1, -1, 1]), p);
    assert_eq!(twofold_squared([-1, 1, 1]), p);
    // the norm over the four sign classes (√A ± √B ± √C) is the same polynomial
    assert_eq!(
        sign_class_product().ratio_to(&p),
        Some(BigRational::from_integer(1.into()))
    );
}

#[test]
fn census_covers_all_trials() {
    let c = relation_census(&[[1, 1, -1], [1, -1, 1], [-1, 1, 1]], 200, 1);
    assert_eq!(c.none_held, 0);
    assert_eq!(c.held.iter().sum::<usize>(), 200);
    // √(e² − eᵢ²) carries an absolute error up to √(4ε)·e per edge (cancellation under
    // the root), so three terms stay below 3·√(4ε).
    assert!(c.max_residual < 3.0 * (4.0 * f64::EPSILON).sqrt());
}
