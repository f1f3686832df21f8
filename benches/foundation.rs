//! Speed goals of the foundation: the DOF grid, the exact twofold-squared identity, and exact
//! root isolation.

use criterion::{criterion_group, criterion_main, Criterion};
use num_rational::BigRational;
use num_traits::One;
use orthocheck::algebra::{Poly, UPoly};
use orthocheck::cases::load_case;
use orthocheck::claims::CaseCheck;
use orthocheck::derivations::{dof, twofold};

fn dof_grid(c: &mut Criterion) {
    // goal: < 200 ms for p ≤ 8, k ≤ 6 with float and exact rank
    c.bench_function("dof_table_p8_k6", |b| {
        b.iter(|| dof::table(8, 6, 1).expect("grid"))
    });
}

fn twofold_identity(c: &mut Criterion) {
    // goal: < 1 ms for the exact verification of eq. p3f3sqr
    let case: orthocheck::claims::PaperCase =
        load_case(&orthocheck_benches::paper_cases().join("twofold_squared.yaml"))
            .expect("case file");
    let CaseCheck::TwofoldSquared(t) = case.check else {
        panic!("not a twofold case")
    };
    let printed = Poly::parse(&t.polynomial.printed).expect("formula");
    c.bench_function("twofold_squared_exact_identity", |b| {
        b.iter(|| {
            let derived = twofold::twofold_squared([1, 1, -1]);
            assert_eq!(derived.ratio_to(&printed), Some(BigRational::one()));
        })
    });
}

fn sturm_isolation(c: &mut Criterion) {
    // goal: < 10 ms for all real roots of a degree-8 polynomial with ~20-digit rational
    // coefficients, refined to width 1e-30
    let roots: Vec<BigRational> = [
        (-977, 311),
        (-523, 997),
        (-7, 613),
        (101, 709),
        (331, 337),
        (499, 211),
        (883, 401),
        (947, 103),
    ]
    .iter()
    .map(|&(n, d)| BigRational::new(n.into(), d.into()))
    .collect();
    let p = UPoly::from_roots(&roots);
    let width = BigRational::new(1.into(), num_traits::pow(num_bigint::BigInt::from(10), 30));
    c.bench_function("sturm_degree8_width_1e-30", |b| {
        b.iter(|| {
            let r = p.real_roots_within(&width);
            assert_eq!(r.len(), 8);
        })
    });
}

criterion_group!(benches, dof_grid, twofold_identity, sturm_isolation);
criterion_main!(benches);
