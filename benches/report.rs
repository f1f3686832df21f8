//! Speed goal of the whole report (every case, ≥ 10,000 trials per noise level, figures and
//! the HTML page): < 5 s after a release build. Beside it the slowest case alone, §4's four
//! points (the joint fit of one configuration to figure and table, refitted for 96 mutants),
//! so that a regression there shows by itself.

use criterion::{criterion_group, criterion_main, Criterion};
use orthocheck::cases;
use orthocheck::report::{html, Report};

fn report(c: &mut Criterion) {
    let all = cases::load_all::<orthocheck::claims::Check>(&orthocheck_benches::paper_cases())
        .expect("the paper cases load");
    let mut g = c.benchmark_group("report");
    g.sample_size(10);
    g.bench_function("full_report_with_html", |b| {
        b.iter(|| {
            let r = Report::from_run(
                orthocheck::claims::run_paper(&all, &|_, _| {}).expect("the report runs"),
                Default::default(),
            );
            html::render(&r).len()
        })
    });
    let ex4: Vec<_> = all
        .iter()
        .filter(|c| c.id == "ex4-four-points")
        .cloned()
        .collect();
    assert_eq!(ex4.len(), 1, "the §4 case is among the paper cases");
    g.bench_function("ex4_four_points", |b| {
        b.iter(|| {
            orthocheck::claims::run_paper(&ex4, &|_, _| {})
                .expect("the §4 case runs")
                .results
                .len()
        })
    });
    g.finish();
}

criterion_group!(benches, report);
criterion_main!(benches);
