//! How often `membership`'s default tolerance rejects a true member, and how often it finds
//! a foreign point far from the body's epipolar geometry, over seeded scenes.
//!
//! Usage: `cargo run --release -p orthocheck-benches --example membership_calibration --
//! [SCENES] [SEED] [absolute]` (defaults 2,000 scenes, seed 1). Each scene: a rigid body of
//! 6–50 points (uniform in [−1, 1]³) in two frames of random rotations, every image
//! coordinate with relative noise up to ε (`synth --noise`: x ↦ x(1 + u), u uniform in
//! [−ε, ε]), or with `absolute` noise of one scale across the image (x ↦ x + u, u uniform in
//! [−ε, ε]: a tracker's pixel noise), ε uniform in 0.1 %–1 %; then 1–3 foreign
//! points, each with images drawn anew in each frame within the body's image box. σ is the
//! members' rms distance from the body's true (noise-free) epipolar line; a foreign point
//! counts as far when its distance from that line exceeds 10 σ. `SHOW_REFUSED=1` names the
//! scenes refused as no rigid body. `STRETCH=2` is the control: frame 2's images (the
//! foreign points' too) are twice as wide as a view of the body, so no rigid body gives the
//! frames, and every scene should be refused.

use nalgebra::Vector2;
use orthocheck::derivations::identity;
use orthocheck::derivations::two_frames::epipolar;
use orthocheck::model::{rng, NoiseModel, Scene};
use orthocheck_benches::{band, print_bands, Calibration, Tally};
use rand::Rng;

/// Distances from the epipolar geometry fitted (exactly, noise-free) to `clean`, in the same
/// units for every point (the ratio to σ is what is reported).
fn distances(clean: &[[Vector2<f64>; 2]], all: &[[Vector2<f64>; 2]]) -> Vec<f64> {
    let g1: Vec<Vector2<f64>> = clean.iter().map(|p| p[0]).collect();
    let g2: Vec<Vector2<f64>> = clean.iter().map(|p| p[1]).collect();
    let [a, b, c, d] = epipolar(&g1, &g2).coefficients;
    let m1 = g1.iter().sum::<Vector2<f64>>() / g1.len() as f64;
    let m2 = g2.iter().sum::<Vector2<f64>>() / g2.len() as f64;
    all.iter()
        .map(|p| {
            (a * (p[0].x - m1.x) + b * (p[0].y - m1.y) + c * (p[1].x - m2.x) + d * (p[1].y - m2.y))
                .abs()
        })
        .collect()
}

/// The width by which `STRETCH` stretches frame 2 (`None`: not set or not a number).
fn stretch() -> Option<f64> {
    std::env::var("STRETCH").ok()?.parse().ok()
}

/// Each point's images in the two frames.
type Pairs = Vec<[Vector2<f64>; 2]>;

/// One seeded scene: the m members' clean images and every point's noisy ones (the foreign
/// points last).
fn scene(seed: u64, absolute: bool) -> (Pairs, Pairs) {
    let mut g = rng(seed);
    let m = g.random_range(6..=50usize);
    let foreign = g.random_range(1..=3usize);
    let eps = g.random_range(0.001..0.01);
    let mut clean = Scene::random(m, 2, g.random()).tracks();
    if let Some(w) = stretch() {
        clean.frames[1].iter_mut().for_each(|y| y.x *= w);
    }
    let noisy = if absolute {
        let mut t = clean.clone();
        for y in t.frames.iter_mut().flatten() {
            *y += Vector2::new(g.random_range(-eps..eps), g.random_range(-eps..eps));
        }
        t
    } else {
        NoiseModel::RelativeCoordinate { eps }.perturb_tracks(&clean, &mut g)
    };
    let pair = |t: &orthocheck::model::Tracks, j: usize| [t.frames[0][j], t.frames[1][j]];
    let clean_pts: Vec<[Vector2<f64>; 2]> = (0..m).map(|j| pair(&clean, j)).collect();
    let mut pts: Vec<[Vector2<f64>; 2]> = (0..m).map(|j| pair(&noisy, j)).collect();
    // each frame's image box, the foreign points drawn in it
    let boxes: Vec<(Vector2<f64>, Vector2<f64>)> = (0..2)
        .map(|f| {
            let lo = pts
                .iter()
                .fold(Vector2::repeat(f64::INFINITY), |a, p| a.inf(&p[f]));
            let hi = pts
                .iter()
                .fold(Vector2::repeat(f64::NEG_INFINITY), |a, p| a.sup(&p[f]));
            (lo, hi)
        })
        .collect();
    for _ in 0..foreign {
        let mut img = |(lo, hi): (Vector2<f64>, Vector2<f64>)| {
            Vector2::new(g.random_range(lo.x..hi.x), g.random_range(lo.y..hi.y))
        };
        let p = [img(boxes[0]), img(boxes[1])];
        pts.push(p);
    }
    (clean_pts, pts)
}

/// One scene judged by the default tolerance, into its band's tally.
fn tally(s: u64, clean: &[[Vector2<f64>; 2]], pts: &[[Vector2<f64>; 2]], band: &mut Tally) {
    let m = clean.len();
    let d = distances(clean, pts);
    let sigma = (d[..m].iter().map(|x| x * x).sum::<f64>() / m as f64).sqrt();
    let f1: Vec<Vector2<f64>> = pts.iter().map(|p| p[0]).collect();
    let f2: Vec<Vector2<f64>> = pts.iter().map(|p| p[1]).collect();
    let tolerance = identity::robust_tolerance(&f1, &f2);
    let judged = identity::membership(&f1, &f2, &tolerance);
    let inside: Vec<bool> = judged.iter().map(|j| j.member).collect();
    band.scenes += 1;
    band.good += m;
    band.lost += judged[..m].iter().filter(|j| !j.member).count();
    let far: Vec<usize> = (m..pts.len()).filter(|&j| d[j] > 10.0 * sigma).collect();
    let found = far.iter().filter(|&&j| !judged[j].member).count();
    band.far_in_scene(far.len(), found);
    let refused = identity::members_rigid(&f1, &f2, &inside, tolerance.largest(&judged)).is_some();
    if refused && std::env::var_os("SHOW_REFUSED").is_some() {
        eprintln!(
            "scene {s}: {m} members, {} of them kept and {} foreign, tolerance {tolerance:?}",
            inside[..m].iter().filter(|x| **x).count(),
            inside[m..].iter().filter(|x| **x).count()
        );
    }
    band.refused += usize::from(refused);
}

fn main() {
    let Calibration {
        scenes,
        seed,
        absolute,
    } = Calibration::from_args(2000);
    // bands of member counts: 6–9, 10–19, 20–50
    let mut bands: [Tally; 3] = Default::default();
    for s in 0..scenes {
        let (clean, pts) = scene(Calibration::scene_seed(seed, s), absolute);
        let m = clean.len();
        tally(s, &clean, &pts, &mut bands[band(m)]);
    }
    print_bands(
        "| members | scenes | true members rejected | foreign > 10 σ found | refused as no rigid body |",
        &bands,
    );
}
