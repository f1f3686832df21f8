//! Exact division by a heap over the quotient terms found so far.
//!
//! Each quotient term `qᵢ` contributes the products `qᵢ · bⱼ` (j ≥ 1) in descending order;
//! the heap merges them with the dividend, so every term of the running remainder is formed
//! once, at its turn, without building the intermediate remainders.

use std::collections::BinaryHeap;

use super::coeff::{Acc, Coef};
use super::monomial::{with_key, Key};
use super::MPoly;

impl MPoly {
    /// `self / d` when `d` divides `self` exactly in ℤ\[x\], else `None` (also for `d = 0`).
    pub fn div_exact(&self, d: &MPoly) -> Option<MPoly> {
        if d.is_zero() {
            return None;
        }
        if self.is_zero() {
            return Some(MPoly::zero(self.nvars()));
        }
        // every monomial met has total degree ≤ deg(self), the order being graded
        if d.degree() > self.degree() {
            return None;
        }
        let (a, b) = MPoly::common_packing(self, d, self.degree());
        with_key!(a.pack.words, div_kernel(&a, &b)).map(MPoly::tighten)
    }
}

/// The next monomial to form: the larger of the dividend's next term and the heap's top.
fn next_key<K: Key>(ak: &[K], ai: usize, heap: &BinaryHeap<(K, u32, u32)>) -> Option<K> {
    match (ak.get(ai), heap.peek()) {
        (Some(x), Some(t)) => Some(if *x >= t.0 { x.clone() } else { t.0.clone() }),
        (Some(x), None) => Some(x.clone()),
        (None, Some(t)) => Some(t.0.clone()),
        (None, None) => None,
    }
}

fn div_kernel<K: Key>(a: &MPoly, b: &MPoly) -> Option<MPoly> {
    let ak: Vec<K> = (0..a.len()).map(|i| K::load(a.packed(i))).collect();
    let bk: Vec<K> = (0..b.len()).map(|j| K::load(b.packed(j))).collect();
    let mask = K::load(&a.pack.guard_mask());
    let (lb, lc) = (&bk[0], &b.coefs[0]);
    let mut q = MPoly {
        pack: a.pack,
        exps: Vec::new(),
        coefs: Vec::new(),
    };
    let mut qk: Vec<K> = Vec::new();
    let mut heap: BinaryHeap<(K, u32, u32)> = BinaryHeap::new();
    let (mut ai, mut acc) = (0, Acc::default());
    while let Some(key) = next_key(&ak, ai, &heap) {
        if ak.get(ai) == Some(&key) {
            acc.add(&a.coefs[ai]);
            ai += 1;
        }
        while heap.peek().is_some_and(|t| t.0 == key) {
            let Some((_, i, j)) = heap.pop() else { break };
            let (iu, ju) = (i as usize, j as usize);
            acc.sub_mul(&q.coefs[iu], &b.coefs[ju]);
            if ju + 1 < bk.len() {
                heap.push((qk[iu].add(&bk[ju + 1]), i, j + 1));
            }
        }
        let c = acc.take();
        if c.is_zero() {
            continue;
        }
        // a term of the remainder that the leading term of b cannot remove: not exact
        let m = key.sub_guarded(lb, &mask)?;
        let k: Coef = c.div_exact(lc)?;
        if bk.len() > 1 {
            heap.push((m.add(&bk[1]), qk.len() as u32, 1));
        }
        m.store(&mut q.exps);
        q.coefs.push(k);
        qk.push(m);
    }
    Some(q)
}
