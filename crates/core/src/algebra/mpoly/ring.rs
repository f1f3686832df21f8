//! The ring context: the variables, in the order that defines the monomial order.

use std::fmt::Write;
use std::sync::Arc;

use super::MPoly;

/// Named variables of a polynomial ring over ℤ (or ℚ), sorted by name; the monomial order
/// is graded lexicographic with the variables in this order.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::mpoly::Ring;
/// let r = Ring::new(&["y", "x"]);
/// let (x, y) = (r.var("x").unwrap(), r.var("y").unwrap());
/// let p = &(&x + &y) * &(&x - &y);
/// assert_eq!(r.display(&p), "x^2 - y^2");
/// ```
#[derive(Clone, Debug, PartialEq, Eq, Hash, Default)]
pub struct Ring {
    names: Vec<Arc<str>>,
}

impl Ring {
    /// The ring in `names` (sorted and deduplicated).
    pub fn new<S: AsRef<str>>(names: &[S]) -> Ring {
        let mut names: Vec<Arc<str>> = names.iter().map(|s| Arc::from(s.as_ref())).collect();
        names.sort();
        names.dedup();
        Ring { names }
    }

    /// Number of variables.
    pub fn nvars(&self) -> usize {
        self.names.len()
    }

    /// Variable names, in order.
    pub fn names(&self) -> &[Arc<str>] {
        &self.names
    }

    /// Index of the variable `name`.
    pub fn index(&self, name: &str) -> Option<usize> {
        self.names.binary_search_by(|n| (**n).cmp(name)).ok()
    }

    /// The variable `name` as a polynomial.
    pub fn var(&self, name: &str) -> Option<MPoly> {
        Some(MPoly::var(self.nvars(), self.index(name)?))
    }

    /// The ring of the variables of both, and where each ring's variables go in it.
    pub fn union(&self, other: &Ring) -> (Ring, Vec<usize>, Vec<usize>) {
        let mut names: Vec<Arc<str>> = self.names.iter().chain(&other.names).cloned().collect();
        names.sort();
        names.dedup();
        let u = Ring { names };
        let (a, b) = (u.place(self), u.place(other));
        (u, a, b)
    }

    /// Where the variables of `sub` (a ring of some of these variables) go in this ring.
    pub fn place(&self, sub: &Ring) -> Vec<usize> {
        sub.names.iter().filter_map(|n| self.index(n)).collect()
    }

    /// The ring keeping only the variables marked in `keep`.
    pub fn subset(&self, keep: &[bool]) -> Ring {
        let names = self
            .names
            .iter()
            .zip(keep)
            .filter(|(_, k)| **k)
            .map(|(n, _)| n.clone())
            .collect();
        Ring { names }
    }

    /// `p` printed in the ring's order (descending terms), e.g. `3*x^2*y - 1`.
    pub fn display(&self, p: &MPoly) -> String {
        if p.is_zero() {
            return "0".into();
        }
        let mut s = String::new();
        for i in 0..p.len() {
            let (c, e) = (p.coef(i), p.exponents(i));
            let neg = c.is_negative();
            let abs = if neg { c.neg() } else { c.clone() };
            s.push_str(match (i, neg) {
                (0, true) => "-",
                (0, false) => "",
                (_, true) => " - ",
                (_, false) => " + ",
            });
            let mono: Vec<String> = e
                .iter()
                .zip(&self.names)
                .filter(|(k, _)| **k > 0)
                .map(|(k, n)| {
                    if *k == 1 {
                        n.to_string()
                    } else {
                        format!("{n}^{k}")
                    }
                })
                .collect();
            let _ = match (mono.is_empty(), abs.is_unit()) {
                (true, _) => write!(s, "{abs}"),
                (false, true) => write!(s, "{}", mono.join("*")),
                (false, false) => write!(s, "{abs}*{}", mono.join("*")),
            };
        }
        s
    }
}
