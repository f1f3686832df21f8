//! Speed goal of the whole report (every case, ≥ 10,000 trials per noise level, figures and
//! the HTML page): < 5 s after a release build. Beside it the slowest case alone, §4's four
//! points (the joint fit of one configuration to figure and table, refitted for 96 mutants),
//! so that a regression there shows by itself, and §2's three frames (its exact views sampled,
//! and the two solutions proven distinct over all of them).

use criterion::{criterion_group, criterion_main, Criterion};
use orthocheck::cases;
use orthocheck::report::{html, Report};

fn report(c: &mut Criterion) {
    let all = cases::load_all::<orthocheck::claims::CaseCheck>(&orthocheck_benches::paper_cases())
        .expect("the paper cases load");
    let mut g = c.benchmark_group("report");
    g.sample_size(10);
    g.bench_function("full_report_with_html", |b| {
        b.iter(|| {
            let r = Report::from_run(
                orthocheck::claims::run_cases(&all, &[], &|_, _| {}).expect("the report runs"),
                Default::default(),
            );
            html::render(&r).len()
        })
    });
    // §4's case (the slowest) and §2's (sampled exact views and the proof over all of them)
    for (id, name) in [
        ("ex4-four-points", "ex4_four_points"),
        ("ex2-three-frames", "ex2_three_frames"),
    ] {
        let one: Vec<_> = all.iter().filter(|c| c.id == id).cloned().collect();
        assert_eq!(one.len(), 1, "{id} is among the paper cases");
        g.bench_function(name, |b| {
            b.iter(|| {
                orthocheck::claims::run_cases(&one, &[], &|_, _| {})
                    .expect("the case runs")
                    .results
                    .len()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, report);
criterion_main!(benches);
