//! Speed goal of the formula audit: every item, exact and at random points, < 2 s; one item
//! costs its own work, not the whole audit's.

use criterion::{criterion_group, criterion_main, Criterion};
use orthocheck::cases;
use orthocheck::claims::audit::{audit_all, Wanted};

fn audit(c: &mut Criterion) {
    let all = cases::load_all::<orthocheck::claims::CaseCheck>(&orthocheck_benches::paper_cases())
        .expect("the paper cases load");
    let mut g = c.benchmark_group("audit");
    g.sample_size(10);
    // the fixed cost of every command: reading, parsing and validating the case files
    g.bench_function("load_cases", |b| {
        b.iter(|| {
            cases::load_all::<orthocheck::claims::CaseCheck>(&orthocheck_benches::paper_cases())
                .expect("the paper cases load")
        })
    });
    g.bench_function("whole_audit", |b| {
        b.iter(|| audit_all(&all, Wanted::All).expect("the audit runs"))
    });
    // one formula item of §2.2, eq. p3f3sqr (the twofold squaring), an Appendix A
    // coefficient (its expansion in the projections), and the dearest item, §2.2's
    // substitution of the linear solution into F₃ (its own work half the audit's); the
    // derived frame equations and the symbolic elimination are kept once derived (once per
    // process), so after the first iteration these are warm figures
    for id in [
        "p3f3-differences/equation-1",
        "p3f3sqr",
        "appA-coefficients/f_b",
        "p3f3-quadratic/substitution",
    ] {
        g.bench_function(format!("one_item/{id}"), |b| {
            b.iter(|| audit_all(&all, Wanted::Id(id)).expect("the audit runs"))
        });
    }
    g.finish();
}

criterion_group!(benches, audit);
criterion_main!(benches);
