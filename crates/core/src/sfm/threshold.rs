//! The inlier threshold of `reconstruct --robust` when none is given: a robust scale of the
//! reprojection residuals.
//!
//! The rule works on the residual norms of image points, ‖y − ŷ‖, not on single coordinates.
//! For errors that are normal, isotropic and of standard deviation σ per coordinate, the
//! norm is Rayleigh distributed, P(‖e‖ ≤ r) = 1 − exp(−r²/(2σ²)). Its median is
//! σ√(2 ln 2) ([`RAYLEIGH_MEDIAN`] σ), so σ = median / [`RAYLEIGH_MEDIAN`]: the median of
//! all residuals is barely moved by outliers (any share below one half), and so is σ. The
//! threshold is the norm's [`INLIER_QUANTILE`] point, σ√(−2 ln 0.01) ([`RAYLEIGH_INLIER`] σ):
//! a good observation is dropped with probability 1 %.
//!
//! The residuals of a least-squares fit are smaller than the errors: a fit of P parameters
//! to N coordinates leaves, on average, a share 1 − P/N of each coordinate's variance (the
//! mean leverage is P/N). σ from a fit's residuals is divided by [`shrink`] = √(1 − P/N).
//! And σ so estimated is known only to ν = N − P degrees of freedom: a residual's squared
//! norm over 2σ̂² is then about F(2, ν) distributed (exactly so for an rms σ̂ independent of
//! the residual; a median's is known to fewer), and the threshold is its 99 % point
//! ([`inlier_multiple`]), wider than the Rayleigh one for a fit of few residual degrees.
//!
//! Noise that grows with the coordinates (relative noise, as `synth --noise` adds it) makes
//! one scale wrong for all of them: a fit's threshold estimates the mix of the two scales
//! ([`Mix`]) from the kept observations' residuals, coordinate by coordinate, and judges the
//! norm of each residual with its coordinates divided by their own weights ([`scaled`]); the
//! threshold is then that of a residual of weight 1. With one scale (λ = 0) this is the
//! plain norm.
//!
//! Exact data have residuals at rounding level, and their median may even be zero; the
//! threshold never falls below a floor ([`floor`]) that rounding cannot reach.

use nalgebra::Vector2;

pub use crate::algebra::mix::{Mix, STEPS};

use super::Conditioning;

/// The median of the norm of a 2-D isotropic normal error, in units of its per-coordinate
/// standard deviation σ: the Rayleigh median √(2 ln 2) = 1.1774… (from
/// 1 − exp(−r²/2) = ½).
pub const RAYLEIGH_MEDIAN: f64 = 1.1774100225154747;
/// The share of good observations (normal errors) that the threshold keeps.
pub const INLIER_QUANTILE: f64 = 0.99;
/// The [`INLIER_QUANTILE`] point of that norm in units of σ: 1 − exp(−r²/2) = 0.99 gives
/// r = √(−2 ln 0.01) = √(2 ln 100) = 3.0348…; the threshold is this many σ, i.e.
/// 3.0349 / 1.1774 = 2.5776 times the median residual (before the fit's correction).
pub const RAYLEIGH_INLIER: f64 = 3.0348542587702925;
/// The floor in units of ε × the image size: 2^10 roundings of the largest coordinate, a
/// thousandfold margin over the rounding of a well-conditioned reconstruction (a few ε).
pub const FLOOR_ULPS: f64 = 1024.0;

/// The residual freedom (coordinates less parameters) a fit needs for the mix of the two
/// noise scales to be estimated from it (below, one scale): a chosen count. `robust_calibration` is
/// insensitive to the count (0, 10 or 40 all drop 0.98 % of good observations under
/// relative noise, seed 1): every scene but the smallest leaves far more.
pub const MIX_MIN_FREEDOM: usize = 10;

/// The robust scale behind a threshold taken from the data.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scale {
    /// The median residual norm (image units; weighed by `mix`), over every observation.
    pub median: f64,
    /// The number of observations it is the median of.
    pub observations: usize,
    /// √(1 − P/N), the average share of an error a fit leaves in its residual (1 for the
    /// residuals of a RANSAC sample).
    pub shrink: f64,
    /// σ per coordinate: median / [`RAYLEIGH_MEDIAN`] / shrink.
    pub sigma: f64,
    /// The rounding floor (image units), [`floor`].
    pub floor: f64,
    /// The residual degrees of freedom σ is known to (`None`: taken as exact, the Rayleigh
    /// point).
    pub freedom: Option<usize>,
    /// The threshold in units of σ, [`inlier_multiple`] of `freedom`.
    pub multiple: f64,
    /// The mix of the two noise scales the residuals were weighed by (λ = 0: one scale, the
    /// plain norm).
    pub mix: Mix,
}

/// Where a threshold came from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Source {
    /// Given (`--threshold`).
    Given,
    /// From the residuals: max(`multiple` σ, floor) ([`Scale`]).
    Data(Scale),
}

/// An inlier threshold: the largest distance (image units) from an image point to its
/// reprojection for an inlier.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Threshold {
    /// The threshold, image units.
    pub value: f64,
    /// Where it came from.
    pub source: Source,
}

impl Threshold {
    /// A given threshold.
    pub fn given(value: f64) -> Threshold {
        Threshold {
            value,
            source: Source::Given,
        }
    }

    /// The threshold of a median residual norm `median` over `observations` residuals, a
    /// fit's `shrink` and a rounding `floor`; `None` when the median is not finite (more
    /// than half the observations have no residual) or negative.
    pub fn from_median(
        median: f64,
        observations: usize,
        shrink: f64,
        floor: f64,
    ) -> Option<Threshold> {
        if !(median.is_finite() && median >= 0.0 && shrink > 0.0 && floor.is_finite()) {
            return None;
        }
        let sigma = median / RAYLEIGH_MEDIAN / shrink;
        Some(Threshold {
            value: (RAYLEIGH_INLIER * sigma).max(floor),
            source: Source::Data(Scale {
                median,
                observations,
                shrink,
                sigma,
                floor,
                freedom: None,
                multiple: RAYLEIGH_INLIER,
                mix: Mix::UNIFORM,
            }),
        })
    }

    /// The threshold with σ known to `freedom` residual degrees of freedom (a given one
    /// stays as it is): [`inlier_multiple`] σ, at least the floor.
    pub fn with_freedom(mut self, freedom: usize) -> Threshold {
        if let Source::Data(s) = &mut self.source {
            s.freedom = Some(freedom);
            s.multiple = inlier_multiple(Some(freedom));
            self.value = (s.multiple * s.sigma).max(s.floor);
        }
        self
    }

    /// The threshold in units of σ: [`RAYLEIGH_INLIER`] for a given one.
    pub fn multiple(&self) -> f64 {
        match self.source {
            Source::Given => RAYLEIGH_INLIER,
            Source::Data(s) => s.multiple,
        }
    }

    /// The threshold with the residuals it was taken from weighed by `mix` (a given one
    /// stays as it is).
    pub fn with_mix(mut self, mix: Mix) -> Threshold {
        if let Source::Data(s) = &mut self.source {
            s.mix = mix;
        }
        self
    }

    /// The mix its residuals are weighed by: one scale for a given threshold.
    pub fn mix(&self) -> Mix {
        match self.source {
            Source::Given => Mix::UNIFORM,
            Source::Data(s) => s.mix,
        }
    }

    /// The threshold of residual norms (infinite where an observation has none; the slice
    /// is reordered); `None` when there are none or the median is not finite.
    pub fn from_residuals(residuals: &mut [f64], shrink: f64, floor: f64) -> Option<Threshold> {
        let m = median(residuals)?;
        Threshold::from_median(m, residuals.len(), shrink, floor)
    }

    /// Whether the rounding floor, not the residuals' scale, set the threshold.
    pub fn floored(&self) -> bool {
        match self.source {
            Source::Given => false,
            Source::Data(s) => s.multiple * s.sigma < s.floor,
        }
    }
}

/// The square of the smallest weight a residual coordinate is divided by, 1/[`STEPS`]: the fit is not
/// weighted, so a coordinate near the origin takes in the errors of others through the fit,
/// and under λ = 1 its own weight would tend to zero.
pub const MIN_WEIGHT_SQUARED: f64 = 1.0 / STEPS as f64;

/// The norm of the residual `e` of the image `y` with each coordinate divided by its weight
/// under `mix` ([`Mix::weight`] of its square, at least √[`MIN_WEIGHT_SQUARED`]): the plain
/// norm under one scale.
pub fn scaled(e: Vector2<f64>, y: Vector2<f64>, mix: &Mix) -> f64 {
    if mix.relative == 0.0 {
        return e.norm();
    }
    let w = |c: f64| mix.weight(c * c).max(MIN_WEIGHT_SQUARED.sqrt());
    Vector2::new(e.x / w(y.x), e.y / w(y.y)).norm()
}

/// The [`INLIER_QUANTILE`] point of a residual's norm in units of σ̂ when σ̂ is known to ν
/// = `freedom` residual degrees of freedom: ‖e‖²/(2σ̂²) is F(2, ν), whose upper tail is
/// (1 + 2f/ν)^(−ν/2), so the point is √(ν ((1 − q)^(−2/ν) − 1)); [`RAYLEIGH_INLIER`] (ν → ∞)
/// for `None` or ν = 0.
pub fn inlier_multiple(freedom: Option<usize>) -> f64 {
    match freedom {
        Some(nu) if nu > 0 => {
            let nu = nu as f64;
            (nu * (-2.0 / nu * (1.0 - INLIER_QUANTILE).ln()).exp_m1()).sqrt()
        }
        _ => RAYLEIGH_INLIER,
    }
}

/// The lower median (the element of rank ⌊(n − 1)/2⌋ in ascending order; the slice is
/// reordered); `None` for an empty slice.
pub fn median(v: &mut [f64]) -> Option<f64> {
    if v.is_empty() {
        return None;
    }
    let m = (v.len() - 1) / 2;
    let (_, x, _) = v.select_nth_unstable_by(m, f64::total_cmp);
    Some(*x)
}

/// √(1 − P/N) for a fit of `parameters` to `coordinates`; 1 when the fit has no redundancy
/// (its residuals are rounding, and the floor decides).
pub fn shrink(coordinates: usize, parameters: usize) -> f64 {
    if coordinates > parameters {
        (1.0 - parameters as f64 / coordinates as f64).sqrt()
    } else {
        1.0
    }
}

/// The parameters of an orthographic reconstruction of `points` points in `frames` frames:
/// 3 per point, 3 + 2 per camera, less the gauge (a rotation and a 3-D shift of the whole),
/// 3p + 5k − 6 (the paper's −1 + 3p + 5(k − 1)).
pub fn parameters(points: usize, frames: usize) -> usize {
    (3 * points + 5 * frames).saturating_sub(6)
}

/// The factor by which rounding in a reconstruction can exceed ε × its size: the bound
/// n·κ²·m of [`Conditioning`] (n = 2k + p, κ the factor's condition, m the metric's), and 1
/// when there is no conditioning or the bound is not finite.
pub fn rounding(conditioning: Option<Conditioning>, points: usize, frames: usize) -> f64 {
    let Some(c) = conditioning else {
        return 1.0;
    };
    let n = (2 * frames + points) as f64;
    let b = n * c.factor * c.factor * c.metric;
    if b.is_finite() {
        b.max(1.0)
    } else {
        1.0
    }
}

/// The smallest threshold: [`FLOOR_ULPS`] · ε · `size` · `rounding` (`size` the image size,
/// the power of two of [`super::Units`]; `rounding` from [`rounding`], at least 1). No
/// residual of exact data reaches it, so a zero median never gives a zero threshold.
pub fn floor(size: f64, rounding: f64) -> f64 {
    FLOOR_ULPS * f64::EPSILON * size * rounding.max(1.0)
}
