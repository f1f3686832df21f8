//! Sparse multivariate polynomials over ℤ the way fast engines store them (FLINT's
//! `fmpz_mpoly`): a ring context names the variables, exponent vectors are packed into u64
//! words (graded lexicographic order = integer order), terms sit in arrays sorted in
//! descending order, coefficients are machine integers until they overflow. Products use a
//! heap (Johnson / Monagan–Pearce) or, when the product is dense, an array of accumulators;
//! exact quotients use a heap as well; gcds are heuristic (GCDHEU) with a primitive
//! remainder sequence behind them when the heuristic gives up.
//!
//! [`crate::algebra::Poly`] (over ℚ, with named variables) is a rational content times one
//! of these primitive integer polynomials.

mod array;
pub mod coeff;
mod div;
pub mod eval;
mod gcd;
mod heap;
pub mod monomial;
pub mod mul;
mod ops;
mod prs;
pub mod ring;

pub use coeff::{content, Acc, Coef};
pub use eval::Scalar;
pub use monomial::Packing;
pub use mul::{mul_array, mul_heap, mul_with, square, MulMethod};
pub use ring::Ring;

/// A polynomial with integer coefficients in `nvars` variables (the variables are named by
/// a [`Ring`]): terms in descending graded lexicographic order, no zero coefficient.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::mpoly::Ring;
/// let r = Ring::new(&["x", "y"]);
/// let p = &r.var("x").unwrap() + &r.var("y").unwrap();
/// let q = p.pow(2);
/// assert_eq!(q.len(), 3);
/// assert_eq!(q.div_exact(&p), Some(p.clone()));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct MPoly {
    pack: Packing,
    /// `len · pack.words` words, term after term.
    exps: Vec<u64>,
    coefs: Vec<Coef>,
}

impl MPoly {
    /// Zero in `nvars` variables.
    pub fn zero(nvars: usize) -> MPoly {
        MPoly {
            pack: Packing::for_degree(nvars, 0),
            exps: Vec::new(),
            coefs: Vec::new(),
        }
    }

    /// The constant `c`.
    pub fn constant(nvars: usize, c: Coef) -> MPoly {
        let mut p = MPoly::zero(nvars);
        if !c.is_zero() {
            p.exps = vec![0; p.pack.words];
            p.coefs.push(c);
        }
        p
    }

    /// Variable `i` of `nvars`.
    pub fn var(nvars: usize, i: usize) -> MPoly {
        let mut e = vec![0; nvars];
        e[i] = 1;
        MPoly::from_terms(nvars, vec![(e, Coef::Small(1))])
    }

    /// From (exponents, coefficient) pairs in any order; equal monomials are added.
    pub fn from_terms(nvars: usize, mut terms: Vec<(Vec<u32>, Coef)>) -> MPoly {
        let deg = terms
            .iter()
            .map(|(e, _)| e.iter().map(|&x| u64::from(x)).sum::<u64>())
            .max()
            .unwrap_or(0);
        let pack = Packing::for_degree(nvars, deg);
        let mut packed: Vec<(Vec<u64>, Coef)> = terms
            .drain(..)
            .map(|(e, c)| {
                let mut w = vec![0; pack.words];
                pack.pack_into(&e, &mut w);
                (w, c)
            })
            .collect();
        packed.sort_by(|a, b| b.0.cmp(&a.0));
        let mut p = MPoly {
            pack,
            exps: Vec::with_capacity(packed.len() * pack.words),
            coefs: Vec::with_capacity(packed.len()),
        };
        let mut acc = Acc::default();
        for (k, (w, c)) in packed.iter().enumerate() {
            acc.add(c);
            if packed.get(k + 1).is_none_or(|n| n.0 != *w) {
                p.push(w, acc.take());
            }
        }
        p.tighten()
    }

    /// Append a term (callers keep the order; zero coefficients are dropped).
    #[inline]
    pub(crate) fn push(&mut self, exps: &[u64], c: Coef) {
        if !c.is_zero() {
            self.exps.extend_from_slice(exps);
            self.coefs.push(c);
        }
    }

    /// The packing of the exponents.
    pub fn packing(&self) -> Packing {
        self.pack
    }

    /// Number of variables.
    pub fn nvars(&self) -> usize {
        self.pack.nvars
    }

    /// Number of terms.
    pub fn len(&self) -> usize {
        self.coefs.len()
    }

    /// Whether zero.
    pub fn is_zero(&self) -> bool {
        self.coefs.is_empty()
    }

    /// Whether zero (same as [`MPoly::is_zero`]).
    pub fn is_empty(&self) -> bool {
        self.coefs.is_empty()
    }

    /// Coefficient of term `i` (0 = leading).
    pub fn coef(&self, i: usize) -> &Coef {
        &self.coefs[i]
    }

    /// All coefficients, leading first.
    pub fn coefs(&self) -> &[Coef] {
        &self.coefs
    }

    /// Packed monomial of term `i`.
    #[inline]
    pub fn packed(&self, i: usize) -> &[u64] {
        let w = self.pack.words;
        &self.exps[i * w..(i + 1) * w]
    }

    /// Exponents of term `i`, one per variable.
    pub fn exponents(&self, i: usize) -> Vec<u32> {
        self.pack.unpack(self.packed(i))
    }

    /// Total degree (0 for zero): that of the leading term, the order being graded.
    pub fn degree(&self) -> u64 {
        if self.is_zero() {
            0
        } else {
            self.pack.degree(self.packed(0))
        }
    }

    /// Degree in variable `i`.
    pub fn degree_in(&self, i: usize) -> u32 {
        (0..self.len())
            .map(|t| self.pack.exponent(self.packed(t), i))
            .max()
            .unwrap_or(0)
    }

    /// Which variables occur.
    pub fn used(&self) -> Vec<bool> {
        let mut any = vec![0u64; self.pack.words];
        for t in 0..self.len() {
            for (a, w) in any.iter_mut().zip(self.packed(t)) {
                *a |= w;
            }
        }
        (0..self.nvars())
            .map(|i| self.pack.exponent(&any, i) > 0)
            .collect()
    }
}
