//! Scale and range: orthographic structure from motion is equivariant under a translation of
//! each frame and one common scale, so every solver works on tracks brought to unit size and
//! maps its answers back; magnitudes the answers cannot represent are a typed error.

use nalgebra::Vector2;

use crate::error::{Error, Result};
use crate::model::Tracks;

/// Coordinates may lie this many orders of magnitude either side of 1 (and the image sizes of
/// one input this many apart): squared edges then stay within 10^±300, inside the normal range
/// of doubles (10^±308) with room for the solvers' products of a few squares.
pub const MAX_ORDERS: i32 = 150;

/// Tracks at unit size and the factor that maps lengths back.
#[derive(Clone, Debug, PartialEq)]
pub struct Normalised {
    /// Every frame centred on its centroid, every coordinate divided by `scale`.
    pub tracks: Tracks,
    /// A power of two (exact to divide and multiply by): input lengths = unit lengths × scale.
    pub scale: f64,
}

impl Normalised {
    /// A squared length of the unit tracks in the input's units.
    pub fn square_back(&self, v: f64) -> f64 {
        v * self.scale * self.scale
    }
}

/// The power of two nearest below `v` (v > 0, finite).
fn pow2_floor(v: f64) -> f64 {
    2f64.powi(v.log2().floor() as i32)
}

/// Centre each frame and divide by one power of two so the largest centred coordinate lies in
/// [1, 2). Division by a power of two is exact, so the unit tracks are the input's own numbers
/// (the centring rounds as any subtraction does). A body whose points coincide in every frame
/// keeps scale 1 (the degenerate-case checks name it). Errors when the input's size lies more
/// than [`MAX_ORDERS`] orders of magnitude from 1, or its extent that far below its position.
pub fn normalise(tracks: &Tracks) -> Result<Normalised> {
    let big = tracks
        .frames
        .iter()
        .flatten()
        .fold(0.0_f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    if big == 0.0 {
        return Ok(Normalised {
            tracks: tracks.clone(),
            scale: 1.0,
        });
    }
    // first bring the coordinates near 1, so the centroids cannot overflow
    let s1 = pow2_floor(big);
    let frames: Vec<Vec<Vector2<f64>>> = tracks
        .frames
        .iter()
        .map(|f| {
            let n = f.len().max(1) as f64;
            let g: Vec<Vector2<f64>> = f.iter().map(|p| p / s1).collect();
            let c = g.iter().fold(Vector2::zeros(), |a, p| a + p / n);
            g.into_iter().map(|p| p - c).collect()
        })
        .collect();
    let extent = frames
        .iter()
        .flatten()
        .fold(0.0_f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    if extent == 0.0 {
        return Ok(Normalised {
            tracks: tracks.clone(),
            scale: 1.0,
        });
    }
    let s2 = pow2_floor(extent);
    let scale = s1 * s2;
    let orders = |v: f64| v.log10().abs();
    if orders(scale) > f64::from(MAX_ORDERS) {
        return Err(out_of_range(big, extent * s1));
    }
    let frames = frames
        .into_iter()
        .map(|f| f.into_iter().map(|p| p / s2).collect())
        .collect();
    Ok(Normalised {
        tracks: Tracks::new(tracks.names.clone(), frames)?,
        scale,
    })
}

/// The typed error for an input whose magnitudes cannot be represented.
fn out_of_range(size: f64, extent: f64) -> Error {
    Error::InvalidInput(format!(
        "coordinates span more than {MAX_ORDERS} orders of magnitude (largest coordinate {}, \
         extent of the images {}): the squared edges could not be represented in double precision",
        crate::numfmt::sig(size),
        crate::numfmt::sig(extent)
    ))
}

/// Map unit squared values back, refusing any that overflow or are not finite.
pub fn squares_back(n: &Normalised, values: &mut [f64]) -> Result<()> {
    for v in values.iter_mut() {
        let w = n.square_back(*v);
        if !w.is_finite() {
            return Err(Error::Numerical(format!(
                "a squared edge of {} (unit scale) times the input's scale squared is not representable",
                crate::numfmt::sig(*v)
            )));
        }
        *v = w;
    }
    Ok(())
}
