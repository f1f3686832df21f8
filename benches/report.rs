//! Speed goal of the whole report (every case, ≥ 10,000 trials per noise level, figures and
//! the HTML page): < 5 s after a release build.

use std::path::Path;

use criterion::{criterion_group, criterion_main, Criterion};
use orthocheck::cases;
use orthocheck::report::{html, Report};

fn report(c: &mut Criterion) {
    let all = cases::load_all(Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/paper_cases"
    )))
    .expect("the paper cases load");
    let mut g = c.benchmark_group("report");
    g.sample_size(10);
    g.bench_function("full_report_with_html", |b| {
        b.iter(|| {
            let r = Report::from_cases(&all).expect("the report runs");
            html::render(&r).len()
        })
    });
    g.finish();
}

criterion_group!(benches, report);
criterion_main!(benches);
