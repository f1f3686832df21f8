//! Tests of `orthocheck_core::derivations::noise`.

use orthocheck_core::derivations::noise::*;
use orthocheck_core::model::StudySolver;
use orthocheck_core::model::{Body, NoiseModel};

#[test]
fn zero_noise_recovers_the_body_and_threads_do_not_matter() {
    let body = Body::triangle(3.0, 4.0, 5.0).unwrap();
    let s3 = Study {
        solver: StudySolver::P3f3,
        body: body.clone(),
        frames: 3,
        trials: 300,
        seed: 1,
        motions: None,
    };
    let r = run_level(&s3, NoiseModel::RelativeCoordinate { eps: 0.0 }, 0, &|_| {});
    assert_eq!(r.failures, 0);
    assert!(r.quantile(0, 1.0).unwrap() < 1e-9);
    let s4 = Study {
        solver: StudySolver::P3f4,
        body,
        frames: 4,
        trials: 3000,
        seed: 9,
        motions: None,
    };
    let a = run_level(&s4, NoiseModel::RelativeLength { eps: 0.01 }, 1, &|_| {});
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let b = pool.install(|| run_level(&s4, NoiseModel::RelativeLength { eps: 0.01 }, 1, &|_| {}));
    assert_eq!(a.sorted, b.sorted);
}

#[test]
fn beyond_the_reservoir_memory_stays_fixed_and_means_stay_exact() {
    let s = Study {
        solver: StudySolver::P3f3,
        body: Body::triangle(3.0, 4.0, 5.0).unwrap(),
        frames: 3,
        // several chunks, each thread's share folded in chunk order
        trials: 3 * CHUNK + 17,
        seed: 2,
        motions: None,
    };
    // the sampling's own code path with a small reservoir, so the test runs unoptimised
    let kept = CHUNK;
    let model = NoiseModel::RelativeCoordinate { eps: 0.001 };
    let r = run_level_keeping(&s, model, 0, &|_| {}, kept);
    let (sums, n) = r.sums.expect("more trials than the reservoir");
    assert_eq!(n, s.trials - r.failures);
    assert_eq!(r.ratios.len(), kept * r.edges);
    assert!(r.sorted.iter().all(|v| v.len() == kept));
    assert!((r.mean(0) - sums[0] / n as f64).abs() == 0.0 && r.mean(0).is_finite());
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let b = one.install(|| run_level_keeping(&s, model, 0, &|_| {}, kept));
    assert_eq!(r.sorted, b.sorted);
}
