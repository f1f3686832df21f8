//! Multiplication: a heap over the shorter operand (Johnson, with Monagan and Pearce's
//! row-by-row insertion so the heap never holds more than one entry per row), or, when the
//! product is dense and its coefficients are words, an array of accumulators indexed by the
//! Kronecker substitution (FLINT's `mul_array`, in the `array` module).

use super::coeff::{Acc, Coef};
use super::heap::Heap;
use super::monomial::{with_key, Key};
use super::MPoly;

/// How to multiply.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MulMethod {
    /// The array when it fits and the product is dense, else the heap.
    Auto,
    /// Always the heap.
    Heap,
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

/// `a · b` by the dense array method, or `None` when it does not apply (see the module doc).
pub fn mul_array(a: &MPoly, b: &MPoly) -> Option<MPoly> {
    if a.is_zero() || b.is_zero() || a.nvars() != b.nvars() {
        return None;
    }
    super::array::product(a, b)
}
