//! Random-point screens modulo several 61-bit primes (Schwartz–Zippel over 𝔽ₚ).
//!
//! Two rational functions are compared through the cross-multiplied polynomial
//! D = `l.num · r.den − k · r.num · l.den`, which needs no division, so a point where a
//! denominator vanishes is as good as any other. A non-zero D of total degree d vanishes at
//! a uniformly random point of 𝔽ₚⁿ with probability at most d/p, provided D is non-zero
//! modulo p: p must not divide every coefficient of D. A height bound H on D's coefficients
//! (from the operands' 1-norms) settles that: distinct primes above 2⁶⁰ dividing one non-zero
//! coefficient number fewer than log₂H / 60, so with m primes, 60·m ≥ log₂H, D stays non-zero
//! modulo one of them. Every point is drawn afresh for each prime, and agrees only where all
//! primes agree; a false identity then passes `n` points with probability at most (d/p)ⁿ,
//! p the smallest prime. Each evaluation is a few word multiplications: a fast screen beside
//! the exact comparison, or the second check after it.

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive};
use rand::Rng;

use super::mpoly::{Coef, Scalar};
use super::{Poly, RatFn};

/// The primes are 2⁶¹ − c for these c, the sixteen largest primes below 2⁶¹: a reduction
/// folds the high bits of a product onto the low ones, times c.
pub const OFFSETS: [u64; 16] = [
    1, 31, 45, 229, 259, 283, 339, 391, 403, 465, 531, 579, 675, 759, 799, 819,
];

/// The Mersenne prime 2⁶¹ − 1, the first of the primes.
pub const PRIME: u64 = (1 << 61) - 1;

/// The j-th prime, 2⁶¹ − `OFFSETS[j]`.
pub const fn prime(j: usize) -> u64 {
    (1 << 61) - OFFSETS[j]
}

/// An element of 𝔽ₚ, p = 2⁶¹ − C.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Residue<const C: u64>(pub u64);

/// An element of 𝔽ₚ, p = [`PRIME`].
pub type Fp = Residue<1>;

/// 2⁶¹ − c for an offset of [`OFFSETS`]; any other c stops the build (the reduction is proven
/// for these, and the inverse needs a prime).
const fn modulus(c: u64) -> u64 {
    let mut i = 0;
    while i < OFFSETS.len() {
        if OFFSETS[i] == c {
            return (1 << 61) - c;
        }
        i += 1;
    }
    panic!("a residue's offset must be one of OFFSETS")
}

impl<const C: u64> Residue<C> {
    /// The modulus.
    pub const P: u64 = modulus(C);

    /// The residue of an integer.
    pub fn from_big(v: &BigInt) -> Self {
        let r = v.mod_floor(&BigInt::from(Self::P));
        Residue(r.to_u64().unwrap_or(0))
    }

    /// `self^e`.
    pub fn pow(self, mut e: u64) -> Self {
        let (mut r, mut b) = (Residue(1), self);
        while e > 0 {
            if e & 1 == 1 {
                r = r.mul(&b);
            }
            b = b.mul(&b);
            e >>= 1;
        }
        r
    }

    /// The inverse (Fermat), `None` for zero.
    pub fn inv(self) -> Option<Self> {
        (self.0 != 0).then(|| self.pow(Self::P - 2))
    }

    /// The residue of a rational, `None` when p divides its denominator.
    pub fn from_rational(q: &BigRational) -> Option<Self> {
        Some(Self::from_big(q.numer()).mul(&Self::from_big(q.denom()).inv()?))
    }

    /// `self − o`.
    pub fn sub(&self, o: &Self) -> Self {
        Scalar::add(self, &Residue(Self::P - o.0))
    }
}

impl<const C: u64> Scalar for Residue<C> {
    fn zero() -> Self {
        Residue(0)
    }
    fn one() -> Self {
        Residue(1)
    }
    fn from_coef(c: &Coef) -> Self {
        match c {
            Coef::Small(s) => Residue(s.rem_euclid(Self::P as i64) as u64),
            Coef::Big(b) => Self::from_big(b),
        }
    }
    #[inline]
    fn add(&self, o: &Self) -> Self {
        let s = self.0 + o.0; // < 2⁶², no overflow
        Residue(if s >= Self::P { s - Self::P } else { s })
    }
    #[inline]
    fn mul(&self, o: &Self) -> Self {
        // 2⁶¹ ≡ C: fold the high bits twice (122 bits → 72 → 62), then one subtraction
        const MASK: u128 = (1 << 61) - 1;
        let t = u128::from(self.0) * u128::from(o.0);
        let x = (t >> 61) * u128::from(C) + (t & MASK);
        let s = ((x >> 61) * u128::from(C) + (x & MASK)) as u64;
        Residue(if s >= Self::P { s - Self::P } else { s })
    }
}

/// The value of `p` at `at` (one residue per variable of `p`'s ring), `None` when p divides
/// the denominator of its content.
pub fn eval_poly<const C: u64>(p: &Poly, at: &[Residue<C>]) -> Option<Residue<C>> {
    let (content, prim) = p.primitive();
    if p.is_zero() {
        return Some(Residue(0));
    }
    Some(Residue::from_rational(content)?.mul(&prim.eval(at)))
}

/// Outcome of [`agree_mod_p`] and [`proportional_mod_p`].
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct ModPAgreement {
    /// Points tried (each drawn afresh for every prime).
    pub points: usize,
    /// Seed of the points.
    pub seed: u64,
    /// Points where `l.num · r.den = k · r.num · l.den` held modulo every prime.
    pub agreeing: usize,
    /// The primes, as many as the height bound asks.
    pub primes: Vec<u64>,
    /// Bits of the height bound of the difference's integer coefficients.
    pub height_bits: u64,
    /// Total degree bound d of the cross-multiplied difference.
    pub degree: u32,
    /// Points that cannot fail: one for an unknown ratio, which the first point fixes.
    pub free_points: usize,
    /// d/p, p the smallest prime: the chance that one point agrees although the two differ;
    /// 1 where the primes cannot cover the height bound.
    pub per_point_bound: f64,
}

impl ModPAgreement {
    /// Whether every point agreed.
    pub fn all_agree(&self) -> bool {
        self.agreeing == self.points
    }

    /// The smallest prime, which the per-point bound divides by.
    pub fn smallest_prime(&self) -> u64 {
        self.primes.iter().copied().min().unwrap_or(PRIME)
    }

    /// log₁₀ of the chance that a false identity agrees at every point: the per-point bound
    /// to the power `points − free_points`, times `points` where the first point fixes an
    /// unknown ratio (it is the first of them where the right side does not vanish, which may
    /// be any). A zero bound (degree 0: a non-zero constant never vanishes) gives the log of
    /// the smallest normal float, still an upper bound and finite.
    pub fn log10_false_pass(&self) -> f64 {
        let n = self.points.saturating_sub(self.free_points) as f64;
        if n == 0.0 {
            return 0.0;
        }
        let which = match self.free_points {
            0 => 0.0,
            _ => (self.points as f64).log10(),
        };
        if self.per_point_bound == 0.0 {
            return f64::MIN_POSITIVE.log10();
        }
        (which + n * self.per_point_bound.log10()).min(0.0)
    }
}

/// Schwartz–Zippel screen of `left = ratio · right` at `points` seeded uniform points.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::{modp::agree_mod_p, rat, RatFn};
/// let l = RatFn::parse("(a + b)^2 / (a - b)").unwrap();
/// let r = RatFn::parse("(a^2 + 2a b + b^2) / (a - b)").unwrap();
/// let s = agree_mod_p(&l, &r, &rat(1, 1), 8, 1);
/// assert_eq!((s.agreeing, s.primes.len()), (8, 1));
/// assert!(s.log10_false_pass() < -17.0 * 8.0);
/// assert_eq!(agree_mod_p(&l, &r, &rat(2, 1), 8, 1).agreeing, 0);
/// ```
pub fn agree_mod_p(
    left: &RatFn,
    right: &RatFn,
    ratio: &BigRational,
    points: usize,
    seed: u64,
) -> ModPAgreement {
    screen(left, right, Some(ratio), points, seed)
}

/// The same screen for `left = k · right` with an unknown non-zero constant k (an equation
/// `= 0` printed with another sign or scale): modulo each prime, k is read off the first point
/// where the right side does not vanish, and every point (that one included) must agree
/// with it: the test of the 2 × 2 minors `L(x₀)·R(x) − L(x)·R(x₀)`.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::{modp::proportional_mod_p, RatFn};
/// let l = RatFn::parse("-3 (a + b)^2").unwrap();
/// let r = RatFn::parse("a^2 + 2a b + b^2").unwrap();
/// assert_eq!(proportional_mod_p(&l, &r, 8, 1).agreeing, 8);
/// let m = RatFn::parse("a^2 + 3a b + b^2").unwrap();
/// assert_eq!(proportional_mod_p(&l, &m, 8, 1).agreeing, 1);
/// ```
pub fn proportional_mod_p(left: &RatFn, right: &RatFn, points: usize, seed: u64) -> ModPAgreement {
    screen(left, right, None, points, seed)
}

/// Both screens: `ratio` known (`L = k·R`), or `None`, read off the first point.
fn screen(
    left: &RatFn,
    right: &RatFn,
    ratio: Option<&BigRational>,
    points: usize,
    seed: u64,
) -> ModPAgreement {
    let sides = Sides::new(left, right);
    let height = match ratio {
        // k = a/b: the integer difference is b·L̃ − a·R̃
        Some(k) => (k.denom().abs() * &sides.norms.0 + k.numer().abs() * &sides.norms.1).bits(),
        // the minors' coefficients are at most 2·‖L̃‖₁·‖R̃‖₁
        None => (BigInt::from(2) * &sides.norms.0 * &sides.norms.1).bits(),
    };
    let primes = primes_for(height);
    let mut g = crate::model::rng(seed);
    let mut agree = vec![true; points];
    for &j in &primes {
        for (ok, a) in agree
            .iter_mut()
            .zip(agreeing_in(j, &sides, ratio, points, &mut g))
        {
            *ok &= a;
        }
    }
    let covered = height.div_ceil(60) <= OFFSETS.len() as u64;
    let primes: Vec<u64> = primes.into_iter().map(prime).collect();
    let smallest = primes.iter().copied().min().unwrap_or(PRIME);
    ModPAgreement {
        points,
        seed,
        agreeing: agree.iter().filter(|a| **a).count(),
        primes,
        height_bits: height,
        degree: sides.degree,
        free_points: usize::from(ratio.is_none()),
        per_point_bound: match covered {
            true => (f64::from(sides.degree) / smallest as f64).min(1.0),
            false => 1.0,
        },
    }
}

/// The four polynomials of a comparison, `L = l.num · r.den` and `R = r.num · l.den`, with
/// the variables they share and the height bounds of L̃ and R̃ (their contents cleared
/// crosswise, so that both have integer coefficients).
struct Sides<'a> {
    /// l.num, r.den, r.num, l.den.
    polys: [&'a Poly; 4],
    /// The variables of both sides, sorted: a point gives one value to each.
    vars: Vec<String>,
    /// Per polynomial, the index in `vars` of each variable of its ring.
    maps: [Vec<usize>; 4],
    /// ‖L̃‖₁ and ‖R̃‖₁, bounds of their products' 1-norms.
    norms: (BigInt, BigInt),
    /// Total degree bound of L − k·R.
    degree: u32,
}

impl<'a> Sides<'a> {
    fn new(left: &'a RatFn, right: &'a RatFn) -> Sides<'a> {
        let polys = [&left.num, &right.den, &right.num, &left.den];
        // every name of the four rings, so that each finds its place below
        let mut vars: Vec<String> = polys
            .iter()
            .flat_map(|p| p.ring().names().iter().map(|n| n.to_string()))
            .collect();
        vars.sort();
        vars.dedup();
        let maps = polys.map(|p| {
            p.ring()
                .names()
                .iter()
                .map(|n| vars.iter().position(|v| **v == **n).unwrap_or(0))
                .collect()
        });
        // a content n/d enters as n on its side and d on the other
        let l1 = |p: &Poly| p.primitive().1.l1_norm();
        let num = |p: &Poly| p.primitive().0.numer().abs();
        let den = |p: &Poly| p.primitive().0.denom().abs();
        let [a, b, c, d] = polys;
        let norms = (
            l1(a) * l1(b) * num(a) * num(b) * den(c) * den(d),
            l1(c) * l1(d) * num(c) * num(d) * den(a) * den(b),
        );
        let degree = (a.degree() + b.degree()).max(c.degree() + d.degree());
        Sides {
            polys,
            vars,
            maps,
            norms,
            degree,
        }
    }
}

/// The primes a height of `bits` asks for (indices into [`OFFSETS`]): each prime exceeds
/// 2⁶⁰, so ⌈bits / 60⌉ of them have a product above the height; at most all of them.
fn primes_for(bits: u64) -> Vec<usize> {
    let m = usize::try_from(bits.div_ceil(60)).unwrap_or(usize::MAX);
    (0..m.clamp(1, OFFSETS.len())).collect()
}

/// At each of `points` fresh points modulo prime j: whether `L = k·R` there (`k` known, or
/// read off the first point where R does not vanish); a point where the prime divides the
/// denominator of a content, or of k, disagrees.
fn agreeing_in(
    j: usize,
    s: &Sides,
    ratio: Option<&BigRational>,
    points: usize,
    g: &mut rand_chacha::ChaCha8Rng,
) -> Vec<bool> {
    macro_rules! dispatch {
        ($($i:literal),*) => {
            match j {
                $($i => agreeing::<{ OFFSETS[$i] }>(s, ratio, points, g),)*
                _ => unreachable!("prime index beyond OFFSETS"),
            }
        };
    }
    dispatch!(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15)
}

fn agreeing<const C: u64>(
    s: &Sides,
    ratio: Option<&BigRational>,
    points: usize,
    g: &mut rand_chacha::ChaCha8Rng,
) -> Vec<bool> {
    let values = cross::<C>(s, points, g);
    let k = match ratio {
        Some(k) => Residue::<C>::from_rational(k),
        None => values
            .iter()
            .flatten()
            .find(|(_, r)| r.0 != 0)
            .and_then(|(l, r)| Some(l.mul(&r.inv()?)))
            .filter(|k| k.0 != 0),
    };
    values
        .iter()
        .map(|v| matches!((v, k), (Some((l, r)), Some(k)) if *l == k.mul(r)))
        .collect()
}

/// (L, R) at each of `points` fresh points, `None` where the prime divides the denominator
/// of a content.
fn cross<const C: u64>(
    s: &Sides,
    points: usize,
    g: &mut rand_chacha::ChaCha8Rng,
) -> Vec<Option<(Residue<C>, Residue<C>)>> {
    let draws: Vec<Vec<Residue<C>>> = (0..points)
        .map(|_| {
            s.vars
                .iter()
                .map(|_| Residue(g.random_range(0..Residue::<C>::P)))
                .collect()
        })
        .collect();
    let values: Vec<Vec<Option<Residue<C>>>> = s
        .polys
        .iter()
        .zip(&s.maps)
        .map(|(p, map)| {
            if p.is_zero() {
                return vec![Some(Residue(0)); points];
            }
            let (content, prim) = p.primitive();
            let Some(c) = Residue::<C>::from_rational(content) else {
                return vec![None; points];
            };
            let local: Vec<Vec<Residue<C>>> = draws
                .iter()
                .map(|d| map.iter().map(|&i| d[i]).collect())
                .collect();
            prim.eval_points(&prim.coef_images(), &local)
                .into_iter()
                .map(|v| Some(c.mul(&v)))
                .collect()
        })
        .collect();
    (0..points)
        .map(|i| {
            let [a, b, c, d] = [0, 1, 2, 3].map(|k| values[k][i]);
            Some((a?.mul(&b?), c?.mul(&d?)))
        })
        .collect()
}
