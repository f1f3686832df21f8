//! Multiplication: a heap over the shorter operand (Johnson, with Monagan and Pearce's
//! row-by-row insertion so the heap never holds more than one entry per row), or, when the
//! product is dense and its coefficients provably fit, an array of i128 accumulators
//! indexed by the Kronecker substitution (FLINT's `mul_array`).

use super::coeff::{Acc, Coef};
use super::heap::Heap;
use super::monomial::{with_key, Key, Packing};
use super::MPoly;

/// How to multiply.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MulMethod {
    /// The array when it fits and the product is dense, else the heap.
    Auto,
    /// Always the heap.
    Heap,
}

/// Largest accumulator array (i128 slots): 128 MiB.
const ARRAY_SLOTS: usize = 1 << 23;

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
    mul_heap(a, b)
}

/// `a · b` by the heap method.
pub fn mul_heap(a: &MPoly, b: &MPoly) -> MPoly {
    if a.is_zero() || b.is_zero() {
        return MPoly::zero(a.nvars());
    }
    let (a, b) = MPoly::common_packing(a, b, a.degree() + b.degree());
    let (a, b) = if a.len() <= b.len() {
        (&a, &b)
    } else {
        (&b, &a)
    };
    with_key!(a.pack.words, heap_kernel(a, b))
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

/// Exponent bounds of the dense product box, when the array method applies: all
/// coefficients small, every coefficient of the product provably within i128
/// (max|a| · max|b| · min(m, n) < 2¹²⁶), the box at most [`ARRAY_SLOTS`] and no larger than
/// the number of term products (so scanning it costs less than the products).
fn array_box(a: &MPoly, b: &MPoly) -> Option<Vec<usize>> {
    let small = |p: &MPoly| p.coefs.iter().all(|c| c.small().is_some());
    if !small(a) || !small(b) {
        return None;
    }
    let max_bits = |p: &MPoly| p.coefs.iter().map(Coef::bits).max().unwrap_or(0);
    let shorter = a.len().min(b.len()) as u64;
    if max_bits(a) + max_bits(b) + u64::from(64 - shorter.leading_zeros()) > 126 {
        return None;
    }
    let dims: Vec<usize> = (0..a.nvars())
        .map(|i| (a.degree_in(i) + b.degree_in(i) + 1) as usize)
        .collect();
    let size = dims.iter().try_fold(1usize, |s, d| s.checked_mul(*d))?;
    let products = a.len().checked_mul(b.len())?;
    (size <= ARRAY_SLOTS && size <= products).then_some(dims)
}

/// `a · b` by the dense array method, or `None` when it does not apply (see the module doc).
pub fn mul_array(a: &MPoly, b: &MPoly) -> Option<MPoly> {
    if a.is_zero() || b.is_zero() || a.nvars() != b.nvars() {
        return None;
    }
    let dims = array_box(a, b)?;
    let pack = Packing::for_degree(a.nvars(), a.degree() + b.degree());
    Some(with_key!(pack.words, array_kernel(a, b, &dims, pack)))
}

fn array_kernel<K: Key>(a: &MPoly, b: &MPoly, dims: &[usize], pack: Packing) -> MPoly {
    // variable 0 most significant: the index order is lexicographic
    let mut stride = vec![1usize; dims.len()];
    for i in (0..dims.len().saturating_sub(1)).rev() {
        stride[i] = stride[i + 1] * dims[i + 1];
    }
    let index = |p: &MPoly, t: usize| -> usize {
        let m = p.packed(t);
        (0..dims.len())
            .map(|i| p.pack.exponent(m, i) as usize * stride[i])
            .sum()
    };
    let small = |c: &Coef| i128::from(c.small().unwrap_or(0));
    let mut bs: Vec<(usize, i128)> = (0..b.len())
        .map(|j| (index(b, j), small(&b.coefs[j])))
        .collect();
    bs.sort_unstable_by_key(|t| t.0);
    let size: usize = dims.iter().product();
    let mut acc = vec![0i128; size];
    for i in 0..a.len() {
        let (base, ca) = (index(a, i), small(&a.coefs[i]));
        let row = &mut acc[base..];
        for &(k, cb) in &bs {
            row[k] += ca * cb;
        }
    }
    let mut terms: Vec<(K, i128)> = Vec::new();
    let (mut e, mut w) = (vec![0u32; dims.len()], vec![0u64; pack.words]);
    for (k, &c) in acc.iter().enumerate().filter(|(_, c)| **c != 0) {
        for (i, x) in e.iter_mut().enumerate() {
            *x = ((k / stride[i]) % dims[i]) as u32;
        }
        pack.pack_into(&e, &mut w);
        terms.push((K::load(&w), c));
    }
    terms.sort_unstable_by(|x, y| y.0.cmp(&x.0));
    let mut out = MPoly {
        pack,
        exps: Vec::with_capacity(terms.len() * pack.words),
        coefs: Vec::with_capacity(terms.len()),
    };
    for (k, c) in terms {
        k.store(&mut out.exps);
        out.coefs.push(Coef::from_i128(c));
    }
    out
}
