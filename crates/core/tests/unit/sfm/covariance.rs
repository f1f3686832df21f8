//! The standard errors the bundle adjustment reports for every point match the spread of
//! the estimates over seeded noise replicates of one scene.

use nalgebra::Vector3;
use orthocheck_core::model::{rng, Scene};
use orthocheck_core::sfm::{reconstruct, Observations, Options};
use rand::Rng;

/// Replicates of one scene: each image coordinate moved by uniform noise of its own seed.
const REPLICATES: u64 = 200;

#[test]
fn standard_errors_match_the_spread_over_noise_replicates() {
    let (p, k) = (20, 6);
    let clean = Scene::random(p, k, 7).tracks();
    // uniform in ±a: the body spans about 2 image units
    let a = 0.003;
    let mut estimates: Vec<Vec<Vector3<f64>>> = Vec::new();
    let mut reported: Vec<Vec<Vector3<f64>>> = Vec::new();
    for r in 0..REPLICATES {
        let mut g = rng(1000 + r);
        let mut t = clean.clone();
        for y in t.frames.iter_mut().flatten() {
            y.x += g.random_range(-a..a);
            y.y += g.random_range(-a..a);
        }
        let o = reconstruct(&Observations::from_tracks(&t), &Options::default())
            .unwrap()
            .into_single()
            .unwrap();
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
        reported.push(o.bundle.unwrap().points_std.expect("standard errors"));
    }
    // per point and coordinate: the spread of the estimates against the mean reported
    // error; with 200 replicates a standard deviation is known to about 5 %
    let n = REPLICATES as f64;
    let mut worst: (f64, usize, usize) = (1.0, 0, 0);
    for j in 0..p {
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
    assert!(
        (1.0 / 1.5..=1.5).contains(&worst.0),
        "point {} coordinate {}: spread / reported = {}",
        worst.1,
        worst.2,
        worst.0
    );
}
