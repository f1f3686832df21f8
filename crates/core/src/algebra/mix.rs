//! Noise of two scales: one across the image and one that grows with the coordinates.
//!
//! An image coordinate x is taken to carry noise of variance σ² ((1 − λ) + λ x²/u²): one
//! scale across the image (λ = 0, a tracker's pixel noise) or growing with the distance
//! from the image's origin (λ = 1, noise relative to the coordinates, as `synth --noise`
//! adds it), u² the mean of the coordinates' squares, so both parts are of one size. A
//! residual divided by its weight w = √((1 − λ) + λ x²/u²) has standard deviation σ. The
//! calibrated tolerances (membership, `reconstruct --robust`) estimate λ from their fit's
//! residuals and judge each residual by its own weight.

/// The mixes tried by [`Mix::most_likely`]: λ = 0, 1/`STEPS`, …, 1.
pub const STEPS: usize = 8;

/// A mix of the two noise scales.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Mix {
    /// λ, the share of the noise that grows with the coordinates.
    pub relative: f64,
    /// u², the unit of the coordinates' squares.
    pub unit: f64,
}

impl Mix {
    /// One scale across the image (λ = 0).
    pub const UNIFORM: Mix = Mix {
        relative: 0.0,
        unit: 1.0,
    };

    /// The weight w of a residual whose coordinates' squares are `square`; 1 (one scale) when
    /// λ is not in (0, 1], u² is not a positive number or `square` is not finite.
    pub fn weight(&self, square: f64) -> f64 {
        let usable = self.relative > 0.0
            && self.relative <= 1.0
            && self.unit > 0.0
            && self.unit.is_finite()
            && square.is_finite();
        if !usable {
            return 1.0;
        }
        ((1.0 - self.relative) + self.relative * square / self.unit).sqrt()
    }

    /// The mix of most likelihood for `residuals`, pairs (d, s) of a residual and its
    /// coordinates' squares: normal errors of standard deviation σ w, σ profiled out, the
    /// least Σ ln w² + n ln Σ (d/w)² over λ on the grid of [`STEPS`]; u² the mean of s.
    /// λ = 0 on a tie, where the residuals are all zero or any is not finite, and where every score
    /// is infinite (a weight of zero: a coordinate at the origin under λ = 1 would claim
    /// exactness); [`Mix::UNIFORM`] when u² is not a positive number.
    pub fn most_likely(residuals: &[(f64, f64)]) -> Mix {
        let n = residuals.len() as f64;
        let unit = residuals.iter().map(|p| p.1).sum::<f64>() / n;
        if !(unit > 0.0 && unit.is_finite()) {
            return Mix::UNIFORM;
        }
        let mut best = (
            f64::INFINITY,
            Mix {
                relative: 0.0,
                unit,
            },
        );
        for step in 0..=STEPS {
            let mix = Mix {
                relative: step as f64 / STEPS as f64,
                unit,
            };
            let (mut logs, mut squares) = (0.0, 0.0);
            for (d, s) in residuals {
                let w2 = mix.weight(*s).powi(2);
                logs += w2.ln();
                squares += d * d / w2;
            }
            // residuals all zero (exact data) or not finite tell nothing of the mix
            if !(squares > 0.0 && squares.is_finite()) {
                continue;
            }
            let score = logs + n * squares.ln();
            if score.is_finite() && score < best.0 {
                best = (score, mix);
            }
        }
        best.1
    }
}
