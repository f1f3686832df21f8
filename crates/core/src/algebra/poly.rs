//! Exact multivariate polynomials over ℚ with named variables.
//!
//! A [`Poly`] is a rational content times a primitive integer polynomial ([`MPoly`]) in
//! the ring of exactly the variables that occur (sorted by name), the primitive part with a
//! positive leading coefficient and the narrowest packing: a canonical form, so structural
//! equality is polynomial equality. Products need no gcd (Gauss's lemma: the product of
//! primitive polynomials is primitive); sums take one content.

use std::borrow::Cow;
use std::collections::BTreeMap;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};
use std::sync::Arc;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use super::mpoly::{Coef, MPoly, Ring};
use crate::error::ParseError;

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

    /// Variables and exponents.
    pub fn factors(&self) -> &[(String, u32)] {
        &self.0
    }
}

/// A polynomial over ℚ in named variables.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::Poly;
/// let p = Poly::parse("(a + b)^2").unwrap();
/// let q = Poly::parse("a^2 + 2*a*b + b^2").unwrap();
/// assert_eq!(p, q);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Poly {
    ring: Arc<Ring>,
    /// Zero exactly for the zero polynomial.
    content: BigRational,
    prim: MPoly,
}

impl Default for Poly {
    fn default() -> Self {
        Poly::zero()
    }
}

fn empty_ring() -> Arc<Ring> {
    Arc::new(Ring::default())
}

impl Poly {
    /// The zero polynomial.
    pub fn zero() -> Self {
        Poly {
            ring: empty_ring(),
            content: BigRational::zero(),
            prim: MPoly::zero(0),
        }
    }

    /// `scale · p` in canonical form (`p` any integer polynomial in `ring`).
    fn from_parts(ring: Arc<Ring>, scale: BigRational, p: MPoly) -> Poly {
        if p.is_zero() || scale.is_zero() {
            return Poly::zero();
        }
        let (g, pp) = p.into_primitive();
        let used = pp.used();
        let (ring, pp) = if used.iter().all(|u| *u) {
            (ring, pp)
        } else {
            (Arc::new(ring.subset(&used)), pp.drop_vars(&used))
        };
        Poly {
            ring,
            content: scale * BigRational::from_integer(g.to_big()),
            prim: pp,
        }
    }

    /// A rational constant.
    pub fn constant(c: BigRational) -> Self {
        if c.is_zero() {
            return Poly::zero();
        }
        Poly {
            ring: empty_ring(),
            content: c,
            prim: MPoly::constant(0, Coef::Small(1)),
        }
    }

    /// An integer constant.
    pub fn int(c: i64) -> Self {
        Poly::constant(BigRational::from_integer(BigInt::from(c)))
    }

    /// The variable `name`.
    pub fn var(name: &str) -> Self {
        Poly::from_monomial(Monomial::var(name))
    }

    /// The monomial `m` with coefficient 1.
    pub fn from_monomial(m: Monomial) -> Self {
        let names: Vec<&str> = m.0.iter().map(|(v, _)| v.as_str()).collect();
        let ring = Ring::new(&names);
        let mut e = vec![0u32; ring.nvars()];
        for (v, k) in &m.0 {
            if let Some(i) = ring.index(v) {
                e[i] += k;
            }
        }
        let p = MPoly::from_terms(ring.nvars(), vec![(e, Coef::Small(1))]);
        Poly::from_parts(Arc::new(ring), BigRational::one(), p)
    }

    /// The ring of the variables that occur.
    pub fn ring(&self) -> &Ring {
        &self.ring
    }

    /// `(content, primitive part)`: `self = content · primitive`, the primitive part an
    /// integer polynomial in [`Poly::ring`] with coprime coefficients and a positive leading
    /// coefficient (graded lexicographic order, variables by name).
    pub fn primitive(&self) -> (&BigRational, &MPoly) {
        (&self.content, &self.prim)
    }

    /// Whether this is the zero polynomial.
    pub fn is_zero(&self) -> bool {
        self.prim.is_zero()
    }

    /// Number of terms.
    pub fn len(&self) -> usize {
        self.prim.len()
    }

    /// Whether there are no terms (same as [`Poly::is_zero`]).
    pub fn is_empty(&self) -> bool {
        self.prim.is_zero()
    }

    /// Terms, in canonical order (by monomial: variable names, then exponents).
    pub fn terms(&self) -> impl Iterator<Item = (Monomial, BigRational)> + use<> {
        let mut t: Vec<(Monomial, BigRational)> = (0..self.len())
            .map(|i| (self.monomial(i), self.coefficient(i)))
            .collect();
        t.sort_by(|a, b| a.0.cmp(&b.0));
        t.into_iter()
    }

    /// The first term in canonical order (what `terms().next()` gives), found without
    /// listing the others.
    pub fn first_term(&self) -> Option<(Monomial, BigRational)> {
        // a monomial's factors in the ring's order (the names' order): the canonical order
        // compares them pair by pair, a variable's name first, then its exponent
        let factors = |e: &[u32]| {
            e.iter()
                .copied()
                .enumerate()
                .filter(|(_, k)| *k > 0)
                .collect::<Vec<_>>()
        };
        let first = (0..self.len())
            .map(|t| (t, factors(&self.prim.exponents(t))))
            .min_by(|a, b| a.1.cmp(&b.1))?
            .0;
        Some((self.monomial(first), self.coefficient(first)))
    }

    fn monomial(&self, i: usize) -> Monomial {
        let e = self.prim.exponents(i);
        Monomial(
            self.ring
                .names()
                .iter()
                .zip(e)
                .filter(|(_, k)| *k > 0)
                .map(|(n, k)| (n.to_string(), k))
                .collect(),
        )
    }

    fn coefficient(&self, i: usize) -> BigRational {
        &self.content * BigRational::from_integer(self.prim.coef(i).to_big())
    }

    /// Both in the ring of the variables of either.
    fn align<'a>(a: &'a Poly, b: &'a Poly) -> (Arc<Ring>, Cow<'a, MPoly>, Cow<'a, MPoly>) {
        if Arc::ptr_eq(&a.ring, &b.ring) || a.ring == b.ring {
            return (
                a.ring.clone(),
                Cow::Borrowed(&a.prim),
                Cow::Borrowed(&b.prim),
            );
        }
        let (u, ta, tb) = a.ring.union(&b.ring);
        let deg = a.prim.degree().max(b.prim.degree());
        let pack = super::mpoly::Packing::for_degree(u.nvars(), deg);
        let pa = Cow::Owned(a.prim.remap(&ta, pack));
        let pb = Cow::Owned(b.prim.remap(&tb, pack));
        (Arc::new(u), pa, pb)
    }

    /// `self + sign · other` over a common denominator of the contents.
    fn combine<'a>(&'a self, other: &'a Poly, negate: bool) -> Poly {
        let cb = if negate {
            -&other.content
        } else {
            other.content.clone()
        };
        if self.is_zero() {
            return Poly {
                content: cb,
                ..other.clone()
            };
        }
        if other.is_zero() {
            return self.clone();
        }
        let (ring, pa, pb) = Poly::align(self, other);
        let ca = &self.content;
        let l = ca.denom().lcm(cb.denom());
        let fa = ca.numer() * (&l / ca.denom());
        let fb = cb.numer() * (&l / cb.denom());
        let g = fa.gcd(&fb);
        let (fa, fb) = (Coef::from_big(fa / &g), Coef::from_big(fb / &g));
        let scaled = |p: Cow<'a, MPoly>, f: &Coef| match *f == Coef::Small(1) {
            true => p,
            false => Cow::Owned(p.scale(f)),
        };
        let sum = &*scaled(pa, &fa) + &*scaled(pb, &fb);
        Poly::from_parts(ring, BigRational::new(g, l), sum)
    }

    /// Σₖ Πⱼ `products[k][j]` in one ring, the union of the factors' variables: each factor
    /// is lifted into it once, and the products and their sum are taken on the integer parts
    /// with no realignment, over one common denominator of the products' contents, with one
    /// content for the sum. Term by term, pairwise sums of products would each align their
    /// operands' variables, bring their contents to a common denominator and take a content.
    pub fn sum_of_products(products: &[Vec<&Poly>]) -> Poly {
        let nonzero = || products.iter().filter(|p| p.iter().all(|f| !f.is_zero()));
        let names: Vec<Arc<str>> = nonzero()
            .flatten()
            .flat_map(|f| f.ring.names().iter().cloned())
            .collect();
        let ring = Ring::new(&names);
        let degree = |p: &Vec<&Poly>| p.iter().map(|f| f.prim.degree()).sum::<u64>();
        let pack = super::mpoly::Packing::for_degree(
            ring.nvars(),
            nonzero().map(degree).max().unwrap_or(0),
        );
        // each factor lifted once: the same power is a factor of many products
        let mut lifted: Vec<(&Poly, MPoly)> = Vec::new();
        let mut parts: Vec<(BigRational, MPoly)> = Vec::new();
        for p in nonzero() {
            let mut prim = MPoly::constant(ring.nvars(), Coef::Small(1));
            for &f in p {
                let at = match lifted.iter().position(|(g, _)| std::ptr::eq(*g, f)) {
                    Some(at) => at,
                    None => {
                        lifted.push((f, f.prim.remap(&ring.place(&f.ring), pack)));
                        lifted.len() - 1
                    }
                };
                prim = &prim * &lifted[at].1;
            }
            let content = p.iter().fold(BigRational::one(), |c, f| c * &f.content);
            parts.push((content, prim));
        }
        let l = parts
            .iter()
            .fold(BigInt::one(), |l, (c, _)| l.lcm(c.denom()));
        let ints = parts
            .into_iter()
            .map(|(c, p)| p.scale(&Coef::from_big(c.numer() * (&l / c.denom()))))
            .collect();
        match sum_pairwise(ints, |a, b| a + b) {
            Some(sum) => Poly::from_parts(Arc::new(ring), BigRational::new(BigInt::one(), l), sum),
            None => Poly::zero(),
        }
    }

    /// Multiply by a rational constant.
    pub fn scale(&self, c: &BigRational) -> Poly {
        if c.is_zero() || self.is_zero() {
            return Poly::zero();
        }
        Poly {
            content: &self.content * c,
            ..self.clone()
        }
    }

    /// Integer power.
    pub fn pow(&self, e: u32) -> Poly {
        if e == 0 {
            return Poly::int(1);
        }
        Poly {
            ring: self.ring.clone(),
            content: num_traits::pow(self.content.clone(), e as usize),
            prim: self.prim.pow(e),
        }
    }

    /// All variable names, sorted.
    pub fn variables(&self) -> Vec<String> {
        self.ring.names().iter().map(|n| n.to_string()).collect()
    }

    /// Total degree (0 for constants and for zero).
    pub fn degree(&self) -> u32 {
        self.prim.degree() as u32
    }

    /// Degree in one variable.
    pub fn degree_in(&self, name: &str) -> u32 {
        self.ring.index(name).map_or(0, |i| self.prim.degree_in(i))
    }

    /// Coefficients with respect to `name`: `self = Σ coeffs[e] · name^e`.
    pub fn coefficients_in(&self, name: &str) -> Vec<Poly> {
        let Some(i) = self.ring.index(name) else {
            return vec![self.clone()];
        };
        self.prim
            .coefficients_in(i)
            .into_iter()
            .map(|p| Poly::from_parts(self.ring.clone(), self.content.clone(), p))
            .collect()
    }

    /// Substitute the polynomial `value` for the variable `name`: `Σₑ cₑ · valueᵉ` over the
    /// coefficients in `name`, each power a product of the squares `value^(2^k)`.
    pub fn substitute(&self, name: &str, value: &Poly) -> Poly {
        if self.ring.index(name).is_none() {
            return self.clone();
        }
        let mut squares = vec![value.clone()];
        let mut out = Poly::zero();
        for (e, c) in self.coefficients_in(name).iter().enumerate() {
            if c.is_zero() {
                continue;
            }
            let mut term = c.clone();
            let mut k = 0;
            while (e >> k) > 0 {
                if squares.len() <= k {
                    let s = &squares[k - 1] * &squares[k - 1];
                    squares.push(s);
                }
                if (e >> k) & 1 == 1 {
                    term = &term * &squares[k];
                }
                k += 1;
            }
            out = &out + &term;
        }
        out
    }

    /// The polynomial with its variables renamed at once by `to` (`(from, to)` pairs; a name
    /// not listed keeps its name): one pass over the terms, where substituting one variable
    /// after another would multiply polynomials. Names renamed to one name multiply
    /// (x·y with x, y → z is z²).
    pub fn rename(&self, to: &[(&str, &str)]) -> Poly {
        if self.is_zero() {
            return Poly::zero();
        }
        let names: Vec<&str> = self
            .ring
            .names()
            .iter()
            .map(|n| {
                to.iter()
                    .find(|(f, _)| **f == **n)
                    .map_or(&**n, |(_, t)| *t)
            })
            .collect();
        let ring = Ring::new(&names);
        let at: Vec<usize> = names.iter().filter_map(|n| ring.index(n)).collect();
        let terms = (0..self.prim.len())
            .map(|t| {
                let mut e = vec![0u32; ring.nvars()];
                for (i, k) in self.prim.exponents(t).into_iter().enumerate() {
                    e[at[i]] += k;
                }
                (e, self.prim.coef(t).clone())
            })
            .collect();
        let p = MPoly::from_terms(ring.nvars(), terms);
        Poly::from_parts(Arc::new(ring), self.content.clone(), p)
    }

    /// Evaluate at a rational point; `None` if a variable has no value.
    pub fn eval(&self, values: &BTreeMap<String, BigRational>) -> Option<BigRational> {
        let at: Vec<&BigRational> = self
            .ring
            .names()
            .iter()
            .map(|n| values.get(&**n))
            .collect::<Option<_>>()?;
        if self.is_zero() {
            return Some(BigRational::zero());
        }
        let nums: Vec<BigInt> = at.iter().map(|x| x.numer().clone()).collect();
        let dens: Vec<BigInt> = at.iter().map(|x| x.denom().clone()).collect();
        let (n, d) = self.prim.eval_fraction(&nums, &dens);
        Some(&self.content * BigRational::new(n, d))
    }

    /// Evaluate in floating point; `None` if a variable has no value. Term by term in the
    /// canonical order, each coefficient rounded once (the rounding of the first engine).
    pub fn eval_f64(&self, values: &BTreeMap<String, f64>) -> Option<f64> {
        let mut sum = 0.0;
        for (m, c) in self.terms() {
            let mut t = c.to_f64()?;
            for (v, e) in &m.0 {
                t *= values.get(v)?.powi(*e as i32);
            }
            sum += t;
        }
        Some(sum)
    }

    /// `self / d` when `d` divides `self` exactly, else `None`.
    ///
    /// # Example
    /// ```
    /// use orthocheck_core::algebra::Poly;
    /// let p = Poly::parse("x^2 - y^2").unwrap();
    /// assert_eq!(p.div_exact(&Poly::parse("x - y").unwrap()), Some(Poly::parse("x + y").unwrap()));
    /// assert_eq!(p.div_exact(&Poly::parse("x - 2y").unwrap()), None);
    /// ```
    pub fn div_exact(&self, d: &Poly) -> Option<Poly> {
        if d.is_zero() {
            return None;
        }
        if self.is_zero() {
            return Some(Poly::zero());
        }
        // a variable of d that self lacks: d cannot divide (self ≠ 0)
        if d.ring.names().iter().any(|n| self.ring.index(n).is_none()) {
            return None;
        }
        let (ring, pa, pb) = Poly::align(self, d);
        // Gauss: primitive / primitive, when exact over ℚ, is an integer polynomial
        let q = pa.div_exact(&pb)?;
        Some(Poly::from_parts(ring, &self.content / &d.content, q))
    }

    /// The greatest common divisor with content one and a positive leading coefficient (in
    /// the order of [`Poly::primitive`]): always exact (the heuristic gcd, and a primitive
    /// remainder sequence when that gives up). The gcd with zero is the other side made
    /// monic in this sense; gcd(0, 0) = 0.
    ///
    /// # Example
    /// ```
    /// use orthocheck_core::algebra::Poly;
    /// let a = Poly::parse("(x + y)^2 (x - 1)/3").unwrap();
    /// let b = Poly::parse("6(x + y)(y + 2)").unwrap();
    /// assert_eq!(a.gcd(&b), Poly::parse("x + y").unwrap());
    /// ```
    pub fn gcd(&self, other: &Poly) -> Poly {
        let (ring, pa, pb) = Poly::align(self, other);
        let g = pa.gcd(&pb);
        Poly::from_parts(ring, BigRational::one(), g.primitive().1)
    }

    /// If `self = k · other` for a non-zero rational `k`, return `k`.
    pub fn ratio_to(&self, other: &Poly) -> Option<BigRational> {
        let same = !self.is_zero() && self.ring == other.ring && self.prim == other.prim;
        same.then(|| &self.content / &other.content)
    }

    /// Parse an expression with `+ - * ^`, parentheses, rational numbers (`3`, `2.5`, `1/3`
    /// through division by a number) and identifiers (`a`, `a_1`, `A_Cst`). Juxtaposition
    /// multiplies, as in printed formulas: `2(a^2 - b^2)c^2`.
    pub fn parse(text: &str) -> Result<Poly, ParseError> {
        let r = super::parse::parse_rational(text, &BTreeMap::new())?;
        r.to_poly().ok_or(ParseError {
            position: 0,
            message: "only division by a non-zero number".into(),
        })
    }
}

impl Add for &Poly {
    type Output = Poly;
    fn add(self, rhs: &Poly) -> Poly {
        self.combine(rhs, false)
    }
}

impl Sub for &Poly {
    type Output = Poly;
    fn sub(self, rhs: &Poly) -> Poly {
        self.combine(rhs, true)
    }
}

impl Mul for &Poly {
    type Output = Poly;
    /// Contents multiply; the product of the primitive parts is primitive (Gauss), with a
    /// positive leading coefficient, in all the variables of both.
    fn mul(self, rhs: &Poly) -> Poly {
        if self.is_zero() || rhs.is_zero() {
            return Poly::zero();
        }
        let (ring, pa, pb) = Poly::align(self, rhs);
        Poly {
            ring,
            content: &self.content * &rhs.content,
            prim: &*pa * &*pb,
        }
    }
}

impl Neg for &Poly {
    type Output = Poly;
    fn neg(self) -> Poly {
        Poly {
            content: -&self.content,
            ..self.clone()
        }
    }
}

impl fmt::Display for Poly {
    /// Terms by descending total degree, then by variable order; `0` for zero.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.is_zero() {
            return write!(f, "0");
        }
        let mut terms: Vec<_> = self.terms().collect();
        terms.sort_by(|(a, _), (b, _)| b.degree().cmp(&a.degree()).then_with(|| a.cmp(b)));
        for (i, (m, c)) in terms.iter().enumerate() {
            let abs = c.abs();
            match (i, c.is_negative()) {
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

/// The sum of `parts`, added in a balanced tree (a running sum would re-merge the growing
/// total once per part); `None` for no part.
pub(crate) fn sum_pairwise<T>(mut parts: Vec<T>, add: impl Fn(&T, &T) -> T) -> Option<T> {
    while parts.len() > 1 {
        let mut next = Vec::with_capacity(parts.len().div_ceil(2));
        let mut it = parts.into_iter();
        while let Some(a) = it.next() {
            next.push(match it.next() {
                Some(b) => add(&a, &b),
                None => a,
            });
        }
        parts = next;
    }
    parts.pop()
}
