//! Exact multivariate polynomials over ℚ with named variables.
//!
//! The representation is canonical (a sorted map from monomials to non-zero rational
//! coefficients), so structural equality is polynomial equality.

use std::collections::BTreeMap;
use std::fmt;
use std::ops::{Add, Mul, Neg, Sub};

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

use super::RatFn;
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
///
/// # Example
/// ```
/// use orthocheck::algebra::Poly;
/// let p = Poly::parse("(a + b)^2").unwrap();
/// let q = Poly::parse("a^2 + 2*a*b + b^2").unwrap();
/// assert_eq!(p, q);
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Poly {
    terms: BTreeMap<Monomial, BigRational>,
}

impl Poly {
    /// The zero polynomial.
    pub fn zero() -> Self {
        Poly::default()
    }

    /// A rational constant.
    pub fn constant(c: BigRational) -> Self {
        let mut p = Poly::zero();
        p.add_term(Monomial::one(), c);
        p
    }

    /// An integer constant.
    pub fn int(c: i64) -> Self {
        Poly::constant(BigRational::from_integer(BigInt::from(c)))
    }

    /// The variable `name`.
    pub fn var(name: &str) -> Self {
        let mut p = Poly::zero();
        p.add_term(Monomial::var(name), BigRational::one());
        p
    }

    /// The monomial `m` with coefficient 1.
    pub fn from_monomial(m: Monomial) -> Self {
        let mut p = Poly::zero();
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

    /// Whether there are no terms (same as [`Poly::is_zero`]).
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
    pub fn scale(&self, c: &BigRational) -> Poly {
        if c.is_zero() {
            return Poly::zero();
        }
        Poly {
            terms: self.terms.iter().map(|(m, k)| (m.clone(), k * c)).collect(),
        }
    }

    /// Integer power.
    pub fn pow(&self, e: u32) -> Poly {
        let mut result = Poly::int(1);
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
    pub fn coefficients_in(&self, name: &str) -> Vec<Poly> {
        let d = self.degree_in(name) as usize;
        let mut out = vec![Poly::zero(); d + 1];
        for (m, c) in &self.terms {
            out[m.exponent(name) as usize].add_term(m.without(name), c.clone());
        }
        out
    }

    /// Substitute the polynomial `value` for the variable `name`.
    pub fn substitute(&self, name: &str, value: &Poly) -> Poly {
        let mut out = Poly::zero();
        let mut powers: Vec<Poly> = vec![Poly::int(1)];
        for (m, c) in &self.terms {
            let e = m.exponent(name) as usize;
            while powers.len() <= e {
                let next = powers.last().map(|p| p * value).unwrap_or_default();
                powers.push(next);
            }
            let rest = Poly {
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
    ///
    /// # Example
    /// ```
    /// use orthocheck::algebra::Poly;
    /// let p = Poly::parse("x^2 - y^2").unwrap();
    /// assert_eq!(p.div_exact(&Poly::parse("x - y").unwrap()), Some(Poly::parse("x + y").unwrap()));
    /// assert_eq!(p.div_exact(&Poly::parse("x - 2y").unwrap()), None);
    /// ```
    pub fn div_exact(&self, d: &Poly) -> Option<Poly> {
        let (dm, dc) = d.leading()?;
        let (dm, dc) = (dm.clone(), dc.clone());
        let mut r = self.clone();
        let mut q = Poly::zero();
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
            let term = Poly {
                terms: BTreeMap::from([(Monomial(t), rc / &dc)]),
            };
            r = &r - &(&term * d);
            q = &q + &term;
        }
        Some(q)
    }

    /// If `self = k · other` for a non-zero rational `k`, return `k`.
    pub fn ratio_to(&self, other: &Poly) -> Option<BigRational> {
        let (m0, c0) = other.terms.iter().next()?;
        let k = self.terms.get(m0)? / c0;
        (k != BigRational::zero() && *self == other.scale(&k)).then_some(k)
    }

    /// Parse an expression with `+ - * ^`, parentheses, rational numbers (`3`, `2.5`, `1/3`
    /// through division by a number) and identifiers (`a`, `a_1`, `A_Cst`). Juxtaposition
    /// multiplies, as in printed formulas: `2(a^2 - b^2)c^2`.
    pub fn parse(text: &str) -> Result<Poly, ParseError> {
        let r = parse_rational(text, &BTreeMap::new())?;
        r.to_poly().ok_or(ParseError {
            position: 0,
            message: "only division by a non-zero number".into(),
        })
    }
}

/// Parse into a rational function; identifiers with a definition stand for it.
pub(crate) fn parse_rational(
    text: &str,
    defs: &BTreeMap<String, RatFn>,
) -> Result<RatFn, ParseError> {
    let tokens = tokenize(text)?;
    let mut parser = Parser {
        tokens,
        pos: 0,
        defs,
    };
    let p = parser.sum()?;
    if parser.pos != parser.tokens.len() {
        return Err(parser.error("unexpected input after the expression"));
    }
    Ok(p)
}

impl Add for &Poly {
    type Output = Poly;
    fn add(self, rhs: &Poly) -> Poly {
        let mut out = self.clone();
        for (m, c) in &rhs.terms {
            out.add_term(m.clone(), c.clone());
        }
        out
    }
}

impl Sub for &Poly {
    type Output = Poly;
    fn sub(self, rhs: &Poly) -> Poly {
        let mut out = self.clone();
        for (m, c) in &rhs.terms {
            out.add_term(m.clone(), -c.clone());
        }
        out
    }
}

impl Mul for &Poly {
    type Output = Poly;
    fn mul(self, rhs: &Poly) -> Poly {
        let mut out = Poly::zero();
        for (m1, c1) in &self.terms {
            for (m2, c2) in &rhs.terms {
                out.add_term(m1.mul(m2), c1 * c2);
            }
        }
        out
    }
}

impl Neg for &Poly {
    type Output = Poly;
    fn neg(self) -> Poly {
        self.scale(&-BigRational::one())
    }
}

impl fmt::Display for Poly {
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

#[derive(Clone, Debug, PartialEq)]
enum Token {
    Num(BigRational),
    Ident(String),
    Op(char),
}

fn tokenize(text: &str) -> Result<Vec<(usize, Token)>, ParseError> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        if ch.is_whitespace() {
            i += 1;
        } else if ch.is_ascii_digit() || ch == '.' {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            let s: String = chars[start..i].iter().collect();
            let value = parse_decimal(&s).ok_or_else(|| ParseError {
                position: start,
                message: format!("'{s}' is not a number"),
            })?;
            out.push((start, Token::Num(value)));
        } else if ch.is_alphabetic() {
            let start = i;
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            out.push((start, Token::Ident(chars[start..i].iter().collect())));
        } else if "+-*/^()".contains(ch) {
            out.push((i, Token::Op(ch)));
            i += 1;
        } else {
            return Err(ParseError {
                position: i,
                message: format!("unexpected character '{ch}'"),
            });
        }
    }
    Ok(out)
}

/// An exact decimal such as `1.2345` or `-16`; `None` if malformed.
pub fn parse_decimal(s: &str) -> Option<BigRational> {
    let (neg, body) = match s.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, s.strip_prefix('+').unwrap_or(s)),
    };
    let (int, frac) = match body.split_once('.') {
        Some((i, f)) => (i, f),
        None => (body, ""),
    };
    if (int.is_empty() && frac.is_empty())
        || !int.chars().all(|c| c.is_ascii_digit())
        || !frac.chars().all(|c| c.is_ascii_digit())
    {
        return None;
    }
    let digits = format!("{int}{frac}");
    let num: BigInt = digits.parse().ok()?;
    let den = num_traits::pow(BigInt::from(10), frac.len());
    let v = BigRational::new(num, den);
    Some(if neg { -v } else { v })
}

struct Parser<'a> {
    tokens: Vec<(usize, Token)>,
    pos: usize,
    defs: &'a BTreeMap<String, RatFn>,
}

impl Parser<'_> {
    fn peek(&self) -> Option<&Token> {
        self.tokens.get(self.pos).map(|(_, t)| t)
    }

    fn error(&self, message: &str) -> ParseError {
        ParseError {
            position: self
                .tokens
                .get(self.pos)
                .map(|(p, _)| *p)
                .unwrap_or(usize::MAX),
            message: message.to_string(),
        }
    }

    fn sum(&mut self) -> Result<RatFn, ParseError> {
        let mut acc = match self.peek() {
            Some(Token::Op('-')) => {
                self.pos += 1;
                -&self.product()?
            }
            Some(Token::Op('+')) => {
                self.pos += 1;
                self.product()?
            }
            _ => self.product()?,
        };
        loop {
            match self.peek() {
                Some(Token::Op('+')) => {
                    self.pos += 1;
                    acc = &acc + &self.product()?;
                }
                Some(Token::Op('-')) => {
                    self.pos += 1;
                    acc = &acc - &self.product()?;
                }
                _ => return Ok(acc),
            }
        }
    }

    fn product(&mut self) -> Result<RatFn, ParseError> {
        let mut acc = self.power()?;
        loop {
            match self.peek() {
                Some(Token::Op('*')) => {
                    self.pos += 1;
                    acc = &acc * &self.power()?;
                }
                Some(Token::Op('/')) => {
                    self.pos += 1;
                    let d = self.power()?;
                    acc = (&acc / &d).ok_or_else(|| self.error("division by zero"))?;
                }
                Some(Token::Num(_)) | Some(Token::Ident(_)) | Some(Token::Op('(')) => {
                    acc = &acc * &self.power()?;
                }
                _ => return Ok(acc),
            }
        }
    }

    fn power(&mut self) -> Result<RatFn, ParseError> {
        let base = self.primary()?;
        if let Some(Token::Op('^')) = self.peek() {
            self.pos += 1;
            match self.peek().cloned() {
                Some(Token::Num(n)) if n.is_integer() => {
                    self.pos += 1;
                    let e = n
                        .to_integer()
                        .to_u32()
                        .ok_or_else(|| self.error("exponent too large"))?;
                    return Ok(base.pow(e));
                }
                _ => return Err(self.error("exponent must be a non-negative integer")),
            }
        }
        Ok(base)
    }

    fn primary(&mut self) -> Result<RatFn, ParseError> {
        match self.peek().cloned() {
            Some(Token::Num(n)) => {
                self.pos += 1;
                Ok(Poly::constant(n).into())
            }
            Some(Token::Ident(name)) => {
                self.pos += 1;
                Ok(match self.defs.get(&name) {
                    Some(d) => d.clone(),
                    None => RatFn::var(&name),
                })
            }
            Some(Token::Op('(')) => {
                self.pos += 1;
                let inner = self.sum()?;
                match self.peek() {
                    Some(Token::Op(')')) => {
                        self.pos += 1;
                        Ok(inner)
                    }
                    _ => Err(self.error("missing ')'")),
                }
            }
            Some(Token::Op('-')) => {
                self.pos += 1;
                Ok(-&self.power()?)
            }
            _ => Err(self.error("expected a number, a variable or '('")),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parse_and_print_round_trip() {
        let p = Poly::parse("2(a_i^2 - b^2)c^2 - 1/2").unwrap();
        assert_eq!(p.to_string(), "2*a_i^2*c^2 - 2*b^2*c^2 - 1/2");
        assert_eq!(Poly::parse(&p.to_string()).unwrap(), p);
    }

    #[test]
    fn substitution_and_coefficients() {
        let p = Poly::parse("x^2 + y").unwrap();
        let q = p.substitute("x", &Poly::parse("y + 1").unwrap());
        assert_eq!(q, Poly::parse("y^2 + 3y + 1").unwrap());
        let c = q.coefficients_in("y");
        assert_eq!(c.len(), 3);
        assert_eq!(c[1], Poly::int(3));
    }

    #[test]
    fn ratio_detects_scalar_multiples() {
        let p = Poly::parse("a - b").unwrap();
        let q = Poly::parse("3b - 3a").unwrap();
        assert_eq!(q.ratio_to(&p), Some(BigRational::from_integer((-3).into())));
        assert_eq!(Poly::parse("a + b").unwrap().ratio_to(&p), None);
    }

    #[test]
    fn parse_errors_name_the_position() {
        let e = Poly::parse("a + * b").unwrap_err();
        assert_eq!(e.position, 4);
        assert!(Poly::parse("a^b").is_err());
        assert!(Poly::parse("(a").is_err());
        assert!(Poly::parse("a / b").is_err());
    }
}
