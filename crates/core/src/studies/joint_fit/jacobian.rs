//! The analytic Jacobian of the joint fit's scaled residuals: the chain body → projections
//! → squared lengths → coefficients, each link differentiated once and shared by every
//! residual that uses it (the central-difference Jacobian costs 42 residual evaluations per
//! step, which made §4's 96 mutant refits the slowest part of the report).

use nalgebra::{DMatrix, Matrix3, Rotation3, Vector3};

use super::{tetrahedron, unpack, JointInput, POINTS};
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

/// d(flat image coordinates)/d(parameters): 2·POINTS·cameras rows, `p.len()` columns.
fn projection_jacobian(inp: &JointInput, p: &[f64]) -> Option<DMatrix<f64>> {
    let squares = super::squares_at(inp, p);
    let body = tetrahedron(&squares)?;
    let db = body_gradient(inp, p)?;
    let cameras = (p.len() - EDGES) / 5;
    let mut d = DMatrix::zeros(2 * POINTS * cameras, p.len());
    for (c, q) in p[EDGES..].chunks(5).enumerate() {
        let w = Vector3::new(q[0], q[1], q[2]);
        let r = Rotation3::new(w);
        let m = r.matrix();
        let jl = left_jacobian(&w);
        let col = EDGES + 5 * c;
        for (j, (x, dx)) in body.iter().zip(&db).enumerate() {
            let row = 2 * (POINTS * c + j);
            // the rotation's columns: −[R X]× J_l, shared by both image coordinates
            let dw = -cross_matrix(&(m * x)) * jl;
            for i in 0..2 {
                for k in 0..EDGES {
                    d[(row + i, k)] = (0..3).map(|l| m[(i, l)] * dx[l][k]).sum();
                }
                for k in 0..3 {
                    d[(row + i, col + k)] = dw[(i, k)];
                }
                d[(row + i, col + 3 + i)] = 1.0;
            }
        }
    }
    Some(d)
}

/// Every squared length of every frame (frame-major, edges in `model::edges` order) with
/// its gradient over the parameters, from the projections `x` and their Jacobian `d`:
/// computed once per Jacobian, shared by every row that uses the edge.
fn length_table(x: &[f64], d: &DMatrix<f64>) -> Vec<(f64, Vec<f64>)> {
    let per_frame = POINTS * (POINTS - 1) / 2;
    (0..x.len() / (2 * POINTS))
        .flat_map(|f| (0..per_frame).map(move |e| (f, crate::model::edge(e))))
        .map(|(f, (i, j))| {
            let (a, b) = (2 * (POINTS * f + i), 2 * (POINTS * f + j));
            let mut g = vec![0.0; d.ncols()];
            for c in 0..2 {
                let diff = 2.0 * (x[a + c] - x[b + c]);
                for (k, gk) in g.iter_mut().enumerate() {
                    *gk += diff * (d[(a + c, k)] - d[(b + c, k)]);
                }
            }
            let v = (x[a] - x[b]).powi(2) + (x[a + 1] - x[b + 1]).powi(2);
            (v, g)
        })
        .collect()
}

/// Per column of a printed row, the gradient of `factor · (F_first − F_second)`'s entry.
/// Entry `triangle[t]` is 2·factor·(L_t(first) − L_t(second)) with L = (α, β, γ) linear in
/// the triangle's squared lengths; the constant is factor·(K(first) − K(second)) with
/// ∂K/∂(a², b², c²) = −2(α, β, γ).
fn row_gradient(lengths: &[(f64, Vec<f64>)], n: usize, m: &RowMatch) -> [Vec<f64>; 7] {
    // the signs of a², b², c² in α, β, γ
    const SIGNS: [[f64; 3]; 3] = [[-1.0, 1.0, 1.0], [1.0, -1.0, 1.0], [1.0, 1.0, -1.0]];
    let per_frame = POINTS * (POINTS - 1) / 2;
    let mut out: [Vec<f64>; 7] = std::array::from_fn(|_| vec![0.0; n]);
    for (f, sign) in [(m.first, 1.0), (m.second, -1.0)] {
        let at = |e: usize| &lengths[(f - 1) * per_frame + e];
        let l = m.triangle.map(|e| at(e).0);
        for (s, e) in m.triangle.iter().enumerate() {
            let g = &at(*e).1;
            let dk = -2.0 * (0..3).map(|t| SIGNS[s][t] * l[t]).sum::<f64>();
            for (t, e_t) in m.triangle.iter().enumerate() {
                let c = sign * m.factor * 2.0 * SIGNS[t][s];
                out[*e_t].iter_mut().zip(g).for_each(|(o, v)| *o += c * v);
            }
            let c = sign * m.factor * dk;
            out[6].iter_mut().zip(g).for_each(|(o, v)| *o += c * v);
        }
    }
    out
}

/// The Jacobian of [`super::scaled`] at `p`, row for row; `None` where `scaled` is
/// undefined or a derivative is not finite.
pub fn scaled_jacobian(inp: &JointInput, matches: &[RowMatch], p: &[f64]) -> Option<DMatrix<f64>> {
    let (_, frames, _) = unpack(inp, p)?;
    let x = super::flat(&frames);
    let d = projection_jacobian(inp, p)?;
    let mut rows: Vec<Vec<f64>> = (0..x.len())
        .map(|i| d.row(i).iter().map(|v| v / inp.figure.half[i]).collect())
        .collect();
    let lengths = length_table(&x, &d);
    for (m, h) in matches.iter().zip(inp.half) {
        let g = row_gradient(&lengths, p.len(), m);
        for j in (0..7).filter(|j| h[*j] > 0.0) {
            rows.push(g[j].iter().map(|v| v / h[j]).collect());
        }
    }
    for k in 0..EDGES {
        let mut e = vec![0.0; p.len()];
        e[k] = 1.0;
        rows.push(e);
    }
    let j = DMatrix::from_fn(rows.len(), p.len(), |i, k| rows[i][k]);
    j.iter().all(|v| v.is_finite()).then_some(j)
}
