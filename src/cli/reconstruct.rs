//! `orthocheck reconstruct`: the body and every frame's camera from many points in many
//! frames (Tomasi–Kanade, bundle adjustment, gaps, RANSAC). Points and frames that cannot
//! take part are dropped and listed; frames that split into groups sharing too few points
//! are reconstructed group by group. When a step raises a warning (its answer may be wrong),
//! the whole result is still printed, with the warnings, and the command exits 1.

use std::path::PathBuf;

use crate::input::load_observations;
use crate::sfm::robust::{RansacOptions, DEFAULT_SEED};
use crate::sfm::{output, reconstruct, Options};
use crate::Error;

use super::{in_file, json_out, out};

/// Arguments of `reconstruct`.
#[derive(clap::Args)]
pub struct Args {
    /// Tracks: YAML (`frames:` lists of [x, y], `null` for a missing point, optional
    /// `points:`) or CSV (`frame,point,x,y`; a missing point has no row).
    #[arg(long)]
    input: PathBuf,
    /// JSON output.
    #[arg(long)]
    json: bool,
    /// RANSAC over the paper's four-point solver before the fit, then every observation
    /// judged: a point keeps the images within the threshold of its reprojection (at least
    /// 3 of them, or both of 2), the others are dropped and listed.
    #[arg(long)]
    robust: bool,
    /// Inlier threshold of --robust: the largest distance, in image units, from an image
    /// point to its reprojection. Default: from the data, 3.035 σ (the 99 % point of the
    /// norm of a 2-D normal error; wider when σ is known to few degrees of freedom) with σ =
    /// median residual norm / 1.1774 (the Rayleigh median), corrected for the fit's
    /// parameters, never below rounding; where the noise grows with the coordinates, each
    /// residual coordinate is weighed by its own scale.
    #[arg(long, allow_negative_numbers = true, requires = "robust")]
    threshold: Option<f64>,
    /// Seed of --robust's sample generator, and of the random starts of variable projection
    /// (tracks with most entries missing, tried when the chain of frame pairs breaks).
    #[arg(long, allow_negative_numbers = true, value_parser = super::SeedParser, default_value_t = DEFAULT_SEED)]
    seed: u64,
    /// Skip the bundle adjustment (Tomasi–Kanade only).
    #[arg(long)]
    no_bundle: bool,
}

/// Load the tracks, reconstruct, print.
pub fn run(a: Args) -> Result<(), Error> {
    if let Some(t) = a.threshold
        && !(t.is_finite() && t > 0.0)
    {
        return Err(Error::InvalidInput(format!(
            "--threshold {t}: the inlier threshold must be a positive number of image units"
        )));
    }
    let obs = load_observations(&a.input)?;
    if a.robust {
        let (what, limit) = if obs.count() < obs.names.len().saturating_mul(obs.frames.len()) {
            (
                "observations of --robust on tracks with gaps",
                crate::limits::RANSAC_GAP_OBSERVATIONS,
            )
        } else {
            (
                "observations of --robust",
                crate::limits::RANSAC_OBSERVATIONS,
            )
        };
        crate::limits::at_most(what, obs.count(), limit)
            .map_err(|m| in_file(&a.input, Error::InvalidInput(m)))?;
    }
    let side = (2 * obs.frames.len()).min(obs.names.len());
    crate::limits::at_most(
        "the Gram matrix side min(2 × frames, points)",
        side,
        crate::limits::RECONSTRUCT_GRAM,
    )
    .map_err(|m| in_file(&a.input, Error::InvalidInput(m)))?;
    let robust = a.robust.then(|| RansacOptions {
        threshold: a.threshold,
        seed: a.seed,
        ..RansacOptions::from_data()
    });
    let options = Options {
        bundle: !a.no_bundle,
        robust,
        seed: a.seed,
        ..Options::default()
    };
    let outcome = reconstruct(&obs, &options).map_err(|e| in_file(&a.input, e.into()))?;
    if a.json {
        json_out(&output::Json(&outcome))?;
    } else {
        out(&output::text(&outcome))?;
    }
    // printed in full first: a warning is for the reader of the result, and the exit code
    // keeps a script from taking it silently
    let warnings = outcome.warnings();
    if warnings.is_empty() {
        Ok(())
    } else {
        Err(Error::Warned(warnings))
    }
}
