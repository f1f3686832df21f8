//! Speed goals of the solvers: p3f3 from projected squared lengths (all roots and
//! feasibility), p3f4, p4f3, the least-squares form, and a noise study of 10⁶ p3f3 trials on
//! every core.

use criterion::{criterion_group, criterion_main, BatchSize, Criterion};
use orthocheck::derivations::noise::{run_level, Study, StudySolver};
use orthocheck::derivations::solver::SquaredLengths;
use orthocheck::derivations::{p3f3, p3f4, p4f3};
use orthocheck::model::{Body, NoiseModel, Scene};

/// Projected squared lengths (PQ, QR, RP) of `k` frames of seeded random scenes.
fn instances<const K: usize>(n: usize) -> Vec<[[f64; 3]; K]> {
    (0..n as u64)
        .map(|seed| {
            let l = SquaredLengths::from_tracks(&Scene::random(3, K, seed).tracks());
            std::array::from_fn(|i| [l.frames[i][0], l.frames[i][1], l.frames[i][2]])
        })
        .collect()
}

fn solvers(c: &mut Criterion) {
    // goal: ≤ 100 ns per p3f3 solve (all roots + feasibility), one thread
    let p3 = instances::<3>(1000);
    let mut i = 0;
    c.bench_function("p3f3_core", |b| {
        b.iter(|| {
            i = if i + 1 == p3.len() { 0 } else { i + 1 };
            p3f3::solve_core(std::hint::black_box(&p3[i]))
        })
    });
    // goal: ≤ 200 ns per p3f4 solve
    let p4 = instances::<4>(1000);
    let mut j = 0;
    c.bench_function("p3f4_core", |b| {
        b.iter(|| {
            j = if j + 1 == p4.len() { 0 } else { j + 1 };
            p3f4::solve_core(std::hint::black_box(&p4[j]))
        })
    });
}

fn four_points(c: &mut Criterion) {
    // goal: ≤ 1 µs per p4f3 solve, with the feasibility and realizability checks
    let inst: Vec<[[f64; 6]; 3]> = (0..1000u64)
        .map(|seed| {
            let l = SquaredLengths::from_tracks(&Scene::random(4, 3, seed).tracks());
            std::array::from_fn(|i| std::array::from_fn(|e| l.frames[i][e]))
        })
        .collect();
    let mut i = 0;
    c.bench_function("p4f3_core", |b| {
        b.iter(|| {
            i = if i + 1 == inst.len() { 0 } else { i + 1 };
            p4f3::solve_core(std::hint::black_box(&inst[i]))
        })
    });
    // goal: ≤ 1 ms for the least-squares form over every triangle, 20 points × 10 frames
    let big = SquaredLengths::from_tracks(&Scene::random(20, 10, 1).tracks());
    c.bench_function("lsq_p20_k10", |b| {
        b.iter(|| p4f3::solve_least_squares(std::hint::black_box(&big)).expect("solves"))
    });
}

fn noise_study(c: &mut Criterion) {
    // goal: < 2 s for 10⁶ p3f3 trials on two cores
    let study = Study {
        solver: StudySolver::P3f3,
        body: Body::triangle(2.0, 3.0, 4.0).expect("a triangle"),
        frames: 3,
        trials: 1_000_000,
        seed: 1,
        motions: None,
    };
    let mut g = c.benchmark_group("noise");
    g.sample_size(10);
    g.bench_function("p3f3_1e6_trials", |b| {
        b.iter_batched(
            || study.clone(),
            |s| run_level(&s, NoiseModel::RelativeCoordinate { eps: 0.01 }, 0, &|_| {}),
            BatchSize::PerIteration,
        )
    });
    g.finish();
}

criterion_group!(benches, solvers, four_points, noise_study);
criterion_main!(benches);
