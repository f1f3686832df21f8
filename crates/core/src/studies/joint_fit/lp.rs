//! Levenberg–Marquardt on the Lᵖ norm of residuals, in stages from least squares towards
//! the largest residual. A step is a handful of small dense products; the residuals and
//! Jacobians are written into buffers the stages keep, so the hundreds of steps of a fit
//! allocate almost nothing (the witness searches and the §4 mutant refits run thousands).

use nalgebra::{DMatrix, DMatrixView};

use crate::algebra::central_jacobian;

/// The exponents of the Lᵖ stages: least squares first, then ever closer to the largest
/// residual (p = 64 weighs a residual 1.1 times another by 1.1⁶⁴ ≈ 450).
const STAGES: [f64; 6] = [2.0, 4.0, 8.0, 16.0, 32.0, 64.0];

/// Levenberg–Marquardt steps per stage.
const STEPS: usize = 200;

/// A problem for the Lᵖ stages.
pub trait LpProblem {
    /// The residuals at `x` into `out` (the callee sets its length); `false` where they are
    /// undefined.
    fn residuals(&self, x: &[f64], out: &mut Vec<f64>) -> bool;

    /// The transpose of the Jacobian of gᵢ = sign(rᵢ)|rᵢ|^(p/2) at `x`, where the residuals
    /// are `raw`, into `jt` (the callee sets its shape: one column per residual, so each
    /// Jacobian row is contiguous); `false` where it is undefined.
    fn lp_jacobian(&self, x: &[f64], raw: &[f64], power: f64, jt: &mut DMatrix<f64>) -> bool;
}

/// gᵢ = sign(rᵢ)|rᵢ|^(p/2) of one residual.
#[inline]
pub fn lp_value(v: f64, power: f64) -> f64 {
    v.signum() * abs_pow(v, power / 2.0)
}

/// |v|^e; the exponents 0 and 1 without `powf`: 1 (what `powf` returns at exponent 0 for
/// every base, C99 Annex F) and |v| (what it returns at exponent 1, the report's bytes
/// unchanged), so the least-squares stage costs no power.
#[inline]
fn abs_pow(v: f64, e: f64) -> f64 {
    if e == 1.0 {
        v.abs()
    } else if e == 0.0 {
        1.0
    } else {
        v.abs().powf(e)
    }
}

/// gᵢ of every residual of `raw` into `out`.
pub fn lp_into(raw: &[f64], power: f64, out: &mut Vec<f64>) {
    out.clear();
    out.extend(raw.iter().map(|v| lp_value(*v, power)));
}

fn cost(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum::<f64>()
}

/// The chain rule from the transposed Jacobian of the residuals, filled in `jt`, to that of
/// gᵢ: ∂gᵢ = (p/2)|rᵢ|^(p/2 − 1) ∂rᵢ; `false` when an entry is not finite (as it is when
/// an entry of the residuals' Jacobian is not).
pub fn chain_rule(jt: &mut DMatrix<f64>, raw: &[f64], power: f64) -> bool {
    let n = jt.nrows();
    if n == 0 {
        return true;
    }
    for (col, r) in jt.as_mut_slice().chunks_exact_mut(n).zip(raw) {
        let s = power / 2.0 * abs_pow(*r, power / 2.0 - 1.0);
        col.iter_mut().for_each(|v| *v *= s);
    }
    jt.as_slice().iter().all(|v| v.is_finite())
}

/// Residuals of a parameter vector (`None`: undefined there).
pub type Residuals<'a> = &'a dyn Fn(&[f64]) -> Option<Vec<f64>>;

/// The Jacobian of [`Residuals`] (`None`: undefined there).
pub type ResidualJacobian<'a> = &'a dyn Fn(&[f64]) -> Option<DMatrix<f64>>;

/// Residuals and an optional Jacobian given as functions returning fresh vectors.
struct Closures<'a> {
    f: Residuals<'a>,
    jac: Option<ResidualJacobian<'a>>,
}

impl LpProblem for Closures<'_> {
    fn residuals(&self, x: &[f64], out: &mut Vec<f64>) -> bool {
        let Some(r) = (self.f)(x) else {
            return false;
        };
        *out = r;
        true
    }

    fn lp_jacobian(&self, x: &[f64], raw: &[f64], power: f64, jt: &mut DMatrix<f64>) -> bool {
        let Some(jac) = self.jac else {
            let g =
                |x: &[f64]| (self.f)(x).map(|r| r.iter().map(|v| lp_value(*v, power)).collect());
            return central_jacobian(&g, x, |_, xj| 1e-7 * xj.abs().max(1.0))
                .map(|m| *jt = m.transpose())
                .is_some();
        };
        let Some(m) = jac(x) else {
            return false;
        };
        *jt = m.transpose();
        chain_rule(jt, raw, power)
    }
}

/// Minimise the largest |rᵢ| of `f` from `x0`: the Lᵖ stages, least squares first, with
/// central-difference Jacobians. `None` when `f` is undefined at the start.
pub fn lp_minimax(f: Residuals, x0: &[f64]) -> Option<Vec<f64>> {
    lp_minimax_with(f, None, x0)
}

/// [`lp_minimax`] with the Jacobian `jac` of `f` when one is known (central differences
/// otherwise).
pub fn lp_minimax_with(
    f: Residuals,
    jac: Option<ResidualJacobian>,
    x0: &[f64],
) -> Option<Vec<f64>> {
    lp_minimax_problem(&Closures { f, jac }, x0)
}

/// [`lp_minimax`] of a problem that writes its residuals and Jacobians into buffers.
pub fn lp_minimax_problem<P: LpProblem + ?Sized>(problem: &P, x0: &[f64]) -> Option<Vec<f64>> {
    let mut ws = Workspace::default();
    let mut p = x0.to_vec();
    for power in STAGES {
        lp_stage(problem, &mut ws, &mut p, power)?;
    }
    Some(p)
}

/// The buffers of a fit, kept from step to step and stage to stage.
#[derive(Default)]
struct Workspace {
    raw: Vec<f64>,
    r: Vec<f64>,
    raw_trial: Vec<f64>,
    r_trial: Vec<f64>,
    trial: Vec<f64>,
    jt: DMatrix<f64>,
    jtj: DMatrix<f64>,
    a: Vec<f64>,
    grad: Vec<f64>,
    dx: Vec<f64>,
}

impl Workspace {
    /// JᵀJ and Jᵀr of the Jacobian whose transpose is `self.jt` and the residuals
    /// `self.r`. JᵀJ is the same product as `&jt * &jt.transpose()` (J as a strided view of
    /// `jt`, no copy); Jᵀr sums its terms in the order of the matrix-vector product
    /// `&jt * r`: r₀'s term first, then one residual at a time.
    fn normal_equations(&mut self) {
        let (n, m) = self.jt.shape();
        if self.jtj.shape() != (n, n) {
            self.jtj = DMatrix::zeros(n, n);
        }
        let j = DMatrixView::from_slice_with_strides(self.jt.as_slice(), m, n, n, 1);
        self.jtj.gemm(1.0, &self.jt, &j, 0.0);
        self.grad.clear();
        self.grad.resize(n, 0.0);
        if m == 0 {
            return;
        }
        let jt = self.jt.as_slice();
        for (g, v) in self.grad.iter_mut().zip(&jt[..n]) {
            *g = v * self.r[0];
        }
        for (k, rk) in self.r.iter().enumerate().skip(1) {
            for (g, v) in self.grad.iter_mut().zip(&jt[k * n..(k + 1) * n]) {
                *g += v * rk;
            }
        }
    }

    /// The damped step: (JᵀJ + λ diag(JᵀJ)) dx = Jᵀr into `self.dx`; `false` when the
    /// matrix is not positive definite.
    fn damped_step(&mut self, lambda: f64) -> bool {
        let n = self.jtj.nrows();
        self.a.clear();
        self.a.extend_from_slice(self.jtj.as_slice());
        for k in 0..n {
            self.a[k * n + k] += lambda * self.jtj[(k, k)].max(1e-12);
        }
        self.dx.clone_from(&self.grad);
        cholesky_solve(&mut self.a, n, &mut self.dx)
    }
}

/// nalgebra's `Cholesky::new(a)` and `solve_mut(b)`, operation for operation, on the
/// column-major n × n `a` (lower triangle read, factored in place) and `b` (solved in
/// place): the same results without its matrix views, which cost more than the arithmetic
/// at this size. `false` where nalgebra's gives `None` (a pivot zero, negative or NaN).
fn cholesky_solve(a: &mut [f64], n: usize, b: &mut [f64]) -> bool {
    for j in 0..n {
        for k in 0..j {
            // column j from row j on, plus −L[j, k] times column k (nalgebra's `axpy`)
            let factor = -a[j + k * n];
            let (left, right) = a.split_at_mut(j * n);
            for (y, x) in right[j..n].iter_mut().zip(&left[k * n + j..k * n + n]) {
                *y += factor * x;
            }
        }
        let diag = a[j * n + j];
        if diag.is_nan() || diag <= 0.0 {
            return false;
        }
        let denom = diag.sqrt();
        a[j * n + j] = denom;
        a[j * n + j + 1..(j + 1) * n]
            .iter_mut()
            .for_each(|v| *v /= denom);
    }
    for i in 0..n {
        let coeff = b[i] / a[i * n + i];
        b[i] = coeff;
        let (_, rest) = b.split_at_mut(i + 1);
        for (y, x) in rest.iter_mut().zip(&a[i * n + i + 1..(i + 1) * n]) {
            *y += -coeff * x;
        }
    }
    for i in (0..n).rev() {
        let dot = dot_unrolled(&a[i * n + i + 1..(i + 1) * n], &b[i + 1..n]);
        b[i] = (b[i] - dot) / a[i * n + i];
    }
    true
}

/// nalgebra's dot product of two dynamic vectors, in its order: eight running sums over
/// blocks of eight, folded pairwise, then the remainder one by one.
fn dot_unrolled(x: &[f64], y: &[f64]) -> f64 {
    let mut acc = [0.0; 8];
    let blocks = x.len() / 8 * 8;
    for (xs, ys) in x[..blocks].chunks_exact(8).zip(y[..blocks].chunks_exact(8)) {
        for t in 0..8 {
            acc[t] += xs[t] * ys[t];
        }
    }
    let mut res = 0.0;
    for t in 0..4 {
        res += acc[t] + acc[t + 4];
    }
    for (a, b) in x[blocks..].iter().zip(&y[blocks..]) {
        res += a * b;
    }
    res
}

/// Levenberg–Marquardt on Σ gᵢ², gᵢ = sign(rᵢ)|rᵢ|^(p/2): the Lᵖ norm of the residuals,
/// from `x` (moved to the stage's end). `None` when the residuals are undefined at `x`.
fn lp_stage<P: LpProblem + ?Sized>(
    problem: &P,
    ws: &mut Workspace,
    x: &mut Vec<f64>,
    power: f64,
) -> Option<()> {
    if !problem.residuals(x, &mut ws.raw) {
        return None;
    }
    lp_into(&ws.raw, power, &mut ws.r);
    let mut c = cost(&ws.r);
    let mut lambda = 1e-3;
    for _ in 0..STEPS {
        if !problem.lp_jacobian(x, &ws.raw, power, &mut ws.jt) {
            break;
        }
        ws.normal_equations();
        let mut improved = false;
        while lambda < 1e12 {
            if !ws.damped_step(lambda) {
                lambda *= 10.0;
                continue;
            }
            ws.trial.clear();
            ws.trial
                .extend(x.iter().zip(ws.dx.iter()).map(|(a, d)| a - d));
            if problem.residuals(&ws.trial, &mut ws.raw_trial) {
                lp_into(&ws.raw_trial, power, &mut ws.r_trial);
                let ct = cost(&ws.r_trial);
                if ct < c {
                    std::mem::swap(x, &mut ws.trial);
                    std::mem::swap(&mut ws.r, &mut ws.r_trial);
                    std::mem::swap(&mut ws.raw, &mut ws.raw_trial);
                    c = ct;
                    lambda = (lambda / 10.0).max(1e-12);
                    improved = true;
                    break;
                }
            }
            lambda *= 10.0;
        }
        if !improved {
            break;
        }
    }
    Some(())
}
