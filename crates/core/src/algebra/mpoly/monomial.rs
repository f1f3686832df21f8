//! Packed exponent vectors: fixed-width fields in u64 words, total degree first.
//!
//! As in FLINT's `mpoly`, a monomial in `n` variables is `n + 1` fields of `bits` bits each,
//! packed most significant first into `words` u64 words: field 0 is the total degree, then
//! the exponents of the variables in ring order. Comparing the words lexicographically as
//! unsigned integers is then the graded lexicographic order, and the product of two
//! monomials is the word-wise sum. The top bit of every field is a guard: it stays clear
//! for every stored exponent, so a subtraction that borrows (a non-divisible quotient) or
//! an addition that overflows sets it and is detected with one mask test per word.

/// Field widths tried, smallest first (each divides 64, so no field straddles two words).
const WIDTHS: [u32; 4] = [8, 16, 32, 64];

/// How the monomials of one polynomial are packed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Packing {
    /// Number of variables.
    pub nvars: usize,
    /// Bits per field (8, 16, 32 or 64), guard bit included.
    pub bits: u32,
    /// Words per monomial.
    pub words: usize,
}

impl Packing {
    /// The narrowest packing of `nvars` variables that holds total degrees up to `max_degree`.
    pub fn for_degree(nvars: usize, max_degree: u64) -> Packing {
        let bits = WIDTHS
            .iter()
            .copied()
            .find(|&b| b == 64 || max_degree < (1u64 << (b - 1)))
            .unwrap_or(64);
        Packing::with_bits(nvars, bits)
    }

    /// The packing of `nvars` variables in fields of `bits` bits.
    pub fn with_bits(nvars: usize, bits: u32) -> Packing {
        Packing {
            nvars,
            bits,
            words: (nvars + 1).div_ceil((64 / bits) as usize),
        }
    }

    /// Largest total degree this packing holds.
    pub fn max_degree(&self) -> u64 {
        (1u64 << (self.bits - 1)) - 1
    }

    fn per_word(&self) -> usize {
        (64 / self.bits) as usize
    }

    /// Word index and shift of field `f` (0 = total degree, 1 + i = variable i).
    fn place(&self, f: usize) -> (usize, u32) {
        let pw = self.per_word();
        (f / pw, 64 - self.bits * ((f % pw) as u32 + 1))
    }

    fn field_mask(&self) -> u64 {
        if self.bits == 64 {
            u64::MAX
        } else {
            (1u64 << self.bits) - 1
        }
    }

    /// Pack exponents (one per variable) into `out` (length `words`).
    pub fn pack_into(&self, exps: &[u32], out: &mut [u64]) {
        out.iter_mut().for_each(|w| *w = 0);
        let deg: u64 = exps.iter().map(|&e| u64::from(e)).sum();
        let (w, s) = self.place(0);
        out[w] |= deg << s;
        for (i, &e) in exps.iter().enumerate() {
            let (w, s) = self.place(i + 1);
            out[w] |= u64::from(e) << s;
        }
    }

    /// The exponent of variable `i` in the packed monomial `m`.
    #[inline]
    pub fn exponent(&self, m: &[u64], i: usize) -> u32 {
        let (w, s) = self.place(i + 1);
        ((m[w] >> s) & self.field_mask()) as u32
    }

    /// The total degree of the packed monomial `m`.
    #[inline]
    pub fn degree(&self, m: &[u64]) -> u64 {
        let (w, s) = self.place(0);
        (m[w] >> s) & self.field_mask()
    }

    /// All exponents of `m`, one per variable.
    pub fn unpack(&self, m: &[u64]) -> Vec<u32> {
        (0..self.nvars).map(|i| self.exponent(m, i)).collect()
    }

    /// The guard bits of every field, per word.
    pub fn guard_mask(&self) -> Vec<u64> {
        let mut mask = vec![0u64; self.words];
        for f in 0..=self.nvars {
            let (w, s) = self.place(f);
            mask[w] |= 1u64 << (s + self.bits - 1);
        }
        mask
    }
}

/// `a · b` into `out` (word-wise sum; the caller chose a packing wide enough).
#[inline]
pub fn mul_into(a: &[u64], b: &[u64], out: &mut [u64]) {
    for ((o, x), y) in out.iter_mut().zip(a).zip(b) {
        *o = x.wrapping_add(*y);
    }
}

/// `a / b` into `out` when `b` divides `a`, else `false` (FLINT's `monomial_divides`: a
/// field that borrows sets its guard bit).
#[inline]
pub fn div_into(a: &[u64], b: &[u64], mask: &[u64], out: &mut [u64]) -> bool {
    let mut ok = true;
    for (((o, x), y), g) in out.iter_mut().zip(a).zip(b).zip(mask) {
        *o = x.wrapping_sub(*y);
        ok &= *o & g == 0;
    }
    ok
}

/// A packed monomial held by value in the heap kernels: a fixed array for one to four
/// words (no allocation), a vector beyond.
pub trait Key: Clone + Ord {
    /// Read from packed words.
    fn load(m: &[u64]) -> Self;
    /// Append the words to `out`.
    fn store(&self, out: &mut Vec<u64>);
    /// Monomial product.
    fn add(&self, o: &Self) -> Self;
    /// Monomial quotient, when `o` divides `self` (`mask`: the guard bits).
    fn sub_guarded(&self, o: &Self, mask: &Self) -> Option<Self>;
    /// The words.
    fn words(&self) -> &[u64];
    /// A hash of the words (multiply and rotate: the packed exponents' bits spread).
    #[inline]
    fn hash(&self) -> u64 {
        self.words().iter().fold(0u64, |h, w| {
            (h ^ w).wrapping_mul(0x9e37_79b9_7f4a_7c15).rotate_left(29)
        })
    }
}

impl<const W: usize> Key for [u64; W] {
    #[inline]
    fn load(m: &[u64]) -> Self {
        let mut k = [0u64; W];
        k.copy_from_slice(m);
        k
    }
    #[inline]
    fn store(&self, out: &mut Vec<u64>) {
        out.extend_from_slice(self);
    }
    #[inline]
    fn add(&self, o: &Self) -> Self {
        let mut k = *self;
        mul_into(self, o, &mut k);
        k
    }
    #[inline]
    fn sub_guarded(&self, o: &Self, mask: &Self) -> Option<Self> {
        let mut k = *self;
        div_into(self, o, mask, &mut k).then_some(k)
    }
    #[inline]
    fn words(&self) -> &[u64] {
        self
    }
}

impl Key for Vec<u64> {
    fn load(m: &[u64]) -> Self {
        m.to_vec()
    }
    fn store(&self, out: &mut Vec<u64>) {
        out.extend_from_slice(self);
    }
    fn add(&self, o: &Self) -> Self {
        let mut k = self.clone();
        mul_into(self, o, &mut k);
        k
    }
    fn sub_guarded(&self, o: &Self, mask: &Self) -> Option<Self> {
        let mut k = self.clone();
        div_into(self, o, mask, &mut k).then_some(k)
    }
    fn words(&self) -> &[u64] {
        self
    }
}

/// Call `$f::<K>($args)` with the key type for `$words` words.
macro_rules! with_key {
    ($words:expr, $f:ident ( $($arg:expr),* )) => {
        match $words {
            1 => $f::<[u64; 1]>($($arg),*),
            2 => $f::<[u64; 2]>($($arg),*),
            3 => $f::<[u64; 3]>($($arg),*),
            4 => $f::<[u64; 4]>($($arg),*),
            _ => $f::<Vec<u64>>($($arg),*),
        }
    };
}
pub(crate) use with_key;
