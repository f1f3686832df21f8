//! The size of a formula read off its text, before the algebra parser expands it: nesting
//! depth, exponents, and upper bounds on the total degree and the number of terms.
//!
//! The algebra parser is recursive and expands as it goes, so a formula of 10,000 nested
//! parentheses would overflow its stack and `(a+b+c)^64` would take hours. This scan follows
//! the same grammar (`+ - * / ^`, parentheses, numbers, identifiers, juxtaposition) with an
//! explicit depth count, and bounds the expansion: terms of a sum add, of a product multiply,
//! of a power raise (numerator and denominator apart, as a rational function's are). The bound
//! ignores cancellation, so it can only overstate.

use std::collections::BTreeMap;

use crate::limits::{
    FORMULA_CHARS, FORMULA_DEGREE, FORMULA_DEPTH, FORMULA_EXPONENT, FORMULA_TERMS,
};

/// Upper bounds on a formula's expansion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Size {
    /// Terms of the numerator.
    num: f64,
    /// Terms of the denominator.
    den: f64,
    /// Total degree (numerator and denominator together).
    degree: f64,
}

impl Size {
    const ONE: Size = Size {
        num: 1.0,
        den: 1.0,
        degree: 0.0,
    };
    const VAR: Size = Size {
        num: 1.0,
        den: 1.0,
        degree: 1.0,
    };

    fn add(self, o: Size) -> Size {
        Size {
            num: self.num * o.den + o.num * self.den,
            den: self.den * o.den,
            degree: self.degree + o.degree,
        }
    }

    fn mul(self, o: Size) -> Size {
        Size {
            num: self.num * o.num,
            den: self.den * o.den,
            degree: self.degree + o.degree,
        }
    }

    fn div(self, o: Size) -> Size {
        Size {
            num: self.num * o.den,
            den: self.den * o.num,
            degree: self.degree + o.degree,
        }
    }

    fn pow(self, e: u64) -> Size {
        let e = e as i32;
        Size {
            num: self.num.powi(e),
            den: self.den.powi(e),
            degree: self.degree * e as f64,
        }
    }
}

/// Check `text` against the formula limits; `defs` are the sizes of the names it may use.
/// `Err` says which limit, in words.
pub(super) fn check(text: &str, defs: &BTreeMap<String, Size>) -> Result<Size, String> {
    if text.chars().count() > FORMULA_CHARS {
        return Err(format!(
            "the formula has more than {FORMULA_CHARS} characters (see docs/limits.md)"
        ));
    }
    let tokens = tokens(text);
    let mut s = Scan {
        tokens: &tokens,
        pos: 0,
        depth: 0,
        defs,
    };
    let size = s.sum()?;
    if size.degree > FORMULA_DEGREE {
        return Err(format!(
            "the formula can reach degree {:.0}, more than the limit of {FORMULA_DEGREE} (see docs/limits.md)",
            size.degree
        ));
    }
    if size.num.max(size.den) > FORMULA_TERMS {
        return Err(format!(
            "the formula can expand to more than {FORMULA_TERMS:e} terms (see docs/limits.md)"
        ));
    }
    Ok(size)
}

#[derive(Clone, Debug, PartialEq)]
enum Tok {
    Num(u64),
    Ident(String),
    Op(char),
}

/// Tokens as the algebra parser reads them; anything it would reject is left to it (the scan
/// stops there and bounds what it read).
fn tokens(text: &str) -> Vec<Tok> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let ch = chars[i];
        if ch.is_ascii_digit() || ch == '.' {
            let start = i;
            while i < chars.len() && (chars[i].is_ascii_digit() || chars[i] == '.') {
                i += 1;
            }
            let s: String = chars[start..i].iter().collect();
            // an integer exponent's value; a decimal counts as a constant
            out.push(Tok::Num(s.parse().unwrap_or(u64::MAX)));
        } else if ch.is_alphabetic() {
            let start = i;
            while i < chars.len() && (chars[i].is_alphanumeric() || chars[i] == '_') {
                i += 1;
            }
            out.push(Tok::Ident(chars[start..i].iter().collect()));
        } else {
            if "+-*/^()".contains(ch) {
                out.push(Tok::Op(ch));
            } else if !ch.is_whitespace() {
                break;
            }
            i += 1;
        }
    }
    out
}

struct Scan<'a> {
    tokens: &'a [Tok],
    pos: usize,
    depth: usize,
    defs: &'a BTreeMap<String, Size>,
}

impl Scan<'_> {
    fn peek(&self) -> Option<&Tok> {
        self.tokens.get(self.pos)
    }

    /// One level deeper (a parenthesis or a unary sign); refused past the limit.
    fn enter(&mut self) -> Result<(), String> {
        self.depth += 1;
        if self.depth > FORMULA_DEPTH {
            return Err(format!(
                "the formula nests more than {FORMULA_DEPTH} levels deep (see docs/limits.md)"
            ));
        }
        Ok(())
    }

    fn sum(&mut self) -> Result<Size, String> {
        if matches!(self.peek(), Some(Tok::Op('+' | '-'))) {
            self.pos += 1;
        }
        let mut acc = self.product()?;
        while matches!(self.peek(), Some(Tok::Op('+' | '-'))) {
            self.pos += 1;
            acc = acc.add(self.product()?);
        }
        Ok(acc)
    }

    fn product(&mut self) -> Result<Size, String> {
        let mut acc = self.power()?;
        loop {
            match self.peek() {
                Some(Tok::Op('*')) => {
                    self.pos += 1;
                    acc = acc.mul(self.power()?);
                }
                Some(Tok::Op('/')) => {
                    self.pos += 1;
                    acc = acc.div(self.power()?);
                }
                Some(Tok::Num(_) | Tok::Ident(_) | Tok::Op('(')) => acc = acc.mul(self.power()?),
                _ => return Ok(acc),
            }
        }
    }

    fn power(&mut self) -> Result<Size, String> {
        let base = self.primary()?;
        if let Some(Tok::Op('^')) = self.peek() {
            self.pos += 1;
            if let Some(&Tok::Num(e)) = self.peek() {
                self.pos += 1;
                if e > FORMULA_EXPONENT {
                    return Err(format!(
                        "the exponent {} is larger than the limit of {FORMULA_EXPONENT} (see docs/limits.md)",
                        if e == u64::MAX { "written".to_string() } else { e.to_string() }
                    ));
                }
                return Ok(base.pow(e));
            }
        }
        Ok(base)
    }

    fn primary(&mut self) -> Result<Size, String> {
        match self.peek().cloned() {
            Some(Tok::Num(_)) => {
                self.pos += 1;
                Ok(Size::ONE)
            }
            Some(Tok::Ident(name)) => {
                self.pos += 1;
                Ok(self.defs.get(&name).copied().unwrap_or(Size::VAR))
            }
            Some(Tok::Op('(')) => {
                self.pos += 1;
                self.enter()?;
                let inner = self.sum()?;
                self.depth -= 1;
                if let Some(Tok::Op(')')) = self.peek() {
                    self.pos += 1;
                }
                Ok(inner)
            }
            Some(Tok::Op('-')) => {
                self.pos += 1;
                self.enter()?;
                let inner = self.power()?;
                self.depth -= 1;
                Ok(inner)
            }
            // what the parser rejects is its to report
            _ => Ok(Size::ONE),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ok(t: &str) -> bool {
        check(t, &BTreeMap::new()).is_ok()
    }

    #[test]
    fn ordinary_formulas_pass_and_bombs_are_refused() {
        assert!(ok("2(-a_1^2+b_1^2+c_1^2) - 2(-a_3^2+b_3^2+c_3^2)"));
        assert!(ok("(x^2 - y)/(x + 1)"));
        let deep = format!("{}x{}", "(".repeat(10_000), ")".repeat(10_000));
        assert!(check(&deep, &BTreeMap::new()).is_err());
        let deep = format!("{}x{}", "(".repeat(1_000), ")".repeat(1_000));
        assert!(check(&deep, &BTreeMap::new())
            .unwrap_err()
            .contains("nests"));
        let at_limit = format!(
            "{}x{}",
            "(".repeat(FORMULA_DEPTH),
            ")".repeat(FORMULA_DEPTH)
        );
        assert!(ok(&at_limit));
        assert!(check("x^1000000000", &BTreeMap::new())
            .unwrap_err()
            .contains("exponent"));
        assert!(ok("x^64"));
        assert!(!ok("x^65"));
        assert!(check("(a+b+c+d+e+f)^40", &BTreeMap::new())
            .unwrap_err()
            .contains("terms"));
        assert!(check("((x^64)^64)^64", &BTreeMap::new())
            .unwrap_err()
            .contains("degree"));
        assert!(!ok(&"-".repeat(10_000)));
        assert!(!ok(&"x".repeat(FORMULA_CHARS + 1)));
    }

    #[test]
    fn definitions_carry_their_size() {
        let mut defs = BTreeMap::new();
        let big = check("(a+b+c+d)^8", &defs).unwrap();
        defs.insert("D".to_string(), big);
        assert!(check("D", &defs).is_ok());
        assert!(check("D^4", &defs).is_err());
    }
}
