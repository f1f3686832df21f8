//! Propagating the rounding of printed data: seeded Monte Carlo over the rounding box, and a
//! witness search for a point of the box that reproduces printed results.

use nalgebra::DMatrix;
use rand::Rng;

use crate::algebra::{min_norm_newton_step, min_norm_newton_with};
use crate::model::rng;

/// Printed values and their rounding half-widths (0 for values known exactly).
#[derive(Clone, Debug, PartialEq)]
pub struct RoundingBox {
    /// The printed values.
    pub center: Vec<f64>,
    /// Half a unit of each value's last printed digit (0 when exact).
    pub half: Vec<f64>,
}

impl RoundingBox {
    /// A uniformly random point of the box.
    pub fn sample<R: Rng>(&self, g: &mut R) -> Vec<f64> {
        self.center
            .iter()
            .zip(&self.half)
            .map(|(c, h)| {
                if *h > 0.0 {
                    c + g.random_range(-h..=*h)
                } else {
                    *c
                }
            })
            .collect()
    }

    /// Largest |x − center| / half over the rounded values (≤ 1 inside the box).
    pub fn shift_ratio(&self, x: &[f64]) -> f64 {
        x.iter()
            .zip(&self.center)
            .zip(&self.half)
            .filter(|(_, h)| **h > 0.0)
            .map(|((x, c), h)| (x - c).abs() / h)
            .fold(0.0, f64::max)
    }
}

/// Evaluate `f` at `trials` seeded uniform points of the box.
pub fn monte_carlo<T>(
    b: &RoundingBox,
    trials: usize,
    seed: u64,
    f: impl Fn(&[f64]) -> T,
) -> Vec<T> {
    let mut g = rng(seed);
    (0..trials).map(|_| f(&b.sample(&mut g))).collect()
}

/// A point of the box where the printed results are reproduced.
#[derive(Clone, Debug, PartialEq)]
pub struct Witness {
    /// The point.
    pub point: Vec<f64>,
    /// Largest |residual| there.
    pub residual: f64,
    /// Largest shift from the printed values in units of their half-widths (≤ 1: inside).
    pub shift_ratio: f64,
}

/// Search the box for a point where `residual` vanishes to `tolerance`, starting from the
/// printed values and moving only the rounded ones (minimum-norm Gauss–Newton).
pub fn witness(
    b: &RoundingBox,
    residual: &dyn Fn(&[f64]) -> Option<Vec<f64>>,
    tolerance: f64,
) -> Option<Witness> {
    witness_step(b, residual, tolerance, 1e-7)
}

/// [`witness`] with the Jacobian's difference step `step` (in units of the box's half-widths;
/// see [`min_norm_newton_step`]).
pub fn witness_step(
    b: &RoundingBox,
    residual: &dyn Fn(&[f64]) -> Option<Vec<f64>>,
    tolerance: f64,
    step: f64,
) -> Option<Witness> {
    witness_with(b, residual, None, tolerance, step)
}

/// The Jacobian of a witness search's residuals over the box's scaled unknowns (each
/// coordinate's shift in units of its half-width, the rounded coordinates only); `None`
/// where it is undefined.
pub type ScaledJacobian<'a> = &'a dyn Fn(&[f64]) -> Option<DMatrix<f64>>;

/// [`witness_step`] with `jacobian` in place of its central differences: it must give
/// exactly the central differences of step `step·max(1, |uₖ|)` (for a caller that forms
/// them without evaluating every residual at every probe).
pub fn witness_with(
    b: &RoundingBox,
    residual: &dyn Fn(&[f64]) -> Option<Vec<f64>>,
    jacobian: Option<ScaledJacobian>,
    tolerance: f64,
    step: f64,
) -> Option<Witness> {
    let free: Vec<usize> = (0..b.center.len()).filter(|&i| b.half[i] > 0.0).collect();
    // unknowns scaled by their half-widths, so the minimum-norm step is a minimum shift in
    // units of rounding
    let embed = |u: &[f64]| {
        let mut x = b.center.clone();
        for (k, &i) in free.iter().enumerate() {
            x[i] += u[k] * b.half[i];
        }
        x
    };
    let f = |u: &[f64]| residual(&embed(u));
    let newton = |u0: &[f64], iterations: usize| match jacobian {
        Some(jac) => min_norm_newton_with(&f, jac, u0, tolerance, iterations),
        None => min_norm_newton_step(&f, u0, tolerance, iterations, step),
    };
    let (mut u, mut r) = newton(&vec![0.0; free.len()], 60)?;
    // The minimum-norm point minimises the shift in the 2-norm; the box is a ∞-norm ball.
    // When that point leaves the box, alternate: clamp into the box, then back onto the
    // solutions by minimum-norm steps (clamping to 0.98 of the box, so that a box whose
    // intersection with the solutions has an interior is entered, not only approached);
    // keep the solution with the smallest largest shift.
    let inf = |u: &[f64]| u.iter().fold(0.0_f64, |a, v| a.max(v.abs()));
    let mut best = (u.clone(), r);
    for _ in 0..200 {
        if r > tolerance || inf(&best.0) <= 1.0 {
            break;
        }
        let clamped: Vec<f64> = u.iter().map(|v| v.clamp(-0.98, 0.98)).collect();
        let Some((v, rv)) = newton(&clamped, 20) else {
            break;
        };
        if rv > tolerance {
            break;
        }
        if inf(&v) < inf(&best.0) {
            best = (v.clone(), rv);
        }
        if inf(&v) >= inf(&u) - 1e-9 {
            break;
        }
        (u, r) = (v, rv);
    }
    let (u, r) = if best.1 <= tolerance { best } else { (u, r) };
    let point = embed(&u);
    Some(Witness {
        shift_ratio: b.shift_ratio(&point),
        residual: r,
        point,
    })
}

/// First-order bound of how far each output of `f` can move over the box `x ± half`:
/// Σₖ |f(x + hₖeₖ) − f(x − hₖeₖ)| / 2 per output (central differences at the box's own
/// half-widths, so curvature over the box is included to second order). `None` if `f` is
/// undefined at a probed point.
pub fn first_order_bound(
    f: &dyn Fn(&[f64]) -> Option<Vec<f64>>,
    x: &[f64],
    half: &[f64],
) -> Option<Vec<f64>> {
    let base = f(x)?;
    let mut bound = vec![0.0; base.len()];
    for (k, h) in half.iter().enumerate() {
        if *h == 0.0 {
            continue;
        }
        let (mut up, mut down) = (x.to_vec(), x.to_vec());
        up[k] += h;
        down[k] -= h;
        let (fu, fd) = (f(&up)?, f(&down)?);
        for (b, (u, d)) in bound.iter_mut().zip(fu.iter().zip(&fd)) {
            *b += (u - d).abs() / 2.0;
        }
    }
    Some(bound)
}

/// The `q`-quantile (0 ≤ q ≤ 1) of sorted finite data, by nearest rank.
pub fn quantile(sorted: &[f64], q: f64) -> Option<f64> {
    if sorted.is_empty() {
        return None;
    }
    let i = ((q * (sorted.len() - 1) as f64).round() as usize).min(sorted.len() - 1);
    Some(sorted[i])
}

/// Fraction of sorted data not above `x` (the percentile rank of `x`, in [0, 1]).
pub fn rank_of(sorted: &[f64], x: f64) -> f64 {
    if sorted.is_empty() {
        return 0.0;
    }
    sorted.partition_point(|v| *v <= x) as f64 / sorted.len() as f64
}
