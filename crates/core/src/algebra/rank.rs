//! Matrix rank: exact over ℚ, and numerical by SVD.

use nalgebra::DMatrix;
use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, ToPrimitive, Zero};

/// The Mersenne prime 2⁶¹ − 1, for the modular lower bound.
const PRIME: u64 = (1 << 61) - 1;

/// How an exact rank was established.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum ExactRankMethod {
    /// The rank modulo a prime reached min(rows, cols); the rank over ℚ cannot exceed that
    /// and is never below the modular rank, so it is proven.
    ModularFull,
    /// Fraction-free (Bareiss) elimination over ℤ.
    FractionFree,
}

impl ExactRankMethod {
    /// How the rank was proven, in words.
    pub fn describe(self) -> &'static str {
        match self {
            ExactRankMethod::ModularFull => "full rank modulo a prime (so full over ℚ)",
            ExactRankMethod::FractionFree => "fraction-free elimination over the integers",
        }
    }
}

/// Exact rank of a rational matrix (rows of equal length).
///
/// The rank modulo a large prime is a lower bound; when it is already min(m, n) it is the
/// rank. Otherwise fraction-free Gaussian elimination over ℤ decides.
///
/// # Example
/// ```
/// use num_rational::BigRational;
/// use orthocheck_core::algebra::exact_rank;
/// let r = |n: i64| BigRational::from_integer(n.into());
/// let m = vec![vec![r(1), r(2)], vec![r(2), r(4)]];
/// assert_eq!(exact_rank(&m).0, 1);
/// ```
pub fn exact_rank(rows: &[Vec<BigRational>]) -> (usize, ExactRankMethod) {
    let m = rows.len();
    let n = rows.first().map_or(0, Vec::len);
    if let Some(r) = modular_rank(rows)
        && r == m.min(n)
    {
        return (r, ExactRankMethod::ModularFull);
    }
    (bareiss_rank(rows), ExactRankMethod::FractionFree)
}

fn to_mod(x: &BigRational) -> Option<u64> {
    let p = BigInt::from(PRIME);
    let num = x.numer().mod_floor(&p).to_u64()?;
    let den = x.denom().mod_floor(&p).to_u64()?;
    if den == 0 {
        return None;
    }
    Some(mul_mod(num, inv_mod(den)))
}

fn mul_mod(a: u64, b: u64) -> u64 {
    ((a as u128 * b as u128) % PRIME as u128) as u64
}

fn inv_mod(a: u64) -> u64 {
    // Fermat: a^(p-2).
    let (mut base, mut e, mut acc) = (a, PRIME - 2, 1u64);
    while e > 0 {
        if e & 1 == 1 {
            acc = mul_mod(acc, base);
        }
        base = mul_mod(base, base);
        e >>= 1;
    }
    acc
}

/// Rank modulo the word prime `PRIME`; `None` if a denominator vanishes modulo the prime.
pub fn modular_rank(rows: &[Vec<BigRational>]) -> Option<usize> {
    let mut a: Vec<Vec<u64>> = rows
        .iter()
        .map(|r| r.iter().map(to_mod).collect::<Option<Vec<u64>>>())
        .collect::<Option<_>>()?;
    let (m, n) = (a.len(), a.first().map_or(0, Vec::len));
    let mut rank = 0;
    for col in 0..n {
        let Some(piv) = (rank..m).find(|&i| a[i][col] != 0) else {
            continue;
        };
        a.swap(rank, piv);
        let inv = inv_mod(a[rank][col]);
        for i in rank + 1..m {
            if a[i][col] == 0 {
                continue;
            }
            let f = mul_mod(a[i][col], inv);
            let (top, bottom) = a.split_at_mut(i);
            for (x, &p) in bottom[0][col..].iter_mut().zip(&top[rank][col..]) {
                *x = (*x + PRIME - mul_mod(f, p)) % PRIME;
            }
        }
        rank += 1;
    }
    Some(rank)
}

/// Fraction-free Gaussian elimination (Bareiss) over ℤ after clearing each row's denominators.
pub fn bareiss_rank(rows: &[Vec<BigRational>]) -> usize {
    let mut a: Vec<Vec<BigInt>> = rows
        .iter()
        .map(|r| {
            let l = r.iter().fold(BigInt::one(), |acc, x| acc.lcm(x.denom()));
            r.iter()
                .map(|x| (x * BigRational::from_integer(l.clone())).to_integer())
                .collect()
        })
        .collect();
    let (m, n) = (a.len(), a.first().map_or(0, Vec::len));
    let mut prev = BigInt::one();
    let mut rank = 0;
    for col in 0..n {
        let Some(piv) = (rank..m).find(|&i| !a[i][col].is_zero()) else {
            continue;
        };
        a.swap(rank, piv);
        for i in rank + 1..m {
            for j in col + 1..n {
                let v = (&a[rank][col] * &a[i][j] - &a[i][col] * &a[rank][j]) / &prev;
                a[i][j] = v;
            }
            a[i][col] = BigInt::zero();
        }
        prev = a[rank][col].clone();
        rank += 1;
    }
    rank
}

/// Solve the square system `A x = b` exactly over ℚ (Gauss–Jordan with exact pivots);
/// `None` when A is singular.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::{exact_solve, rat};
/// let a = vec![vec![rat(2, 1), rat(1, 1)], vec![rat(1, 1), rat(3, 1)]];
/// let x = exact_solve(&a, &[rat(3, 1), rat(5, 1)]).unwrap();
/// assert_eq!(x, [rat(4, 5), rat(7, 5)]);
/// ```
pub fn exact_solve(a: &[Vec<BigRational>], b: &[BigRational]) -> Option<Vec<BigRational>> {
    let n = a.len();
    if b.len() != n || a.iter().any(|r| r.len() != n) {
        return None;
    }
    let mut m: Vec<Vec<BigRational>> = a
        .iter()
        .zip(b)
        .map(|(r, bi)| {
            r.iter()
                .cloned()
                .chain(std::iter::once(bi.clone()))
                .collect()
        })
        .collect();
    for c in 0..n {
        let p = (c..n).find(|&r| !m[r][c].is_zero())?;
        m.swap(c, p);
        let inv = BigRational::one() / &m[c][c];
        for v in m[c].iter_mut() {
            *v = &*v * &inv;
        }
        for r in 0..n {
            if r != c && !m[r][c].is_zero() {
                let f = m[r][c].clone();
                let pivot = m[c].clone();
                for (v, p) in m[r].iter_mut().zip(&pivot).skip(c) {
                    *v -= &f * p;
                }
            }
        }
    }
    Some(m.into_iter().map(|r| r[n].clone()).collect())
}

/// Numerical rank by singular values.
#[derive(Clone, Debug, serde::Serialize)]
pub struct SvdRank {
    /// Number of singular values above `tolerance`.
    pub rank: usize,
    /// σmax · max(m, n) · ε.
    pub tolerance: f64,
    /// Singular values, descending.
    pub singular_values: Vec<f64>,
    /// σmax / σmin over all min(m, n) singular values; `None` when rank-deficient (a
    /// rounding-level σmin would make the number meaningless and machine-dependent).
    pub condition: Option<f64>,
}

/// Rank with the tolerance σmax·max(m,n)·ε, and the 2-norm condition number.
///
/// # Example
/// ```
/// use nalgebra::DMatrix;
/// use orthocheck_core::algebra::svd_rank;
/// let m = DMatrix::from_row_slice(2, 2, &[1.0, 2.0, 2.0, 4.0]);
/// assert_eq!(svd_rank(&m).rank, 1);
/// ```
pub fn svd_rank(m: &DMatrix<f64>) -> SvdRank {
    svd_rank_above(m, 0.0)
}

/// Iterations the SVD of [`svd_rank_above`] may take (it converges in a few per singular
/// value on finite input; the bound only stops a loop).
pub const SVD_MAX_ITERATIONS: usize = 10_000;

/// Like [`svd_rank`], but singular values up to `noise` (a bound on the Frobenius norm of
/// the rounding error in the entries) also count as zero: a matrix made only of rounding
/// noise then has rank 0 instead of full rank. A non-finite matrix, or one whose SVD does not
/// converge within [`SVD_MAX_ITERATIONS`], has rank 0 and no singular values.
pub fn svd_rank_above(m: &DMatrix<f64>, noise: f64) -> SvdRank {
    let (rows, cols) = m.shape();
    if rows == 0 || cols == 0 {
        return SvdRank {
            rank: 0,
            tolerance: 0.0,
            singular_values: Vec::new(),
            condition: None,
        };
    }
    // nalgebra's SVD can iterate forever on a non-finite matrix (or fail to converge): such a
    // matrix has no numerical rank, and the iterations are bounded
    let svd = m
        .iter()
        .all(|v| v.is_finite())
        .then(|| nalgebra::SVD::try_new(m.clone(), false, false, f64::EPSILON, SVD_MAX_ITERATIONS))
        .flatten();
    let Some(svd) = svd else {
        return SvdRank {
            rank: 0,
            tolerance: f64::INFINITY,
            singular_values: Vec::new(),
            condition: None,
        };
    };
    let mut sv: Vec<f64> = svd.singular_values.iter().copied().collect();
    sv.sort_by(|a, b| b.total_cmp(a));
    let smax = sv.first().copied().unwrap_or(0.0);
    let tol = (smax * rows.max(cols) as f64 * f64::EPSILON).max(noise);
    let rank = sv.iter().filter(|&&s| s > tol).count();
    let smin = sv.last().copied().unwrap_or(0.0);
    SvdRank {
        rank,
        tolerance: tol,
        condition: (rank == rows.min(cols) && smin > 0.0).then(|| smax / smin),
        singular_values: sv,
    }
}
