//! The standard errors the bundle adjustment reports for every point match the spread of
//! the estimates over seeded noise replicates of one scene: complete tracks (the camera
//! system's point terms summed chunk by chunk in one product) and short tracks in many
//! frames (summed point by point).

use nalgebra::Vector3;
use orthocheck_core::model::{rng, Scene, Tracks};
use orthocheck_core::sfm::{bundle_adjust, reconstruct, BundleOptions, Observations, Options};
use rand::Rng;

/// The largest ratio (or inverse ratio) of the estimates' spread to the mean reported
/// standard error over every point and coordinate, from `replicates` noisy copies of
/// `clean` (uniform noise in ±`a`) seen where `seen` says: (ratio, point, coordinate). The
/// first copy is reconstructed by the pipeline; every copy is adjusted from that fit, so the
/// estimates are the adjustment's optimum of each, in one basin, whatever the starts.
fn worst_ratio(
    clean: &Tracks,
    seen: &dyn Fn(usize, usize) -> bool,
    a: f64,
    replicates: u64,
) -> (f64, usize, usize) {
    let mut estimates: Vec<Vec<Vector3<f64>>> = Vec::new();
    let mut reported: Vec<Vec<Vector3<f64>>> = Vec::new();
    let mut start = None;
    for r in 0..replicates {
        let mut g = rng(1000 + r);
        let mut t = clean.clone();
        for y in t.frames.iter_mut().flatten() {
            y.x += g.random_range(-a..a);
            y.y += g.random_range(-a..a);
        }
        let obs = Observations::seen_where(&t, seen);
        let from = start.get_or_insert_with(|| {
            reconstruct(&obs, &Options::default())
                .unwrap()
                .into_single()
                .unwrap()
                .reconstruction
        });
        let o = bundle_adjust(&obs, from, &BundleOptions::default()).unwrap();
        let mut e = o.reconstruction.points.clone();
        // the mirror (Necker) twin gives the same images: take the one nearer the first
        if let Some(first) = estimates.first() {
            let mirrored: Vec<Vector3<f64>> =
                e.iter().map(|x| Vector3::new(x.x, x.y, -x.z)).collect();
            let dist = |v: &[Vector3<f64>]| -> f64 {
                v.iter()
                    .zip(first)
                    .map(|(x, y)| (x - y).norm_squared())
                    .sum()
            };
            if dist(&mirrored) < dist(&e) {
                e = mirrored;
            }
        }
        estimates.push(e);
        reported.push(o.report.points_std.expect("standard errors"));
    }
    let n = replicates as f64;
    let mut worst: (f64, usize, usize) = (1.0, 0, 0);
    for j in 0..clean.names.len() {
        for c in 0..3 {
            let xs: Vec<f64> = estimates.iter().map(|e| e[j][c]).collect();
            let mean = xs.iter().sum::<f64>() / n;
            let spread = (xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
            let said = reported.iter().map(|e| e[j][c]).sum::<f64>() / n;
            let ratio = spread / said;
            if (ratio.ln()).abs() > worst.0.ln().abs() {
                worst = (ratio, j, c);
            }
        }
    }
    worst
}

/// The worst ratio of [`worst_ratio`] is within a factor of 1.5 either way.
fn within_a_factor_of_one_and_a_half((ratio, point, coordinate): (f64, usize, usize)) {
    assert!(
        (1.0 / 1.5..=1.5).contains(&ratio),
        "point {point} coordinate {coordinate}: spread / reported = {ratio}"
    );
}

#[test]
fn standard_errors_match_the_spread_over_noise_replicates() {
    // 200 replicates know a standard deviation to about 5 %; uniform in ±0.003 where the
    // body spans about 2 image units
    let clean = Scene::random(20, 6, 7).tracks();
    let worst = worst_ratio(&clean, &|_, _| true, 0.003, 200);
    within_a_factor_of_one_and_a_half(worst);
}

#[test]
fn standard_errors_of_short_tracks_match_the_spread_too() {
    // each point in 4 consecutive frames of 12 (from its own first, round the end): every
    // point's camera rows a fraction of the system's, so its terms are summed one by one;
    // 150 replicates know a standard deviation to about 6 %
    let (p, k) = (40, 12);
    let clean = Scene::random(p, k, 11).tracks();
    let first: Vec<usize> = (0..p).map(|j| (j * 7) % k).collect();
    let seen = move |f: usize, j: usize| (f + k - first[j]) % k < 4;
    let worst = worst_ratio(&clean, &seen, 0.003, 150);
    within_a_factor_of_one_and_a_half(worst);
}
