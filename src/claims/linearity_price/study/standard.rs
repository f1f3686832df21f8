//! The standard method for orthographic tracks, as the study calls it: Tomasi–Kanade
//! factorisation with its metric upgrade (`sfm::tomasi_kanade`), optionally refined by bundle
//! adjustment (`sfm::bundle_adjust`), turned into squared edges (the mirror solution has the
//! same edges, so the Necker ambiguity does not touch the error).

use crate::model::{edges, Tracks};
use crate::sfm::{bundle_adjust, tomasi_kanade, BundleOptions, Observations};

/// Whether this build has the standard method (the `sfm` module).
pub const AVAILABLE: bool = true;

/// The squared edges of the standard reconstruction from the first `frames` frames of
/// `tracks`, refined by bundle adjustment when `refine`; `None` when the factorisation or the
/// adjustment fails (a degenerate scene, a metric upgrade with no solution).
pub fn squares(tracks: &Tracks, frames: usize, refine: bool) -> Option<Vec<f64>> {
    let t = Tracks {
        names: tracks.names.clone(),
        frames: tracks.frames.get(..frames)?.to_vec(),
    };
    let start = tomasi_kanade(&t).ok()?;
    let rec = if refine {
        bundle_adjust(
            &Observations::from_tracks(&t),
            &start,
            // only the body is read
            &BundleOptions {
                standard_errors: false,
                ..BundleOptions::default()
            },
        )
        .ok()?
        .reconstruction
    } else {
        start
    };
    let p = &rec.points;
    Some(
        edges(p.len())
            .iter()
            .map(|&(i, j)| (p[i] - p[j]).norm_squared())
            .collect(),
    )
}
