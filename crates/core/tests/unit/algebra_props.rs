use std::collections::BTreeMap;

use num_rational::BigRational;
use orthocheck_core::algebra::{exact_rank, rat, svd_rank, Poly, RatFn, UPoly};
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

/// A random expression text: sums, products, quotients (often by a difference that is zero)
/// and powers of numbers and variables, with now and then a stray character or parenthesis.
fn expression() -> impl Strategy<Value = String> {
    let leaf =
        prop::sample::select(vec!["x", "y", "2", "0.5", "0", "x_1", "3y"]).prop_map(String::from);
    let tree = leaf.prop_recursive(4, 24, 2, |inner| {
        (
            inner.clone(),
            prop::sample::select(vec!["+", "-", "*", "/", " ", "^2"]),
            inner,
        )
            .prop_map(|(a, op, b)| match op {
                "/" => format!("({a})/({b} - {b})"),
                "^2" => format!("({a})^2"),
                _ => format!("({a}){op}({b})"),
            })
    });
    (
        tree,
        prop::sample::select(vec!["", ")", "(", "#", "^x", "/ 0", " / (x - y)"]),
    )
        .prop_map(|(t, tail)| format!("{t}{tail}"))
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
    fn a_decimal_is_its_digits_over_a_power_of_ten(
        neg in any::<bool>(), int in "[0-9]{0,21}", frac in "[0-9]{0,21}",
    ) {
        prop_assume!(!(int.is_empty() && frac.is_empty()));
        let digits: num_bigint::BigInt = format!("0{int}{frac}").parse().unwrap();
        let ten = num_traits::pow(num_bigint::BigInt::from(10), frac.len());
        let sign = if neg { "-" } else { "" };
        let v = orthocheck_core::algebra::parse_decimal(&format!("{sign}{int}.{frac}")).unwrap();
        let want = BigRational::new(digits, ten);
        prop_assert_eq!(v, if neg { -want } else { want });
    }

    #[test]
    fn renaming_is_substituting_the_new_names(a in poly(), to in prop::sample::select(vec![
        [("x", "y"), ("y", "x")], [("x", "w"), ("z", "x")], [("x", "z"), ("y", "z")], [("y", "v"), ("w", "x")],
    ])) {
        // one at a time through fresh names, so that a swap does not clash
        let fresh = to.iter().fold(a.clone(), |p, (f, _)| p.substitute(f, &Poly::var(&format!("#{f}"))));
        let want = to.iter().fold(fresh, |p, (f, t)| p.substitute(&format!("#{f}"), &Poly::var(t)));
        prop_assert_eq!(a.rename(&to), want);
    }

    #[test]
    fn checking_a_text_gives_the_parse_s_verdict(text in expression()) {
        prop_assert_eq!(RatFn::check(&text), RatFn::parse(&text).map(drop), "{}", text);
    }

    #[test]
    fn the_first_term_is_the_first_of_the_terms(a in poly()) {
        prop_assert_eq!(a.first_term(), a.terms().next());
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

/// The polynomial engine against oracles that share none of its code: exact evaluation at
/// random rational points from the printed terms (`Σ c · Π xᵉ`, term by term), and
/// evaluation at random points of 𝔽ₚ (p = 2⁶¹ − 1). A product, power, substitution or
/// quotient that is wrong differs from its oracle at a random point with probability at
/// least 1 − d/p (Schwartz–Zippel) over 𝔽ₚ, and at almost every rational point.
mod oracles {
    use std::collections::BTreeMap;

    use num_bigint::BigInt;
    use num_rational::BigRational;
    use num_traits::{One, Zero};
    use orthocheck_core::algebra::modp::{eval_poly, Fp, Residue, PRIME};
    use orthocheck_core::algebra::mpoly::Scalar;
    use orthocheck_core::algebra::{Poly, RatFn};
    use proptest::prelude::*;

    const VARS: [&str; 8] = ["a", "b", "c", "d_1", "u", "v", "w", "x"];

    type Terms = Vec<(i64, i64, bool, Vec<u32>)>;

    /// `PROPTEST_CASES` when set (a long run), else `default`.
    fn cases(default: u32) -> u32 {
        std::env::var("PROPTEST_CASES")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(default)
    }

    /// Sparse terms in eight variables: most exponents 0, some up to 3, a few up to `high`
    /// (130: total degrees past 127 need 16-bit fields, their products more).
    fn sparse(max: usize, high: u32) -> impl Strategy<Value = Terms> {
        let e = prop_oneof![12 => Just(0u32), 6 => 1u32..=3, 1 => 4u32..=high];
        prop::collection::vec(
            (
                -9i64..=9,
                1i64..=4,
                prop::bool::weighted(0.2),
                prop::collection::vec(e, 8),
            ),
            0..max,
        )
    }

    /// Dense terms in the first three variables, each exponent up to `deg`.
    fn dense(min: usize, max: usize, deg: u32) -> impl Strategy<Value = Terms> {
        prop::collection::vec(
            (
                -9i64..=9,
                1i64..=3,
                prop::bool::weighted(0.1),
                prop::collection::vec(0u32..=deg, 3),
            ),
            min..max,
        )
    }

    /// The polynomial of the terms; a flagged coefficient is multiplied by 2⁶³ + 1 (past
    /// the machine-word fast path).
    fn poly(t: &Terms) -> Poly {
        t.iter().fold(Poly::zero(), |acc, (n, d, big, e)| {
            let mut c = BigRational::new((*n).into(), (*d).into());
            if *big {
                c *= BigRational::from_integer(BigInt::from(i64::MAX) + 2);
            }
            let m = VARS
                .iter()
                .zip(e)
                .fold(Poly::constant(c), |m, (v, k)| &m * &Poly::var(v).pow(*k));
            &acc + &m
        })
    }

    /// A point: a rational and a residue per variable.
    #[derive(Clone, Debug)]
    struct Point {
        q: BTreeMap<String, BigRational>,
        p: BTreeMap<String, Fp>,
    }

    fn points() -> impl Strategy<Value = Vec<Point>> {
        let one = (
            prop::collection::vec((-40i64..40, 1i64..=11), 8),
            prop::collection::vec(0u64..PRIME, 8),
        )
            .prop_map(|(q, p)| Point {
                q: VARS
                    .iter()
                    .zip(q)
                    .map(|(v, (n, d))| (v.to_string(), BigRational::new(n.into(), d.into())))
                    .collect(),
                p: VARS
                    .iter()
                    .zip(p)
                    .map(|(v, r)| (v.to_string(), Residue(r)))
                    .collect(),
            });
        prop::collection::vec(one, 2)
    }

    /// The oracle: Σ c · Π xᵉ over the printed terms, powers by repeated multiplication.
    fn naive(p: &Poly, at: &BTreeMap<String, BigRational>) -> BigRational {
        p.terms()
            .map(|(m, c)| {
                m.factors()
                    .iter()
                    .fold(c, |t, (v, e)| (0..*e).fold(t, |t, _| t * &at[v]))
            })
            .fold(<BigRational as Zero>::zero(), |s, t| s + t)
    }

    /// The value over 𝔽ₚ (the content's denominator is a product of small numbers and
    /// powers of 2⁶³ + 1, never a multiple of p).
    fn modp(p: &Poly, at: &BTreeMap<String, Fp>) -> Fp {
        let xs: Vec<Fp> = p.variables().iter().map(|v| at[v]).collect();
        eval_poly(p, &xs).unwrap_or(Residue(0))
    }

    fn pow_q(x: &BigRational, e: u32) -> BigRational {
        (0..e).fold(<BigRational as One>::one(), |t, _| t * x)
    }

    /// Sum, difference, product, power and coefficients of `a`, `b` at every point.
    fn ring_at(a: &Poly, b: &Poly, e: u32, pts: &[Point]) -> Result<(), TestCaseError> {
        let (ab, ap) = (a * b, a.pow(e));
        let (s, d) = (a + b, a - b);
        for pt in pts {
            let (x, y) = (naive(a, &pt.q), naive(b, &pt.q));
            prop_assert_eq!(naive(&ab, &pt.q), &x * &y);
            prop_assert_eq!(naive(&s, &pt.q), &x + &y);
            prop_assert_eq!(naive(&d, &pt.q), &x - &y);
            prop_assert_eq!(naive(&ap, &pt.q), pow_q(&x, e));
            prop_assert_eq!(ab.eval(&pt.q), Some(&x * &y));
            let (xp, yp) = (modp(a, &pt.p), modp(b, &pt.p));
            prop_assert_eq!(modp(&ab, &pt.p), xp.mul(&yp));
            prop_assert_eq!(modp(&d, &pt.p), xp.sub(&yp));
            prop_assert_eq!(modp(&ap, &pt.p), xp.pow(u64::from(e)));
            for v in ["a", "c", "x"] {
                let k = a.coefficients_in(v);
                let back = k
                    .iter()
                    .enumerate()
                    .fold(<BigRational as Zero>::zero(), |t, (i, c)| {
                        t + naive(c, &pt.q) * pow_q(&pt.q[v], i as u32)
                    });
                prop_assert_eq!(back, x.clone());
            }
        }
        prop_assert_eq!(&ab, &(b * a));
        prop_assert_eq!(Poly::parse(&ab.to_string()).ok(), Some(ab.clone()));
        Ok(())
    }

    /// `a·b / b = a`; `(a·b + c) / b` refused when `c ≠ 0` has lower degree than `b` (b
    /// cannot divide c, so not the sum); any quotient given is exact.
    fn division(a: &Poly, b: &Poly, c: &Poly, pts: &[Point]) -> Result<(), TestCaseError> {
        let ab = a * b;
        prop_assert_eq!(ab.div_exact(b), (!b.is_zero()).then(|| a.clone()));
        let n = &ab + c;
        let q = n.div_exact(b);
        if !c.is_zero() && c.degree() < b.degree() {
            prop_assert!(q.is_none(), "{} / {} accepted", n, b);
        }
        if let Some(q) = q {
            for pt in pts {
                prop_assert_eq!(naive(&q, &pt.q) * naive(b, &pt.q), naive(&n, &pt.q));
            }
        }
        Ok(())
    }

    /// Substituting `q` for `v` then evaluating = evaluating with v := q(point).
    fn substitution(a: &Poly, q: &Poly, v: &str, pts: &[Point]) -> Result<(), TestCaseError> {
        let s = a.substitute(v, q);
        for pt in pts {
            let mut at = pt.q.clone();
            at.insert(v.into(), naive(q, &pt.q));
            prop_assert_eq!(naive(&s, &pt.q), naive(a, &at));
            let mut ap = pt.p.clone();
            ap.insert(v.into(), modp(q, &pt.p));
            prop_assert_eq!(modp(&s, &pt.p), modp(a, &ap));
        }
        Ok(())
    }

    /// g = gcd(a·c, b·c): c divides g, g divides both (quotients exact, checked by
    /// multiplying back); (a·c)/(b·c) in lowest terms is the same function at every point
    /// and its denominator is no larger than b's.
    fn gcd_planted(a: &Poly, b: &Poly, c: &Poly, pts: &[Point]) -> Result<(), TestCaseError> {
        let (x, y) = (a * c, b * c);
        let g = x.gcd(&y);
        if x.is_zero() && y.is_zero() {
            prop_assert!(g.is_zero());
            return Ok(());
        }
        for side in [&x, &y] {
            let q = side.div_exact(&g);
            prop_assert!(
                q.as_ref().is_some_and(|q| &(q * &g) == side),
                "{} ∤ {}",
                g,
                side
            );
        }
        if !c.is_zero() {
            prop_assert!(g.div_exact(c).is_some(), "{} ∤ {}", c, g);
        }
        let (hx, hy) = (x.primitive().1, y.primitive().1);
        if x.ring() == y.ring()
            && x.len() + y.len() <= 40
            && let Some(h) = hx.gcd_heuristic(hy)
        {
            prop_assert_eq!(h.primitive().1, hx.gcd_prs(hy).primitive().1);
        }
        if y.is_zero() {
            return Ok(());
        }
        let r = RatFn {
            num: x.clone(),
            den: y.clone(),
        }
        .reduced();
        prop_assert!(r.den.degree() <= b.degree(), "{} not cancelled by {}", y, c);
        prop_assert_eq!(&r.num * b, a * &r.den);
        for pt in pts {
            let dy = naive(&y, &pt.q);
            if !dy.is_zero() {
                prop_assert_eq!(r.eval(&pt.q), Some(naive(&x, &pt.q) / dy));
            }
        }
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: cases(64), rng_seed: proptest::test_runner::RngSeed::Fixed(11), ..ProptestConfig::default() })]

        #[test]
        fn ring_operations_match_evaluation(a in sparse(8, 130), b in sparse(8, 130), e in 0u32..4, pts in points()) {
            ring_at(&poly(&a), &poly(&b), e, &pts)?;
        }

        #[test]
        fn dense_ring_operations_match_evaluation(a in dense(4, 24, 10), b in dense(4, 24, 10), e in 0u32..3, pts in points()) {
            ring_at(&poly(&a), &poly(&b), e, &pts)?;
        }

        #[test]
        fn evaluation_matches_the_printed_terms(a in sparse(10, 130), d in dense(1, 30, 12), pts in points()) {
            for p in [poly(&a), poly(&d)] {
                for pt in &pts {
                    prop_assert_eq!(p.eval(&pt.q), Some(naive(&p, &pt.q)));
                }
            }
        }

        #[test]
        fn substitution_matches_evaluation(a in sparse(7, 8), q in sparse(4, 6), v in 0usize..8, pts in points()) {
            substitution(&poly(&a), &poly(&q), VARS[v], &pts)?;
        }

        #[test]
        fn dense_substitution_matches_evaluation(a in dense(3, 12, 6), q in dense(1, 3, 4), v in 0usize..3, pts in points()) {
            substitution(&poly(&a), &poly(&q), VARS[v], &pts)?;
        }

        #[test]
        fn exact_division_recovers_the_factor(a in sparse(7, 130), b in sparse(6, 130), c in sparse(3, 130), pts in points()) {
            division(&poly(&a), &poly(&b), &poly(&c), &pts)?;
        }

        #[test]
        fn dense_exact_division_recovers_the_factor(a in dense(2, 20, 10), b in dense(2, 16, 10), c in dense(1, 6, 10), pts in points()) {
            division(&poly(&a), &poly(&b), &poly(&c), &pts)?;
        }

        #[test]
        fn gcd_contains_the_planted_factor(a in sparse(5, 12), b in sparse(5, 12), c in sparse(4, 12), pts in points()) {
            gcd_planted(&poly(&a), &poly(&b), &poly(&c), &pts)?;
        }

        #[test]
        fn dense_gcd_contains_the_planted_factor(a in dense(1, 4, 5), b in dense(1, 4, 5), c in dense(1, 4, 5), pts in points()) {
            gcd_planted(&poly(&a), &poly(&b), &poly(&c), &pts)?;
        }
    }
}
