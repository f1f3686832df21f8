//! Speed goals of orthographic structure from motion: Tomasi–Kanade for 10⁴ points in 100
//! frames (< 100 ms), bundle adjustment of 100 points in 20 frames from the Tomasi–Kanade
//! start on 1 % noise (< 50 ms), and at its declared limit, 250 points in 200 frames
//! (`limits::BUNDLE_FRAMES`, `limits::BUNDLE_WORK`: ≤ 0.1 s per iteration, docs/limits.md),
//! one thread.

use criterion::{criterion_group, criterion_main, Criterion};
use orthocheck::model::{rng, NoiseModel, Scene};
use orthocheck::sfm::{bundle_adjust, tomasi_kanade, BundleOptions, Observations};

fn sfm(c: &mut Criterion) {
    let big = Scene::random(10_000, 100, 1).tracks();
    let mut g = c.benchmark_group("sfm");
    g.sample_size(10);
    // goal: < 100 ms
    g.bench_function("tomasi_kanade_10000x100", |b| {
        b.iter(|| tomasi_kanade(std::hint::black_box(&big)))
    });
    let clean = Scene::random(100, 20, 2).tracks();
    let noisy = NoiseModel::RelativeCoordinate { eps: 0.01 }.perturb_tracks(&clean, &mut rng(3));
    let start = tomasi_kanade(&noisy).expect("a generic scene");
    let obs = Observations::from_tracks(&noisy);
    // goal: < 50 ms
    g.bench_function("bundle_adjust_100x20", |b| {
        b.iter(|| {
            bundle_adjust(
                &obs,
                std::hint::black_box(&start),
                &BundleOptions::default(),
            )
        })
    });
    let clean = Scene::random(250, 200, 4).tracks();
    let noisy = NoiseModel::RelativeCoordinate { eps: 0.01 }.perturb_tracks(&clean, &mut rng(5));
    let start = tomasi_kanade(&noisy).expect("a generic scene");
    let obs = Observations::from_tracks(&noisy);
    // goal: ≤ 0.1 s per iteration; one iteration, then the whole adjustment
    for (name, iterations) in [
        ("bundle_adjust_250x200_one_iteration", 1),
        ("bundle_adjust_250x200", 100),
    ] {
        let options = BundleOptions {
            max_iterations: iterations,
            ..BundleOptions::default()
        };
        g.bench_function(name, |b| {
            b.iter(|| bundle_adjust(&obs, std::hint::black_box(&start), &options))
        });
    }
    g.finish();
}

criterion_group!(benches, sfm);
criterion_main!(benches);
