//! The shared judge of an identity decided at random rational points (Schwartz–Zippel).

use super::{ClaimBuilder, Tolerance, ToleranceSource, Value};
use crate::studies::points::PointCheck;

/// The tolerance of a random-point check: the Schwartz–Zippel bound on the probability that
/// a false identity agrees at every point.
pub fn points_tolerance(p: &PointCheck) -> Tolerance {
    Tolerance {
        bound: None,
        source: ToleranceSource::FalsePass {
            log10: crate::check::Real(p.log10_failure_bound()),
        },
        how: "Schwartz–Zippel: a false identity passes with probability at most (degree of the difference / size of the sample set) per point, to the power of the number of points".into(),
    }
}

/// The random-point check's numbers, as details.
pub fn points_details<'b>(r: ClaimBuilder<'b>, p: &PointCheck) -> ClaimBuilder<'b> {
    r.detail("seed of the points", p.seed)
        .detail("degree of the difference", p.degree as usize)
        .detail("sample set size per coordinate", PointCheck::sample_size())
        .detail(
            "log10 of the failure bound",
            Value::real(p.log10_failure_bound()),
        )
}
