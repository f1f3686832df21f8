//! `reconstruct --robust` on turntable sequences with gaps and moved images: how often it
//! runs, where its first judgement comes from, how many moved images it finds and how many
//! good ones it drops.
//!
//! Usage: `cargo run --release -p orthocheck-benches --example robust_turntable -- [SCENES]
//! [SEED]` (defaults 200, 1). Each scene: `sfm::turntable::Turntable` with 60–300 points,
//! 20–60 frames, each point in 3–10 consecutive frames, elevation 10°–70°, relative noise
//! 0.1 %–1 %; then 2 % of the images moved by 5 %–30 % of the image's scale in a random
//! direction (far beyond the noise). Rows: the first judgement from a sample or from the
//! fit of every observation (`robust_start`), and the scenes refused (`SHOW_ERRORS=1` prints
//! why).

use std::collections::BTreeSet;

use nalgebra::Vector2;
use orthocheck::model::rng;
use orthocheck::sfm::robust::RansacOptions;
use orthocheck::sfm::turntable::Turntable;
use orthocheck::sfm::{reconstruct, Component, Observations, Options, Units};
use rand::Rng;

/// Per row: groups, moved images, of them dropped, good images, of them dropped, scenes
/// with warnings (a scene counted in the row of its first group).
#[derive(Default)]
struct Row {
    groups: usize,
    moved: usize,
    found: usize,
    good: usize,
    lost: usize,
    warned: usize,
}

/// One scene: the turntable's observations and the images moved (frame, point).
fn scene(seed: u64) -> (Observations, BTreeSet<(usize, usize)>) {
    let mut g = rng(seed);
    let t = Turntable {
        points: g.random_range(60..=300),
        frames: g.random_range(20..=60),
        window: g.random_range(3..=10),
        elevation: g.random_range(10.0f64..70.0).to_radians(),
        noise: Some(g.random_range(0.001..0.01)),
        seed: g.random(),
    };
    let (_, mut obs) = t.generate();
    let units = Units::of(&obs).expect("finite images");
    let seen: Vec<(usize, usize)> = obs.seen().map(|(f, j, _)| (f, j)).collect();
    let mut moved = BTreeSet::new();
    while moved.len() < seen.len() / 50 {
        moved.insert(seen[g.random_range(0..seen.len())]);
    }
    for &(f, j) in &moved {
        let a = g.random_range(0.0..std::f64::consts::TAU);
        let r = g.random_range(0.05..0.3) * units.scale;
        if let Some(y) = obs.frames[f][j].as_mut() {
            *y += Vector2::new(a.cos(), a.sin()) * r;
        }
    }
    (obs, moved)
}

/// Tallies one group of robust mode's answer: its moved and good images, found and lost.
fn tally(row: &mut Row, obs: &Observations, moved: &BTreeSet<(usize, usize)>, c: &Component) {
    let Some(r) = &c.robust else { return };
    let dropped: BTreeSet<(&str, usize)> = r
        .dropped
        .iter()
        .map(|d| (d.point.as_str(), d.frame))
        .collect();
    for (f, j, _) in obs.seen().filter(|(f, _, _)| c.frames.contains(&(f + 1))) {
        let out = dropped.contains(&(obs.names[j].as_str(), f + 1));
        if moved.contains(&(f, j)) {
            row.moved += 1;
            row.found += usize::from(out);
        } else {
            row.good += 1;
            row.lost += usize::from(out);
        }
    }
    row.groups += 1;
}

fn main() {
    let orthocheck_benches::Calibration { scenes, seed, .. } =
        orthocheck_benches::Calibration::from_args(200);
    let mut rows: [Row; 2] = Default::default();
    let mut refused = 0usize;
    let options = Options {
        robust: Some(RansacOptions::from_data()),
        ..Options::default()
    };
    for s in 0..scenes {
        let (obs, moved) = scene(seed.wrapping_mul(7_919).wrapping_add(s));
        let out = match reconstruct(&obs, &options) {
            Ok(out) => out,
            Err(e) => {
                if std::env::var_os("SHOW_ERRORS").is_some() {
                    eprintln!("scene {s}: {e}");
                }
                refused += 1;
                continue;
            }
        };
        let whole = |c: &Component| c.robust.as_ref().is_some_and(|r| r.whole_fit);
        for c in &out.components {
            tally(&mut rows[usize::from(whole(c))], &obs, &moved, c);
        }
        if let Some(first) = out.components.first() {
            rows[usize::from(whole(first))].warned += usize::from(!out.warnings().is_empty());
        }
    }
    println!(
        "| first judgement | groups | moved images dropped | good images dropped | warned scenes |"
    );
    println!("|---|---:|---:|---:|---:|");
    for (label, r) in ["a sample", "the fit of every observation"]
        .iter()
        .zip(&rows)
    {
        println!(
            "| {label} | {} | {} of {} ({:.2} %) | {} of {} ({:.2} %) | {} |",
            r.groups,
            r.found,
            r.moved,
            100.0 * r.found as f64 / r.moved.max(1) as f64,
            r.lost,
            r.good,
            100.0 * r.lost as f64 / r.good.max(1) as f64,
            r.warned
        );
    }
    println!("refused: {refused} of {scenes} scenes");
}
