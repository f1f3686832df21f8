//! Floating-point roots: a cancellation-free quadratic, the `roots` crate's closed forms,
//! companion-matrix eigenvalues, and a comparison of the methods.

use nalgebra::{DMatrix, Schur};
use num_complex::Complex64;

/// Roots of `a x² + b x + c`, real and complex; the sign of the square root is chosen
/// against cancellation (`q = −(b + sign(b)√Δ)/2`, roots `q/a` and `c/q`).
///
/// A vanishing `a` degrades to the linear root; `0 = 0` gives no roots.
///
/// # Example
/// ```
/// use orthocheck_core::algebra::quadratic;
/// let r = quadratic(1.0, -1e8, 1.0);
/// // the small root keeps full relative precision
/// assert!((r[0].re - 1e-8).abs() < 1e-22);
/// ```
pub fn quadratic(a: f64, b: f64, c: f64) -> Vec<Complex64> {
    let (r, n) = quadratic_roots(a, b, c);
    r[..n].to_vec()
}

/// [`quadratic`] without allocation: the roots (real ones ascending, complex ones with the
/// negative imaginary part first) and how many there are (0, 1 or 2).
#[inline]
pub fn quadratic_roots(a: f64, b: f64, c: f64) -> ([Complex64; 2], usize) {
    let zero = Complex64::new(0.0, 0.0);
    if a == 0.0 {
        return if b == 0.0 {
            ([zero; 2], 0)
        } else {
            ([Complex64::new(-c / b, 0.0), zero], 1)
        };
    }
    let disc = b * b - 4.0 * a * c;
    if disc >= 0.0 {
        let sq = disc.sqrt();
        let q = -0.5 * (b + b.signum() * sq);
        if q == 0.0 {
            // b = 0 and c = 0: a double root at zero.
            return ([zero; 2], 2);
        }
        let (r1, r2) = (q / a, c / q);
        let (lo, hi) = if r1 <= r2 { (r1, r2) } else { (r2, r1) };
        ([Complex64::new(lo, 0.0), Complex64::new(hi, 0.0)], 2)
    } else {
        let re = -b / (2.0 * a);
        let im = (-disc).sqrt() / (2.0 * a.abs());
        ([Complex64::new(re, -im), Complex64::new(re, im)], 2)
    }
}

/// Real roots of a polynomial of degree ≤ 4 (coefficients constant term first) by the
/// `roots` crate's closed forms. Used as a cross-check only.
pub fn closed_form_real(coeffs: &[f64]) -> Vec<f64> {
    let c = trim(coeffs);
    let mut r: Vec<f64> = match c.len() {
        0 | 1 => Vec::new(),
        2 => roots::find_roots_linear(c[1], c[0]).as_ref().to_vec(),
        3 => roots::find_roots_quadratic(c[2], c[1], c[0])
            .as_ref()
            .to_vec(),
        4 => roots::find_roots_cubic(c[3], c[2], c[1], c[0])
            .as_ref()
            .to_vec(),
        5 => roots::find_roots_quartic(c[4], c[3], c[2], c[1], c[0])
            .as_ref()
            .to_vec(),
        _ => Vec::new(),
    };
    r.sort_by(f64::total_cmp);
    r
}

fn trim(coeffs: &[f64]) -> &[f64] {
    let mut n = coeffs.len();
    while n > 0 && coeffs[n - 1] == 0.0 {
        n -= 1;
    }
    &coeffs[..n]
}

/// How the companion-matrix roots were obtained.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub enum EigenMethod {
    /// Real Schur decomposition converged within the iteration limit.
    Schur,
    /// Schur did not converge; Durand–Kerner iteration was used instead.
    DurandKerner,
}

/// Iteration limit for the Schur decomposition (nalgebra's unbounded default can loop).
const SCHUR_MAX_ITER: usize = 10_000;

/// All complex roots (coefficients constant term first) as eigenvalues of the companion
/// matrix, with a Durand–Kerner fallback when Schur does not converge.
pub fn companion_roots(coeffs: &[f64]) -> (Vec<Complex64>, EigenMethod) {
    let c = trim(coeffs);
    let n = c.len().saturating_sub(1);
    if n == 0 {
        return (Vec::new(), EigenMethod::Schur);
    }
    let lead = c[n];
    let mut m = DMatrix::<f64>::zeros(n, n);
    for i in 1..n {
        m[(i, i - 1)] = 1.0;
    }
    for i in 0..n {
        m[(i, n - 1)] = -c[i] / lead;
    }
    let mut roots: Vec<Complex64>;
    let method;
    match Schur::try_new(m, f64::EPSILON, SCHUR_MAX_ITER) {
        Some(s) => {
            roots = s.complex_eigenvalues().iter().copied().collect();
            method = EigenMethod::Schur;
        }
        None => {
            roots = durand_kerner(c);
            method = EigenMethod::DurandKerner;
        }
    }
    roots.sort_by(|a, b| a.re.total_cmp(&b.re).then(a.im.total_cmp(&b.im)));
    (roots, method)
}

/// Durand–Kerner (Weierstrass) simultaneous iteration, a fixed number of sweeps.
pub fn durand_kerner(c: &[f64]) -> Vec<Complex64> {
    let n = c.len() - 1;
    let lead = c[n];
    let eval = |z: Complex64| {
        c.iter()
            .rev()
            .fold(Complex64::new(0.0, 0.0), |acc, &k| acc * z + k / lead)
    };
    let seed = Complex64::new(0.4, 0.9);
    let mut z: Vec<Complex64> = (0..n).map(|i| seed.powu(i as u32)).collect();
    for _ in 0..500 {
        for i in 0..n {
            let denom = (0..n)
                .filter(|&j| j != i)
                .fold(Complex64::new(1.0, 0.0), |acc, j| acc * (z[i] - z[j]));
            if denom.norm() > 0.0 {
                let zi = z[i];
                z[i] = zi - eval(zi) / denom;
            }
        }
    }
    z
}

/// Agreement of independent root finders on one polynomial.
#[derive(Clone, Debug, serde::Serialize)]
pub struct RootAgreement {
    /// Real roots from the companion matrix (imaginary part below `imag_tol`).
    pub companion_real: Vec<f64>,
    /// Real roots from the closed form (degree ≤ 4), if applicable.
    pub closed_form_real: Option<Vec<f64>>,
    /// Real roots from the stable quadratic, if degree 2.
    pub quadratic_real: Option<Vec<f64>>,
    /// Largest absolute disagreement between matched real roots across methods.
    pub max_disagreement: f64,
    /// Whether all methods found the same number of real roots.
    pub same_count: bool,
    /// Which eigenvalue method ran.
    pub eigen_method: EigenMethod,
}

/// Compare the methods on one polynomial (coefficients constant term first). A complex
/// root counts as real when its imaginary part is below `imag_tol`.
pub fn compare_methods(coeffs: &[f64], imag_tol: f64) -> RootAgreement {
    let (all, eigen_method) = companion_roots(coeffs);
    let companion_real: Vec<f64> = all
        .iter()
        .filter(|z| z.im.abs() <= imag_tol)
        .map(|z| z.re)
        .collect();
    let c = trim(coeffs);
    let closed = (c.len() <= 5).then(|| closed_form_real(c));
    let quad = (c.len() == 3).then(|| {
        quadratic(c[2], c[1], c[0])
            .iter()
            .filter(|z| z.im == 0.0)
            .map(|z| z.re)
            .collect::<Vec<f64>>()
    });
    let mut max_dis: f64 = 0.0;
    let mut same = true;
    for other in [closed.as_ref(), quad.as_ref()].into_iter().flatten() {
        if other.len() != companion_real.len() {
            same = false;
        }
        for (x, y) in companion_real.iter().zip(other) {
            max_dis = max_dis.max((x - y).abs());
        }
    }
    RootAgreement {
        companion_real,
        closed_form_real: closed,
        quadratic_real: quad,
        max_disagreement: max_dis,
        same_count: same,
        eigen_method,
    }
}
