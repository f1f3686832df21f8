//! Evaluation at a point of any coefficient domain, and substitution.
//!
//! Evaluation uses a table of the powers of every variable (each power formed once, by one
//! product from the previous one): a term then costs one product per variable it contains.

use num_bigint::BigInt;
use num_rational::BigRational;

use super::coeff::Coef;
use super::MPoly;

/// A commutative ring in which integer polynomials can be evaluated.
pub trait Scalar: Clone {
    /// Zero.
    fn zero() -> Self;
    /// One.
    fn one() -> Self;
    /// The image of an integer.
    fn from_coef(c: &Coef) -> Self;
    /// Sum.
    fn add(&self, o: &Self) -> Self;
    /// Product.
    fn mul(&self, o: &Self) -> Self;
}

impl Scalar for BigRational {
    fn zero() -> Self {
        num_traits::Zero::zero()
    }
    fn one() -> Self {
        num_traits::One::one()
    }
    fn from_coef(c: &Coef) -> Self {
        BigRational::from_integer(c.to_big())
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
}

impl Scalar for BigInt {
    fn zero() -> Self {
        num_traits::Zero::zero()
    }
    fn one() -> Self {
        num_traits::One::one()
    }
    fn from_coef(c: &Coef) -> Self {
        c.to_big()
    }
    fn add(&self, o: &Self) -> Self {
        self + o
    }
    fn mul(&self, o: &Self) -> Self {
        self * o
    }
}

/// `x^0 … x^d` for each variable.
fn power_table<T: Scalar>(p: &MPoly, at: &[T]) -> Vec<Vec<T>> {
    let degrees: Vec<usize> = (0..at.len()).map(|i| p.degree_in(i) as usize).collect();
    powers(&degrees, at)
}

/// `x^0 … x^dᵢ` for each variable i, the degrees given.
fn powers<T: Scalar>(degrees: &[usize], at: &[T]) -> Vec<Vec<T>> {
    at.iter()
        .zip(degrees)
        .map(|(x, &d)| {
            let mut pw = Vec::with_capacity(d + 1);
            pw.push(T::one());
            for k in 0..d {
                let next = pw[k].mul(x);
                pw.push(next);
            }
            pw
        })
        .collect()
}

impl MPoly {
    /// The value at `at` (one value per variable).
    pub fn eval<T: Scalar>(&self, at: &[T]) -> T {
        let pw = power_table(self, at);
        let mut sum = T::zero();
        for t in 0..self.len() {
            let m = self.packed(t);
            let mut v = T::from_coef(&self.coefs[t]);
            for (i, table) in pw.iter().enumerate() {
                let e = self.pack.exponent(m, i) as usize;
                if e > 0 {
                    v = v.mul(&table[e]);
                }
            }
            sum = sum.add(&v);
        }
        sum
    }

    /// The values at several points, the coefficients' images given (`coefs[t]` the image
    /// of term t's coefficient, so that each is reduced once, not once per point). Each
    /// term's exponents are decoded once, into places in a point's table of powers; then
    /// point after point, its table in the nearest cache, every term is one product per
    /// variable it contains.
    pub fn eval_points<T: Scalar>(&self, coefs: &[T], points: &[Vec<T>]) -> Vec<T> {
        // each degree found once (a pass over the terms), not once per point
        let degrees: Vec<usize> = (0..self.nvars())
            .map(|i| self.degree_in(i) as usize)
            .collect();
        // variable i's powers start at `first[i]` of a point's table
        let first: Vec<usize> = degrees
            .iter()
            .scan(0, |at, d| {
                let here = *at;
                *at += d + 1;
                Some(here)
            })
            .collect();
        let (mut places, mut ends) = (Vec::new(), Vec::with_capacity(self.len()));
        for t in 0..self.len() {
            let m = self.packed(t);
            for (i, at) in first.iter().enumerate() {
                let e = self.pack.exponent(m, i) as usize;
                if e > 0 {
                    places.push(at + e);
                }
            }
            ends.push(places.len());
        }
        points
            .iter()
            .map(|at| {
                let table: Vec<T> = powers(&degrees, at).into_iter().flatten().collect();
                let mut sum = T::zero();
                let mut start = 0;
                // one image per term: fewer is a caller's error, and indexing says so
                for (c, &end) in coefs[..self.len()].iter().zip(&ends) {
                    let v = places[start..end]
                        .iter()
                        .fold(c.clone(), |v, &k| v.mul(&table[k]));
                    sum = sum.add(&v);
                    start = end;
                }
                sum
            })
            .collect()
    }

    /// The image of every coefficient, in term order (for [`MPoly::eval_points`]).
    pub fn coef_images<T: Scalar>(&self) -> Vec<T> {
        self.coefs.iter().map(T::from_coef).collect()
    }

    /// The 1-norm, the sum of the coefficients' magnitudes.
    pub fn l1_norm(&self) -> BigInt {
        self.coefs
            .iter()
            .map(|c| num_traits::Signed::abs(&c.to_big()))
            .sum()
    }

    /// The value at the rational point `nums[i] / dens[i]` as `(numerator, denominator)`,
    /// by integer arithmetic only: with dᵢ raised to the degree kᵢ of the polynomial in
    /// variable i, `Π dᵢ^kᵢ · p(n/d) = Σ c · Π nᵢ^eᵢ · dᵢ^(kᵢ−eᵢ)`, so no gcd is taken
    /// until the caller forms the one quotient.
    pub fn eval_fraction(&self, nums: &[BigInt], dens: &[BigInt]) -> (BigInt, BigInt) {
        let deg: Vec<usize> = (0..self.nvars())
            .map(|i| self.degree_in(i) as usize)
            .collect();
        let table = |x: &BigInt, d: usize| {
            let mut pw = vec![BigInt::from(1)];
            for k in 0..d {
                let next = &pw[k] * x;
                pw.push(next);
            }
            pw
        };
        let np: Vec<Vec<BigInt>> = nums.iter().zip(&deg).map(|(x, d)| table(x, *d)).collect();
        let dp: Vec<Vec<BigInt>> = dens.iter().zip(&deg).map(|(x, d)| table(x, *d)).collect();
        let mut sum = BigInt::from(0);
        for t in 0..self.len() {
            let m = self.packed(t);
            let mut v = self.coefs[t].to_big();
            for i in 0..self.nvars() {
                let e = self.pack.exponent(m, i) as usize;
                if e > 0 {
                    v *= &np[i][e];
                }
                if deg[i] > e {
                    v *= &dp[i][deg[i] - e];
                }
            }
            sum += v;
        }
        let den = dp
            .iter()
            .zip(&deg)
            .fold(BigInt::from(1), |acc, (p, d)| acc * &p[*d]);
        (sum, den)
    }

    /// The polynomial with variable `i` replaced by the integer `x` (variable `i` then no
    /// longer occurs): one pass over the terms with a power table of `x`.
    pub fn eval_var(&self, i: usize, x: &BigInt) -> MPoly {
        let d = self.degree_in(i) as usize;
        let mut pw = vec![BigInt::from(1)];
        for k in 0..d {
            let next = &pw[k] * x;
            pw.push(next);
        }
        let terms = (0..self.len())
            .map(|t| {
                let mut e = self.exponents(t);
                let k = std::mem::take(&mut e[i]) as usize;
                (e, Coef::from_big(self.coefs[t].to_big() * &pw[k]))
            })
            .collect();
        MPoly::from_terms(self.nvars(), terms)
    }

    /// The polynomial with variable `i` replaced by `value` (same ring): `Σₑ cₑ · valueᵉ`
    /// over the coefficients `cₑ` in variable `i`, the powers of `value` formed by repeated
    /// squaring (`value^(2^k)`, each needed power a product of those).
    pub fn substitute(&self, i: usize, value: &MPoly) -> MPoly {
        let parts = self.coefficients_in(i);
        let mut squares = vec![value.clone()];
        let mut out = MPoly::zero(self.nvars());
        for (e, c) in parts.iter().enumerate() {
            if c.is_zero() {
                continue;
            }
            let mut term = c.clone();
            let mut k = 0;
            while (e >> k) > 0 {
                if squares.len() <= k {
                    let s = &squares[k - 1] * &squares[k - 1];
                    squares.push(s);
                }
                if (e >> k) & 1 == 1 {
                    term = &term * &squares[k];
                }
                k += 1;
            }
            out = &out + &term;
        }
        out
    }
}
