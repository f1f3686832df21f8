//! Exact real-root isolation of univariate polynomials over ℚ (Sturm sequences).
//!
//! Roots are isolated per factor of the square-free (Yun) decomposition, so each root carries
//! its multiplicity; isolating intervals refine by exact bisection to any width.

use std::cmp::Ordering;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, ToPrimitive, Zero};

/// A univariate polynomial over ℚ, coefficients from the constant term up.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::UPoly;
/// // (x - 1)^2 (x + 2): roots 1 (double) and -2
/// let p = UPoly::from_i64(&[2, -3, 0, 1]);
/// let roots = p.real_roots();
/// assert_eq!(roots.len(), 2);
/// assert_eq!(roots[0].multiplicity, 1);
/// assert_eq!(roots[1].multiplicity, 2);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UPoly {
    coeffs: Vec<BigRational>,
}

/// A dyadic rational n / 2^k: interval ends stay dyadic under bisection, so evaluation and
/// refinement run in integer arithmetic with shifts instead of rational normalisation.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Dyadic {
    n: BigInt,
    k: u32,
}

impl Dyadic {
    fn int(n: BigInt) -> Self {
        Dyadic { n, k: 0 }
    }

    fn at(&self, k: u32) -> BigInt {
        &self.n << (k - self.k)
    }

    fn mid(a: &Dyadic, b: &Dyadic) -> Dyadic {
        let k = a.k.max(b.k);
        Dyadic {
            n: a.at(k) + b.at(k),
            k: k + 1,
        }
    }

    fn sub(a: &Dyadic, b: &Dyadic) -> Dyadic {
        let k = a.k.max(b.k);
        Dyadic {
            n: a.at(k) - b.at(k),
            k,
        }
    }

    fn half(&self) -> Dyadic {
        Dyadic {
            n: self.n.clone(),
            k: self.k + 1,
        }
    }

    fn to_rational(&self) -> BigRational {
        BigRational::new(self.n.clone(), BigInt::one() << self.k)
    }
}

impl PartialOrd for Dyadic {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Dyadic {
    fn cmp(&self, other: &Self) -> Ordering {
        let k = self.k.max(other.k);
        self.at(k).cmp(&other.at(k))
    }
}

/// A real root in `[lo, hi]` (open at `lo` unless `lo == hi`, an exactly hit rational root).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RealRoot {
    lo: Dyadic,
    hi: Dyadic,
    /// Multiplicity of the root in the original polynomial.
    pub multiplicity: u32,
    /// The square-free factor the root belongs to, with integer coefficients.
    factor: Vec<BigInt>,
}

impl RealRoot {
    /// Lower end of the isolating interval.
    pub fn lo(&self) -> BigRational {
        self.lo.to_rational()
    }

    /// Upper end of the isolating interval.
    pub fn hi(&self) -> BigRational {
        self.hi.to_rational()
    }

    /// Midpoint of the isolating interval as `f64`.
    pub fn to_f64(&self) -> f64 {
        Dyadic::mid(&self.lo, &self.hi)
            .to_rational()
            .to_f64()
            .unwrap_or(f64::NAN)
    }

    /// Width of the interval.
    pub fn width(&self) -> BigRational {
        Dyadic::sub(&self.hi, &self.lo).to_rational()
    }

    /// Bisect until the interval is no wider than `width`.
    pub fn refine(&mut self, width: &BigRational) {
        let s_hi = sign_at(&self.factor, &self.hi);
        while self.width() > *width {
            // Bisect a batch of steps between width checks (each check builds a rational).
            for _ in 0..16 {
                let mid = Dyadic::mid(&self.lo, &self.hi);
                let s_mid = sign_at(&self.factor, &mid);
                if s_mid == Ordering::Equal {
                    self.lo = mid.clone();
                    self.hi = mid;
                    return;
                }
                // The upper end is never a root (exact hits are recorded as points) while the
                // lower end may be a neighbouring exact root, so compare with the upper end.
                if s_mid == s_hi {
                    self.hi = mid;
                } else {
                    self.lo = mid;
                }
            }
        }
    }
}

impl UPoly {
    /// From rational coefficients, constant term first; trailing zeros are dropped.
    pub fn new(mut coeffs: Vec<BigRational>) -> Self {
        while coeffs.last().is_some_and(Zero::is_zero) {
            coeffs.pop();
        }
        UPoly { coeffs }
    }

    /// From integer coefficients, constant term first.
    pub fn from_i64(coeffs: &[i64]) -> Self {
        UPoly::new(
            coeffs
                .iter()
                .map(|&c| BigRational::from_integer(c.into()))
                .collect(),
        )
    }

    /// The product of `(x - r)` over the given roots.
    pub fn from_roots(roots: &[BigRational]) -> Self {
        let mut p = UPoly::new(vec![BigRational::one()]);
        for r in roots {
            p = p.mul(&UPoly::new(vec![-r.clone(), BigRational::one()]));
        }
        p
    }

    /// Coefficients, constant term first.
    pub fn coeffs(&self) -> &[BigRational] {
        &self.coeffs
    }

    /// Degree (`None` for the zero polynomial).
    pub fn degree(&self) -> Option<usize> {
        self.coeffs.len().checked_sub(1)
    }

    /// Whether this is zero.
    pub fn is_zero(&self) -> bool {
        self.coeffs.is_empty()
    }

    /// Exact value at `x`.
    pub fn eval(&self, x: &BigRational) -> BigRational {
        self.coeffs
            .iter()
            .rev()
            .fold(BigRational::zero(), |acc, c| acc * x + c)
    }

    /// Product.
    pub fn mul(&self, other: &UPoly) -> UPoly {
        if self.is_zero() || other.is_zero() {
            return UPoly::new(vec![]);
        }
        let mut out = vec![BigRational::zero(); self.coeffs.len() + other.coeffs.len() - 1];
        for (i, a) in self.coeffs.iter().enumerate() {
            for (j, b) in other.coeffs.iter().enumerate() {
                out[i + j] += a * b;
            }
        }
        UPoly::new(out)
    }

    /// Derivative.
    pub fn derivative(&self) -> UPoly {
        UPoly::new(
            self.coeffs
                .iter()
                .enumerate()
                .skip(1)
                .map(|(i, c)| c * BigRational::from_integer(i.into()))
                .collect(),
        )
    }

    /// Quotient and remainder; `None` when dividing by zero.
    pub fn div_rem(&self, d: &UPoly) -> Option<(UPoly, UPoly)> {
        let dd = d.degree()?;
        let lead = &d.coeffs[dd];
        let mut rem = self.coeffs.clone();
        let mut quot = vec![BigRational::zero(); rem.len().saturating_sub(dd)];
        while rem.len() > dd && !rem.is_empty() {
            let k = rem.len() - 1 - dd;
            let f = &rem[rem.len() - 1] / lead;
            for (i, c) in d.coeffs.iter().enumerate() {
                rem[k + i] -= &f * c;
            }
            quot[k] = f;
            rem.pop();
            while rem.last().is_some_and(Zero::is_zero) {
                rem.pop();
            }
        }
        Some((UPoly::new(quot), UPoly::new(rem)))
    }

    /// Monic greatest common divisor.
    pub fn gcd(&self, other: &UPoly) -> UPoly {
        let (mut a, mut b) = (self.clone(), other.clone());
        while !b.is_zero() {
            let r = match a.div_rem(&b) {
                Some((_, r)) => r,
                None => break,
            };
            a = b;
            b = r;
        }
        a.monic()
    }

    fn monic(&self) -> UPoly {
        match self.coeffs.last() {
            Some(l) => UPoly::new(self.coeffs.iter().map(|c| c / l).collect()),
            None => self.clone(),
        }
    }

    /// Difference.
    pub fn sub(&self, other: &UPoly) -> UPoly {
        let n = self.coeffs.len().max(other.coeffs.len());
        UPoly::new(
            (0..n)
                .map(|k| {
                    self.coeffs.get(k).cloned().unwrap_or_default()
                        - other.coeffs.get(k).cloned().unwrap_or_default()
                })
                .collect(),
        )
    }

    /// Whether the polynomial has no repeated root: proved modulo a prime when it can be (a
    /// constant gcd of p and p′ there), else decided by the exact gcd over ℚ, whose rational
    /// remainders grow fast with the degree.
    pub fn is_square_free(&self) -> bool {
        match self.degree() {
            None => false,
            Some(0) => true,
            Some(_) => {
                square_free_mod_prime(&integer_coeffs(self))
                    || self.gcd(&self.derivative()).degree() == Some(0)
            }
        }
    }

    /// Yun's square-free decomposition: `self = c · Π fᵢ^i`; returns `(i, fᵢ)` for non-constant fᵢ.
    pub fn square_free_factors(&self) -> Vec<(u32, UPoly)> {
        let mut out = Vec::new();
        if self.degree().unwrap_or(0) == 0 {
            return out;
        }
        let f1 = self.derivative();
        let a0 = self.gcd(&f1);
        let (Some((mut b, _)), Some((c, _))) = (self.div_rem(&a0), f1.div_rem(&a0)) else {
            return out;
        };
        let mut d = c.sub(&b.derivative());
        let mut i = 1;
        while b.degree().unwrap_or(0) > 0 {
            let a = b.gcd(&d);
            if a.degree().unwrap_or(0) > 0 {
                out.push((i, a.clone()));
            }
            let (Some((nb, _)), Some((nc, _))) = (b.div_rem(&a), d.div_rem(&a)) else {
                break;
            };
            b = nb;
            d = nc.sub(&b.derivative());
            i += 1;
        }
        out
    }

    /// All distinct real roots, ascending, each in an isolating interval with its multiplicity.
    pub fn real_roots(&self) -> Vec<RealRoot> {
        let mut out = Vec::new();
        if self.degree().unwrap_or(0) == 0 {
            return out;
        }
        let whole = integer_coeffs(self);
        let factors = if square_free_mod_prime(&whole) {
            vec![(1, self.clone())]
        } else {
            self.square_free_factors()
        };
        for (mult, f) in factors {
            let int = integer_coeffs(&f);
            let seq = sturm_sequence(&int);
            let bound = root_bound(&int);
            isolate(
                &seq,
                &Dyadic::int(-bound.n.clone()),
                &bound,
                mult,
                &int,
                &mut out,
            );
        }
        // Roots of different factors are distinct (the factors are coprime), but their
        // first intervals may overlap: halve overlapping neighbours until all are disjoint,
        // so that the order by interval is the order of the roots.
        loop {
            out.sort_by(|a, b| a.lo.cmp(&b.lo).then_with(|| a.hi.cmp(&b.hi)));
            let overlapping: Vec<usize> = (1..out.len())
                .filter(|&i| out[i - 1].hi >= out[i].lo)
                .collect();
            if overlapping.is_empty() {
                return out;
            }
            for i in overlapping {
                for j in [i - 1, i] {
                    let half = out[j].width() / BigRational::from_integer(2.into());
                    out[j].refine(&half);
                }
            }
        }
    }

    /// Real roots refined to intervals no wider than `width`.
    pub fn real_roots_within(&self, width: &BigRational) -> Vec<RealRoot> {
        let mut roots = self.real_roots();
        for r in &mut roots {
            r.refine(width);
        }
        roots
    }
}

/// Integer coefficients with the same roots and the same sign pattern (positive scaling).
fn integer_coeffs(p: &UPoly) -> Vec<BigInt> {
    let lcm = p
        .coeffs
        .iter()
        .fold(BigInt::one(), |acc, c| super::integer::lcm(&acc, c.denom()));
    // c·lcm in ℤ without a rational product (whose reduction is a gcd of long integers)
    let ints: Vec<BigInt> = p
        .coeffs
        .iter()
        .map(|c| c.numer() * (&lcm / c.denom()))
        .collect();
    let g = super::integer::content(&ints);
    if g.is_zero() {
        ints
    } else {
        ints.into_iter().map(|c| c / &g).collect()
    }
}

/// Sign of `p(n/2^k)` from integer coefficients: Horner on `Σ aᵢ nⁱ 2^(k(deg−i))`, all in ℤ.
fn sign_at(p: &[BigInt], x: &Dyadic) -> Ordering {
    let mut coeffs = p.iter().rev();
    let mut acc = coeffs.next().cloned().unwrap_or_default();
    let mut shift = x.k as usize;
    for c in coeffs {
        acc = acc * &x.n + (c << shift);
        shift += x.k as usize;
    }
    acc.sign_ordering()
}

trait SignOrdering {
    fn sign_ordering(&self) -> Ordering;
}

impl SignOrdering for BigInt {
    fn sign_ordering(&self) -> Ordering {
        if self.is_positive() {
            Ordering::Greater
        } else if self.is_negative() {
            Ordering::Less
        } else {
            Ordering::Equal
        }
    }
}

/// Sturm sequence of a square-free integer polynomial, each member scaled positively to ℤ.
fn sturm_sequence(p: &[BigInt]) -> Vec<Vec<BigInt>> {
    let mut seq = vec![p.to_vec()];
    let mut b = primitive(&int_derivative(p));
    let mut a = p.to_vec();
    while !b.is_empty() {
        seq.push(b.clone());
        // −(a mod b), up to a positive factor: the pseudo-remainder, sign-corrected.
        let r = pseudo_remainder(&a, &b);
        a = b;
        b = primitive(&r.iter().map(|c| -c).collect::<Vec<_>>());
    }
    seq
}

fn int_derivative(p: &[BigInt]) -> Vec<BigInt> {
    p.iter()
        .enumerate()
        .skip(1)
        .map(|(i, c)| c * BigInt::from(i))
        .collect()
}

/// Divide by the (positive) gcd of the coefficients; trailing zeros dropped.
fn primitive(p: &[BigInt]) -> Vec<BigInt> {
    let mut v = p.to_vec();
    while v.last().is_some_and(Zero::is_zero) {
        v.pop();
    }
    let g = super::integer::content(&v);
    if g.is_zero() || g.is_one() {
        v
    } else {
        v.into_iter().map(|c| c / &g).collect()
    }
}

/// `m·a mod b` for a positive `m` (a power of |lc(b)|): same sign pattern as `a mod b`.
fn pseudo_remainder(a: &[BigInt], b: &[BigInt]) -> Vec<BigInt> {
    let db = b.len() - 1;
    let lb = &b[db];
    let mut r = a.to_vec();
    let mut flips = false;
    while r.len() > db && !r.is_empty() {
        let dr = r.len() - 1;
        let lr = r[dr].clone();
        for c in r.iter_mut() {
            *c *= lb;
        }
        if lb.is_negative() {
            flips = !flips;
        }
        for (i, c) in b.iter().enumerate() {
            r[dr - db + i] -= &lr * c;
        }
        r.pop();
        while r.last().is_some_and(Zero::is_zero) {
            r.pop();
        }
    }
    if flips {
        r.iter().map(|c| -c).collect()
    } else {
        r
    }
}

/// Whether gcd(p, p′) = 1, decided modulo the prime 2⁶¹ − 1 (a constant gcd there, with the
/// degree kept, proves a constant gcd over ℚ).
fn square_free_mod_prime(p: &[BigInt]) -> bool {
    const PRIME: u64 = (1 << 61) - 1;
    let prime = BigInt::from(PRIME);
    let red = |v: &[BigInt]| -> Vec<u64> {
        let mut out: Vec<u64> = v
            .iter()
            .map(|c| c.mod_floor(&prime).to_u64().unwrap_or(0))
            .collect();
        while out.last() == Some(&0) {
            out.pop();
        }
        out
    };
    let a = red(p);
    if a.len() != p.len() {
        return false; // the prime divides the leading coefficient: no conclusion
    }
    let mulm = |x: u64, y: u64| ((x as u128 * y as u128) % PRIME as u128) as u64;
    let inv = |x: u64| {
        let (mut base, mut e, mut acc) = (x, PRIME - 2, 1u64);
        while e > 0 {
            if e & 1 == 1 {
                acc = mulm(acc, base);
            }
            base = mulm(base, base);
            e >>= 1;
        }
        acc
    };
    let (mut x, mut y) = (a, red(&int_derivative(p)));
    while !y.is_empty() {
        let ly = inv(*y.last().unwrap_or(&1));
        while x.len() >= y.len() && !x.is_empty() {
            let f = mulm(*x.last().unwrap_or(&0), ly);
            let off = x.len() - y.len();
            for (i, c) in y.iter().enumerate() {
                x[off + i] = (x[off + i] + PRIME - mulm(f, *c)) % PRIME;
            }
            while x.last() == Some(&0) {
                x.pop();
            }
        }
        std::mem::swap(&mut x, &mut y);
    }
    x.len() == 1
}

fn variations(seq: &[Vec<BigInt>], x: &Dyadic) -> usize {
    let signs: Vec<Ordering> = seq
        .iter()
        .map(|p| sign_at(p, x))
        .filter(|s| *s != Ordering::Equal)
        .collect();
    signs.windows(2).filter(|w| w[0] != w[1]).count()
}

/// A power of two strictly greater than every root's modulus (Cauchy's bound).
fn root_bound(p: &[BigInt]) -> Dyadic {
    let lead = p.last().map(|c| c.abs()).unwrap_or_else(BigInt::one);
    let max = p[..p.len().saturating_sub(1)]
        .iter()
        .map(|c| c.abs())
        .max()
        .unwrap_or_default();
    // 1 + max/lead < 2^e  ⇐  lead + max < lead·2^e
    let mut b = BigInt::one();
    while &lead * &b <= &lead + &max {
        b <<= 1;
    }
    Dyadic::int(b)
}

/// Isolate the roots of the square-free `int` in `(lo, hi]`.
fn isolate(
    seq: &[Vec<BigInt>],
    lo: &Dyadic,
    hi: &Dyadic,
    mult: u32,
    int: &[BigInt],
    out: &mut Vec<RealRoot>,
) {
    let count = variations(seq, lo).saturating_sub(variations(seq, hi));
    if count == 0 {
        return;
    }
    let root = |lo: &Dyadic, hi: &Dyadic| RealRoot {
        lo: lo.clone(),
        hi: hi.clone(),
        multiplicity: mult,
        factor: int.to_vec(),
    };
    if sign_at(int, hi) == Ordering::Equal {
        out.push(root(hi, hi));
        if count > 1 {
            // The other roots lie strictly below hi; move hi down to a non-root below them.
            let mut step = Dyadic::sub(hi, lo).half();
            let h = loop {
                let cand = Dyadic::sub(hi, &step);
                if sign_at(int, &cand) != Ordering::Equal
                    && variations(seq, lo) - variations(seq, &cand) == count - 1
                {
                    break cand;
                }
                step = step.half();
            };
            isolate(seq, lo, &h, mult, int, out);
        }
        return;
    }
    if count == 1 {
        out.push(root(lo, hi));
        return;
    }
    let mid = Dyadic::mid(lo, hi);
    isolate(seq, lo, &mid, mult, int, out);
    isolate(seq, &mid, hi, mult, int, out);
}
