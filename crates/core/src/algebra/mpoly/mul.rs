//! Multiplication: a heap over the shorter operand (Johnson, with Monagan and Pearce's
//! row-by-row insertion so the heap never holds more than one entry per row), a hash table
//! of the product's monomials sorted once at the end, or, when the product is dense and its
//! coefficients are words, an array of accumulators indexed by the Kronecker substitution
//! (FLINT's `mul_array`, in the `array` module).
//!
//! The heap pops every product through about log₂ m comparisons of unrelated monomials,
//! which a processor mispredicts half the time; the table adds each product where its
//! monomial hashes, and sorts only the distinct monomials. The heap is kept for a short
//! operand, whose heap is shallow.

use super::coeff::{Acc, Coef};
use super::heap::Heap;
use super::monomial::{with_key, Key};
use super::MPoly;

/// How to multiply.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MulMethod {
    /// The array when it fits and the product is dense, else the table, or the heap for a
    /// short operand.
    Auto,
    /// Always the heap.
    Heap,
    /// Always the hash table.
    Hash,
}

/// `a · b` with the method chosen by shape.
pub fn mul(a: &MPoly, b: &MPoly) -> MPoly {
    mul_with(a, b, MulMethod::Auto)
}

/// `a · b` with `method`.
pub fn mul_with(a: &MPoly, b: &MPoly, method: MulMethod) -> MPoly {
    if a.is_zero() || b.is_zero() {
        return MPoly::zero(a.nvars());
    }
    if method == MulMethod::Auto
        && let Some(p) = mul_array(a, b)
    {
        return p;
    }
    let (a, b) = MPoly::common_packing(a, b, a.degree() + b.degree());
    let (a, b) = if a.len() <= b.len() {
        (&a, &b)
    } else {
        (&b, &a)
    };
    let hash = match method {
        MulMethod::Auto => a.len() >= HASH_ROWS,
        MulMethod::Heap => false,
        MulMethod::Hash => true,
    };
    match hash {
        true => with_key!(a.pack.words, hash_kernel(a, b)),
        false => with_key!(a.pack.words, heap_kernel(a, b)),
    }
}

/// `a²`: the table adds each product of two distinct terms once, doubled, so a square costs
/// about half the products of `a · a` (the dense array where it applies, the heap for a short
/// `a`, as for any product).
pub fn square(a: &MPoly) -> MPoly {
    if a.len() < HASH_ROWS || mul_array_applies(a, a) {
        return mul(a, a);
    }
    let (a, _) = MPoly::common_packing(a, a, 2 * a.degree());
    with_key!(a.pack.words, square_kernel(&a))
}

/// [`hash_kernel`] of `a · a` over the pairs i ≤ j.
fn square_kernel<K: Key>(a: &MPoly) -> MPoly {
    let ak: Vec<K> = (0..a.len()).map(|i| K::load(a.packed(i))).collect();
    let mut table = Table::<K>::with_room(a.len() * 4);
    for (i, x) in ak.iter().enumerate() {
        let e = table.entry(x.add(x));
        table.sums[e].add_mul(&a.coefs[i], &a.coefs[i]);
        for (j, y) in ak.iter().enumerate().skip(i + 1) {
            let e = table.entry(x.add(y));
            table.sums[e].add_mul(&a.coefs[i], &a.coefs[j]);
            table.sums[e].add_mul(&a.coefs[i], &a.coefs[j]);
        }
    }
    table.into_poly(a.pack)
}

/// `a · b` by the heap method.
pub fn mul_heap(a: &MPoly, b: &MPoly) -> MPoly {
    mul_with(a, b, MulMethod::Heap)
}

/// Rows of the shorter operand from which the hash table replaces the heap.
const HASH_ROWS: usize = 8;

/// Marks an empty place of the table.
const EMPTY: u32 = u32::MAX;

/// The hash kernel: each product added at its monomial's place of an open-addressing table
/// (linear probing, at most half full), the distinct monomials then sorted once. `a` and `b`
/// share a packing that holds the product.
fn hash_kernel<K: Key>(a: &MPoly, b: &MPoly) -> MPoly {
    let ak: Vec<K> = (0..a.len()).map(|i| K::load(a.packed(i))).collect();
    let bk: Vec<K> = (0..b.len()).map(|j| K::load(b.packed(j))).collect();
    let mut table = Table::<K>::with_room((a.len() + b.len()) * 2);
    for (i, x) in ak.iter().enumerate() {
        for (j, y) in bk.iter().enumerate() {
            let e = table.entry(x.add(y));
            table.sums[e].add_mul(&a.coefs[i], &b.coefs[j]);
        }
    }
    table.into_poly(a.pack)
}

/// Monomials with their running sums, found through an index of places.
struct Table<K> {
    /// Per place, the entry there or [`EMPTY`].
    places: Vec<u32>,
    keys: Vec<K>,
    sums: Vec<Acc>,
}

impl<K: Key> Table<K> {
    /// A table for about `n` monomials before it grows.
    fn with_room(n: usize) -> Self {
        Table {
            places: vec![EMPTY; (2 * n).next_power_of_two()],
            keys: Vec::with_capacity(n),
            sums: Vec::with_capacity(n),
        }
    }

    /// The entry of monomial `k`, a new one (its sum zero) when `k` is new.
    #[inline]
    fn entry(&mut self, k: K) -> usize {
        let mask = self.places.len() - 1;
        let mut h = k.hash() as usize & mask;
        loop {
            match self.places[h] {
                EMPTY => break,
                e if self.keys[e as usize] == k => return e as usize,
                _ => h = (h + 1) & mask,
            }
        }
        let e = self.keys.len();
        self.places[h] = e as u32;
        self.keys.push(k);
        self.sums.push(Acc::default());
        if 2 * self.keys.len() > self.places.len() {
            self.grow();
        }
        e
    }

    /// Twice the places, every entry placed again.
    fn grow(&mut self) {
        let mask = 2 * self.places.len() - 1;
        self.places = vec![EMPTY; mask + 1];
        for (e, k) in self.keys.iter().enumerate() {
            let mut h = k.hash() as usize & mask;
            while self.places[h] != EMPTY {
                h = (h + 1) & mask;
            }
            self.places[h] = e as u32;
        }
    }

    /// The non-zero sums in descending monomial order.
    fn into_poly(self, pack: super::monomial::Packing) -> MPoly {
        let mut order: Vec<(K, u32)> = self.keys.into_iter().zip(0u32..).collect();
        order.sort_unstable_by(|x, y| y.0.cmp(&x.0));
        let mut sums = self.sums;
        let mut out = MPoly {
            pack,
            exps: Vec::with_capacity(order.len() * pack.words),
            coefs: Vec::with_capacity(order.len()),
        };
        for (k, e) in order {
            let c = sums[e as usize].take();
            if !c.is_zero() {
                k.store(&mut out.exps);
                out.coefs.push(c);
            }
        }
        out
    }
}

/// The heap kernel: `a` is the shorter operand; both share a packing that holds the product.
/// Every entry's successors are smaller than it, so each product is taken from the top and
/// replaced by its successor in the same row in one sift.
fn heap_kernel<K: Key>(a: &MPoly, b: &MPoly) -> MPoly {
    let ak: Vec<K> = (0..a.len()).map(|i| K::load(a.packed(i))).collect();
    let bk: Vec<K> = (0..b.len()).map(|j| K::load(b.packed(j))).collect();
    let small = |p: &MPoly| {
        p.coefs
            .iter()
            .map(Coef::small)
            .collect::<Option<Vec<i64>>>()
    };
    let smalls = small(a).zip(small(b));
    let mut out = MPoly {
        pack: a.pack,
        exps: Vec::new(),
        coefs: Vec::new(),
    };
    let mut heap: Heap<K> = Heap::with_capacity(ak.len());
    heap.push((ak[0].add(&bk[0]), 0, 0));
    let mut acc = Acc::default();
    while let Some(key) = heap.top().map(|t| t.0.clone()) {
        while let Some((k, i, j)) = heap.top() {
            if *k != key {
                break;
            }
            let (iu, ju) = (*i as usize, *j as usize);
            match &smalls {
                Some((sa, sb)) => acc.add_i128(i128::from(sa[iu]) * i128::from(sb[ju])),
                None => acc.add_mul(&a.coefs[iu], &b.coefs[ju]),
            }
            let next =
                (ju + 1 < bk.len()).then(|| (ak[iu].add(&bk[ju + 1]), iu as u32, ju as u32 + 1));
            heap.replace_top(next);
            // row i + 1 enters only once row i has started (Monagan–Pearce)
            if ju == 0 && iu + 1 < ak.len() {
                heap.push((ak[iu + 1].add(&bk[0]), iu as u32 + 1, 0));
            }
        }
        let c = acc.take();
        if !c.is_zero() {
            key.store(&mut out.exps);
            out.coefs.push(c);
        }
    }
    out
}

/// Whether [`mul_array`] applies to `a · b`.
fn mul_array_applies(a: &MPoly, b: &MPoly) -> bool {
    !a.is_zero() && !b.is_zero() && a.nvars() == b.nvars() && super::array::applies(a, b)
}

/// `a · b` by the dense array method, or `None` when it does not apply (see the module doc).
pub fn mul_array(a: &MPoly, b: &MPoly) -> Option<MPoly> {
    if a.is_zero() || b.is_zero() || a.nvars() != b.nvars() {
        return None;
    }
    super::array::product(a, b)
}
