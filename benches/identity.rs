//! Speed goal of the point-identity search: every ordered choice of four frame-2 points for
//! n = 30 (657,720 of them), ranked by the equal-scale epipolar residual, < 1 s on two cores.

use criterion::{criterion_group, criterion_main, Criterion};
use orthocheck::derivations::identity::{epipolar_residual, rank_quadruples};
use orthocheck::model::Scene;

fn search(c: &mut Criterion) {
    let t = Scene::random(30, 2, 1).tracks();
    let mut g = c.benchmark_group("identity");
    g.sample_size(10);
    g.bench_function("four_point_search_n30", |b| {
        b.iter(|| {
            let r = rank_quadruples(&t.frames[0], &t.frames[1], |a, b| epipolar_residual(a, b));
            assert_eq!(r.len(), 657_720);
            r
        })
    });
    g.finish();
}

criterion_group!(benches, search);
criterion_main!(benches);
