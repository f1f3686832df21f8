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
    FORMULA_BITS, FORMULA_CHARS, FORMULA_DEGREE, FORMULA_DEPTH, FORMULA_DIGITS, FORMULA_EXPONENT,
    FORMULA_TERMS,
};

/// Upper bounds on a formula's expansion, as a quotient of two integer polynomials.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Size {
    /// Terms of the numerator.
    num: f64,
    /// Terms of the denominator.
    den: f64,
    /// Total degree (numerator and denominator together).
    degree: f64,
    /// Bits of the numerator's largest coefficient.
    num_bits: f64,
    /// Bits of the denominator's largest coefficient.
    den_bits: f64,
}

/// Bits a coefficient of a product gains from its terms: at most `min(terms)` products
/// meet in one monomial.
fn spread(a: f64, b: f64) -> f64 {
    a.min(b).max(1.0).log2()
}

impl Size {
    const ONE: Size = Size {
        num: 1.0,
        den: 1.0,
        degree: 0.0,
        num_bits: 0.0,
        den_bits: 0.0,
    };
    const VAR: Size = Size {
        degree: 1.0,
        ..Size::ONE
    };

    /// A decimal literal of `digits` digits, `decimals` of them after the point: an integer
    /// below 10^digits over 10^decimals.
    fn literal(digits: usize, decimals: usize) -> Size {
        Size {
            num_bits: digits as f64 * std::f64::consts::LOG2_10,
            den_bits: decimals as f64 * std::f64::consts::LOG2_10,
            ..Size::ONE
        }
    }

    /// (n₁d₂ + n₂d₁) / (d₁d₂).
    fn add(self, o: Size) -> Size {
        let cross = |a: Size, b: Size| a.num_bits + b.den_bits + spread(a.num, b.den);
        Size {
            num: self.num * o.den + o.num * self.den,
            den: self.den * o.den,
            degree: self.degree + o.degree,
            num_bits: cross(self, o).max(cross(o, self)) + 1.0,
            den_bits: self.den_bits + o.den_bits + spread(self.den, o.den),
        }
    }

    fn mul(self, o: Size) -> Size {
        Size {
            num: self.num * o.num,
            den: self.den * o.den,
            degree: self.degree + o.degree,
            num_bits: self.num_bits + o.num_bits + spread(self.num, o.num),
            den_bits: self.den_bits + o.den_bits + spread(self.den, o.den),
        }
    }

    fn div(self, o: Size) -> Size {
        self.mul(Size {
            num: o.den,
            den: o.num,
            num_bits: o.den_bits,
            den_bits: o.num_bits,
            ..o
        })
    }

    /// The `e`-th power: `e - 1` products with the base, each adding at most log₂ of the
    /// base's terms (`P^e` has coefficients below `C^e · t^(e-1)`).
    fn pow(self, e: u64) -> Size {
        let k = e as f64;
        let (n, d) = (self.num, self.den);
        let e = e as i32;
        Size {
            num: n.powi(e),
            den: d.powi(e),
            degree: self.degree * k,
            num_bits: self.num_bits * k + (k - 1.0).max(0.0) * n.max(1.0).log2(),
            den_bits: self.den_bits * k + (k - 1.0).max(0.0) * d.max(1.0).log2(),
        }
    }

    /// Bits of the largest coefficient, numerator or denominator.
    pub fn bits(&self) -> f64 {
        self.num_bits.max(self.den_bits)
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
    if size.bits() > FORMULA_BITS {
        return Err(format!(
            "the formula's coefficients can reach {:.0} bits, more than the limit of \
             {FORMULA_BITS} (see docs/limits.md)",
            size.bits()
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
    /// A number: its value as an exponent, its digits, and those after the point.
    Num(u64, usize, usize),
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
            let digits = s.chars().filter(char::is_ascii_digit).count();
            let decimals = s.split_once('.').map_or(0, |(_, f)| f.len());
            // an integer exponent's value; a decimal counts as a constant
            out.push(Tok::Num(s.parse().unwrap_or(u64::MAX), digits, decimals));
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
                Some(Tok::Num(..) | Tok::Ident(_) | Tok::Op('(')) => acc = acc.mul(self.power()?),
                _ => return Ok(acc),
            }
        }
    }

    fn power(&mut self) -> Result<Size, String> {
        let base = self.primary()?;
        if let Some(Tok::Op('^')) = self.peek() {
            self.pos += 1;
            if let Some(&Tok::Num(e, ..)) = self.peek() {
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
            Some(Tok::Num(_, digits, decimals)) => {
                self.pos += 1;
                if digits > FORMULA_DIGITS {
                    return Err(format!(
                        "a number in the formula has {digits} digits, more than the limit of \
                         {FORMULA_DIGITS} (see docs/limits.md)"
                    ));
                }
                Ok(Size::literal(digits, decimals))
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
    fn number_size_is_bounded_before_any_arithmetic() {
        let err = |t: &str| check(t, &BTreeMap::new()).unwrap_err();
        assert!(err("((((9)^64)^64)^64)^64").contains("bits"));
        assert!(err(&format!("({})^64", "9".repeat(5000))).contains("5000 digits"));
        assert!(ok(&"9".repeat(FORMULA_DIGITS)));
        assert!(!ok(&"9".repeat(FORMULA_DIGITS + 1)));
        // (10^99 x + 1)^12 stays within the bits (about 4,010), the 13th power not (4,344)
        let big = format!("1{}", "0".repeat(FORMULA_DIGITS - 1));
        assert!(ok(&format!("({big}x + 1)^12")));
        assert!(err(&format!("({big}x + 1)^13")).contains("bits"));
        // 0.5 + 0.25 over the common denominator is (5·100 + 25·10) / (10·100): the bound
        // covers the 750
        let sum = check("0.5 + 0.25", &BTreeMap::new()).unwrap();
        assert!(sum.bits() >= 750f64.log2());
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
