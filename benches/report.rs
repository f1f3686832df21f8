//! Speed goal of the whole report (every case, ≥ 10,000 trials per noise level, figures and
//! the HTML page): ≤ 2 s wall and 3 s CPU on two cores after a release build (measured as the
//! command in docs/architecture.md, "Where the report's time goes"). Beside it the dearest cases
//! alone, so that a regression there shows by itself: §4's four points (the joint fit of one
//! configuration to figure and table, refitted for 96 mutants), §2's three frames (its exact
//! views sampled, and the two solutions proven distinct over all of them) and the exact
//! solution counts (the lines-first construction in a multiquadratic field).

use criterion::{criterion_group, criterion_main, Criterion};
use orthocheck::cases;
use orthocheck::report::{html, Report};

/// The allocator of the `orthocheck` command (src/main.rs).
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

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
    // the dearest cases
    for (id, name) in [
        ("ex4-four-points", "ex4_four_points"),
        ("ex2-three-frames", "ex2_three_frames"),
        ("solution-count", "solution_count"),
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
