//! Sparse polynomial products: Fateman's p · (p + 1), p = (1 + x + y + z + t)^n. For n = 10
//! by the method the shape picks (the dense array) and by the heap; for n = 20 (sums within
//! an i128) and n = 30 (sums beyond it) by the array on one thread, the sizes and the
//! thread count `scripts/fateman.py` runs in python-flint, and n = 20 on every core. And
//! the Schwartz–Zippel screen modulo word primes: (1 + x + y + z + t)^8 against its
//! expansion at 64 points, as the audit runs it.

use criterion::{criterion_group, criterion_main, Criterion};
use orthocheck::algebra::mpoly::{mul_with, Coef, MPoly, MulMethod, Ring};

/// p and p + 1.
fn operands(n: u32) -> (MPoly, MPoly) {
    let r = Ring::new(&["x", "y", "z", "t"]);
    let one = MPoly::constant(r.nvars(), Coef::Small(1));
    let s = r
        .names()
        .iter()
        .filter_map(|v| r.var(v))
        .fold(one.clone(), |acc, v| &acc + &v);
    let p = s.pow(n);
    let q = &p + &one;
    (p, q)
}

fn fateman(c: &mut Criterion) {
    let (p, q) = operands(10);
    let mut g = c.benchmark_group("fateman10");
    g.sample_size(20);
    g.bench_function("auto", |b| b.iter(|| mul_with(&p, &q, MulMethod::Auto)));
    g.bench_function("heap", |b| b.iter(|| mul_with(&p, &q, MulMethod::Heap)));
    g.finish();
    let mut g = c.benchmark_group("fateman");
    g.sample_size(10);
    // one thread, as python-flint's default, and n = 20 on every core; the product is
    // dropped untimed, as the example times it
    let pool = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a thread pool")
    };
    let (one, all) = (pool(1), pool(0));
    for n in [20, 30] {
        let (p, q) = operands(n);
        g.bench_function(format!("n{n}"), |b| {
            b.iter_with_large_drop(|| one.install(|| mul_with(&p, &q, MulMethod::Auto)))
        });
        if n == 20 {
            g.bench_function("n20-every-core", |b| {
                b.iter_with_large_drop(|| all.install(|| mul_with(&p, &q, MulMethod::Auto)))
            });
        }
    }
    g.finish();
}

fn screen(c: &mut Criterion) {
    use orthocheck::algebra::{modp::agree_mod_p, rat, RatFn};
    let power = RatFn::parse("(1 + x + y + z + t)^8").expect("a formula");
    let expanded = RatFn::from(power.num.clone());
    let one = rat(1, 1);
    c.bench_function("screen_mod_p/64_points", |b| {
        b.iter(|| agree_mod_p(&power, &expanded, &one, 64, 1))
    });
}

criterion_group!(benches, fateman, screen);
criterion_main!(benches);
