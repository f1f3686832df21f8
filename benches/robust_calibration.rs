//! How often `reconstruct --robust` with its threshold from the data drops a good
//! observation, and how often it drops a bad one far from its true image, over seeded
//! scenes.
//!
//! Usage: `cargo run --release -p orthocheck-benches --example robust_calibration --
//! [SCENES] [SEED] [absolute]` (defaults 1,000 scenes, seed 1). Each scene: a rigid body of
//! 6–50 points (uniform in [−1, 1]³) in 3–8 frames of random rotations, every image
//! coordinate with relative noise up to ε (`synth --noise`: x ↦ x(1 + u), u uniform in
//! [−ε, ε]), or with `absolute` noise of one scale across the image (x ↦ x + u), ε uniform
//! in 0.1 %–1 %; then 1–3 observations replaced by points drawn in the frame's image box.
//! σ is the good observations' rms error per coordinate; a bad observation counts as far
//! when its distance from its true image exceeds 10 σ. A good observation is dropped when
//! the report lists it, alone or as an image of a rejected point. A second table splits the
//! dropped good observations: those on a point with a bad image (a point left with fewer
//! than three images within the threshold is rejected whole, `judge::MIN_IMAGES`) and those
//! on a point whose images are all good (the threshold's own rejections).

use std::collections::HashSet;

use nalgebra::Vector2;
use orthocheck::model::{rng, NoiseModel, Scene, Tracks};
use orthocheck::sfm::robust::RansacOptions;
use orthocheck::sfm::{reconstruct, Observations, Options};
use orthocheck_benches::{band, print_bands, Calibration, Tally, BANDS};
use rand::Rng;

/// The scene's noisy tracks, the corrupted (frame, point) pairs and σ.
fn scene(seed: u64, absolute: bool) -> (Tracks, Tracks, HashSet<(usize, usize)>, usize) {
    let mut g = rng(seed);
    let m = g.random_range(6..=50usize);
    let k = g.random_range(3..=8usize);
    let eps = g.random_range(0.001..0.01);
    let clean = Scene::random(m, k, g.random()).tracks();
    let mut noisy = if absolute {
        let mut t = clean.clone();
        for y in t.frames.iter_mut().flatten() {
            *y += Vector2::new(g.random_range(-eps..eps), g.random_range(-eps..eps));
        }
        t
    } else {
        NoiseModel::RelativeCoordinate { eps }.perturb_tracks(&clean, &mut g)
    };
    let mut bad = HashSet::new();
    for _ in 0..g.random_range(1..=3usize) {
        let (f, j) = (g.random_range(0..k), g.random_range(0..m));
        let row = &clean.frames[f];
        let lo = row
            .iter()
            .fold(Vector2::repeat(f64::INFINITY), |a, y| a.inf(y));
        let hi = row
            .iter()
            .fold(Vector2::repeat(f64::NEG_INFINITY), |a, y| a.sup(y));
        noisy.frames[f][j] = Vector2::new(g.random_range(lo.x..hi.x), g.random_range(lo.y..hi.y));
        bad.insert((f, j));
    }
    (clean, noisy, bad, m)
}

/// Whether the good observation `p` (frame, point) is on a point with a bad image.
fn beside(bad: &HashSet<(usize, usize)>, p: &(usize, usize)) -> bool {
    bad.iter().any(|b| b.1 == p.1)
}

/// The observations (frame, point) robust mode drops from `noisy`, with its threshold from
/// the data; `None` when the scene is refused.
fn dropped_by_robust_mode(noisy: &Tracks) -> Option<HashSet<(usize, usize)>> {
    let options = Options {
        robust: Some(RansacOptions::from_data()),
        ..Options::default()
    };
    let obs = Observations::from_tracks(noisy);
    let r = reconstruct(&obs, &options).ok()?.into_single()?.robust?;
    let index = |name: &str| {
        noisy
            .names
            .iter()
            .position(|n| n == name)
            .unwrap_or(usize::MAX)
    };
    Some(
        r.dropped
            .iter()
            .map(|d| (d.frame - 1, index(&d.point)))
            .collect(),
    )
}

/// The second table: per band, good observations dropped beside a bad image, and those
/// dropped on all-good points of all such.
fn print_split(split: &[[usize; 3]; 3], bands: &[Tally; 3]) {
    println!("| points | good dropped beside a bad image | good dropped on all-good points |");
    println!("|---|---:|---:|");
    for ((name, [beside, alone, of]), b) in BANDS.iter().zip(split).zip(bands) {
        println!(
            "| {name} | {beside} | {alone} of {of} ({:.2} %) |",
            100.0 * *alone as f64 / (*of).max(1) as f64
        );
        debug_assert!(beside + alone == b.lost);
    }
}

fn main() {
    let Calibration {
        scenes,
        seed,
        absolute,
    } = Calibration::from_args(1000);
    let mut bands: [Tally; 3] = Default::default();
    // per band: good observations dropped beside a bad image, on all-good points, and of
    // those (refused scenes counted, as in the band's good observations)
    let mut split = [[0usize; 3]; 3];
    for s in 0..scenes {
        let (clean, noisy, bad, m) = scene(Calibration::scene_seed(seed, s), absolute);
        let k = clean.frames.len();
        let good: Vec<(usize, usize)> = (0..k)
            .flat_map(|f| (0..m).map(move |j| (f, j)))
            .filter(|p| !bad.contains(p))
            .collect();
        let err = |&(f, j): &(usize, usize)| (noisy.frames[f][j] - clean.frames[f][j]).norm();
        let sigma =
            (good.iter().map(|p| err(p).powi(2)).sum::<f64>() / (2 * good.len()) as f64).sqrt();
        let (tally, row) = (&mut bands[band(m)], &mut split[band(m)]);
        tally.scenes += 1;
        tally.good += good.len();
        row[2] += good.iter().filter(|p| !beside(&bad, p)).count();
        let Some(dropped) = dropped_by_robust_mode(&noisy) else {
            tally.refused += 1;
            continue;
        };
        for p in good.iter().filter(|p| dropped.contains(p)) {
            tally.lost += 1;
            row[usize::from(!beside(&bad, p))] += 1;
        }
        let far: Vec<&(usize, usize)> = bad.iter().filter(|p| err(p) > 10.0 * sigma).collect();
        let found = far.iter().filter(|p| dropped.contains(p)).count();
        tally.far_in_scene(far.len(), found);
    }
    print_bands(
        "| points | scenes | good observations dropped | bad > 10 σ dropped | refused |",
        &bands,
    );
    println!();
    print_split(&split, &bands);
}
