//! The shared judge of an identity decided at random points modulo word primes
//! (Schwartz–Zippel).

use super::{ClaimBuilder, Tolerance, ToleranceSource, Value};
use crate::studies::points::PointCheck;

/// The tolerance of a random-point check: the Schwartz–Zippel bound on the probability that
/// a false identity agrees at every point.
pub fn points_tolerance(p: &PointCheck) -> Tolerance {
    Tolerance {
        bound: None,
        source: ToleranceSource::FalsePass {
            log10: crate::check::Real(p.log10_false_pass()),
        },
        how: "Schwartz–Zippel modulo primes enough for the difference's height (one of them keeps it non-zero): a false identity passes with probability at most (degree of the difference / smallest prime) per point, to the power of the number of points".into(),
    }
}

/// The random-point check's numbers, as details.
pub fn points_details<'b>(r: ClaimBuilder<'b>, p: &PointCheck) -> ClaimBuilder<'b> {
    let r = r
        .detail("seed of the points", p.seed)
        .detail("degree of the difference", p.degree as usize);
    prime_details(r, p).detail(
        "log10 of the failure bound",
        Value::real(p.log10_false_pass()),
    )
}

/// The primes a random-point check ran modulo: how many, the smallest, and the height bound
/// of the difference that set their number.
pub fn prime_details<'b>(r: ClaimBuilder<'b>, p: &PointCheck) -> ClaimBuilder<'b> {
    r.detail("primes", p.primes.len())
        .detail("smallest prime", p.smallest_prime())
        .detail(
            "height bound of the difference (bits)",
            p.height_bits as usize,
        )
}
