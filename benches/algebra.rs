//! Sparse polynomial products: Fateman's p · (p + 1), p = (1 + x + y + z + t)^10, by the
//! method the shape picks (the dense array) and by the heap.

use criterion::{criterion_group, criterion_main, Criterion};
use orthocheck::algebra::mpoly::{mul_with, Coef, MPoly, MulMethod, Ring};

fn fateman(c: &mut Criterion) {
    let r = Ring::new(&["x", "y", "z", "t"]);
    let one = MPoly::constant(r.nvars(), Coef::Small(1));
    let s = r
        .names()
        .iter()
        .filter_map(|v| r.var(v))
        .fold(one.clone(), |acc, v| &acc + &v);
    let p = s.pow(10);
    let q = &p + &one;
    let mut g = c.benchmark_group("fateman10");
    g.sample_size(20);
    g.bench_function("auto", |b| b.iter(|| mul_with(&p, &q, MulMethod::Auto)));
    g.bench_function("heap", |b| b.iter(|| mul_with(&p, &q, MulMethod::Heap)));
    g.finish();
}

criterion_group!(benches, fateman);
criterion_main!(benches);
