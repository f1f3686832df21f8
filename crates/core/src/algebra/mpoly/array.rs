//! The dense array product (FLINT's `mul_array`), accumulated in cache-sized chunks.
//!
//! Exponents index a box over the product's degree bounds (Kronecker substitution). The
//! leading variables cut the box into chunks of at most [`CHUNK_BYTES`] of accumulators,
//! which stay in the inner caches: each operand's terms are grouped by their leading
//! exponents, and a chunk of the product sums the pairs of groups whose leading exponents
//! add up to its own. One slot per point of the whole box instead touches a new cache line
//! with nearly every product, and its memory grows with the box. Chunks are drained in
//! descending lexicographic order, so one stable pass by total degree puts the product in
//! the ring's graded order, with no sort. Each line of a chunk (its slots that share every
//! exponent but the last) keeps the span its products touched, and a drain reads those
//! spans alone: most of a dense product's box is never touched (4.8 % of Fateman's n = 20
//! box holds a term).
//!
//! Where both operands' terms fill at least half of their rows along the last variable (a
//! dense product such as Fateman's), a pair of groups is multiplied row by row: up to eight
//! terms of one row sweep the other together, so the products that meet in a slot are summed
//! in registers and the slot is written once, in order. Otherwise each product is added at
//! its own index.
//!
//! Coefficients are machine words, so every product fits an i128. A slot is an i128 when
//! the sums provably fit it (max|a| · max|b| · min(m, n) < 2¹²⁶), else an i128 and a count
//! of its overflows (FLINT's three-limb accumulator): the count is at most the number of
//! products, so that slot is exact for any operands of word-sized coefficients.

use num_bigint::BigInt;

use super::coeff::Coef;
use super::monomial::Packing;
use super::MPoly;

/// Bytes of accumulators in one chunk (within a core's second-level cache).
const CHUNK_BYTES: usize = 128 << 10;

/// Largest chunk or group index (entries): 128 MiB of i128 slots.
const MAX_ENTRIES: usize = 1 << 23;

/// A chunk's accumulator.
trait Slot: Copy + Default {
    /// Add a product of two words.
    fn add(&mut self, p: i128);
    /// Add the products `x[i] · w[i]` of words, which meet in this slot.
    fn add_dot(&mut self, x: &[i64], w: &[i64]);
    /// Whether the sum is zero.
    fn is_zero(&self) -> bool;
    /// The sum.
    fn coef(self) -> Coef;
}

impl Slot for i128 {
    #[inline(always)]
    fn add(&mut self, p: i128) {
        *self += p;
    }
    #[inline(always)]
    fn add_dot(&mut self, x: &[i64], w: &[i64]) {
        // every partial sum of a slot's products fits: the plan bounded their magnitudes' sum
        let dot = x
            .iter()
            .zip(w)
            .map(|(&x, &w)| i128::from(x) * i128::from(w));
        *self += dot.sum::<i128>();
    }
    fn is_zero(&self) -> bool {
        *self == 0
    }
    fn coef(self) -> Coef {
        Coef::from_i128(self)
    }
}

/// `lo + 2¹²⁸ · wraps`.
#[derive(Clone, Copy, Default)]
struct Wide {
    lo: i128,
    wraps: i64,
}

impl Slot for Wide {
    #[inline(always)]
    fn add(&mut self, p: i128) {
        let (s, over) = self.lo.overflowing_add(p);
        self.lo = s;
        // an overflow wraps by 2¹²⁸ in the direction of p's sign
        self.wraps += i64::from(over) * ((p >> 127) as i64 | 1);
    }
    #[inline(always)]
    fn add_dot(&mut self, x: &[i64], w: &[i64]) {
        for (&x, &w) in x.iter().zip(w) {
            self.add(i128::from(x) * i128::from(w));
        }
    }
    fn is_zero(&self) -> bool {
        self.lo == 0 && self.wraps == 0
    }
    fn coef(self) -> Coef {
        if self.wraps == 0 {
            return Coef::from_i128(self.lo);
        }
        Coef::from_big((BigInt::from(self.wraps) << 128u32) + BigInt::from(self.lo))
    }
}

/// The box, and the number of leading variables that index chunks, when the array method
/// applies: every coefficient a word, the box no larger than the number of term products
/// (so scanning it costs less than the products), a chunk and the index of groups within
/// [`MAX_ENTRIES`]. The split is the fewest leading variables that leave a chunk within
/// [`CHUNK_BYTES`] and one variable inside it; none when finding the pairs of groups
/// (chunks × groups of `a`) could cost more than the products.
fn plan(a: &MPoly, b: &MPoly, slot: usize) -> Option<(Vec<usize>, usize)> {
    if !a.coefs.iter().chain(&b.coefs).all(|c| c.small().is_some()) {
        return None;
    }
    let dims: Vec<usize> = (0..a.nvars())
        .map(|i| (a.degree_in(i) + b.degree_in(i) + 1) as usize)
        .collect();
    let size = dims.iter().try_fold(1usize, |s, d| s.checked_mul(*d))?;
    let products = a.len().checked_mul(b.len())?;
    if size > products {
        return None;
    }
    let max = dims.len().saturating_sub(1);
    let mut split = (0..=max)
        .find(|&s| dims[s..].iter().product::<usize>() * slot <= CHUNK_BYTES)
        .unwrap_or(max);
    let outer: usize = dims[..split].iter().product();
    if outer.saturating_mul(outer) > products {
        split = 0;
    }
    let (outer, inner) = dims.split_at(split);
    let entries = |d: &[usize]| d.iter().product::<usize>();
    (entries(outer) <= MAX_ENTRIES && entries(inner) <= MAX_ENTRIES).then_some((dims, split))
}

/// Whether the sums of `a · b` provably fit an i128.
fn fits_i128(a: &MPoly, b: &MPoly) -> bool {
    let max_bits = |p: &MPoly| p.coefs.iter().map(Coef::bits).max().unwrap_or(0);
    let shorter = a.len().min(b.len()) as u64;
    max_bits(a) + max_bits(b) + u64::from(64 - shorter.leading_zeros()) <= 126
}

/// Whether the array method applies to `a · b` (see [`plan`]).
pub(super) fn applies(a: &MPoly, b: &MPoly) -> bool {
    let slot = match fits_i128(a, b) {
        true => size_of::<i128>(),
        false => size_of::<Wide>(),
    };
    plan(a, b, slot).is_some()
}

/// `a · b` by the array method, or `None` when it does not apply (see [`plan`]).
pub(super) fn product(a: &MPoly, b: &MPoly) -> Option<MPoly> {
    let pack = Packing::for_degree(a.nvars(), a.degree() + b.degree());
    if fits_i128(a, b) {
        let (dims, split) = plan(a, b, size_of::<i128>())?;
        Some(product_in::<i128>(a, b, &dims, split, pack))
    } else {
        let (dims, split) = plan(a, b, size_of::<Wide>())?;
        Some(product_in::<Wide>(a, b, &dims, split, pack))
    }
}

/// Strides of a lexicographic index over `dims` (the first dimension most significant).
fn strides(dims: &[usize]) -> Vec<usize> {
    let mut s = vec![1usize; dims.len()];
    for i in (0..dims.len().saturating_sub(1)).rev() {
        s[i] = s[i + 1] * dims[i + 1];
    }
    s
}

/// The exponents of index `k` into `out`.
fn decode(k: usize, stride: &[usize], dims: &[usize], out: &mut [u32]) {
    for ((x, s), d) in out.iter_mut().zip(stride).zip(dims) {
        *x = ((k / s) % d) as u32;
    }
}

/// One operand's terms, grouped by their leading (outer) exponents: the terms of outer index
/// `o` are `start[o]..start[o + 1]`, each its index in a chunk and its coefficient.
struct Groups {
    start: Vec<u32>,
    terms: Vec<(usize, i64)>,
}

impl Groups {
    fn new(p: &MPoly, dims: &[usize], split: usize) -> Groups {
        let (outer, inner) = dims.split_at(split);
        let (so, si) = (strides(outer), strides(inner));
        let index = |m: &[u64], vars: std::ops::Range<usize>, stride: &[usize]| -> usize {
            vars.zip(stride)
                .map(|(i, s)| p.pack.exponent(m, i) as usize * s)
                .sum()
        };
        let mut keyed: Vec<(usize, (usize, i64))> = (0..p.len())
            .map(|t| {
                let m = p.packed(t);
                let o = index(m, 0..split, &so);
                let i = index(m, split..dims.len(), &si);
                (o, (i, p.coefs[t].small().unwrap_or(0)))
            })
            .collect();
        keyed.sort_unstable_by_key(|t| (t.0, t.1 .0));
        let mut start = vec![0u32; outer.iter().product::<usize>() + 1];
        for t in &keyed {
            start[t.0 + 1] += 1;
        }
        for o in 1..start.len() {
            start[o] += start[o - 1];
        }
        Groups {
            start,
            terms: keyed.into_iter().map(|t| t.1).collect(),
        }
    }

    fn terms(&self, o: usize) -> &[(usize, i64)] {
        &self.terms[self.start[o] as usize..self.start[o + 1] as usize]
    }

    /// The non-empty outer indices, ascending.
    fn occupied(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.start.len() - 1).filter(|&o| self.start[o] < self.start[o + 1])
    }
}

/// `chunk[ia + ib] += ca · cb` over every pair of terms; `chunk.len()` is a power of two
/// above every index, so the mask changes no index and spares the bounds check. Two terms
/// of `a` share each pass over `b`: its loads and the loop's count are paid once for two.
#[inline]
fn accumulate<S: Slot>(chunk: &mut [S], a: &[(usize, i64)], b: &[(usize, i64)]) {
    let mask = chunk.len().wrapping_sub(1);
    if !chunk.len().is_power_of_two() {
        return;
    }
    let mut pairs = a.chunks_exact(2);
    for two in &mut pairs {
        let ((i0, c0), (i1, c1)) = (two[0], two[1]);
        let (c0, c1) = (i128::from(c0), i128::from(c1));
        for &(ib, cb) in b {
            // both factors are sign-extended words: one widening multiplication each
            let cb = i128::from(cb);
            chunk[(i0 + ib) & mask].add(c0 * cb);
            chunk[(i1 + ib) & mask].add(c1 * cb);
        }
    }
    for &(ia, ca) in pairs.remainder() {
        let ca = i128::from(ca);
        for &(ib, cb) in b {
            chunk[(ia + ib) & mask].add(ca * i128::from(cb));
        }
    }
}

/// One operand's groups as rows along the last variable: each row the coefficients of
/// consecutive exponents of that variable (a gap filled with zeros), with the chunk index of
/// its first one. Group `o` holds rows `start[o]..start[o + 1]`.
struct Rows {
    start: Vec<u32>,
    rows: Vec<Row>,
    coefs: Vec<i64>,
}

/// A row of coefficients in a chunk: its first coefficient's chunk index is
/// `line · last + t`.
#[derive(Clone, Copy)]
struct Row {
    /// Its line (the index over the inner exponents but the last) and last exponent.
    line: usize,
    t: usize,
    /// Offset into the coefficients, and length.
    off: usize,
    len: usize,
}

impl Rows {
    /// The rows of `g`, `last` the size of the last variable's dimension.
    fn new(g: &Groups, last: usize) -> Rows {
        let groups = g.start.len() - 1;
        let mut out = Rows {
            start: Vec::with_capacity(groups + 1),
            rows: Vec::new(),
            coefs: Vec::with_capacity(g.terms.len()),
        };
        out.start.push(0);
        for o in 0..groups {
            let first = out.rows.len();
            for &(i, c) in g.terms(o) {
                match out.rows[first..].last_mut() {
                    // the same exponents but the last: the row goes on (terms ascend)
                    Some(r) if r.line == i / last => {
                        let gap = i % last - r.t - r.len;
                        out.coefs.extend(std::iter::repeat_n(0, gap));
                        r.len += gap + 1;
                    }
                    _ => out.rows.push(Row {
                        line: i / last,
                        t: i % last,
                        off: out.coefs.len(),
                        len: 1,
                    }),
                }
                out.coefs.push(c);
            }
            out.start.push(out.rows.len() as u32);
        }
        out
    }

    fn group(&self, o: usize) -> &[Row] {
        &self.rows[self.start[o] as usize..self.start[o + 1] as usize]
    }

    fn coefs(&self, r: &Row) -> &[i64] {
        &self.coefs[r.off..r.off + r.len]
    }
}

/// `chunk[at + i + j] += a[i] · b[j]`: the product of two rows (neither empty). Up to
/// [`WINDOW`] terms of the shorter row at a time sweep the longer one (see [`sweep`]).
#[inline]
fn convolve<S: Slot>(chunk: &mut [S], at: usize, a: &[i64], b: &[i64]) {
    let (a, b) = if a.len() <= b.len() { (a, b) } else { (b, a) };
    // the rows' exponents add up inside the box, so the slots are the chunk's
    let out = &mut chunk[at..at + a.len() + b.len() - 1];
    let mut blocks = a.chunks_exact(WINDOW);
    let mut k = 0;
    for x in &mut blocks {
        sweep::<S, WINDOW>(&mut out[k..], x, b);
        k += WINDOW;
    }
    let x = blocks.remainder();
    match x.len() {
        1 => sweep::<S, 1>(&mut out[k..], x, b),
        2 => sweep::<S, 2>(&mut out[k..], x, b),
        3 => sweep::<S, 3>(&mut out[k..], x, b),
        4 => sweep::<S, 4>(&mut out[k..], x, b),
        5 => sweep::<S, 5>(&mut out[k..], x, b),
        6 => sweep::<S, 6>(&mut out[k..], x, b),
        7 => sweep::<S, 7>(&mut out[k..], x, b),
        _ => {}
    }
}

/// Terms of a row that sweep the other row together: eight was the fastest of 2, 4, 6, 8
/// and 12 on Fateman's product.
const WINDOW: usize = 8;

/// `out[i + j] += x[i] · b[j]` for `N` terms `x` and a row `b` at least `N` long. The `N`
/// products that meet in a slot are summed in registers and the slot written once, in order:
/// in the body of the sweep they are `x` reversed against a window of `N` consecutive terms
/// of `b`, so the one loop's count is `b`'s length, whatever `N`.
#[inline(always)]
fn sweep<S: Slot, const N: usize>(out: &mut [S], x: &[i64], b: &[i64]) {
    let mut rev = [0i64; N];
    rev.iter_mut()
        .zip(x.iter().rev())
        .for_each(|(r, &x)| *r = x);
    let (m, out) = (b.len(), &mut out[..b.len() + N - 1]);
    // the ends, where fewer than N products meet: slot j meets b[..=j] with x[..=j], and
    // slot m + j meets b[m - N + 1 + j..] with x[j + 1..] (x in reverse), for j < N - 1
    for j in 0..N - 1 {
        out[j].add_dot(&rev[N - 1 - j..], &b[..=j]);
        out[m + j].add_dot(&rev[..N - 1 - j], &b[m - N + 1 + j..]);
    }
    for (slot, w) in out[N - 1..m].iter_mut().zip(b.windows(N)) {
        slot.add_dot(&rev, w);
    }
}

/// The product's terms as drained, chunk after chunk (descending lexicographic order), their
/// sums kept as accumulated until they take their place in the graded order.
struct Drained<S> {
    pack: Packing,
    degree: Vec<u32>,
    exps: Vec<u64>,
    sums: Vec<S>,
}

impl<S: Slot> Drained<S> {
    /// Move the non-zero slots of a chunk of `ops` (outer exponents in `s.e[..split]`)
    /// out, zeroing it: line by line, descending, each line only over its span of touched
    /// slots.
    fn drain(&mut self, s: &mut Scratch<S>, ops: &Operands) {
        let (n, split, last) = (s.e.len(), ops.outer.len(), ops.last);
        let lines = &ops.inner[..ops.inner.len().saturating_sub(1)];
        let line_strides = strides(lines);
        // a slot's exponents are its line's plus t in the last variable: packing is linear
        let mut unit = vec![0u64; self.pack.words];
        let has_last = n > split;
        if has_last {
            let mut e1 = vec![0u32; n];
            e1[n - 1] = 1;
            self.pack.pack_into(&e1, &mut unit);
        }
        let mut base = vec![0u64; self.pack.words];
        for line in (0..s.spans.len()).rev() {
            let (lo, hi) = std::mem::replace(&mut s.spans[line], EMPTY);
            if lo >= hi {
                continue;
            }
            decode(
                line,
                &line_strides,
                lines,
                &mut s.e[split..split + lines.len()],
            );
            if has_last {
                s.e[n - 1] = 0;
            }
            self.pack.pack_into(&s.e, &mut base);
            let degree = self.pack.degree(&base) as u32;
            for t in (lo..hi).rev() {
                let c = std::mem::take(&mut s.chunk[line * last + t]);
                if !c.is_zero() {
                    let t64 = t as u64;
                    let word = base.iter().zip(&unit);
                    self.exps.extend(word.map(|(b, u)| b.wrapping_add(t64 * u)));
                    self.degree.push(degree + t as u32);
                    self.sums.push(c);
                }
            }
        }
    }

    /// `self`'s terms followed by `next`'s.
    fn append(mut self, next: Drained<S>) -> Drained<S> {
        self.degree.extend(next.degree);
        self.exps.extend(next.exps);
        self.sums.extend(next.sums);
        self
    }

    /// The terms in graded order: a stable counting pass by descending total degree.
    fn into_poly(self, max_degree: usize) -> MPoly {
        let words = self.pack.words;
        let mut first = vec![0usize; max_degree + 2];
        for &d in &self.degree {
            first[max_degree - d as usize + 1] += 1;
        }
        for i in 1..first.len() {
            first[i] += first[i - 1];
        }
        let mut exps = vec![0u64; self.exps.len()];
        let mut coefs = vec![Coef::Small(0); self.sums.len()];
        for (t, (&d, c)) in self.degree.iter().zip(self.sums).enumerate() {
            let slot = &mut first[max_degree - d as usize];
            exps[*slot * words..(*slot + 1) * words]
                .copy_from_slice(&self.exps[t * words..(t + 1) * words]);
            coefs[*slot] = c.coef();
            *slot += 1;
        }
        MPoly {
            pack: self.pack,
            exps,
            coefs,
        }
    }
}

/// A line's span of touched slots when none is.
const EMPTY: (usize, usize) = (usize::MAX, 0);

/// A chunk being accumulated: its slots, the touched span of each line (the slots that
/// share all inner exponents but the last), and the exponents of a slot.
struct Scratch<S> {
    chunk: Vec<S>,
    spans: Vec<(usize, usize)>,
    e: Vec<u32>,
}

/// Term products from which a product's chunks are computed on every core: below, the
/// threads' start and the chunks' buffers cost more than they share.
const PARALLEL_PRODUCTS: usize = 1 << 22;

/// What every chunk of `a · b` reads: both operands grouped by their outer exponents, as
/// terms and as rows.
struct Operands<'p> {
    outer: &'p [usize],
    /// Strides of the outer index.
    outer_strides: Vec<usize>,
    inner: &'p [usize],
    /// The last variable's dimension (1 with no inner variable): a line's slots.
    last: usize,
    ga: Groups,
    gb: Groups,
    ra: Rows,
    rb: Rows,
    /// `a`'s occupied groups with their outer exponents.
    a_groups: Vec<(usize, Vec<u32>)>,
    /// Both operands' rows at least half full: their zeros cost less than an index per
    /// product.
    dense: bool,
}

impl<'p> Operands<'p> {
    fn new(a: &MPoly, b: &MPoly, dims: &'p [usize], split: usize) -> Operands<'p> {
        let (outer, inner) = dims.split_at(split);
        let outer_strides = strides(outer);
        let (ga, gb) = (Groups::new(a, dims, split), Groups::new(b, dims, split));
        let a_groups = ga
            .occupied()
            .map(|o| {
                let mut v = vec![0u32; split];
                decode(o, &outer_strides, outer, &mut v);
                (o, v)
            })
            .collect();
        let last = inner.last().copied().unwrap_or(1);
        let (ra, rb) = (Rows::new(&ga, last), Rows::new(&gb, last));
        let dense = ra.coefs.len() <= 2 * a.len() && rb.coefs.len() <= 2 * b.len();
        Operands {
            outer,
            outer_strides,
            inner,
            last,
            ga,
            gb,
            ra,
            rb,
            a_groups,
            dense,
        }
    }

    /// Chunk `o` of the product, drained into `out`; `s` is zero and stays so.
    fn chunk_into<S: Slot>(&self, o: usize, s: &mut Scratch<S>, out: &mut Drained<S>) {
        let split = self.outer.len();
        decode(o, &self.outer_strides, self.outer, &mut s.e[..split]);
        let mut touched = false;
        for (pa, va) in self.a_groups.iter().take_while(|g| g.0 <= o) {
            // the leading exponents of b's group are o's less a's, when none is negative
            if va.iter().zip(&s.e[..split]).any(|(x, y)| x > y) {
                continue;
            }
            let tb = self.gb.terms(o - pa);
            if tb.is_empty() {
                continue;
            }
            touched = true;
            if self.dense {
                for x in self.ra.group(*pa) {
                    for y in self.rb.group(o - pa) {
                        let (line, t) = (x.line + y.line, x.t + y.t);
                        let at = line * self.last + t;
                        convolve(&mut s.chunk, at, self.ra.coefs(x), self.rb.coefs(y));
                        let span = &mut s.spans[line];
                        span.0 = span.0.min(t);
                        span.1 = span.1.max(t + x.len + y.len - 1);
                    }
                }
            } else {
                accumulate(&mut s.chunk, self.ga.terms(*pa), tb);
            }
        }
        if touched && !self.dense {
            // products added one by one leave no spans: every line is read whole
            s.spans.iter_mut().for_each(|span| *span = (0, self.last));
        }
        if touched {
            out.drain(s, self);
        }
    }
}

/// `a · b` over the box `dims` in chunks of the variables after `split`, accumulated in
/// `S`; `pack` holds the product's degree. The chunks are taken in descending order, on every
/// core for a large product: each worker drains a run of consecutive chunks, and the runs
/// are joined in order, so the terms are the same whatever the number of threads.
fn product_in<S: Slot + Send>(
    a: &MPoly,
    b: &MPoly,
    dims: &[usize],
    split: usize,
    pack: Packing,
) -> MPoly {
    use rayon::prelude::*;
    let ops = Operands::new(a, b, dims, split);
    let inner = ops.inner.iter().product::<usize>();
    let lines = inner / ops.last;
    let start = || {
        let out = Drained {
            pack,
            degree: Vec::new(),
            exps: Vec::new(),
            sums: Vec::new(),
        };
        let s = Scratch {
            chunk: vec![S::default(); inner.next_power_of_two()],
            spans: vec![EMPTY; lines],
            e: vec![0u32; dims.len()],
        };
        (s, out)
    };
    let step = |(mut s, mut out): (Scratch<S>, Drained<S>), o: usize| {
        ops.chunk_into(o, &mut s, &mut out);
        (s, out)
    };
    let chunks = 0..ops.outer.iter().product::<usize>();
    let drained = if a.len().saturating_mul(b.len()) < PARALLEL_PRODUCTS {
        chunks.rev().fold(start(), step).1
    } else {
        let runs: Vec<Drained<S>> = chunks
            .into_par_iter()
            .rev()
            .fold(start, step)
            .map(|run| run.1)
            .collect();
        runs.into_iter()
            .reduce(Drained::append)
            .unwrap_or_else(|| start().1)
    };
    drained.into_poly((a.degree() + b.degree()) as usize)
}
