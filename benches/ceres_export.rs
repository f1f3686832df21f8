//! Bundle-adjustment problems written to plain text for the Ceres comparison
//! (`scripts/ceres_bench/`), with orthocheck's own adjustment of each, timed.
//!
//! Usage: `cargo run --release -p orthocheck-benches --example ceres_export -- OUTDIR
//! [--repeat R] [--only NAME] [--longer N] [--reach C1,C2,…] [--csv NAME PATH]...` (R
//! defaults to 5; `--only` exports one problem; `--longer N` also times the adjustment
//! allowed N iterations; `--reach` finds, from one run of `--longer` iterations (10,000 by
//! default), how many iterations bring the cost to at most each Cᵢ, input units, and times
//! the adjustment stopped there). Writes `OUTDIR/NAME.txt` for
//! - `dense_250x200`: 250 points in 200 frames, 1 % noise, seeds 4 and 5 (`synth --points 250
//!   --frames 200 --seed 4 --noise 0.01`, the problem of `benches/bundle_libraries` and of
//!   docs/limits.md's "Bundle adjustment's cost"), from the Tomasi–Kanade start;
//! - `turntable_500x36w5`: `synth --turntable --points 500 --frames 36 --window 5 --noise
//!   0.001 --seed 1` (30° elevation), from the pipeline's start for tracks with gaps
//!   (variable projection from the chained pairs);
//! - `family_largest`: the scene of the turntable family (`turntable_family`, seed 1, its 400
//!   scenes) with the most observations, from the pipeline's start;
//! - every `--csv NAME PATH`: a tracks file (gaps allowed) read as `reconstruct` reads it,
//!   from the pipeline's start;
//!
//! each start being what `sfm::reconstruct` makes before its bundle adjustment
//! (`Options { bundle: false, .. }`, the default seed). For each it prints the median wall
//! time of `R` calls of `sfm::bundle_adjust` with the default options (what `reconstruct`
//! runs, one thread), its iterations and final cost, and the median of `R` calls stopped
//! before the first iteration (`max_iterations: 0`: the grouping, the units and the points'
//! standard errors, the work beside the iterations).
//!
//! The file is in the units the adjustment works in (`sfm::Units`: y ↦ (y − centre)/scale,
//! `scale` a power of two), so a solver reading it sees the numbers orthocheck's
//! Levenberg–Marquardt sees; ½ Σ ‖r‖² in the input's units is scale² times the cost in these.
//! Lines (numbers with 17 significant digits, so they read back exactly):
//!
//! ```text
//! name NAME
//! units CENTRE_X CENTRE_Y SCALE
//! sizes FRAMES POINTS OBSERVATIONS
//! rust ITERATIONS COST_INPUT_UNITS START_COST_INPUT_UNITS MEDIAN_SECONDS OVERHEAD_SECONDS
//! frame F R00 R01 R02 R10 R11 R12 R20 R21 R22 T0 T1          (the start, one per frame)
//! point J X Y Z                                              (the start, one per point)
//! obs F J X Y                                                (one per observation)
//! rust_frame F R00 … R22 T0 T1                               (orthocheck's result)
//! rust_point J X Y Z
//! ```
//!
//! Frames and points are numbered from 0 in the file.

use std::path::{Path, PathBuf};
use std::time::Instant;

use orthocheck::model::{rng, NoiseModel, Scene};
use orthocheck::sfm::turntable::Turntable;
use orthocheck::sfm::turntable::{family_scene, family_seed};
use orthocheck::sfm::{
    bundle_adjust, reconstruct, tomasi_kanade, BundleOptions, Observations, Options, Reconstruction,
};
use orthocheck_benches::problem_text;

/// The adjustment alone: Ceres computes no standard errors.
fn loop_only() -> BundleOptions {
    BundleOptions {
        standard_errors: false,
        ..BundleOptions::default()
    }
}

/// ½ Σ ‖r‖² of `rec` over `obs` (in their units).
fn cost(obs: &Observations, rec: &Reconstruction) -> f64 {
    obs.seen()
        .map(|(f, j, y)| (rec.frames[f].project(&rec.points[j]) - y).norm_squared())
        .sum::<f64>()
        / 2.0
}

/// The median of `runs` timed calls, and the last call's answer.
fn timed<T>(runs: usize, mut f: impl FnMut() -> T) -> (f64, T) {
    let mut secs = Vec::new();
    let mut last = None;
    for _ in 0..runs.max(1) {
        let t = Instant::now();
        last = Some(f());
        secs.push(t.elapsed().as_secs_f64());
    }
    secs.sort_by(f64::total_cmp);
    (secs[secs.len() / 2], last.expect("one run at least"))
}

/// The turntable family's largest problem: of seed 1's 400 scenes, by observations, the
/// first whose points seen twice or more the pipeline takes whole (one group, nothing
/// dropped); its number and those observations.
fn family_largest() -> (u64, Observations) {
    let mut scenes: Vec<(u64, Observations)> = (0..400)
        .map(|s| {
            let obs = family_scene(family_seed(1, s)).obs;
            let twice: Vec<usize> = obs
                .by_point()
                .iter()
                .enumerate()
                .filter(|(_, seen)| seen.len() >= 2)
                .map(|(j, _)| j)
                .collect();
            (s, obs.select_points(&twice))
        })
        .collect();
    scenes.sort_by_key(|(s, obs)| (std::cmp::Reverse(obs.count()), *s));
    let options = Options {
        bundle: false,
        ..Options::default()
    };
    scenes
        .into_iter()
        .find(|(_, obs)| {
            reconstruct(obs, &options).is_ok_and(|o| {
                o.dropped_points.is_empty()
                    && o.dropped_frames.is_empty()
                    && o.components.len() == 1
            })
        })
        .expect("a scene taken whole")
}

/// The start `reconstruct` makes before its bundle adjustment (the frames here form one
/// group, and no point or frame is dropped).
fn pipeline_start(obs: &Observations) -> Reconstruction {
    let options = Options {
        bundle: false,
        ..Options::default()
    };
    let outcome = reconstruct(obs, &options).expect("a reconstruction");
    assert!(
        outcome.dropped_points.is_empty() && outcome.dropped_frames.is_empty(),
        "the pipeline dropped points or frames"
    );
    outcome
        .into_single()
        .expect("one group of frames")
        .reconstruction
}

/// Longer adjustments: `limit` iterations (timed over `repeat` runs, or once when `reach`
/// is given), and for each cost in `reach` the iterations that reach it, timed.
fn longer_runs(
    obs: &Observations,
    start: &Reconstruction,
    (repeat, limit): (usize, usize),
    reach: &[f64],
) {
    let options = BundleOptions {
        max_iterations: limit,
        ..loop_only()
    };
    let (secs, long) = timed(if reach.is_empty() { repeat } else { 1 }, || {
        bundle_adjust(obs, start, &options).expect("an adjustment")
    });
    println!(
        "  the same with max_iterations {limit}: {secs:.4} s ({}), {} iterations{}, cost {:.12e}",
        if reach.is_empty() {
            format!("median of {repeat}")
        } else {
            "one run".into()
        },
        long.report.iterations,
        if long.report.converged {
            ""
        } else {
            " (limit)"
        },
        cost(obs, &long.reconstruction)
    );
    for &target in reach {
        let Some(m) = long.report.costs.iter().position(|&c| c <= target) else {
            println!("  cost ≤ {target:.12e}: not reached in {limit} iterations");
            continue;
        };
        let options = BundleOptions {
            max_iterations: m,
            ..loop_only()
        };
        let (secs, at) = timed(repeat, || {
            bundle_adjust(obs, start, &options).expect("an adjustment")
        });
        println!(
            "  cost ≤ {target:.12e}: after {m} iterations, median {secs:.4} s of {repeat} (the adjustment stopped there), cost {:.12e}",
            cost(obs, &at.reconstruction)
        );
    }
}

/// Adjust `start` with orthocheck (timed), print the figures, write the problem file.
fn export(
    dir: &Path,
    name: &str,
    obs: &Observations,
    start: &Reconstruction,
    repeat: usize,
    longer: Option<usize>,
    reach: &[f64],
) {
    let start_cost = cost(obs, start);
    let (secs, adjusted) = timed(repeat, || {
        bundle_adjust(obs, start, &loop_only()).expect("an adjustment")
    });
    let (with_std, _) = timed(repeat, || {
        bundle_adjust(obs, start, &BundleOptions::default()).expect("an adjustment")
    });
    let (overhead, _) = timed(repeat, || {
        let none = BundleOptions {
            max_iterations: 0,
            ..loop_only()
        };
        bundle_adjust(obs, start, &none).expect("an adjustment")
    });
    let report = &adjusted.report;
    let final_cost = cost(obs, &adjusted.reconstruction);
    println!(
        "{name}: {} frames, {} points, {} observations ({:.1} % missing); start cost {start_cost:.12e}",
        obs.frames.len(),
        obs.names.len(),
        obs.count(),
        100.0 * (1.0 - obs.count() as f64 / (obs.frames.len() * obs.names.len()) as f64)
    );
    println!(
        "  orthocheck bundle_adjust: median {secs:.4} s of {repeat}, {} iterations{}, cost {final_cost:.12e} (report {:.12e}); with max_iterations 0: {overhead:.4} s; with the standard errors: {with_std:.4} s",
        report.iterations,
        if report.converged { "" } else { " (limit)" },
        report.costs.last().copied().unwrap_or(f64::NAN),
    );
    if let Some(limit) = longer {
        longer_runs(obs, start, (repeat, limit), reach);
    }
    let text = problem_text(
        name,
        obs,
        (start, &adjusted.reconstruction),
        (report.iterations, final_cost, start_cost),
        (secs, overhead),
    );
    let path = dir.join(format!("{name}.txt"));
    std::fs::write(&path, text).expect("the problem file is written");
    println!("  written to {}", path.display());
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let dir = PathBuf::from(
        args.first()
            .expect("usage: ceres_export OUTDIR [--repeat R] [--csv NAME PATH]..."),
    );
    std::fs::create_dir_all(&dir).expect("the output folder");
    let repeat = args
        .iter()
        .position(|a| a == "--repeat")
        .and_then(|i| args.get(i + 1))
        .and_then(|r| r.parse().ok())
        .unwrap_or(5);
    let only: Option<&String> = args
        .iter()
        .position(|a| a == "--only")
        .and_then(|i| args.get(i + 1));
    let wanted = |name: &str| only.is_none_or(|o| o == name);
    // --reach C1,C2,…: the iterations orthocheck needs to bring the cost (input units) to at
    // most each Ci, from one run of --longer iterations (10,000 by default), and the median
    // time of the adjustment stopped there
    let reach: Vec<f64> = args
        .iter()
        .position(|a| a == "--reach")
        .and_then(|i| args.get(i + 1))
        .map(|r| r.split(',').filter_map(|c| c.parse().ok()).collect())
        .unwrap_or_default();
    // --longer N: also time the adjustment with N iterations at most (the pipeline's is 100)
    let longer: Option<usize> = args
        .iter()
        .position(|a| a == "--longer")
        .and_then(|i| args.get(i + 1))
        .and_then(|r| r.parse().ok())
        .or((!reach.is_empty()).then_some(10_000));

    if wanted("dense_250x200") {
        let clean = Scene::random(250, 200, 4).tracks();
        let noisy =
            NoiseModel::RelativeCoordinate { eps: 0.01 }.perturb_tracks(&clean, &mut rng(5));
        let start = tomasi_kanade(&noisy).expect("a generic scene");
        let obs = Observations::from_tracks(&noisy);
        export(&dir, "dense_250x200", &obs, &start, repeat, longer, &reach);
    }
    if wanted("turntable_500x36w5") {
        let t = Turntable {
            points: 500,
            frames: 36,
            window: 5,
            elevation: 30f64.to_radians(),
            noise: Some(0.001),
            seed: 1,
        };
        let (_, obs) = t.generate();
        let start = pipeline_start(&obs);
        export(
            &dir,
            "turntable_500x36w5",
            &obs,
            &start,
            repeat,
            longer,
            &reach,
        );
    }
    if wanted("family_largest") {
        let (s, obs) = family_largest();
        eprintln!(
            "family_largest: scene {s} of seed 1, {} points in {} frames, {} observations",
            obs.names.len(),
            obs.frames.len(),
            obs.count()
        );
        let start = pipeline_start(&obs);
        export(&dir, "family_largest", &obs, &start, repeat, longer, &reach);
    }
    let mut i = 0;
    while i < args.len() {
        if args[i] == "--csv" && i + 2 < args.len() {
            let (name, path) = (&args[i + 1], Path::new(&args[i + 2]));
            if wanted(name) {
                let obs = orthocheck::input::load_observations(path).expect("a tracks file");
                let start = pipeline_start(&obs);
                export(&dir, name, &obs, &start, repeat, longer, &reach);
            }
            i += 3;
        } else {
            i += 1;
        }
    }
}
