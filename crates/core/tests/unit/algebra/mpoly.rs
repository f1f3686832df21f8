//! Tests of `orthocheck_core::algebra::mpoly`.

use orthocheck_core::algebra::mpoly::coeff::Coef;
use orthocheck_core::algebra::mpoly::mul::{mul_array, mul_heap, mul_with, MulMethod};
use orthocheck_core::algebra::mpoly::ring::Ring;
mod coeff;
mod monomial;

use orthocheck_core::algebra::mpoly::*;

fn fateman(n: u32) -> MPoly {
    let r = Ring::new(&["x", "y", "z", "t"]);
    let one = MPoly::constant(4, Coef::Small(1));
    let s = r
        .names()
        .iter()
        .fold(one, |acc, v| &acc + &r.var(v).unwrap_or(MPoly::zero(4)));
    s.pow(n)
}

#[test]
fn heap_and_array_products_agree() {
    let p = fateman(6);
    let q = &p + &MPoly::constant(4, Coef::Small(1));
    let heap = mul_heap(&p, &q);
    let array = mul_array(&p, &q).unwrap();
    assert_eq!(heap, array);
    assert_eq!(heap.len(), 1820); // the monomials of degree ≤ 12 in four variables
    assert_eq!(heap.div_exact(&p), Some(q.clone()));
    assert_eq!(
        (&heap + &MPoly::constant(4, Coef::Small(1))).div_exact(&p),
        None
    );
}

#[test]
fn a_large_array_product_is_the_same_on_any_number_of_threads() {
    // 2380² term products: above the size from which the chunks are shared by the threads
    let p = fateman(13);
    let q = &p + &MPoly::constant(4, Coef::Small(1));
    let on = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| mul_array(&p, &q).unwrap())
    };
    let one = on(1);
    assert_eq!(one, on(2));
    assert_eq!(one, mul_with(&p, &q, MulMethod::Hash));
    assert_eq!(one.len(), 27405); // the monomials of degree ≤ 26 in four variables
}

#[test]
fn big_coefficients_multiply_and_divide() {
    let r = Ring::new(&["x", "y"]);
    let x = r.var("x").unwrap();
    let big = MPoly::constant(2, Coef::Small(i64::MAX));
    let p = &(&x * &big) + &r.var("y").unwrap();
    let p3 = p.pow(3);
    assert!(p3.coefs().iter().any(|c| matches!(c, Coef::Big(_))));
    assert_eq!(p3.div_exact(&p), Some(p.pow(2)));
    assert_eq!(mul_heap(&p.pow(2), &p), p3);
}

#[test]
fn gcd_recovers_a_common_factor() {
    let r = Ring::new(&["a", "b", "c"]);
    let v = |n: &str| r.var(n).unwrap();
    let two = MPoly::constant(3, Coef::Small(2));
    let g = &(&v("a") * &v("b")) - &(&two * &v("c"));
    let a = &g.pow(2) * &(&v("a") + &two);
    let b = &g * &(&v("b") - &v("c")).pow(2);
    assert_eq!(a.gcd(&b), g.clone());
    assert_eq!(a.gcd_prs(&b), g.clone());
    let six = MPoly::constant(3, Coef::Small(6));
    assert_eq!((&a * &six).gcd(&(&b * &(&two * &two))), &g * &two);
    assert_eq!((&a * &six).gcd_prs(&(&b * &(&two * &two))), &g * &two);
    assert_eq!(v("a").gcd(&v("b")), MPoly::constant(3, Coef::Small(1)));
    assert_eq!(v("a").gcd_prs(&v("b")), MPoly::constant(3, Coef::Small(1)));
}

/// Degree 300 with 64-bit coefficients: the first image would pass the heuristic's size
/// limit, so it gives up at once, and the answer comes from the remainder sequence.
#[test]
fn gcd_falls_back_when_the_heuristic_gives_up() {
    let r = Ring::new(&["x", "y"]);
    let (x, y) = (r.var("x").unwrap(), r.var("y").unwrap());
    let one = MPoly::constant(2, Coef::Small(1));
    let k = MPoly::constant(2, Coef::Small(1 << 62));
    let g = &(&x + &y) + &one;
    let a = &g * &(&(&k * &x.pow(300)) + &y);
    let b = &g * &(&x.pow(300) - &(&k * &y));
    assert_eq!(a.gcd_heuristic(&b), None);
    assert_eq!(a.gcd(&b), g.clone());
    assert_eq!(a.gcd(&(&b * &y)), g.clone());
    assert_eq!((&a * &y.pow(2)).gcd(&(&b * &y)), &g * &y);
    // coprime after the planted factor is removed
    assert_eq!(a.gcd(&(&b + &one)), one);
}

#[test]
fn substitution_and_evaluation() {
    let r = Ring::new(&["x", "y"]);
    let (x, y) = (r.var("x").unwrap(), r.var("y").unwrap());
    let p = &x.pow(3) + &y;
    let q = p.substitute(0, &(&y + &MPoly::constant(2, Coef::Small(1))));
    let at = [num_bigint::BigInt::from(5), num_bigint::BigInt::from(7)];
    assert_eq!(q.eval(&at), num_bigint::BigInt::from(8 * 8 * 8 + 7));
    assert_eq!(r.display(&q), "y^3 + 3*y^2 + 4*y + 1");
}

mod array_against_heap {
    use super::*;
    use num_bigint::BigInt;
    use proptest::prelude::*;

    /// `len` terms (repeated exponents add up in `from_terms`) in `nvars` variables,
    /// exponents below `e`, signed coefficients of up to `bits` bits.
    fn terms(nvars: usize, len: std::ops::Range<usize>, e: u32, bits: u32) -> BoxedStrategy<MPoly> {
        let c = (1i64 << (bits - 1)) - 1;
        prop::collection::vec((prop::collection::vec(0..e, nvars), -c..=c), len)
            .prop_map(move |t| {
                let t = t.into_iter().map(|(x, c)| (x, Coef::Small(c))).collect();
                MPoly::from_terms(nvars, t)
            })
            .boxed()
    }

    /// Every exponent vector below `e` in `n` variables, coefficients of up to `bits` bits,
    /// about one in seven of them zero.
    fn full_box(n: u32, e: u32, bits: u32) -> BoxedStrategy<MPoly> {
        let c = (1i64 << (bits - 1)) - 1;
        let len = e.pow(n) as usize;
        prop::collection::vec(prop::option::weighted(0.85, -c..=c), len)
            .prop_map(move |cs| {
                let t = cs
                    .into_iter()
                    .enumerate()
                    .map(|(k, c)| {
                        let x = (0..n).map(|i| (k as u32 / e.pow(i)) % e).collect();
                        (x, Coef::Small(c.unwrap_or(0)))
                    })
                    .collect();
                MPoly::from_terms(n as usize, t)
            })
            .boxed()
    }

    /// The array applies (the shapes below are dense enough) and gives the heap's product.
    fn agree(a: &MPoly, b: &MPoly) -> Result<(), TestCaseError> {
        let p = mul_array(a, b);
        prop_assert!(p.is_some());
        prop_assert_eq!(p, Some(mul_heap(a, b)));
        Ok(())
    }

    fn pair(nvars: usize) -> BoxedStrategy<(MPoly, MPoly)> {
        let e = if nvars == 1 { 1100 } else { 6 };
        (terms(nvars, 55..60, e, 20), terms(nvars, 55..60, e, 20)).boxed()
    }

    /// Every exponent below `e` in two variables, each with coefficient `c`.
    fn square(e: u32, c: i64) -> MPoly {
        let t = (0..e * e)
            .map(|k| (vec![k / e, k % e], Coef::Small(c)))
            .collect();
        MPoly::from_terms(2, t)
    }

    // sums of up to 400 products near 2¹²⁶ wrap an i128 many times, upwards and downwards
    #[test]
    fn sums_beyond_an_i128_are_exact() -> Result<(), TestCaseError> {
        let (top, bottom) = (square(20, i64::MAX), square(20, -i64::MAX));
        agree(&top, &top)?;
        agree(&bottom, &top)?;
        let p = mul_array(&top, &top).ok_or_else(|| TestCaseError::fail("no array"))?;
        let central = (0..p.len()).find(|&t| p.exponents(t) == [19, 19]);
        let expected = Coef::from_big(BigInt::from(i64::MAX).pow(2) * 400);
        prop_assert_eq!(central.map(|t| p.coef(t).clone()), Some(expected));
        Ok(())
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 48, rng_seed: proptest::test_runner::RngSeed::Fixed(5), ..ProptestConfig::default() })]

        // the whole box in one chunk, or one variable alone beyond a chunk
        #[test]
        fn one_chunk((a, b) in (1usize..4).prop_flat_map(pair)) {
            agree(&a, &b)?;
        }

        // chunks indexed by one leading variable (three variables) and by two (four), with
        // coefficients whose products need the upper word
        #[test]
        fn chunks(a in terms(3, 300..400, 16, 40), b in terms(3, 300..400, 16, 40),
                  c in terms(4, 500..700, 11, 50), d in terms(4, 500..700, 11, 50)) {
            agree(&a, &b)?;
            agree(&c, &d)?;
        }

        // rows at least half full (the products row by row): every exponent of a box, about
        // one coefficient in seven zero (gaps inside the rows), one to four variables, one
        // chunk or several, sums within an i128 or beyond; b's exponents one lower, so that
        // the box's sides are even (a power of two among them, whose last slot ends the chunk);
        // rows of up to 19 terms, so that every number of terms sweeping together (one to
        // eight) and several sweeps of a row pair occur
        #[test]
        fn dense_rows((a, b) in (1u32..5, 3u32..20, prop::sample::select(vec![40u32, 62]))
            .prop_flat_map(|(n, e, bits)| {
                let e = match n { 1 => e.max(5), 2 => e.max(4), 3 => e.min(10), _ => e.min(6) };
                (full_box(n, e, bits), full_box(n, e - 1, bits))
            })) {
            agree(&a, &b)?;
        }

        // the hash table against the heap: one word of exponents, two, more than four (a
        // vector), small coefficients, and big ones (sums past an i128 among them)
        #[test]
        fn hash_and_heap_agree((a, b) in (prop::sample::select(vec![2usize, 9, 40]), prop::sample::select(vec![12u32, 62]))
                                   .prop_flat_map(|(n, bits)| (terms(n, 8..60, 4, bits), terms(n, 8..60, 4, bits))),
                               big in any::<bool>()) {
            // a coefficient beyond a word multiplies into the big-integer path
            let a = match big {
                true => &a * &MPoly::constant(a.nvars(), Coef::from_big(BigInt::from(1u8) << 70)),
                false => a,
            };
            prop_assert_eq!(mul_with(&a, &b, MulMethod::Hash), mul_with(&a, &b, MulMethod::Heap));
            // a square over the pairs i ≤ j, and powers by squaring
            prop_assert_eq!(orthocheck_core::algebra::mpoly::square(&b), mul_with(&b, &b, MulMethod::Heap));
            let cube = mul_with(&mul_with(&b, &b, MulMethod::Heap), &b, MulMethod::Heap);
            prop_assert_eq!(b.pow(3), cube);
        }

        // word-sized coefficients: the slots that count their overflows
        #[test]
        fn wide_slots(a in terms(3, 300..400, 16, 62), b in terms(3, 300..400, 16, 62)) {
            agree(&a, &b)?;
        }
    }
}
