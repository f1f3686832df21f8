//! Tests of `orthocheck_core::sfm::threshold`.

use orthocheck_core::sfm::threshold::*;

#[test]
fn the_constants_are_their_formulas() {
    let close = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b;
    assert!(close(RAYLEIGH_MEDIAN, (2.0 * 2f64.ln()).sqrt()));
    assert!(close(
        RAYLEIGH_INLIER,
        (-2.0 * (1.0 - INLIER_QUANTILE).ln()).sqrt()
    ));
    // the Rayleigh distribution function at the two points
    let cdf = |r: f64| 1.0 - (-r * r / 2.0).exp();
    assert!((cdf(RAYLEIGH_MEDIAN) - 0.5).abs() < 1e-15);
    assert!((cdf(RAYLEIGH_INLIER) - INLIER_QUANTILE).abs() < 1e-15);
}

#[test]
fn the_threshold_follows_the_median_and_never_falls_to_zero() {
    let mut r = vec![3.0, f64::INFINITY, 1.0, 2.0, 100.0];
    // the lower median of [1, 2, 3, 100, ∞] is 3
    let t = Threshold::from_residuals(&mut r, 1.0, 0.0).unwrap();
    assert_eq!(t.value, RAYLEIGH_INLIER * (3.0 / RAYLEIGH_MEDIAN / 1.0));
    assert!(!t.floored());
    let mut zeros = vec![0.0; 7];
    let f = floor(4.0, 1.0);
    let z = Threshold::from_residuals(&mut zeros, 1.0, f).unwrap();
    assert!(z.value > 0.0 && z.value == f && z.floored());
    let mut unexplained = vec![1.0, f64::INFINITY, f64::INFINITY];
    assert!(Threshold::from_residuals(&mut unexplained, 1.0, f).is_none());
    assert!(median(&mut []).is_none());
}

#[test]
fn a_fit_s_residuals_are_corrected_for_its_parameters() {
    assert_eq!(shrink(100, 75), 0.5);
    assert_eq!(shrink(10, 12), 1.0);
    assert_eq!(parameters(40, 8), 154);
    assert_eq!(rounding(None, 40, 8), 1.0);
}

#[test]
fn the_multiple_is_the_99_percent_point_of_a_norm_over_an_estimated_scale() {
    use orthocheck_core::model::rng;
    use rand::Rng;
    // ν → ∞ gives the Rayleigh point; ν = 2: (1 + f)^(−1) = 0.01, f = 99, √(2 · 99)
    assert_eq!(inlier_multiple(None), RAYLEIGH_INLIER);
    assert!((inlier_multiple(Some(2)) - 198f64.sqrt()).abs() < 1e-12);
    assert!((inlier_multiple(Some(1 << 30)) - RAYLEIGH_INLIER).abs() < 1e-8);
    // seeded draws of ‖(z₁, z₂)‖ / √(χ²_ν / ν): the share within the multiple is 99 % to
    // within 4 binomial standard deviations (√(0.01 · 0.99 / n))
    let normal = |g: &mut rand_chacha::ChaCha8Rng| {
        // Box–Muller
        let (u, v): (f64, f64) = (g.random_range(f64::EPSILON..1.0), g.random());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    };
    let n = 40_000;
    for nu in [3usize, 9, 40] {
        let mut g = rng(nu as u64);
        let m = inlier_multiple(Some(nu));
        let within = (0..n)
            .filter(|_| {
                let e = normal(&mut g).hypot(normal(&mut g));
                let chi: f64 = (0..nu).map(|_| normal(&mut g).powi(2)).sum();
                e / (chi / nu as f64).sqrt() <= m
            })
            .count();
        let share = within as f64 / n as f64;
        let sd = (0.01 * 0.99 / n as f64).sqrt();
        assert!((share - 0.99).abs() < 4.0 * sd, "ν = {nu}: {share}");
    }
}

#[test]
fn a_threshold_with_its_freedom_and_mix_says_so() {
    let mut r = vec![1.0, 2.0, 3.0];
    let t = Threshold::from_residuals(&mut r, 1.0, 0.0).unwrap();
    let mix = Mix {
        relative: 0.5,
        unit: 4.0,
    };
    let w = t.with_mix(mix).with_freedom(5);
    assert_eq!(w.mix(), mix);
    assert_eq!(w.multiple(), inlier_multiple(Some(5)));
    assert!(w.value > t.value);
    // a given threshold has neither
    let g = Threshold::given(0.1).with_mix(mix).with_freedom(5);
    assert_eq!(
        (g.value, g.mix(), g.multiple()),
        (0.1, Mix::UNIFORM, RAYLEIGH_INLIER)
    );
    // the weighed norm: each coordinate over √((1 − λ) + λ x²/u²)
    let e = nalgebra::Vector2::new(1.0, 1.0);
    let y = nalgebra::Vector2::new(2.0, 0.0);
    let expected = (1.0f64 / 1.0 + 1.0 / 0.5).sqrt();
    assert!((scaled(e, y, &mix) - expected).abs() < 1e-15);
    assert_eq!(scaled(e, y, &Mix::UNIFORM), e.norm());
    // under λ = 1 a coordinate at the origin would have weight 0: it is divided by √(1/8)
    let relative = Mix {
        relative: 1.0,
        unit: 1.0,
    };
    let at_origin = scaled(
        nalgebra::Vector2::new(1.0, 0.0),
        nalgebra::Vector2::new(0.0, 5.0),
        &relative,
    );
    assert!((at_origin - 8f64.sqrt()).abs() < 1e-15, "{at_origin}");
}
