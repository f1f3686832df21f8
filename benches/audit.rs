//! Speed goal of the formula audit: every item, exact and at random points, < 2 s.

use criterion::{criterion_group, criterion_main, Criterion};
use orthocheck::cases;

fn audit(c: &mut Criterion) {
    let all = cases::load_all::<orthocheck::claims::Check>(&orthocheck_benches::paper_cases())
        .expect("the paper cases load");
    let mut g = c.benchmark_group("audit");
    g.sample_size(10);
    g.bench_function("whole_audit", |b| {
        b.iter(|| orthocheck::claims::audit::audit_all(&all).expect("the audit runs"))
    });
    g.finish();
}

criterion_group!(benches, audit);
criterion_main!(benches);
