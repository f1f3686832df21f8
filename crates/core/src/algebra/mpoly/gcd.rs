//! Greatest common divisors: the heuristic GCD of Char, Geddes and Gonnet (GCDHEU).
//!
//! One variable is evaluated at a large integer ξ, the gcd of the images is found
//! recursively (integers at the bottom), and the candidate is rebuilt from the balanced
//! ξ-adic digits of its coefficients. A candidate that divides both inputs exactly is the
//! gcd (ξ > 2·min(‖A‖∞, ‖B‖∞) + 2 makes the lifting faithful); otherwise ξ grows and the
//! attempt repeats. The images grow by a factor of the degree per variable, so a size
//! limit gives up rather than compute with huge integers; [`MPoly::gcd`] then falls back to
//! the primitive remainder sequences of [`super::prs`], which always answer.
//!
//! Before either, a test modulo a prime settles the common case of coprime inputs: for each
//! variable both use, the two are evaluated at a point in the others, and the univariate gcd
//! of the images has degree zero. Where the first input's leading coefficient in that
//! variable does not vanish at the point, the true gcd keeps its degree in the image, so it
//! has degree zero in every variable: it is a constant.

use num_bigint::BigInt;
use num_integer::Integer;
use num_traits::{Signed, Zero};

use super::coeff::Coef;
use super::eval::Scalar;
use super::MPoly;
use crate::algebra::modp::Fp;

/// Largest coefficient (in bits) an evaluated image may reach.
const IMAGE_BITS: u64 = 1 << 14;
/// Attempts with growing ξ per level.
const ATTEMPTS: usize = 6;

impl MPoly {
    /// The gcd with a positive leading coefficient (integer content included): the
    /// heuristic gcd when it answers, else the primitive remainder sequence
    /// ([`MPoly::gcd_prs`]), so there is always an answer and it is always exact.
    ///
    /// # Example
    /// ```
    /// use orthocheck_core::algebra::mpoly::Ring;
    /// let r = Ring::new(&["x", "y"]);
    /// let (x, y) = (r.var("x").unwrap(), r.var("y").unwrap());
    /// let g = &x + &y;
    /// let a = &g * &(&x - &y);
    /// let b = &g * &(&x * &y);
    /// assert_eq!(a.gcd(&b), g);
    /// ```
    pub fn gcd(&self, other: &MPoly) -> MPoly {
        self.gcd_heuristic(other)
            .unwrap_or_else(|| super::prs::gcd_prs(self, other))
    }

    /// The gcd by primitive polynomial remainder sequences alone (the fallback of
    /// [`MPoly::gcd`]; public so that the two can be compared).
    pub fn gcd_prs(&self, other: &MPoly) -> MPoly {
        super::prs::gcd_prs(self, other)
    }

    /// The heuristic gcd alone: `None` when it gives up (images too large, or every ξ
    /// tried was unlucky). An answer is always right: it divides both inputs, checked.
    pub fn gcd_heuristic(&self, other: &MPoly) -> Option<MPoly> {
        // gcd(0, b) = b with a positive leading coefficient
        let normal = |p: &MPoly| {
            let (c, pp) = p.primitive();
            pp.scale(&c.gcd(&Coef::Small(0)))
        };
        if self.is_zero() {
            return Some(normal(other));
        }
        if other.is_zero() {
            return Some(normal(self));
        }
        let (ca, a) = self.primitive();
        let (cb, b) = other.primitive();
        let g = match coprime(&a, &b) {
            true => MPoly::constant(a.nvars(), Coef::Small(1)),
            false => heu(&a, &b)?,
        };
        Some(g.scale(&ca.gcd(&cb)))
    }
}

/// Whether `a` and `b` (of one ring) are proven coprime up to a constant, by the test of
/// the module's doc modulo 2⁶¹ − 1; `false` says nothing.
fn coprime(a: &MPoly, b: &MPoly) -> bool {
    let (ua, ub) = (a.used(), b.used());
    let n = a.nvars();
    // the points: fixed residues, the same at every run
    let at: Vec<Fp> = (0..n as u64)
        .map(|k| {
            Fp::from_coef(&Coef::Small(
                (0x2545_f491_4f6c_dd1d_u64.wrapping_mul(k + 7) >> 4) as i64,
            ))
        })
        .collect();
    (0..n).filter(|&i| ua[i] && ub[i]).all(|i| {
        let (ea, eb) = (image(a, i, &at), image(b, i, &at));
        // the leading coefficient must survive, for the gcd's degree to survive
        ea.last().is_some_and(|c| c.0 != 0) && gcd_degree(ea, eb) == 0
    })
}

/// `p` with every variable but `i` set to its residue in `at`: a polynomial in xᵢ, its
/// coefficients from the constant up (as many as xᵢ's degree in `p` plus one).
fn image(p: &MPoly, i: usize, at: &[Fp]) -> Vec<Fp> {
    let mut out = vec![Fp::zero(); p.degree_in(i) as usize + 1];
    for t in 0..p.len() {
        let e = p.exponents(t);
        let v = e
            .iter()
            .enumerate()
            .filter(|&(k, &x)| k != i && x > 0)
            .fold(Fp::from_coef(p.coef(t)), |v, (k, &x)| {
                v.mul(&at[k].pow(u64::from(x)))
            });
        let slot = &mut out[e[i] as usize];
        *slot = slot.add(&v);
    }
    out
}

/// The degree of the gcd of two univariate polynomials modulo the prime (coefficients from
/// the constant up; a zero polynomial has no degree, and the gcd is then the other).
fn gcd_degree(mut a: Vec<Fp>, mut b: Vec<Fp>) -> usize {
    let trim = |p: &mut Vec<Fp>| {
        while p.last().is_some_and(|c| c.0 == 0) {
            p.pop();
        }
    };
    trim(&mut a);
    trim(&mut b);
    while !b.is_empty() {
        // a mod b
        let inv = b.last().and_then(|c| c.inv()).unwrap_or(Fp::zero());
        while a.len() >= b.len() {
            let f = a.last().map_or(Fp::zero(), |c| c.mul(&inv));
            let shift = a.len() - b.len();
            for (k, c) in b.iter().enumerate() {
                a[shift + k] = a[shift + k].sub(&f.mul(c));
            }
            trim(&mut a);
        }
        std::mem::swap(&mut a, &mut b);
    }
    a.len().saturating_sub(1)
}

/// gcd of two primitive polynomials with positive leading coefficients.
fn heu(a: &MPoly, b: &MPoly) -> Option<MPoly> {
    let n = a.nvars();
    if a == b {
        return Some(a.clone());
    }
    if a.degree() == 0 || b.degree() == 0 {
        return Some(MPoly::constant(n, Coef::Small(1)));
    }
    let (ua, ub) = (a.used(), b.used());
    let Some(i) = (0..n).find(|&i| ua[i] || ub[i]) else {
        return Some(MPoly::constant(n, Coef::Small(1)));
    };
    let norm = |p: &MPoly| {
        p.coefs()
            .iter()
            .map(|c| c.to_big().abs())
            .max()
            .unwrap_or_default()
    };
    let mut xi: BigInt = norm(a).min(norm(b)) * 2 + 29;
    let deg = u64::from(a.degree_in(i).max(b.degree_in(i)));
    let bits = |p: &MPoly| p.coefs().iter().map(Coef::bits).max().unwrap_or(0);
    for _ in 0..ATTEMPTS {
        if bits(a).max(bits(b)) + deg * xi.bits() > IMAGE_BITS {
            return None;
        }
        let (ea, eb) = (a.eval_var(i, &xi), b.eval_var(i, &xi));
        // the images only grow with ξ: a level below that gave up gives up again
        let g = ea.gcd_heuristic(&eb)?;
        let cand = lift(&g, i, &xi).primitive().1;
        if !cand.is_zero() && a.div_exact(&cand).is_some() && b.div_exact(&cand).is_some() {
            return Some(cand);
        }
        // the growth factor of the original algorithm (≈ 2.73, irrational-looking)
        xi = xi * 73794 / 27011;
    }
    None
}

/// `Σ digitsₖ · xᵢᵏ`: each coefficient of `g` (which is free of xᵢ) written in balanced
/// base ξ, digit k going to xᵢᵏ.
fn lift(g: &MPoly, i: usize, xi: &BigInt) -> MPoly {
    let half: BigInt = xi / 2;
    let mut terms = Vec::new();
    for t in 0..g.len() {
        let e = g.exponents(t);
        let mut c = g.coef(t).to_big();
        let mut k = 0u32;
        while !c.is_zero() {
            let mut d = c.mod_floor(xi);
            if d > half {
                d -= xi;
            }
            c = (c - &d) / xi;
            if !d.is_zero() {
                let mut ek = e.clone();
                ek[i] = k;
                terms.push((ek, Coef::from_big(d)));
            }
            k += 1;
        }
    }
    MPoly::from_terms(g.nvars(), terms)
}
