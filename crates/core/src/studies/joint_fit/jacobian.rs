//! The analytic Jacobian of the joint fit's scaled residuals: the chain body → projections
//! → squared lengths → coefficients, each link differentiated once and shared by every
//! residual that uses it (the central-difference Jacobian costs 42 residual evaluations per
//! step, which made §4's 96 mutant refits the slowest part of the report).

use nalgebra::{DMatrix, Matrix3, Rotation3, Vector3};

use super::{tetrahedron, JointInput, POINTS};
use crate::studies::printed_matrix::RowMatch;

/// Number of parameters: six edge offsets, then per camera a rotation vector and a 2-D
/// translation.
const EDGES: usize = 6;

/// A value and its gradient with respect to the six edge offsets (forward mode).
#[derive(Clone, Copy, Debug)]
struct Dual {
    v: f64,
    g: [f64; EDGES],
}

impl Dual {
    fn constant(v: f64) -> Self {
        Dual { v, g: [0.0; EDGES] }
    }
    fn map(self, v: f64, dv: f64) -> Self {
        Dual {
            v,
            g: self.g.map(|x| x * dv),
        }
    }
    fn zip(self, o: Dual, v: f64, da: f64, db: f64) -> Self {
        Dual {
            v,
            g: std::array::from_fn(|k| self.g[k] * da + o.g[k] * db),
        }
    }
    fn add(self, o: Dual) -> Self {
        self.zip(o, self.v + o.v, 1.0, 1.0)
    }
    fn sub(self, o: Dual) -> Self {
        self.zip(o, self.v - o.v, 1.0, -1.0)
    }
    fn mul(self, o: Dual) -> Self {
        self.zip(o, self.v * o.v, o.v, self.v)
    }
    fn div(self, o: Dual) -> Self {
        let q = self.v / o.v;
        self.zip(o, q, 1.0 / o.v, -q / o.v)
    }
    fn scale(self, c: f64) -> Self {
        self.map(self.v * c, c)
    }
    fn sqrt(self) -> Self {
        let s = self.v.sqrt();
        self.map(s, 0.5 / s)
    }
}

/// d(body point)/d(edge offsets): per point, a 3 × 6 matrix. The values follow
/// [`tetrahedron`] step by step; `None` where it has no body or a square root's derivative
/// is unbounded (a flat tetrahedron).
fn body_gradient(inp: &JointInput, p: &[f64]) -> Option<[[[f64; EDGES]; 3]; POINTS]> {
    let s: Vec<Dual> = inp
        .edges
        .iter()
        .enumerate()
        .map(|(k, (lo, hi))| {
            let mut g = [0.0; EDGES];
            g[k] = (hi - lo) / 2.0;
            Dual {
                v: (lo + hi) / 2.0 + p[k] * (hi - lo) / 2.0,
                g,
            }
        })
        .collect();
    let two = Dual::constant(2.0);
    let a = s[0].sqrt();
    let rx = s[2].add(s[0]).sub(s[1]).div(a.scale(2.0));
    let ry = s[2].sub(rx.mul(rx)).sqrt();
    let tx = s[3].add(s[0]).sub(s[4]).div(a.scale(2.0));
    let ty = s[3].add(s[2]).sub(s[5]).div(two).sub(rx.mul(tx)).div(ry);
    let tz = s[3].sub(tx.mul(tx)).sub(ty.mul(ty)).sqrt();
    let z = Dual::constant(0.0);
    let pts = [[z, z, z], [a, z, z], [rx, ry, z], [tx, ty, tz]];
    let grad = pts.map(|q| q.map(|c| c.g));
    grad.iter()
        .flatten()
        .flatten()
        .all(|v| v.is_finite())
        .then_some(grad)
}

fn cross_matrix(v: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::new(0.0, -v.z, v.y, v.z, 0.0, -v.x, -v.y, v.x, 0.0)
}

/// The left Jacobian of SO(3) at the rotation vector `w`: exp(w + δ) ≈ exp(J δ) exp(w), so
/// d(exp(w) X)/dw = −[exp(w) X]× J.
fn left_jacobian(w: &Vector3<f64>) -> Matrix3<f64> {
    let t2 = w.norm_squared();
    let t = t2.sqrt();
    // (1 − cos θ)/θ² written without cancellation; (θ − sin θ)/θ³ by its Taylor series
    // below θ = 0.1, where the next term (θ⁸/39916800 < 3·10⁻¹⁶) is below the unit
    // roundoff, and in closed form above, where the cancellation costs at most a factor
    // 1/θ² ≤ 100 of the unit roundoff
    let a = if t == 0.0 {
        0.5
    } else {
        let s = (t / 2.0).sin() / t;
        2.0 * s * s
    };
    let b = if t < 0.1 {
        1.0 / 6.0 - t2 / 120.0 + t2 * t2 / 5040.0 - t2 * t2 * t2 / 362_880.0
    } else {
        (t - t.sin()) / (t2 * t)
    };
    let k = cross_matrix(w);
    Matrix3::identity() + k * a + k * k * b
}

/// `o[k] += c · g[k]` over the columns that the quantities of frame `f` (0-based) depend
/// on: the edge offsets and the frame's camera. Every other column of their derivatives is
/// exactly +0, and adding c·(±0) to a sum begun at +0 leaves it unchanged, so those columns
/// are skipped.
#[inline]
fn add_on_support(o: &mut [f64], c: f64, g: &[f64], f: usize) {
    let cam = EDGES + 5 * f..EDGES + 5 * f + 5;
    for (o, g) in o[..EDGES].iter_mut().zip(&g[..EDGES]) {
        *o += c * g;
    }
    for (o, g) in o[cam.clone()].iter_mut().zip(&g[cam]) {
        *o += c * g;
    }
}

/// The flat image coordinates into `x` (as [`super::scaled`] projects them) and their
/// derivatives over the parameters into `d`, row-major with `p.len()` columns; `false`
/// where there is no body or a derivative of it is unbounded.
fn projection_jacobian(inp: &JointInput, p: &[f64], x: &mut Vec<f64>, d: &mut Vec<f64>) -> bool {
    let squares = super::squares_at(inp, p);
    let (Some(body), Some(db)) = (tetrahedron(&squares), body_gradient(inp, p)) else {
        return false;
    };
    let n = p.len();
    let cameras = (n - EDGES) / 5;
    x.clear();
    d.clear();
    d.resize(2 * POINTS * cameras * n, 0.0);
    for (c, q) in p[EDGES..].chunks(5).enumerate() {
        let w = Vector3::new(q[0], q[1], q[2]);
        let r = Rotation3::new(w);
        let m = r.matrix();
        let jl = left_jacobian(&w);
        let col = EDGES + 5 * c;
        for (j, (b, db)) in body.iter().zip(&db).enumerate() {
            let row = 2 * (POINTS * c + j);
            let y = m * b;
            x.extend([y.x + q[3], y.y + q[4]]);
            // the rotation's columns: −[R X]× J_l, shared by both image coordinates
            let dw = -cross_matrix(&y) * jl;
            for i in 0..2 {
                let d = &mut d[(row + i) * n..(row + i + 1) * n];
                for k in 0..EDGES {
                    d[k] = (0..3).map(|l| m[(i, l)] * db[l][k]).sum();
                }
                for k in 0..3 {
                    d[col + k] = dw[(i, k)];
                }
                d[col + 3 + i] = 1.0;
            }
        }
    }
    true
}

/// Every squared length of every frame (frame-major, edges in `model::edges` order) into
/// `values`, and its gradient over the `n` parameters into `grads` (one run of `n` per
/// length), from the projections `x` and their derivatives `d` (row-major): computed once
/// per Jacobian, shared by every row that uses the edge.
fn length_table(x: &[f64], d: &[f64], n: usize, values: &mut Vec<f64>, grads: &mut Vec<f64>) {
    let per_frame = POINTS * (POINTS - 1) / 2;
    values.clear();
    grads.clear();
    for f in 0..x.len() / (2 * POINTS) {
        for e in 0..per_frame {
            let (i, j) = crate::model::edge(e);
            let (a, b) = (2 * (POINTS * f + i), 2 * (POINTS * f + j));
            let start = grads.len();
            grads.resize(start + n, 0.0);
            let g = &mut grads[start..];
            for c in 0..2 {
                let diff = 2.0 * (x[a + c] - x[b + c]);
                let (da, db) = (&d[(a + c) * n..], &d[(b + c) * n..]);
                let cam = EDGES + 5 * f..EDGES + 5 * f + 5;
                for range in [0..EDGES, cam] {
                    for ((gk, u), v) in g[range.clone()]
                        .iter_mut()
                        .zip(&da[range.clone()])
                        .zip(&db[range])
                    {
                        *gk += diff * (u - v);
                    }
                }
            }
            values.push((x[a] - x[b]).powi(2) + (x[a + 1] - x[b + 1]).powi(2));
        }
    }
}

/// Per column of a printed row, the gradient of `factor · (F_first − F_second)`'s entry, into
/// `out` (column `c`'s gradient at `out[c·n..(c + 1)·n]`). Entry `triangle[t]` is
/// 2·factor·(L_t(first) − L_t(second)) with L = (α, β, γ) linear in the triangle's squared
/// lengths; the constant is factor·(K(first) − K(second)) with ∂K/∂(a², b², c²) = −2(α, β, γ).
fn row_gradient(values: &[f64], grads: &[f64], n: usize, m: &RowMatch, out: &mut [f64]) {
    // the signs of a², b², c² in α, β, γ
    const SIGNS: [[f64; 3]; 3] = [[-1.0, 1.0, 1.0], [1.0, -1.0, 1.0], [1.0, 1.0, -1.0]];
    let per_frame = POINTS * (POINTS - 1) / 2;
    out.fill(0.0);
    for (f, sign) in [(m.first, 1.0), (m.second, -1.0)] {
        let at = |e: usize| (f - 1) * per_frame + e;
        let l = m.triangle.map(|e| values[at(e)]);
        for (s, e) in m.triangle.iter().enumerate() {
            let g = &grads[at(*e) * n..(at(*e) + 1) * n];
            let dk = -2.0 * (0..3).map(|t| SIGNS[s][t] * l[t]).sum::<f64>();
            for (t, e_t) in m.triangle.iter().enumerate() {
                let c = sign * m.factor * 2.0 * SIGNS[t][s];
                add_on_support(&mut out[*e_t * n..(*e_t + 1) * n], c, g, f - 1);
            }
            let c = sign * m.factor * dk;
            add_on_support(&mut out[6 * n..7 * n], c, g, f - 1);
        }
    }
}

/// `row` = `v / h` entry by entry, where `v` is +0 outside the columns of the 0-based
/// `frames`: for h > 0 those entries are +0 / h = +0 and need no division.
fn divide_row(row: &mut [f64], v: &[f64], h: f64, frames: [usize; 2]) {
    if h.is_nan() || h <= 0.0 {
        row.iter_mut().zip(v).for_each(|(o, v)| *o = v / h);
        return;
    }
    row.fill(0.0);
    let cams = frames.map(|f| EDGES + 5 * f..EDGES + 5 * f + 5);
    for range in [0..EDGES, cams[0].clone(), cams[1].clone()] {
        for (o, v) in row[range.clone()].iter_mut().zip(&v[range]) {
            *o = v / h;
        }
    }
}

/// The Jacobian of [`super::scaled`] at `p`, row for row; `None` where `scaled` is
/// undefined or a derivative is not finite.
pub fn scaled_jacobian(inp: &JointInput, matches: &[RowMatch], p: &[f64]) -> Option<DMatrix<f64>> {
    let mut jt = DMatrix::zeros(0, 0);
    scaled_jacobian_into(inp, matches, p, &mut jt).then(|| jt.transpose())
}

/// The transpose of [`scaled_jacobian`] into `jt` (reshaped when needed, every entry
/// written): one Jacobian row per column of `jt`, contiguous in memory; `false` where it
/// is `None`.
pub fn scaled_jacobian_into(
    inp: &JointInput,
    matches: &[RowMatch],
    p: &[f64],
    jt: &mut DMatrix<f64>,
) -> bool {
    let (mut x, mut d) = (Vec::new(), Vec::new());
    if !projection_jacobian(inp, p, &mut x, &mut d) {
        return false;
    }
    let n = p.len();
    let coefficients: usize = inp
        .half
        .iter()
        .take(matches.len())
        .map(|h| h.iter().filter(|v| **v > 0.0).count())
        .sum();
    let rows = x.len() + coefficients + EDGES;
    if jt.shape() != (n, rows) {
        *jt = DMatrix::zeros(n, rows);
    }
    let out = jt.as_mut_slice();
    for (i, h) in inp.figure.half.iter().enumerate().take(x.len()) {
        let frame = i / (2 * POINTS);
        divide_row(
            &mut out[i * n..(i + 1) * n],
            &d[i * n..(i + 1) * n],
            *h,
            [frame; 2],
        );
    }
    let (mut values, mut grads) = (Vec::new(), Vec::new());
    length_table(&x, &d, n, &mut values, &mut grads);
    let mut g = vec![0.0; 7 * n];
    let mut row = x.len();
    for (m, h) in matches.iter().zip(inp.half) {
        row_gradient(&values, &grads, n, m, &mut g);
        for c in (0..7).filter(|c| h[*c] > 0.0) {
            divide_row(
                &mut out[row * n..(row + 1) * n],
                &g[c * n..(c + 1) * n],
                h[c],
                [m.first - 1, m.second - 1],
            );
            row += 1;
        }
    }
    for e in 0..EDGES {
        for (k, o) in out[(row + e) * n..(row + e + 1) * n].iter_mut().enumerate() {
            *o = if k == e { 1.0 } else { 0.0 };
        }
    }
    out.iter().all(|v| v.is_finite())
}
