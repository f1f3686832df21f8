//! Exact and floating algebra: polynomials over ℚ, exact root isolation, float roots, rank.

pub mod cholesky;
pub mod damping;
mod diff;
pub mod enclosure;
pub mod float_roots;
mod gram;
pub mod integer;
pub mod interval;
mod lanczos;
pub mod mix;
pub mod modp;
pub mod mpoly;
mod multiquad;
mod newton;
mod parse;
pub mod perm;
pub mod poly;
mod procrustes;
pub mod rank;
pub mod ratfn;
pub mod student;
pub mod sturm;

pub use diff::central_jacobian;
pub use enclosure::{centre, Grad, Scalar};
pub use float_roots::{
    closed_form_real, companion_roots, compare_methods, quadratic, quadratic_roots, EigenMethod,
    RootAgreement,
};
pub use gram::gram;
pub use interval::Interval;
pub use lanczos::largest_eigenvalue;
pub use multiquad::{Multiquad, MultiquadField};
pub use newton::{min_norm_newton, min_norm_newton_step, min_norm_newton_with};
pub use parse::parse_decimal;
pub use perm::{permutations, permutations4};
pub use poly::{Monomial, Poly};
pub use procrustes::{complete_rotation, kabsch, nearest_rotation, orthonormal_rows};
pub use rank::{exact_rank, exact_solve, svd_rank, svd_rank_above, ExactRankMethod, SvdRank};
pub use ratfn::{determinant, solve_linear, solve_linear_fraction_free, RatFn};
pub use sturm::{RealRoot, UPoly};

use num_rational::BigRational;

/// A rational `n / d` (panics only on `d == 0`, which callers never pass).
pub fn rat(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

/// Units of rounding allowed before a computed quantity counts as zero: the quantities
/// tested this way come from a few dozen additions and products of the inputs.
pub const NEGLIGIBLE_ULPS: f64 = 64.0;

/// Whether a 3 × 3 positive semidefinite matrix `m`, a sum of products whose entries round
/// to about ε·`terms` of its size, is nonsingular beyond rounding: its smallest eigenvalue
/// is not [`negligible`] against `terms` times its largest. λmax ≤ tr and λmid·λmax ≤
/// (tr/2)², so λmin ≥ 4 det/tr²; where that bound, halved for the determinant's own
/// rounding (about 20ε·tr³), clears the threshold, the eigenvalues are not computed (they
/// were a third of bundle adjustment's time on 100,000 points). The fast path needs
/// det > 32ε·`terms`·tr³, at least 96ε·tr³, so rounding moves det by under a fifth and
/// λmin stays above 1.5 times the threshold: it never says nonsingular where the
/// eigenvalues would not.
pub fn psd3_nonsingular(m: &nalgebra::Matrix3<f64>, terms: f64) -> bool {
    let tr = m.trace();
    if !tr.is_finite() || tr <= 0.0 {
        return false;
    }
    let bound = 2.0 * m.determinant() / (tr * tr);
    if bound > 0.0 && !negligible(bound, tr * terms) {
        return true;
    }
    let e = m.symmetric_eigenvalues();
    !negligible(e.min(), e.max() * terms)
}

/// The relative rounding level of a square root of a difference of squares, √(e² − eᵢ²):
/// cancellation leaves an absolute error near √(64ε)·e, far above 64ε. Quantities built from
/// such depths (the two-frame constructions) are compared at this level.
pub fn sqrt_rounding() -> f64 {
    (NEGLIGIBLE_ULPS * f64::EPSILON).sqrt()
}

/// Whether `value`, computed from terms whose absolute values sum to `magnitude`, is zero
/// up to rounding (|value| ≤ 64·ε·magnitude). Used to detect exactly degenerate input, never
/// to accept a noisy result.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::negligible;
/// assert!(negligible(0.1 + 0.2 - 0.3, 0.6));
/// assert!(!negligible(1e-9, 1.0));
/// ```
#[inline]
pub fn negligible(value: f64, magnitude: f64) -> bool {
    value.abs() <= NEGLIGIBLE_ULPS * f64::EPSILON * magnitude
}
