//! Tests of `orthocheck_core::algebra::mix`: the mix of noise scales of most likelihood.

use orthocheck_core::algebra::mix::{Mix, STEPS};
use orthocheck_core::model::rng;
use rand::Rng;

/// Seeded residuals (d, x²) of coordinates x uniform in [−2, 2] with normal-like noise
/// (a sum of three uniforms) of standard deviation proportional to √((1 − λ) + λ x²/u²)
/// for the given λ.
fn residuals(relative: f64, seed: u64) -> Vec<(f64, f64)> {
    let mut g = rng(seed);
    let xs: Vec<f64> = (0..400).map(|_| g.random_range(-2.0..2.0)).collect();
    let unit = xs.iter().map(|x| x * x).sum::<f64>() / xs.len() as f64;
    xs.iter()
        .map(|x| {
            let w = ((1.0 - relative) + relative * x * x / unit).sqrt();
            let z: f64 = (0..3).map(|_| g.random_range(-1.0..1.0)).sum();
            (1e-3 * w * z, x * x)
        })
        .collect()
}

#[test]
fn the_mix_of_most_likelihood_tells_the_two_scales_apart() {
    for seed in 1..=5 {
        // one scale: λ at most one step; relative: at least 7/8 (the grid's last but one)
        let uniform = Mix::most_likely(&residuals(0.0, seed));
        assert!(uniform.relative <= 1.0 / STEPS as f64, "{uniform:?}");
        let relative = Mix::most_likely(&residuals(1.0, seed));
        assert!(relative.relative >= 7.0 / STEPS as f64, "{relative:?}");
        assert!((relative.unit - 4.0 / 3.0).abs() < 0.2, "{relative:?}");
    }
}

#[test]
fn a_coordinate_at_the_origin_never_makes_the_noise_purely_relative() {
    // under λ = 1 the weight of x = 0 is zero and its likelihood unbounded
    let mut r = residuals(1.0, 7);
    r.push((0.0, 0.0));
    let mix = Mix::most_likely(&r);
    assert!(mix.relative < 1.0, "{mix:?}");
    assert!(Mix::most_likely(&[(1.0, 0.0), (2.0, 0.0)]) == Mix::UNIFORM);
    assert_eq!(Mix::UNIFORM.weight(9.0), 1.0);
    let m = Mix {
        relative: 1.0,
        unit: 4.0,
    };
    assert_eq!(m.weight(16.0), 2.0);
    assert_eq!(m.weight(f64::NAN), 1.0);
    // residuals all zero (exact data) or not finite say nothing of the mix: one scale
    assert_eq!(Mix::most_likely(&[(0.0, 1.0), (0.0, 4.0)]).relative, 0.0);
    assert_eq!(
        Mix::most_likely(&[(f64::NAN, 1.0), (1.0, 4.0)]).relative,
        0.0
    );
}
