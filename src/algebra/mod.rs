//! Exact and floating algebra: polynomials over ℚ, exact root isolation, float roots, rank.

mod float_roots;
mod poly;
mod rank;
mod sturm;

pub use float_roots::{
    closed_form_real, companion_roots, compare_methods, quadratic, EigenMethod, RootAgreement,
};
pub use poly::{parse_decimal, Monomial, Poly};
pub use rank::{exact_rank, svd_rank, ExactRankMethod, SvdRank};
pub use sturm::{RealRoot, UPoly};

use num_rational::BigRational;

/// A rational `n / d` (panics only on `d == 0`, which callers never pass).
pub fn rat(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}
