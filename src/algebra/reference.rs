//! The first polynomial engine (a map from name-based monomials to rationals), kept only
//! as the reference of the differential tests of [`super::Poly`].

#![allow(dead_code)]

use std::collections::BTreeMap;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// A monomial: variables with positive exponents, sorted by variable name.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Default)]
pub struct Monomial(Vec<(String, u32)>);

impl Monomial {
    /// The monomial `1`.
    pub fn one() -> Self {
        Monomial(Vec::new())
    }

    /// A single variable to the first power.
    pub fn var(name: &str) -> Self {
        Monomial(vec![(name.to_string(), 1)])
    }

    /// Total degree.
    pub fn degree(&self) -> u32 {
        self.0.iter().map(|(_, e)| e).sum()
    }

    /// Exponent of `name` (0 if absent).
    pub fn exponent(&self, name: &str) -> u32 {
        self.0
            .iter()
            .find(|(v, _)| v == name)
            .map(|(_, e)| *e)
            .unwrap_or(0)
    }

    /// The monomial with `name` removed.
    fn without(&self, name: &str) -> Monomial {
        Monomial(self.0.iter().filter(|(v, _)| v != name).cloned().collect())
    }

    /// Variables and exponents.
    pub fn factors(&self) -> &[(String, u32)] {
        &self.0
    }

    fn mul(&self, other: &Monomial) -> Monomial {
        let mut out: Vec<(String, u32)> = Vec::with_capacity(self.0.len() + other.0.len());
        let (mut i, mut j) = (0, 0);
        while i < self.0.len() || j < other.0.len() {
            match (self.0.get(i), other.0.get(j)) {
                (Some(a), Some(b)) if a.0 == b.0 => {
                    out.push((a.0.clone(), a.1 + b.1));
                    i += 1;
                    j += 1;
                }
                (Some(a), Some(b)) if a.0 < b.0 => {
                    out.push(a.clone());
                    i += 1;
                }
                (Some(_), Some(b)) => {
                    out.push(b.clone());
                    j += 1;
                }
                (Some(a), None) => {
                    out.push(a.clone());
                    i += 1;
                }
                (None, Some(b)) => {
                    out.push(b.clone());
                    j += 1;
                }
                (None, None) => break,
            }
        }
        Monomial(out)
    }
}

/// A polynomial over ℚ in named variables.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct RefPoly {
    terms: BTreeMap<Monomial, BigRational>,
}

impl RefPoly {
    /// The zero polynomial.
    pub fn zero() -> Self {
        RefPoly::default()
    }

    /// A rational constant.
    pub fn constant(c: BigRational) -> Self {
        let mut p = RefPoly::zero();
        p.add_term(Monomial::one(), c);
        p
    }

    /// An integer constant.
    pub fn int(c: i64) -> Self {
        RefPoly::constant(BigRational::from_integer(BigInt::from(c)))
    }

    /// The variable `name`.
    pub fn var(name: &str) -> Self {
        let mut p = RefPoly::zero();
        p.add_term(Monomial::var(name), BigRational::one());
        p
    }

    /// The monomial `m` with coefficient 1.
    pub fn from_monomial(m: Monomial) -> Self {
        let mut p = RefPoly::zero();
        p.add_term(m, BigRational::one());
        p
    }

    /// Whether this is the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.terms.is_empty()
    }

    /// Number of terms.
    pub fn len(&self) -> usize {
        self.terms.len()
    }

    /// Whether there are no terms (same as [`RefPoly::is_zero`]).
    pub fn is_empty(&self) -> bool {
        self.terms.is_empty()
    }

    /// Terms, in canonical order.
    pub fn terms(&self) -> impl Iterator<Item = (&Monomial, &BigRational)> {
        self.terms.iter()
    }

    fn add_term(&mut self, m: Monomial, c: BigRational) {
        if c.is_zero() {
            return;
        }
        let entry = self.terms.entry(m);
        match entry {
            std::collections::btree_map::Entry::Vacant(v) => {
                v.insert(c);
            }
            std::collections::btree_map::Entry::Occupied(mut o) => {
                let s = o.get() + c;
                if s.is_zero() {
                    o.remove();
                } else {
                    *o.get_mut() = s;
                }
            }
        }
    }

    /// Multiply by a rational constant.
    pub fn scale(&self, c: &BigRational) -> RefPoly {
        if c.is_zero() {
            return RefPoly::zero();
        }
        RefPoly {
            terms: self.terms.iter().map(|(m, k)| (m.clone(), k * c)).collect(),
        }
    }

    /// Integer power.
    pub fn pow(&self, e: u32) -> RefPoly {
        let mut result = RefPoly::int(1);
        let mut base = self.clone();
        let mut e = e;
        while e > 0 {
            if e & 1 == 1 {
                result = &result * &base;
            }
            e >>= 1;
            if e > 0 {
                base = &base * &base;
            }
        }
        result
    }

    /// All variable names, sorted.
    pub fn variables(&self) -> Vec<String> {
        let mut v: Vec<String> = self
            .terms
            .keys()
            .flat_map(|m| m.0.iter().map(|(n, _)| n.clone()))
            .collect();
        v.sort();
        v.dedup();
        v
    }

    /// Total degree (0 for constants and for zero).
    pub fn degree(&self) -> u32 {
        self.terms.keys().map(Monomial::degree).max().unwrap_or(0)
    }

    /// Degree in one variable.
    pub fn degree_in(&self, name: &str) -> u32 {
        self.terms
            .keys()
            .map(|m| m.exponent(name))
            .max()
            .unwrap_or(0)
    }

    /// Coefficients with respect to `name`: `self = Σ coeffs[e] · name^e`.
    pub fn coefficients_in(&self, name: &str) -> Vec<RefPoly> {
        let d = self.degree_in(name) as usize;
        let mut out = vec![RefPoly::zero(); d + 1];
        for (m, c) in &self.terms {
            out[m.exponent(name) as usize].add_term(m.without(name), c.clone());
        }
        out
    }

    /// Substitute the polynomial `value` for the variable `name`.
    pub fn substitute(&self, name: &str, value: &RefPoly) -> RefPoly {
        let mut out = RefPoly::zero();
        let mut powers: Vec<RefPoly> = vec![RefPoly::int(1)];
        for (m, c) in &self.terms {
            let e = m.exponent(name) as usize;
            while powers.len() <= e {
                let next = powers.last().map(|p| p * value).unwrap_or_default();
                powers.push(next);
            }
            let rest = RefPoly {
                terms: BTreeMap::from([(m.without(name), c.clone())]),
            };
            out = &out + &(&rest * &powers[e]);
        }
        out
    }

    /// Evaluate at a rational point; `None` if a variable has no value.
    pub fn eval(&self, values: &BTreeMap<String, BigRational>) -> Option<BigRational> {
        let mut sum = BigRational::zero();
        for (m, c) in &self.terms {
            let mut t = c.clone();
            for (v, e) in &m.0 {
                let x = values.get(v)?;
                t *= num_traits::pow(x.clone(), *e as usize);
            }
            sum += t;
        }
        Some(sum)
    }

    /// Evaluate in floating point; `None` if a variable has no value.
    pub fn eval_f64(&self, values: &BTreeMap<String, f64>) -> Option<f64> {
        let mut sum = 0.0;
        for (m, c) in &self.terms {
            let mut t = c.to_f64()?;
            for (v, e) in &m.0 {
                t *= values.get(v)?.powi(*e as i32);
            }
            sum += t;
        }
        Some(sum)
    }

    /// The leading term in graded lexicographic order (total degree, then the exponents of
    /// the variables in alphabetical order): a monomial order, so division terminates.
    fn leading(&self) -> Option<(&Monomial, &BigRational)> {
        self.terms.iter().max_by(|(a, _), (b, _)| {
            a.degree().cmp(&b.degree()).then_with(|| {
                // the first variable (alphabetically) whose exponents differ decides
                let mut vars: Vec<&String> = a.0.iter().chain(&b.0).map(|(v, _)| v).collect();
                vars.sort();
                vars.dedup();
                vars.iter()
                    .map(|v| a.exponent(v).cmp(&b.exponent(v)))
                    .find(|o| o.is_ne())
                    .unwrap_or(std::cmp::Ordering::Equal)
            })
        })
    }

    /// `self / d` when `d` divides `self` exactly (multivariate division with remainder
    /// zero), else `None`.
    pub fn div_exact(&self, d: &RefPoly) -> Option<RefPoly> {
        let (dm, dc) = d.leading()?;
        let (dm, dc) = (dm.clone(), dc.clone());
        let mut r = self.clone();
        let mut q = RefPoly::zero();
        while let Some((rm, rc)) = r.leading() {
            // the quotient of the leading monomials, if it is a monomial
            let mut t = Vec::new();
            for (v, e) in &rm.0 {
                let de = dm.exponent(v);
                if de > *e {
                    return None;
                }
                if *e > de {
                    t.push((v.clone(), e - de));
                }
            }
            if dm.0.iter().any(|(v, _)| rm.exponent(v) == 0) {
                return None;
            }
            let term = RefPoly {
                terms: BTreeMap::from([(Monomial(t), rc / &dc)]),
            };
            r = &r - &(&term * d);
            q = &q + &term;
        }
        Some(q)
    }

    /// If `self = k · other` for a non-zero rational `k`, return `k`.
    pub fn ratio_to(&self, other: &RefPoly) -> Option<BigRational> {
        let (m0, c0) = other.terms.iter().next()?;
        let k = self.terms.get(m0)? / c0;
        (k != BigRational::zero() && *self == other.scale(&k)).then_some(k)
    }
}

impl Add for &RefPoly {
    type Output = RefPoly;
    fn add(self, rhs: &RefPoly) -> RefPoly {
        let mut out = self.clone();
        for (m, c) in &rhs.terms {
            out.add_term(m.clone(), c.clone());
        }
        out
    }
}

impl Sub for &RefPoly {
    type Output = RefPoly;
    fn sub(self, rhs: &RefPoly) -> RefPoly {
        let mut out = self.clone();
        for (m, c) in &rhs.terms {
            out.add_term(m.clone(), -c.clone());
        }
        out
    }
}

impl Mul for &RefPoly {
    type Output = RefPoly;
    fn mul(self, rhs: &RefPoly) -> RefPoly {
        let mut out = RefPoly::zero();
        for (m1, c1) in &self.terms {
            for (m2, c2) in &rhs.terms {
                out.add_term(m1.mul(m2), c1 * c2);
            }
        }
        out
    }
}

impl Neg for &RefPoly {
    type Output = RefPoly;
    fn neg(self) -> RefPoly {
        self.scale(&-BigRational::one())
    }
}

impl fmt::Display for RefPoly {
    /// Terms by descending total degree, then by variable order; `0` for zero.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.terms.is_empty() {
            return write!(f, "0");
        }
        let mut terms: Vec<_> = self.terms.iter().collect();
        terms.sort_by(|(a, _), (b, _)| b.degree().cmp(&a.degree()).then_with(|| a.cmp(b)));
        for (i, (m, c)) in terms.iter().enumerate() {
            let neg = c.is_negative();
            let abs = c.abs();
            match (i, neg) {
                (0, true) => write!(f, "-")?,
                (0, false) => {}
                (_, true) => write!(f, " - ")?,
                (_, false) => write!(f, " + ")?,
            }
            let mono: Vec<String> =
                m.0.iter()
                    .map(|(v, e)| {
                        if *e == 1 {
                            v.clone()
                        } else {
                            format!("{v}^{e}")
                        }
                    })
                    .collect();
            if mono.is_empty() {
                write!(f, "{abs}")?;
            } else if abs.is_one() {
                write!(f, "{}", mono.join("*"))?;
            } else {
                write!(f, "{abs}*{}", mono.join("*"))?;
            }
        }
        Ok(())
    }
}

/// Differential tests: the packed engine against this one, on random polynomials in up to
/// eight variables (sparse, with exponents that force wider packings) and in three
/// variables at high degree (dense), with small and word-overflowing coefficients. Both
/// print canonically, so equal text is equal polynomials.
#[cfg(test)]
mod differential {
    use super::RefPoly;
    use crate::algebra::mpoly::{mul_array, mul_heap};
    use crate::algebra::{Monomial, Poly, RatFn};
    use num_bigint::BigInt;
    use num_rational::BigRational;
    use proptest::prelude::*;
    use std::collections::BTreeMap;

    const VARS: [&str; 8] = ["a", "b", "c", "d_1", "u", "v", "w", "x"];

    type Terms = Vec<(i64, i64, bool, Vec<u32>)>;

    /// `PROPTEST_CASES` when set (a long run), else `default`.
    fn cases(default: u32) -> u32 {
        std::env::var("PROPTEST_CASES")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or(default)
    }

    /// Sparse terms in the eight variables: most exponents 0, some up to 3, a few up to
    /// `high` (130: total degrees past 127 need 16-bit fields, their products more).
    fn sparse(max: usize, high: u32) -> impl Strategy<Value = Terms> {
        let e = prop_oneof![12 => Just(0u32), 6 => 1u32..=3, 1 => 4u32..=high];
        prop::collection::vec(
            (
                (-9i64..=9),
                (1i64..=4),
                prop::bool::weighted(0.2),
                prop::collection::vec(e, 8),
            ),
            0..max,
        )
    }

    /// Dense terms in three variables of degree up to 10 each.
    fn dense(min: usize, max: usize) -> impl Strategy<Value = Terms> {
        prop::collection::vec(
            (
                (-9i64..=9),
                (1i64..=3),
                prop::bool::weighted(0.1),
                prop::collection::vec(0u32..=10, 3),
            ),
            min..max,
        )
    }

    /// The same polynomial in both engines; a flagged coefficient is multiplied by 2⁶³ + 1.
    fn both(t: &Terms) -> (Poly, RefPoly) {
        let (mut p, mut r) = (Poly::zero(), RefPoly::zero());
        for (n, d, big, e) in t {
            let mut c = BigRational::new((*n).into(), (*d).into());
            if *big {
                c *= BigRational::from_integer(BigInt::from(i64::MAX) + 2);
            }
            let (mut pm, mut rm) = (Poly::constant(c.clone()), RefPoly::constant(c));
            for (v, k) in VARS.iter().zip(e) {
                pm = &pm * &Poly::var(v).pow(*k);
                rm = &rm * &RefPoly::var(v).pow(*k);
            }
            p = &p + &pm;
            r = &r + &rm;
        }
        (p, r)
    }

    fn same(p: &Poly, r: &RefPoly) -> Result<(), TestCaseError> {
        prop_assert_eq!(p.to_string(), r.to_string());
        let pt: Vec<(Monomial, BigRational)> = p.terms().collect();
        prop_assert_eq!(pt.len(), r.len());
        prop_assert_eq!((p.degree(), p.variables()), (r.degree(), r.variables()));
        Ok(())
    }

    fn point(x: &[(i64, i64)]) -> BTreeMap<String, BigRational> {
        VARS.iter()
            .zip(x)
            .map(|(n, (a, b))| (n.to_string(), BigRational::new((*a).into(), (*b).into())))
            .collect()
    }

    /// Ring operations, powers, coefficients and ratios of `a`, `b` in both engines.
    fn ring_agrees(a: &Terms, b: &Terms, e: u32) -> Result<(), TestCaseError> {
        let ((pa, ra), (pb, rb)) = (both(a), both(b));
        same(&pa, &ra)?;
        same(&(&pa * &pb), &(&ra * &rb))?;
        same(&(&pa + &pb), &(&ra + &rb))?;
        same(&(&pa - &pb), &(&ra - &rb))?;
        same(&pa.pow(e), &ra.pow(e))?;
        for v in VARS {
            prop_assert_eq!(pa.degree_in(v), ra.degree_in(v));
            let (pc, rc) = (pa.coefficients_in(v), ra.coefficients_in(v));
            prop_assert_eq!(pc.len(), rc.len());
            for (x, y) in pc.iter().zip(&rc) {
                same(x, y)?;
            }
        }
        prop_assert_eq!(pa.ratio_to(&pb), ra.ratio_to(&rb));
        let k = BigRational::new((-3).into(), 7.into());
        prop_assert_eq!(pa.scale(&k).ratio_to(&pa), ra.scale(&k).ratio_to(&ra));
        Ok(())
    }

    /// `a·b / b = a`; `(a·b + c) / b` refused when `c ≠ 0` has lower degree than `b` (then b
    /// cannot divide c, so not the sum either).
    fn division_agrees(a: &Terms, b: &Terms, c: &Terms) -> Result<(), TestCaseError> {
        let ((pa, ra), (pb, rb), (pc, rc)) = (both(a), both(b), both(c));
        let (pab, rab) = (&pa * &pb, &ra * &rb);
        let (pq, rq) = (pab.div_exact(&pb), rab.div_exact(&rb));
        prop_assert_eq!(pq.is_some(), rq.is_some());
        prop_assert_eq!(pq.is_some(), !pb.is_zero());
        if let (Some(pq), Some(rq)) = (&pq, &rq) {
            same(pq, rq)?;
            prop_assert!(pb.is_zero() || *pq == pa);
        }
        let (pn, rn) = (&pab + &pc, &rab + &rc);
        let (x, y) = (pn.div_exact(&pb), rn.div_exact(&rb));
        prop_assert_eq!(
            x.as_ref().map(|p| p.to_string()),
            y.as_ref().map(|p| p.to_string())
        );
        if !pc.is_zero() && pc.degree() < pb.degree() {
            prop_assert!(x.is_none(), "{} / {} accepted", pn, pb);
        }
        Ok(())
    }

    /// The gcd of `a·c` and `b·c` is divisible by `c` and divides both; `(a·c)/(b·c)` in
    /// lowest terms is the same function with a denominator no larger than `b`'s.
    fn gcd_agrees(a: &Terms, b: &Terms, c: &Terms) -> Result<(), TestCaseError> {
        let ((pa, ra), (pb, rb), (pc, rc)) = (both(a), both(b), both(c));
        let (x, y) = (&pa * &pc, &pb * &pc);
        let Some(g) = x.gcd(&y) else {
            return Ok(());
        };
        let rg = RefPoly::from_text(&g);
        if !x.is_zero() || !y.is_zero() {
            prop_assert!((&ra * &rc).div_exact(&rg).is_some(), "{} ∤ {}", g, x);
            prop_assert!((&rb * &rc).div_exact(&rg).is_some(), "{} ∤ {}", g, y);
        }
        if !x.is_zero() {
            prop_assert!(rg.div_exact(&rc).is_some(), "{} ∤ {}", pc, g);
        }
        if !y.is_zero() {
            let f = RatFn { num: x.clone(), den: y.clone() };
            let r = f.reduced();
            let (rn, rd) = (RefPoly::from_text(&r.num), RefPoly::from_text(&r.den));
            let (rx, ry) = (&ra * &rc, &rb * &rc);
            prop_assert_eq!((&rn * &ry).to_string(), (&rx * &rd).to_string());
            prop_assert!(r.den.degree() <= pb.degree(), "{} not cancelled by {}", y, pc);
        }
        Ok(())
    }

    fn eval_agrees(a: &Terms, q: &Terms, v: usize, x: &[(i64, i64)]) -> Result<(), TestCaseError> {
        let ((pa, ra), (pq, rq)) = (both(a), both(q));
        same(&pa.substitute(VARS[v], &pq), &ra.substitute(VARS[v], &rq))?;
        let at = point(x);
        prop_assert_eq!(pa.eval(&at), ra.eval(&at));
        let atf: BTreeMap<String, f64> = VARS
            .iter()
            .zip(x)
            .map(|(n, (a, b))| (n.to_string(), *a as f64 / *b as f64))
            .collect();
        prop_assert_eq!(
            pa.eval_f64(&atf).map(f64::to_bits),
            ra.eval_f64(&atf).map(f64::to_bits)
        );
        Ok(())
    }

    fn rationals() -> impl Strategy<Value = Vec<(i64, i64)>> {
        prop::collection::vec(((-30i64..30), (1i64..=9)), 8)
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: cases(128), rng_seed: proptest::test_runner::RngSeed::Fixed(11), ..ProptestConfig::default() })]

        #[test]
        fn ring_operations_agree(a in sparse(8, 130), b in sparse(8, 130), e in 0u32..4) {
            ring_agrees(&a, &b, e)?;
        }

        #[test]
        fn dense_ring_operations_agree(a in dense(4, 24), b in dense(4, 24), e in 0u32..3) {
            ring_agrees(&a, &b, e)?;
        }

        #[test]
        fn substitution_and_evaluation_agree(a in sparse(7, 8), q in sparse(4, 6), v in 0usize..8, x in rationals()) {
            eval_agrees(&a, &q, v, &x)?;
        }

        #[test]
        fn dense_substitution_and_evaluation_agree(a in dense(3, 12), q in dense(1, 4), v in 0usize..3, x in rationals()) {
            eval_agrees(&a, &q, v, &x)?;
        }

        #[test]
        fn exact_division_agrees(a in sparse(7, 130), b in sparse(6, 130), c in sparse(3, 130)) {
            division_agrees(&a, &b, &c)?;
        }

        #[test]
        fn dense_exact_division_agrees(a in dense(2, 20), b in dense(2, 16), c in dense(1, 6)) {
            division_agrees(&a, &b, &c)?;
        }

        #[test]
        fn gcd_is_a_common_divisor_the_factor_divides(a in sparse(5, 130), b in sparse(5, 130), c in sparse(4, 130)) {
            gcd_agrees(&a, &b, &c)?;
        }

        #[test]
        fn dense_gcd_is_a_common_divisor_the_factor_divides(a in dense(1, 6), b in dense(1, 6), c in dense(1, 5)) {
            gcd_agrees(&a, &b, &c)?;
        }

        #[test]
        fn heap_and_array_products_agree(a in dense(4, 30), b in dense(4, 30)) {
            let ((pa, _), (pb, _)) = (both(&a), both(&b));
            let (x, y) = (pa.primitive().1.clone(), pb.primitive().1.clone());
            // in a common ring: the product of the Polys aligns them
            let z = &pa * &pb;
            if x.nvars() == y.nvars() && x.nvars() == z.ring().nvars() {
                let heap = mul_heap(&x, &y);
                prop_assert_eq!(&heap, z.primitive().1);
                if let Some(arr) = mul_array(&x, &y) {
                    prop_assert_eq!(arr, heap);
                }
            }
        }
    }

    impl RefPoly {
        /// The reference image of a packed polynomial, term by term.
        fn from_text(p: &Poly) -> RefPoly {
            p.terms().fold(RefPoly::zero(), |acc, (m, c)| {
                &acc + &RefPoly::from_monomial(super::Monomial(m.factors().to_vec())).scale(&c)
            })
        }
    }
}
