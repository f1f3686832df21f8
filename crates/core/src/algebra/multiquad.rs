//! Exact arithmetic in a multiquadratic field ℚ(√d₁, …, √dₖ), the dᵢ positive rationals and
//! every √dᵢ the positive real root: the field of a few square roots at once (the directions
//! of lines found by solving one quadratic each), with an exact sign, so that comparisons and
//! zero tests need no rounding.
//!
//! An element is stored as integer coefficients over one common denominator, in the basis of
//! the integers Dᵢ = pᵢqᵢ (√(p/q) = √(pq)/q): a product then costs integer products and one
//! content reduction, not a rational normalisation (a gcd) per coefficient product.

use std::ops::{Add, Mul, Neg, Sub};
use std::rc::Rc;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// The generators of a multiquadratic field: their squares dᵢ, and the integers Dᵢ = pᵢqᵢ
/// (dᵢ = pᵢ/qᵢ in lowest terms) whose roots are the basis.
#[derive(Debug, PartialEq)]
pub struct MultiquadField {
    squares: Vec<BigRational>,
    integers: Vec<BigInt>,
}

impl MultiquadField {
    /// The generators' squares dᵢ.
    pub fn squares(&self) -> &[BigRational] {
        &self.squares
    }
}

/// An element Σ c_S ∏_{i∈S} √dᵢ over the subsets S of the generators (a bit mask each).
///
/// The basis need not be independent (a dᵢ may be a square, or a product of others): the
/// coefficients are then not unique, but the value, and so [`Multiquad::sign`], is.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::{rat, Multiquad};
/// use std::cmp::Ordering;
/// let field = Multiquad::field(vec![rat(2, 1), rat(3, 1)]);
/// let (r2, r3) = (Multiquad::root(&field, 0), Multiquad::root(&field, 1));
/// // (√2 + √3)² = 5 + 2√6, and √6 < 2.5
/// let s = &r2 + &r3;
/// let five = Multiquad::constant(&field, rat(5, 1));
/// assert_eq!((&(&s * &s) - &five).sign(), Ordering::Greater);
/// assert_eq!((&(&(&s * &s) - &five) - &Multiquad::constant(&field, rat(5, 1))).sign(), Ordering::Less);
/// ```
#[derive(Clone, Debug)]
pub struct Multiquad {
    field: Rc<MultiquadField>,
    /// Coefficients of ∏_{i∈S} √Dᵢ, over `den`.
    num: Vec<BigInt>,
    /// Positive. Not kept in lowest terms: a content gcd on every product costs more than the
    /// growth it saves; elements made or scaled from rationals are reduced.
    den: BigInt,
}

impl Multiquad {
    /// The field of the generators' squares dᵢ (each must be positive; at most 16 of them).
    pub fn field(squares: Vec<BigRational>) -> Rc<MultiquadField> {
        assert!(squares.len() <= 16 && squares.iter().all(Signed::is_positive));
        // lowest terms, the denominator positive: √(p/q) = √(pq)/q needs q > 0
        let squares: Vec<BigRational> = squares.iter().map(BigRational::reduced).collect();
        let integers = squares.iter().map(|d| d.numer() * d.denom()).collect();
        Rc::new(MultiquadField { squares, integers })
    }

    /// The rational `c` in the field.
    pub fn constant(field: &Rc<MultiquadField>, c: BigRational) -> Multiquad {
        let mut num = vec![BigInt::zero(); 1 << field.squares.len()];
        let (n, den) = c.into_raw();
        num[0] = n;
        Multiquad::reduced(field, num, den)
    }

    /// The generator √dᵢ = √Dᵢ / qᵢ.
    pub fn root(field: &Rc<MultiquadField>, i: usize) -> Multiquad {
        let mut num = vec![BigInt::zero(); 1 << field.squares.len()];
        num[1 << i] = BigInt::one();
        Multiquad::reduced(field, num, field.squares[i].denom().clone())
    }

    /// The element's field.
    pub fn squares(&self) -> &Rc<MultiquadField> {
        &self.field
    }

    /// The element times the rational `c`.
    pub fn scale(&self, c: &BigRational) -> Multiquad {
        let num = self.num.iter().map(|x| x * c.numer()).collect();
        Multiquad::reduced(&self.field, num, &self.den * c.denom())
    }

    /// The sign of the real value, exactly.
    pub fn sign(&self) -> std::cmp::Ordering {
        sign_of(&self.num, &self.field.integers)
    }

    /// Whether the value is zero.
    pub fn is_zero(&self) -> bool {
        self.sign() == std::cmp::Ordering::Equal
    }

    /// `num / den` in lowest terms, the denominator positive.
    fn reduced(field: &Rc<MultiquadField>, mut num: Vec<BigInt>, mut den: BigInt) -> Multiquad {
        if den.is_negative() {
            num.iter_mut().for_each(|x| *x = -&*x);
            den = -den;
        }
        let mut g = den.clone();
        for x in num.iter().filter(|x| !x.is_zero()) {
            if g.is_one() {
                break;
            }
            g = super::integer::gcd(&g, x);
        }
        if num.iter().all(Zero::is_zero) {
            g = den.clone();
        }
        if !g.is_one() {
            num.iter_mut().for_each(|x| *x /= &g);
            den /= &g;
        }
        Multiquad {
            field: field.clone(),
            num,
            den,
        }
    }
}

/// The sign of Σ c_S √D_S with generators `d` (c has 2^|d| entries). Split off the last
/// generator: x = a + b√d with a, b over the others. Where a and b agree in sign, that is the
/// sign; where they differ, the larger of a² and b²d wins.
fn sign_of(c: &[BigInt], d: &[BigInt]) -> std::cmp::Ordering {
    use std::cmp::Ordering::*;
    let Some((last, rest)) = d.split_last() else {
        return c[0].sign().cmp(&num_bigint::Sign::NoSign);
    };
    let (a, b) = c.split_at(c.len() / 2);
    let (sa, sb) = (sign_of(a, rest), sign_of(b, rest));
    if sb == Equal || sa == sb {
        return sa;
    }
    if sa == Equal {
        return sb;
    }
    // a² − d·b², over the remaining generators
    let diff: Vec<BigInt> = {
        let sq = |x: &[BigInt]| product(x, x, rest);
        let (aa, bb) = (sq(a), sq(b));
        aa.iter().zip(&bb).map(|(p, q)| p - q * last).collect()
    };
    match sign_of(&diff, rest) {
        Greater => sa,
        Less => sb,
        Equal => Equal,
    }
}

/// The product of two coefficient vectors over the generators `d`: √d_S·√d_T = √d_{S⊕T}·∏_{S∩T} dᵢ.
fn product(x: &[BigInt], y: &[BigInt], d: &[BigInt]) -> Vec<BigInt> {
    let mut out = vec![BigInt::zero(); x.len()];
    for (s, a) in x.iter().enumerate().filter(|(_, a)| !a.is_zero()) {
        for (t, b) in y.iter().enumerate().filter(|(_, b)| !b.is_zero()) {
            let shared = (0..d.len())
                .filter(|i| (s & t) >> i & 1 == 1)
                .fold(a * b, |p, i| p * &d[i]);
            out[s ^ t] += shared;
        }
    }
    out
}

/// Equal values of one field (the representation is not unique); elements of different
/// fields are not equal.
impl PartialEq for Multiquad {
    fn eq(&self, o: &Multiquad) -> bool {
        Rc::ptr_eq(&self.field, &o.field) && (self - o).is_zero()
    }
}

impl Add for &Multiquad {
    type Output = Multiquad;
    fn add(self, o: &Multiquad) -> Multiquad {
        debug_assert!(Rc::ptr_eq(&self.field, &o.field));
        // over the least common denominator: one gcd of the denominators, none of the sum's
        // content (rarely more than one; the coefficient growth is what a product reduces)
        let g = super::integer::gcd(&self.den, &o.den);
        let (fa, fb) = (&o.den / &g, &self.den / &g);
        let num = self
            .num
            .iter()
            .zip(&o.num)
            .map(|(a, b)| a * &fa + b * &fb)
            .collect();
        Multiquad {
            field: self.field.clone(),
            num,
            den: fa * &self.den,
        }
    }
}

impl Sub for &Multiquad {
    type Output = Multiquad;
    fn sub(self, o: &Multiquad) -> Multiquad {
        self + &-o
    }
}

impl Neg for &Multiquad {
    type Output = Multiquad;
    fn neg(self) -> Multiquad {
        Multiquad {
            field: self.field.clone(),
            num: self.num.iter().map(|a| -a).collect(),
            den: self.den.clone(),
        }
    }
}

impl Mul for &Multiquad {
    type Output = Multiquad;
    fn mul(self, o: &Multiquad) -> Multiquad {
        debug_assert!(Rc::ptr_eq(&self.field, &o.field));
        Multiquad {
            field: self.field.clone(),
            num: product(&self.num, &o.num, &self.field.integers),
            den: &self.den * &o.den,
        }
    }
}
