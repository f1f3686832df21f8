//! Speed goals of orthographic structure from motion: Tomasi–Kanade for 10⁴ points in 100
//! frames (< 100 ms), bundle adjustment of 100 points in 20 frames from the Tomasi–Kanade
//! start on 1 % noise (< 50 ms), one thread.

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
        b.iter(|| bundle_adjust(&obs, std::hint::black_box(&start), &BundleOptions::default()))
    });
    g.finish();
}

criterion_group!(benches, sfm);
criterion_main!(benches);
