//! The expression parser shared by [`Poly::parse`] and [`RatFn::parse`]: `+ - * / ^`,
//! parentheses, exact decimals and identifiers; juxtaposition multiplies. The same parser
//! evaluates at a point modulo a prime, which tells cheaply whether a text parses.

use std::collections::BTreeMap;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;

use super::{Poly, RatFn};
use crate::error::ParseError;

/// What an identifier stands for, if it has a definition.
pub(crate) type Lookup<'a> = &'a dyn Fn(&str) -> Option<&'a RatFn>;

/// Parse into a rational function; identifiers with a definition stand for it.
pub(crate) fn parse_rational(
    text: &str,
    defs: &BTreeMap<String, RatFn>,
) -> Result<RatFn, ParseError> {
    parse_looking_up(text, &|name| defs.get(name))
}

/// Parse into a rational function; an identifier stands for what `lookup` gives it.
pub(crate) fn parse_looking_up(text: &str, lookup: Lookup) -> Result<RatFn, ParseError> {
    let leaf = |name: &str| lookup(name).cloned().unwrap_or_else(|| RatFn::var(name));
    evaluate(text, &leaf)
}

/// Whether `text` parses, with the errors [`parse_rational`] gives (no definitions): the
/// expression is evaluated at a point modulo 2⁶¹ − 1, where a divisor that is not zero as a
/// polynomial rarely vanishes; only where one does is the text parsed exactly, to tell.
pub(crate) fn check(text: &str) -> Result<(), ParseError> {
    match evaluate(text, &Residue::at) {
        Err(e) if e.message == DIVISION_BY_ZERO => parse_rational(text, &BTreeMap::new()).map(drop),
        r => r.map(drop),
    }
}

/// The text's value, an identifier standing for `leaf(name)`.
fn evaluate<V: Operand>(text: &str, leaf: &dyn Fn(&str) -> V) -> Result<V, ParseError> {
    let tokens = tokenize(text)?;
    let mut parser = Parser {
        tokens,
        pos: 0,
        leaf,
    };
    let p = parser.sum()?;
    if parser.pos != parser.tokens.len() {
        return Err(parser.error("unexpected input after the expression"));
    }
    Ok(p)
}

const DIVISION_BY_ZERO: &str = "division by zero";

/// What the parser computes with.
trait Operand: Sized {
    fn number(n: &BigRational) -> Self;
    fn add(&self, o: &Self) -> Self;
    fn sub(&self, o: &Self) -> Self;
    fn mul(&self, o: &Self) -> Self;
    /// `None` when dividing by zero.
    fn div(&self, o: &Self) -> Option<Self>;
    fn neg(&self) -> Self;
    fn pow(&self, e: u32) -> Self;
}

impl Operand for RatFn {
    fn number(n: &BigRational) -> Self {
        Poly::constant(n.clone()).into()
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn sub(&self, o: &Self) -> Self {
        self - o
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
    fn div(&self, o: &Self) -> Option<Self> {
        self / o
    }
    fn neg(&self) -> Self {
        -self
    }
    fn pow(&self, e: u32) -> Self {
        RatFn::pow(self, e)
    }
}

/// A value modulo the prime 2⁶¹ − 1, `None` where it is not known (a number whose
/// denominator the prime divides, a quotient by zero).
#[derive(Clone, Copy)]
struct Residue(Option<u64>);

const P: u64 = (1 << 61) - 1;

impl Residue {
    /// An identifier's value: a hash of its name (FNV-1a), the same at every run.
    fn at(name: &str) -> Residue {
        let h = name.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
            (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
        });
        Residue(Some(h % P))
    }

    fn of(n: &BigInt) -> u64 {
        let r = n % BigInt::from(P);
        let r = r.to_i64().unwrap_or(0);
        r.rem_euclid(P as i64) as u64
    }

    fn both(&self, o: &Self, f: impl Fn(u64, u64) -> u64) -> Self {
        Residue(self.0.zip(o.0).map(|(a, b)| f(a, b)))
    }

    fn mul_mod(a: u64, b: u64) -> u64 {
        ((u128::from(a) * u128::from(b)) % u128::from(P)) as u64
    }

    fn pow_mod(mut a: u64, mut e: u64) -> u64 {
        let mut r = 1;
        while e > 0 {
            if e & 1 == 1 {
                r = Residue::mul_mod(r, a);
            }
            a = Residue::mul_mod(a, a);
            e >>= 1;
        }
        r
    }

    /// The inverse of a non-zero residue (Fermat).
    fn inv(a: u64) -> u64 {
        Residue::pow_mod(a, P - 2)
    }
}

impl Operand for Residue {
    fn number(n: &BigRational) -> Self {
        let d = Residue::of(n.denom());
        Residue((d != 0).then(|| Residue::mul_mod(Residue::of(n.numer()), Residue::inv(d))))
    }
    fn add(&self, o: &Self) -> Self {
        self.both(o, |a, b| (a + b) % P)
    }
    fn sub(&self, o: &Self) -> Self {
        self.both(o, |a, b| (a + P - b) % P)
    }
    fn mul(&self, o: &Self) -> Self {
        self.both(o, Residue::mul_mod)
    }
    fn div(&self, o: &Self) -> Option<Self> {
        match o.0 {
            // zero here: the exact parse tells whether the divisor is zero
            Some(0) | None => None,
            Some(b) => Some(Residue(
                self.0.map(|a| Residue::mul_mod(a, Residue::inv(b))),
            )),
        }
    }
    fn neg(&self) -> Self {
        Residue(self.0.map(|a| (P - a) % P))
    }
    fn pow(&self, e: u32) -> Self {
        Residue(self.0.map(|a| Residue::pow_mod(a, u64::from(e))))
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
    let v = match decimal_in_words(int, frac) {
        Some((num, den)) => BigRational::new_raw(num.into(), den.into()),
        None => {
            let num: BigInt = format!("{int}{frac}").parse().ok()?;
            BigRational::new(num, num_traits::pow(BigInt::from(10), frac.len()))
        }
    };
    Some(if neg { -v } else { v })
}

/// `int.frac` (ASCII digits) as a reduced fraction of machine words, when its digits fit:
/// the denominator is 2^a·5^b, so reducing is dividing out those factors alone, and the
/// big-integer gcd of the general case is not needed for the printed numbers of a case.
fn decimal_in_words(int: &str, frac: &str) -> Option<(u64, u64)> {
    // 10^19 > u64::MAX, so up to 18 fractional digits and 19 digits in all
    if frac.len() > 18 || int.len() + frac.len() > 19 {
        return None;
    }
    let mut num = 0u64;
    for b in int.bytes().chain(frac.bytes()) {
        num = num.checked_mul(10)?.checked_add(u64::from(b - b'0'))?;
    }
    let mut den = 10u64.pow(frac.len() as u32);
    for p in [2, 5] {
        while den.is_multiple_of(p) && num.is_multiple_of(p) {
            (num, den) = (num / p, den / p);
        }
    }
    Some(if num == 0 { (0, 1) } else { (num, den) })
}

/// The identifiers of `text`, in order of first appearance.
pub(crate) fn identifiers(text: &str) -> Result<Vec<String>, ParseError> {
    let mut out: Vec<String> = Vec::new();
    for (_, t) in tokenize(text)? {
        if let Token::Ident(name) = t
            && !out.contains(&name)
        {
            out.push(name);
        }
    }
    Ok(out)
}

struct Parser<'a, V> {
    tokens: Vec<(usize, Token)>,
    pos: usize,
    leaf: &'a dyn Fn(&str) -> V,
}

impl<V: Operand> Parser<'_, V> {
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

    fn sum(&mut self) -> Result<V, ParseError> {
        let mut acc = match self.peek() {
            Some(Token::Op('-')) => {
                self.pos += 1;
                self.product()?.neg()
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
                    acc = acc.add(&self.product()?);
                }
                Some(Token::Op('-')) => {
                    self.pos += 1;
                    acc = acc.sub(&self.product()?);
                }
                _ => return Ok(acc),
            }
        }
    }

    fn product(&mut self) -> Result<V, ParseError> {
        let mut acc = self.power()?;
        loop {
            match self.peek() {
                Some(Token::Op('*')) => {
                    self.pos += 1;
                    acc = acc.mul(&self.power()?);
                }
                Some(Token::Op('/')) => {
                    self.pos += 1;
                    let d = self.power()?;
                    acc = acc.div(&d).ok_or_else(|| self.error(DIVISION_BY_ZERO))?;
                }
                Some(Token::Num(_)) | Some(Token::Ident(_)) | Some(Token::Op('(')) => {
                    acc = acc.mul(&self.power()?);
                }
                _ => return Ok(acc),
            }
        }
    }

    fn power(&mut self) -> Result<V, ParseError> {
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

    fn primary(&mut self) -> Result<V, ParseError> {
        match self.peek().cloned() {
            Some(Token::Num(n)) => {
                self.pos += 1;
                Ok(V::number(&n))
            }
            Some(Token::Ident(name)) => {
                self.pos += 1;
                Ok((self.leaf)(&name))
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
                Ok(self.power()?.neg())
            }
            _ => Err(self.error("expected a number, a variable or '('")),
        }
    }
}
