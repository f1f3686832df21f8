//! Repacking, merge-based addition, scalar operations, content, powers, splitting.

use std::borrow::Cow;
use std::cmp::Ordering;
use std::ops::{Add, Mul, Neg, Sub};

use super::coeff::{content, Coef};
use super::monomial::Packing;
use super::MPoly;

impl MPoly {
    /// The same polynomial with variable `i` of `self` moved to `to[i]` of `pack.nvars`
    /// variables, repacked with `pack`. `to` must be increasing, so the term order is kept;
    /// `pack` must hold the degree.
    pub fn remap(&self, to: &[usize], pack: Packing) -> MPoly {
        let identity = pack.nvars == self.nvars() && to.iter().enumerate().all(|(i, t)| i == *t);
        if identity && pack == self.pack {
            return self.clone();
        }
        let mut out = MPoly {
            pack,
            exps: Vec::with_capacity(self.len() * pack.words),
            coefs: self.coefs.clone(),
        };
        let (mut e, mut w) = (vec![0u32; pack.nvars], vec![0u64; pack.words]);
        for t in 0..self.len() {
            let m = self.packed(t);
            for (i, &j) in to.iter().enumerate() {
                e[j] = self.pack.exponent(m, i);
            }
            pack.pack_into(&e, &mut w);
            out.exps.extend_from_slice(&w);
        }
        out
    }

    /// Repacked with `pack` (same variables).
    pub fn repack(&self, pack: Packing) -> MPoly {
        let to: Vec<usize> = (0..self.nvars()).collect();
        self.remap(&to, pack)
    }

    /// Repacked to the narrowest packing for its degree (the canonical form).
    pub fn tighten(self) -> MPoly {
        let want = Packing::for_degree(self.nvars(), self.degree());
        if want == self.pack {
            self
        } else {
            self.repack(want)
        }
    }

    /// Drop the variables not marked in `keep` (they must not occur).
    pub fn drop_vars(&self, keep: &[bool]) -> MPoly {
        let kept: Vec<usize> = (0..keep.len()).filter(|&i| keep[i]).collect();
        let pack = Packing::for_degree(kept.len(), self.degree());
        let mut out = MPoly {
            pack,
            exps: Vec::with_capacity(self.len() * pack.words),
            coefs: self.coefs.clone(),
        };
        let (mut e, mut w) = (vec![0u32; kept.len()], vec![0u64; pack.words]);
        for t in 0..self.len() {
            for (d, &i) in kept.iter().enumerate() {
                e[d] = self.pack.exponent(self.packed(t), i);
            }
            pack.pack_into(&e, &mut w);
            out.exps.extend_from_slice(&w);
        }
        out
    }

    /// Both in one packing that holds total degree `deg` and both operands: borrowed where
    /// one is packed so already (a copy of its terms would cost as much as the operation).
    pub(crate) fn common_packing<'a>(
        a: &'a MPoly,
        b: &'a MPoly,
        deg: u64,
    ) -> (Cow<'a, MPoly>, Cow<'a, MPoly>) {
        let want = Packing::for_degree(a.nvars(), deg.max(a.degree()).max(b.degree()));
        let bits = want.bits.max(a.pack.bits).max(b.pack.bits);
        let pack = Packing::with_bits(a.nvars(), bits);
        let fit = |p: &'a MPoly| match p.pack == pack {
            true => Cow::Borrowed(p),
            false => Cow::Owned(p.repack(pack)),
        };
        (fit(a), fit(b))
    }

    /// `self + sign · other` by merging the two sorted term arrays.
    fn merge(&self, other: &MPoly, negate: bool) -> MPoly {
        let (a, b) = MPoly::common_packing(self, other, 0);
        let mut out = MPoly {
            pack: a.pack,
            exps: Vec::with_capacity(a.exps.len() + b.exps.len()),
            coefs: Vec::with_capacity(a.len() + b.len()),
        };
        let sb = |c: &Coef| if negate { c.neg() } else { c.clone() };
        let (mut i, mut j) = (0, 0);
        while i < a.len() && j < b.len() {
            match a.packed(i).cmp(b.packed(j)) {
                Ordering::Greater => {
                    out.push(a.packed(i), a.coefs[i].clone());
                    i += 1;
                }
                Ordering::Less => {
                    out.push(b.packed(j), sb(&b.coefs[j]));
                    j += 1;
                }
                Ordering::Equal => {
                    out.push(a.packed(i), a.coefs[i].add(&sb(&b.coefs[j])));
                    i += 1;
                    j += 1;
                }
            }
        }
        for t in i..a.len() {
            out.push(a.packed(t), a.coefs[t].clone());
        }
        for t in j..b.len() {
            out.push(b.packed(t), sb(&b.coefs[t]));
        }
        out.tighten()
    }

    /// Multiply every coefficient by `c`.
    pub fn scale(&self, c: &Coef) -> MPoly {
        if c.is_zero() {
            return MPoly::zero(self.nvars());
        }
        let mut out = self.clone();
        out.coefs.iter_mut().for_each(|k| *k = k.mul(c));
        out
    }

    /// Divide every coefficient by `c`, which divides each exactly (else `None`).
    pub fn div_coef(&self, c: &Coef) -> Option<MPoly> {
        let mut out = self.clone();
        for k in out.coefs.iter_mut() {
            *k = k.div_exact(c)?;
        }
        Some(out)
    }

    /// The gcd of the coefficients, signed like the leading coefficient (0 for zero).
    pub fn content(&self) -> Coef {
        let g = content(&self.coefs);
        match self.coefs.first() {
            Some(lc) if lc.is_negative() => g.neg(),
            _ => g,
        }
    }

    /// [`MPoly::primitive`] of an owned polynomial: its coefficients divided in place, and
    /// nothing copied when the content is one.
    pub fn into_primitive(mut self) -> (Coef, MPoly) {
        let g = self.content();
        if g.is_zero() || g == Coef::Small(1) {
            return (if g.is_zero() { Coef::Small(0) } else { g }, self);
        }
        let divided: Option<Vec<Coef>> = self.coefs.iter().map(|k| k.div_exact(&g)).collect();
        if let Some(c) = divided {
            self.coefs = c;
        }
        (g, self)
    }

    /// `(content, primitive part)`: the primitive part has a positive leading coefficient.
    pub fn primitive(&self) -> (Coef, MPoly) {
        let g = self.content();
        if g.is_zero() || g == Coef::Small(1) {
            return (if g.is_zero() { Coef::Small(0) } else { g }, self.clone());
        }
        let p = self.div_coef(&g).unwrap_or_else(|| self.clone());
        (g, p)
    }

    /// `self^e` by repeated squaring (each square through [`super::mul::square`]).
    pub fn pow(&self, e: u32) -> MPoly {
        let mut result: Option<MPoly> = None;
        let mut base = std::borrow::Cow::Borrowed(self);
        let mut e = e;
        while e > 0 {
            if e & 1 == 1 {
                result = Some(match result {
                    None => base.clone().into_owned(),
                    Some(r) => &r * &*base,
                });
            }
            e >>= 1;
            if e > 0 {
                base = std::borrow::Cow::Owned(super::mul::square(&base));
            }
        }
        result.unwrap_or_else(|| MPoly::constant(self.nvars(), Coef::Small(1)))
    }

    /// `self = Σₑ out[e] · xᵢᵉ`: the coefficients with respect to variable `i` (each still in
    /// all variables, with xᵢ absent).
    pub fn coefficients_in(&self, i: usize) -> Vec<MPoly> {
        let d = self.degree_in(i) as usize;
        let mut out: Vec<Vec<(Vec<u32>, Coef)>> = vec![Vec::new(); d + 1];
        for t in 0..self.len() {
            let mut e = self.exponents(t);
            let k = std::mem::take(&mut e[i]) as usize;
            out[k].push((e, self.coefs[t].clone()));
        }
        out.into_iter()
            .map(|terms| MPoly::from_terms(self.nvars(), terms))
            .collect()
    }
}

impl Add for &MPoly {
    type Output = MPoly;
    fn add(self, rhs: &MPoly) -> MPoly {
        self.merge(rhs, false)
    }
}

impl Sub for &MPoly {
    type Output = MPoly;
    fn sub(self, rhs: &MPoly) -> MPoly {
        self.merge(rhs, true)
    }
}

impl Neg for &MPoly {
    type Output = MPoly;
    fn neg(self) -> MPoly {
        self.scale(&Coef::Small(-1))
    }
}

impl Mul for &MPoly {
    type Output = MPoly;
    fn mul(self, rhs: &MPoly) -> MPoly {
        super::mul::mul(self, rhs)
    }
}
