//! The expression parser shared by [`Poly::parse`] and [`RatFn::parse`]: `+ - * / ^`,
//! parentheses, exact decimals and identifiers; juxtaposition multiplies.

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
    let tokens = tokenize(text)?;
    let mut parser = Parser {
        tokens,
        pos: 0,
        lookup,
    };
    let p = parser.sum()?;
    if parser.pos != parser.tokens.len() {
        return Err(parser.error("unexpected input after the expression"));
    }
    Ok(p)
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

struct Parser<'a> {
    tokens: Vec<(usize, Token)>,
    pos: usize,
    lookup: Lookup<'a>,
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
                Ok(match (self.lookup)(&name) {
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
