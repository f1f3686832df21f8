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

