//! The standard method for orthographic tracks, as the study calls it: Tomasi–Kanade
//! factorisation with its metric upgrade, optionally refined by bundle adjustment, turned
//! into squared edges (the mirror solution has the same edges).

use crate::model::Tracks;

/// Whether this build has the standard method (the `sfm` module).
pub const AVAILABLE: bool = false;

/// The squared edges of the standard reconstruction from the first `frames` frames of
/// `tracks`, refined by bundle adjustment when `refine`; `None` when it fails. This build
/// has no factorisation: always `None` (and [`AVAILABLE`] says so, so no trial reads it).
pub fn squares(_tracks: &Tracks, _frames: usize, _refine: bool) -> Option<Vec<f64>> {
    None
}
