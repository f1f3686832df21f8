//! Members of the one-parameter family of bodies two frames allow (§5.1), sampled at angles
//! β evenly spread in (0, π).

use nalgebra::Vector2;

use crate::derivations::identity::rigidity;
use crate::derivations::two_frames::{family, Member};
use crate::error::{Error, Result};

/// `samples` angles evenly spread in the open interval (0, π): β_i = π i / (samples + 1).
/// The ends are left out, where the two views coincide or mirror each other.
pub fn betas(samples: usize) -> Vec<f64> {
    (1..=samples)
        .map(|i| std::f64::consts::PI * i as f64 / (samples + 1) as f64)
        .collect()
}

/// The family's members at [`betas`]`(samples)` for the two frames `f1`, `f2` (the same
/// points in the same order). A degenerate pair of frames, one whose epipolar geometry is
/// undetermined, or one no rigid body gives, is `InvalidInput`.
pub fn sample_family(
    f1: &[Vector2<f64>],
    f2: &[Vector2<f64>],
    samples: usize,
) -> Result<Vec<Member>> {
    if let Some(d) = rigidity(f1, f2) {
        return Err(Error::InvalidInput(d.to_string()));
    }
    family(f1, f2, &betas(samples))
        .ok_or_else(|| Error::InvalidInput("the epipolar geometry is undetermined".into()))
}
