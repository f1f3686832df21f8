use std::collections::BTreeMap;

use num_rational::BigRational;
use orthocheck::algebra::{exact_rank, rat, svd_rank, Poly, UPoly};
use proptest::prelude::*;

/// A random polynomial in x, y, z: up to 5 terms, exponents ≤ 3, coefficients in [−9, 9]/[1, 4].
fn poly() -> impl Strategy<Value = Poly> {
    prop::collection::vec(
        ((-9i64..=9), (1i64..=4), (0u32..=3), (0u32..=3), (0u32..=3)),
        0..5,
    )
    .prop_map(|terms| {
        terms
            .into_iter()
            .fold(Poly::zero(), |acc, (n, d, a, b, c)| {
                let t = &(&Poly::var("x").pow(a) * &Poly::var("y").pow(b)) * &Poly::var("z").pow(c);
                &acc + &t.scale(&rat(n, d))
            })
    })
}

fn point() -> impl Strategy<Value = BTreeMap<String, BigRational>> {
    (
        (-20i64..=20),
        (1i64..=7),
        (-20i64..=20),
        (1i64..=7),
        (-20i64..=20),
        (1i64..=7),
    )
        .prop_map(|(a, b, c, d, e, f)| {
            BTreeMap::from([
                ("x".to_string(), rat(a, b)),
                ("y".to_string(), rat(c, d)),
                ("z".to_string(), rat(e, f)),
            ])
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 256, rng_seed: proptest::test_runner::RngSeed::Fixed(7), ..ProptestConfig::default() })]

    #[test]
    fn ring_laws(a in poly(), b in poly(), c in poly()) {
        prop_assert_eq!(&(&a + &b) + &c, &a + &(&b + &c));
        prop_assert_eq!(&a + &b, &b + &a);
        prop_assert_eq!(&a * &b, &b * &a);
        prop_assert_eq!(&(&a * &b) * &c, &a * &(&b * &c));
        prop_assert_eq!(&a * &(&b + &c), &(&a * &b) + &(&a * &c));
        prop_assert!((&a - &a).is_zero());
        prop_assert_eq!(a.pow(2), &a * &a);
    }

    #[test]
    fn printing_round_trips(a in poly()) {
        prop_assert_eq!(Poly::parse(&a.to_string()).unwrap(), a);
    }

    #[test]
    fn evaluation_is_a_homomorphism(a in poly(), b in poly(), q in poly(), at in point()) {
        let ev = |p: &Poly| p.eval(&at).unwrap();
        prop_assert_eq!(ev(&(&a * &b)), ev(&a) * ev(&b));
        prop_assert_eq!(ev(&(&a - &b)), ev(&a) - ev(&b));
        // substituting q for x then evaluating = evaluating with x := q(at)
        let mut at_q = at.clone();
        at_q.insert("x".into(), ev(&q));
        prop_assert_eq!(ev(&a.substitute("x", &q)), a.eval(&at_q).unwrap());
    }

    #[test]
    fn root_isolation_finds_known_roots(
        roots in prop::collection::vec(((-50i64..=50), (1i64..=9), (1u32..=3)), 1..5)
    ) {
        let mut all = Vec::new();
        let mut want: BTreeMap<BigRational, u32> = BTreeMap::new();
        for (n, d, m) in &roots {
            for _ in 0..*m {
                all.push(rat(*n, *d));
            }
            *want.entry(rat(*n, *d)).or_default() += m;
        }
        let p = UPoly::from_roots(&all);
        let width = rat(1, 1_000_000_000_000);
        let got = p.real_roots_within(&width);
        prop_assert_eq!(got.len(), want.len());
        for (r, (x, m)) in got.iter().zip(&want) {
            prop_assert!(r.lo() <= *x && *x <= r.hi(), "{} not in [{}, {}]", x, r.lo(), r.hi());
            prop_assert!(r.width() <= width);
            prop_assert_eq!(r.multiplicity, *m);
        }
    }

    #[test]
    fn exact_and_float_rank_agree_on_products(
        a in prop::collection::vec(-5i64..=5, 12), b in prop::collection::vec(-5i64..=5, 12)
    ) {
        // (4×3)·(3×4) has rank ≤ 3
        let m: Vec<Vec<BigRational>> = (0..4)
            .map(|i| (0..4).map(|j| (0..3).map(|k| rat(a[i * 3 + k] * b[k * 4 + j], 1)).sum()).collect())
            .collect();
        let f = nalgebra::DMatrix::from_fn(4, 4, |i, j| {
            (0..3).map(|k| (a[i * 3 + k] * b[k * 4 + j]) as f64).sum::<f64>()
        });
        let (r, _) = exact_rank(&m);
        prop_assert!(r <= 3);
        prop_assert_eq!(svd_rank(&f).rank, r);
    }
}
