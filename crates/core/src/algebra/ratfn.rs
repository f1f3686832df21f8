//! Rational functions over ℚ: a numerator and a denominator polynomial, compared by
//! cross-multiplication (no cancellation needed to decide equality).

use std::borrow::Cow;
use std::collections::BTreeMap;
use std::ops::{Add, Div, Mul, Neg, Sub};

use num_rational::BigRational;
use num_traits::{One, Zero};

use super::Poly;
use crate::error::ParseError;

/// `num / den` with `den ≠ 0`.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::RatFn;
/// let f = RatFn::parse("(x^2 - y^2)/(x - y)").unwrap();
/// assert!(f.equals(&RatFn::parse("x + y").unwrap()));
/// ```
#[derive(Clone, Debug)]
pub struct RatFn {
    /// Numerator.
    pub num: Poly,
    /// Denominator (never the zero polynomial).
    pub den: Poly,
}

impl From<Poly> for RatFn {
    fn from(p: Poly) -> Self {
        RatFn {
            num: p,
            den: Poly::int(1),
        }
    }
}

impl RatFn {
    /// The variable `name`.
    pub fn var(name: &str) -> Self {
        Poly::var(name).into()
    }

    /// An integer constant.
    pub fn int(c: i64) -> Self {
        Poly::int(c).into()
    }

    /// Parse an expression like [`Poly::parse`], with division by any non-zero expression.
    pub fn parse(text: &str) -> Result<RatFn, ParseError> {
        super::parse::parse_rational(text, &BTreeMap::new())
    }

    /// Parse with named definitions: an identifier that has a definition stands for it
    /// (the paper's abbreviations, such as `d_a1` or `f_cb`).
    pub fn parse_with(text: &str, defs: &BTreeMap<String, RatFn>) -> Result<RatFn, ParseError> {
        super::parse::parse_rational(text, defs)
    }

    /// Parse with the definitions `lookup` gives: an identifier stands for its definition
    /// when it has one, else for a variable.
    pub fn parse_looking_up<'a>(
        text: &str,
        lookup: &'a dyn Fn(&str) -> Option<&'a RatFn>,
    ) -> Result<RatFn, ParseError> {
        super::parse::parse_looking_up(text, lookup)
    }

    /// Whether `text` parses, with the error [`RatFn::parse`] would give, without its
    /// algebra: the expression is evaluated at a point modulo a prime, and parsed exactly
    /// only where a divisor vanishes there (to tell a zero divisor from a root).
    ///
    /// # Example
    /// ```
    /// use orthocheck_core::algebra::RatFn;
    /// assert!(RatFn::check("(a^2 - b^2) / (a - b)").is_ok());
    /// assert!(RatFn::check("1 / (a - a)").is_err());
    /// assert_eq!(RatFn::check("(a"), RatFn::parse("(a").map(drop));
    /// ```
    pub fn check(text: &str) -> Result<(), ParseError> {
        super::parse::check(text)
    }

    /// The identifiers of `text` (the names [`RatFn::parse_with`] looks up), in order of
    /// first appearance; an error where the text does not tokenize.
    pub fn identifiers(text: &str) -> Result<Vec<String>, ParseError> {
        super::parse::identifiers(text)
    }

    /// Whether the two are the same rational function: n₁d₂ = n₂d₁ exactly. Where one
    /// denominator divides the other, d₂ = q·d₁, that is n₁q = n₂: the smaller product.
    pub fn equals(&self, other: &RatFn) -> bool {
        self.is_multiple(other, &BigRational::one())
    }

    /// Whether `self = k · other`: n₁d₂ = k·n₂d₁, through the quotient of the denominators
    /// where one divides the other.
    pub fn is_multiple(&self, other: &RatFn, k: &BigRational) -> bool {
        let (left, right, c) = self.cross(other);
        left.scale(&c) == right.scale(k)
    }

    /// If `self = k · other` for a non-zero rational `k`, return `k`; with d₂ = c·d₁,
    /// k = c · (n₁ / n₂).
    pub fn ratio_to(&self, other: &RatFn) -> Option<BigRational> {
        let (left, right, c) = self.cross(other);
        left.ratio_to(&right).map(|k| k * c)
    }

    /// The two numerators over a common denominator, the first to be scaled by the
    /// rational: n₁·c against n₂ where the denominators are proportional (d₂ = c·d₁); where
    /// one divides the other, each numerator multiplied by what its denominator lacks (n₁q
    /// against n₂ for d₂ = q·d₁); else crosswise, n₁d₂ against n₂d₁.
    fn cross<'a>(&'a self, other: &'a RatFn) -> (Cow<'a, Poly>, Cow<'a, Poly>, BigRational) {
        let one = BigRational::one();
        if let Some(c) = other.den.ratio_to(&self.den) {
            return (Cow::Borrowed(&self.num), Cow::Borrowed(&other.num), c);
        }
        let (left, right) = if let Some(q) = other.den.div_exact(&self.den) {
            (Cow::Owned(&self.num * &q), Cow::Borrowed(&other.num))
        } else if let Some(q) = self.den.div_exact(&other.den) {
            (Cow::Borrowed(&self.num), Cow::Owned(&other.num * &q))
        } else {
            (
                Cow::Owned(&self.num * &other.den),
                Cow::Owned(&other.num * &self.den),
            )
        };
        (left, right, one)
    }

    /// Whether this is zero.
    pub fn is_zero(&self) -> bool {
        self.num.is_zero()
    }

    /// The polynomial, when the denominator is a constant.
    pub fn to_poly(&self) -> Option<Poly> {
        match (self.den.len(), self.den.first_term()) {
            (1, Some((m, c))) if m.degree() == 0 => Some(self.num.scale(&c.recip())),
            _ => None,
        }
    }

    /// Integer power.
    pub fn pow(&self, e: u32) -> RatFn {
        RatFn {
            num: self.num.pow(e),
            den: self.den.pow(e),
        }
    }

    /// Substitute `value` for the variable `name`.
    pub fn substitute(&self, name: &str, value: &RatFn) -> RatFn {
        // P(N/D) = Σ cₑ Nᵉ D^(d−e) / D^d for each of numerator and denominator
        let homogenise = |p: &Poly| -> (Poly, u32) {
            let c = p.coefficients_in(name);
            let d = c.len().saturating_sub(1) as u32;
            let mut out = Poly::zero();
            for (e, ce) in c.iter().enumerate() {
                let term = &(ce * &value.num.pow(e as u32)) * &value.den.pow(d - e as u32);
                out = &out + &term;
            }
            (out, d)
        };
        let (n, dn) = homogenise(&self.num);
        let (m, dm) = homogenise(&self.den);
        // (n / D^dn) / (m / D^dm)
        let (num, den) = if dn >= dm {
            (n, &m * &value.den.pow(dn - dm))
        } else {
            (&n * &value.den.pow(dm - dn), m)
        };
        RatFn { num, den }
    }

    /// Evaluate at a rational point; `None` if a variable has no value or the denominator
    /// vanishes there.
    pub fn eval(&self, values: &BTreeMap<String, BigRational>) -> Option<BigRational> {
        let d = self.den.eval(values)?;
        if d.is_zero() {
            return None;
        }
        Some(self.num.eval(values)? / d)
    }

    /// All variable names, sorted.
    pub fn variables(&self) -> Vec<String> {
        let mut v = self.num.variables();
        v.extend(self.den.variables());
        v.sort();
        v.dedup();
        v
    }
}

impl Add for &RatFn {
    type Output = RatFn;
    fn add(self, o: &RatFn) -> RatFn {
        if self.den == o.den {
            return RatFn {
                num: &self.num + &o.num,
                den: self.den.clone(),
            };
        }
        // one denominator a multiple of the other (D and D², …): the larger one serves both,
        // which keeps repeated abbreviations from multiplying out
        if let Some(k) = o.den.div_exact(&self.den) {
            return RatFn {
                num: &(&self.num * &k) + &o.num,
                den: o.den.clone(),
            };
        }
        if let Some(k) = self.den.div_exact(&o.den) {
            return RatFn {
                num: &self.num + &(&o.num * &k),
                den: self.den.clone(),
            };
        }
        RatFn {
            num: &(&self.num * &o.den) + &(&o.num * &self.den),
            den: &self.den * &o.den,
        }
    }
}

impl Sub for &RatFn {
    type Output = RatFn;
    fn sub(self, o: &RatFn) -> RatFn {
        self + &(-o)
    }
}

impl Mul for &RatFn {
    type Output = RatFn;
    fn mul(self, o: &RatFn) -> RatFn {
        RatFn {
            num: &self.num * &o.num,
            den: &self.den * &o.den,
        }
    }
}

impl Div for &RatFn {
    type Output = Option<RatFn>;
    #[allow(clippy::suspicious_arithmetic_impl)] // a/b ÷ c/d = ad / bc
    /// `None` when dividing by zero.
    fn div(self, o: &RatFn) -> Option<RatFn> {
        (!o.num.is_zero()).then(|| RatFn {
            num: &self.num * &o.den,
            den: &self.den * &o.num,
        })
    }
}

impl Neg for &RatFn {
    type Output = RatFn;
    fn neg(self) -> RatFn {
        RatFn {
            num: -&self.num,
            den: self.den.clone(),
        }
    }
}

impl Default for RatFn {
    fn default() -> Self {
        Poly::zero().into()
    }
}

/// Solve the square linear system `m · x = rhs` over rational functions by Gaussian
/// elimination (pivots: the first non-zero entry); `None` when singular.
pub fn solve_linear(m: &[Vec<RatFn>], rhs: &[RatFn]) -> Option<Vec<RatFn>> {
    let n = m.len();
    let mut a: Vec<Vec<RatFn>> = m
        .iter()
        .zip(rhs)
        .map(|(r, b)| {
            r.iter()
                .cloned()
                .chain(std::iter::once(b.clone()))
                .collect()
        })
        .collect();
    for c in 0..n {
        let p = (c..n).find(|&r| !a[r][c].is_zero())?;
        a.swap(c, p);
        let pivot = a[c][c].clone();
        for v in a[c].iter_mut().skip(c) {
            *v = (&*v / &pivot)?;
        }
        for r in 0..n {
            if r != c && !a[r][c].is_zero() {
                let f = a[r][c].clone();
                let row = a[c].clone();
                for (v, p) in a[r].iter_mut().zip(&row).skip(c) {
                    *v = &*v - &(&f * p);
                }
            }
        }
    }
    Some(a.into_iter().map(|r| r[n].clone()).collect())
}

impl RatFn {
    /// One.
    pub fn one() -> Self {
        Poly::constant(BigRational::one()).into()
    }

    /// The same function in lowest terms: numerator and denominator divided by their gcd
    /// (each quotient checked by exact division), the denominator with content one and a
    /// positive leading coefficient, so equal functions get equal parts.
    ///
    /// The arithmetic operators keep the forms they build (a displayed derivation shows the
    /// factors its steps produced); call this where smallness matters more.
    ///
    /// # Example
    /// ```
    /// use orthocheck_core::algebra::{Poly, RatFn};
    /// let f = RatFn::parse("(2x^2 - 2y^2) / (4x + 4y)").unwrap().reduced();
    /// assert_eq!((f.num.to_string(), f.den.to_string()), ("1/2*x - 1/2*y".into(), "1".into()));
    /// ```
    pub fn reduced(&self) -> RatFn {
        if self.num.is_zero() {
            return RatFn::default();
        }
        let g = self.num.gcd(&self.den);
        let (num, den) =
            match (g.degree() > 0).then(|| (self.num.div_exact(&g), self.den.div_exact(&g))) {
                Some((Some(n), Some(d))) => (n, d),
                _ => (self.num.clone(), self.den.clone()),
            };
        let c = den.primitive().0.recip();
        RatFn {
            num: num.scale(&c),
            den: den.scale(&c),
        }
    }
}

impl RatFn {
    /// Substitute every entry of `values` at once. When the values used share one
    /// denominator D, a numerator or denominator of total degree d in the substituted names
    /// becomes Σ cₘ·Nᵐ·D^(d−|m|) / D^d: one power of D for all names, where substituting one
    /// name after another would multiply a power of D per name. Otherwise one after another.
    ///
    /// # Example
    /// ```
    /// use std::collections::BTreeMap;
    /// use orthocheck_core::algebra::RatFn;
    /// let f = RatFn::parse("u^2 + u v").unwrap();
    /// let values: BTreeMap<String, RatFn> = [
    ///     ("u".to_string(), RatFn::parse("x / (x + 1)").unwrap()),
    ///     ("v".to_string(), RatFn::parse("1 / (x + 1)").unwrap()),
    /// ].into();
    /// let g = f.substitute_all(&values);
    /// assert_eq!(g.den.degree(), 2);
    /// assert!(g.equals(&RatFn::parse("(x^2 + x) / (x + 1)^2").unwrap()));
    /// ```
    pub fn substitute_all(&self, values: &BTreeMap<String, RatFn>) -> RatFn {
        let vars = self.variables();
        let used: BTreeMap<&str, &RatFn> = values
            .iter()
            .filter(|(k, _)| vars.contains(k))
            .map(|(k, v)| (k.as_str(), v))
            .collect();
        let Some(d0) = used.values().next().map(|v| &v.den) else {
            return self.clone();
        };
        if !used.values().all(|v| v.den == *d0) {
            return used
                .iter()
                .fold(self.clone(), |f, (k, v)| f.substitute(k, v));
        }
        let (n, dn) = homogenise_all(&self.num, &used, d0);
        let (m, dm) = homogenise_all(&self.den, &used, d0);
        // (n / D^dn) / (m / D^dm)
        if dn >= dm {
            RatFn {
                num: n,
                den: &m * &d0.pow(dn - dm),
            }
        } else {
            RatFn {
                num: &n * &d0.pow(dm - dn),
                den: m,
            }
        }
    }
}

/// `p` with each name of `used` (value Nⱼ / D) replaced, times D^d: (Σ cₘ·Nᵐ·D^(d−|m|), d),
/// d the total degree of `p` in those names. The terms are grouped by their monomial m in
/// the names first (one product per group, not per term), powers are computed once, and the
/// products are summed in one ring ([`Poly::sum_of_products`]).
fn homogenise_all(p: &Poly, used: &BTreeMap<&str, &RatFn>, d: &Poly) -> (Poly, u32) {
    let names: Vec<&str> = used.keys().copied().collect();
    let groups = split_in(p, &names);
    let degree = |m: &[u32]| m.iter().sum::<u32>();
    let top = groups.iter().map(|(m, _)| degree(m)).max().unwrap_or(0);
    let mut powers: BTreeMap<(usize, u32), Poly> = BTreeMap::new();
    let mut dpow: BTreeMap<u32, Poly> = BTreeMap::new();
    for (m, _) in &groups {
        for (i, &e) in m.iter().enumerate().filter(|(_, e)| **e > 0) {
            powers
                .entry((i, e))
                .or_insert_with(|| used[names[i]].num.pow(e));
        }
        if top > degree(m) {
            dpow.entry(top - degree(m))
                .or_insert_with(|| d.pow(top - degree(m)));
        }
    }
    let products: Vec<Vec<&Poly>> = groups
        .iter()
        .map(|(m, c)| {
            let n = m.iter().enumerate().filter(|(_, e)| **e > 0);
            // no power D⁰ is kept: a group of the top degree has no factor of D
            std::iter::once(c)
                .chain(n.map(|(i, &e)| &powers[&(i, e)]))
                .chain(dpow.get(&(top - degree(m))))
                .collect()
        })
        .collect();
    (Poly::sum_of_products(&products), top)
}

/// `p = Σₘ cₘ · namesᵐ`: each monomial m in `names` (exponents in their order) with its
/// coefficient, a polynomial free of them; zero coefficients left out.
fn split_in(p: &Poly, names: &[&str]) -> Vec<(Vec<u32>, Poly)> {
    let Some((first, rest)) = names.split_first() else {
        return vec![(Vec::new(), p.clone())];
    };
    let mut out = Vec::new();
    for (e, c) in p.coefficients_in(first).into_iter().enumerate() {
        if c.is_zero() {
            continue;
        }
        for (mut m, q) in split_in(&c, rest) {
            m.insert(0, e as u32);
            out.push((m, q));
        }
    }
    out
}

/// A row of rational functions over their common denominator: polynomials, the same
/// equation multiplied through.
fn polynomial_row(row: &[RatFn]) -> Vec<Poly> {
    // l = lcm of the denominators
    let mut l = Poly::int(1);
    for f in row {
        let g = l.gcd(&f.den);
        l = &l * &f.den.div_exact(&g).unwrap_or_else(|| f.den.clone());
    }
    row.iter()
        .map(|f| match l.div_exact(&f.den) {
            Some(k) => &f.num * &k,
            None => Poly::zero(),
        })
        .collect()
}

/// The determinant by Bareiss's fraction-free elimination: every division is exact
/// (Sylvester's identity), so entries stay polynomials of bounded size. `None` only if an
/// exact division failed, which the identity rules out.
pub fn determinant(m: &[Vec<Poly>]) -> Option<Poly> {
    let n = m.len();
    let mut a: Vec<Vec<Poly>> = m.to_vec();
    let (mut prev, mut negate) = (Poly::int(1), false);
    for k in 0..n {
        let Some(p) = (k..n).find(|&r| !a[r][k].is_zero()) else {
            return Some(Poly::zero());
        };
        if p != k {
            a.swap(k, p);
            negate = !negate;
        }
        for i in k + 1..n {
            for j in k + 1..n {
                let t = &(&a[k][k] * &a[i][j]) - &(&a[i][k] * &a[k][j]);
                a[i][j] = t.div_exact(&prev)?;
            }
        }
        prev = a[k][k].clone();
    }
    Some(if negate { -&prev } else { prev })
}

/// Solve the square system `m · x = rhs` fraction-free: rows over common denominators,
/// then Cramer's rule with Bareiss determinants, each solution in lowest terms
/// ([`RatFn::reduced`]); `None` when singular. The same solutions as [`solve_linear`], in
/// canonical form.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::{solve_linear_fraction_free, RatFn};
/// let m = vec![vec![RatFn::var("u"), RatFn::int(1)], vec![RatFn::int(1), RatFn::var("v")]];
/// let x = solve_linear_fraction_free(&m, &[RatFn::int(1), RatFn::int(0)]).unwrap();
/// assert!(x[0].equals(&RatFn::parse("v / (u v - 1)").unwrap()));
/// ```
pub fn solve_linear_fraction_free(m: &[Vec<RatFn>], rhs: &[RatFn]) -> Option<Vec<RatFn>> {
    let n = m.len();
    let rows: Vec<Vec<Poly>> = m
        .iter()
        .zip(rhs)
        .map(|(r, b)| polynomial_row(&[r.as_slice(), std::slice::from_ref(b)].concat()))
        .collect();
    let a: Vec<Vec<Poly>> = rows.iter().map(|r| r[..n].to_vec()).collect();
    let det = determinant(&a)?;
    if det.is_zero() {
        return None;
    }
    (0..n)
        .map(|i| {
            let mut ai = a.clone();
            for (row, full) in ai.iter_mut().zip(&rows) {
                row[i] = full[n].clone();
            }
            let num = determinant(&ai)?;
            Some(
                RatFn {
                    num,
                    den: det.clone(),
                }
                .reduced(),
            )
        })
        .collect()
}
