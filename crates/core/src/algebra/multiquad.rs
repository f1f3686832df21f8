//! Exact arithmetic in a multiquadratic field ℚ(√d₁, …, √dₖ), the dᵢ positive rationals and
//! every √dᵢ the positive real root: the field of a few square roots at once (the directions
//! of lines found by solving one quadratic each), with an exact sign, so that comparisons and
//! zero tests need no rounding.

use std::ops::{Add, Mul, Neg, Sub};
use std::rc::Rc;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

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
#[derive(Clone, Debug, PartialEq)]
pub struct Multiquad {
    squares: Rc<[BigRational]>,
    coeffs: Vec<BigRational>,
}

impl Multiquad {
    /// The generators' squares dᵢ (each must be positive; at most 16 of them).
    pub fn field(squares: Vec<BigRational>) -> Rc<[BigRational]> {
        assert!(squares.len() <= 16 && squares.iter().all(Signed::is_positive));
        squares.into()
    }

    /// The rational `c` in the field.
    pub fn constant(field: &Rc<[BigRational]>, c: BigRational) -> Multiquad {
        let mut coeffs = vec![BigRational::zero(); 1 << field.len()];
        coeffs[0] = c;
        Multiquad {
            squares: field.clone(),
            coeffs,
        }
    }

    /// The generator √dᵢ.
    pub fn root(field: &Rc<[BigRational]>, i: usize) -> Multiquad {
        let mut coeffs = vec![BigRational::zero(); 1 << field.len()];
        coeffs[1 << i] = BigRational::from_integer(1.into());
        Multiquad {
            squares: field.clone(),
            coeffs,
        }
    }

    /// The generators' squares of the element's field.
    pub fn squares(&self) -> &Rc<[BigRational]> {
        &self.squares
    }

    /// The element times the rational `c`.
    pub fn scale(&self, c: &BigRational) -> Multiquad {
        Multiquad {
            squares: self.squares.clone(),
            coeffs: self.coeffs.iter().map(|x| x * c).collect(),
        }
    }

    /// The sign of the real value, exactly.
    pub fn sign(&self) -> std::cmp::Ordering {
        sign_of(&self.coeffs, &self.squares)
    }

    /// Whether the value is zero.
    pub fn is_zero(&self) -> bool {
        self.sign() == std::cmp::Ordering::Equal
    }
}

/// The sign of Σ c_S √d_S with generators `d` (c has 2^|d| entries). Split off the last
/// generator: x = a + b√d with a, b over the others. Where a and b agree in sign, that is the
/// sign; where they differ, the larger of a² and b²d wins.
fn sign_of(c: &[BigRational], d: &[BigRational]) -> std::cmp::Ordering {
    use std::cmp::Ordering::*;
    let Some((last, rest)) = d.split_last() else {
        return c[0].cmp(&BigRational::zero());
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
    let diff: Vec<BigRational> = {
        let sq = |x: &[BigRational]| product(x, x, rest);
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
fn product(x: &[BigRational], y: &[BigRational], d: &[BigRational]) -> Vec<BigRational> {
    let mut out = vec![BigRational::zero(); x.len()];
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

impl Add for &Multiquad {
    type Output = Multiquad;
    fn add(self, o: &Multiquad) -> Multiquad {
        debug_assert!(Rc::ptr_eq(&self.squares, &o.squares));
        Multiquad {
            squares: self.squares.clone(),
            coeffs: self
                .coeffs
                .iter()
                .zip(&o.coeffs)
                .map(|(a, b)| a + b)
                .collect(),
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
            squares: self.squares.clone(),
            coeffs: self.coeffs.iter().map(|a| -a).collect(),
        }
    }
}

impl Mul for &Multiquad {
    type Output = Multiquad;
    fn mul(self, o: &Multiquad) -> Multiquad {
        debug_assert!(Rc::ptr_eq(&self.squares, &o.squares));
        Multiquad {
            squares: self.squares.clone(),
            coeffs: product(&self.coeffs, &o.coeffs, &self.squares),
        }
    }
}
