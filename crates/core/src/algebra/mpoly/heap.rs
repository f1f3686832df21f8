//! A binary max-heap of (monomial, row, column) entries ordered by the monomial alone, with
//! `replace_top`: the kernels replace a popped entry by its successor in one sift.

use super::monomial::Key;

/// Heap entry: a monomial and the term indices it came from.
pub type Entry<K> = (K, u32, u32);

/// A max-heap on the monomial.
pub struct Heap<K: Key> {
    v: Vec<Entry<K>>,
}

impl<K: Key> Heap<K> {
    /// An empty heap with room for `n` entries.
    pub fn with_capacity(n: usize) -> Self {
        Heap {
            v: Vec::with_capacity(n),
        }
    }

    /// The largest entry.
    #[inline]
    pub fn top(&self) -> Option<&Entry<K>> {
        self.v.first()
    }

    /// Insert.
    #[inline]
    pub fn push(&mut self, e: Entry<K>) {
        self.v.push(e);
        let mut i = self.v.len() - 1;
        while i > 0 {
            let parent = (i - 1) / 2;
            if self.v[parent].0 >= self.v[i].0 {
                break;
            }
            self.v.swap(parent, i);
            i = parent;
        }
    }

    /// Replace the largest entry by `e`, or remove it when `e` is `None`.
    #[inline]
    pub fn replace_top(&mut self, e: Option<Entry<K>>) {
        let e = match e {
            Some(e) => e,
            None => match self.v.pop() {
                Some(last) if !self.v.is_empty() => last,
                _ => return,
            },
        };
        self.sift_down(e);
    }

    /// Put `e` at the root and move it down: children move up into the hole, `e` is
    /// written once at its place.
    #[inline]
    fn sift_down(&mut self, e: Entry<K>) {
        let n = self.v.len();
        let mut i = 0;
        loop {
            let l = 2 * i + 1;
            if l >= n {
                break;
            }
            let c = if l + 1 < n && self.v[l + 1].0 > self.v[l].0 {
                l + 1
            } else {
                l
            };
            if e.0 >= self.v[c].0 {
                break;
            }
            self.v[i] = self.v[c].clone();
            i = c;
        }
        self.v[i] = e;
    }
}
