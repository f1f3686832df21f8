//! The fit behind the restricted witness as a problem of the Lᵖ stages: exact views of the
//! body, one rotation per frame, whose coordinates round to the figure and whose roots round
//! to the printed solutions. Its central differences use that a rotation moves only its own
//! frame's coordinates: a probe re-projects one frame, and the shifts of the other frames
//! are the ones at the point itself.

use nalgebra::{DMatrix, Rotation3, Vector3};

use super::RestrictedDesign;
use crate::derivations::p3f3::{match_solutions_at, real_solutions_at};
use crate::studies::joint_fit::lp::{lp_value, LpProblem};

/// Parameters per frame: a rotation vector.
const PARAMS: usize = 3;

/// Coordinates per frame: P, Q, R.
const COORDS: usize = 6;

/// The views of a triangle through rotation vectors, and the residuals of those views.
pub(super) struct ViewsFit<'a, 'b> {
    /// The figure, the printed solutions and their half units.
    pub(super) inp: &'a RestrictedDesign<'b>,
    /// The body's triangle, P at the origin.
    pub(super) tri: [Vector3<f64>; 3],
}

impl ViewsFit<'_, '_> {
    /// Frame `f`'s view through the rotation vector `w` (P, Q, R as x, y) into `out`.
    fn view(&self, w: &[f64], out: &mut [f64]) {
        let r = Rotation3::new(Vector3::new(w[0], w[1], w[2]));
        for (x, o) in self.tri.iter().zip(out.chunks_exact_mut(2)) {
            let y = r * x;
            o.copy_from_slice(&[y.x, y.y]);
        }
    }

    /// The views of every frame at rotation vectors `p`.
    pub(super) fn views(&self, p: &[f64]) -> Vec<f64> {
        let mut x = vec![0.0; p.len() / PARAMS * COORDS];
        for (w, o) in p.chunks(PARAMS).zip(x.chunks_exact_mut(COORDS)) {
            self.view(w, o);
        }
        x
    }

    /// The shift of coordinate `i` of `x` in half-widths.
    fn shift(&self, x: &[f64], i: usize) -> f64 {
        let b = self.inp.figure_box;
        (x[i] - b.center[i]) / b.half[i]
    }

    /// Each paired root's deviation from its printed solution, in half units, appended to
    /// `out`; `false` when the roots do not pair with the solutions.
    fn deviations(&self, x: &[f64], out: &mut Vec<f64>) -> bool {
        let (roots, n) = real_solutions_at(x);
        let Some((m, k)) = match_solutions_at(&roots[..n], self.inp.targets) else {
            return false;
        };
        for (s, (t, h)) in m[..k]
            .iter()
            .zip(self.inp.targets.iter().zip(self.inp.target_half))
        {
            out.extend((0..3).map(|e| (s[e] - t[e]) / h[e]));
        }
        true
    }

    /// The rounded coordinates' indices.
    fn free(&self) -> impl Iterator<Item = usize> + '_ {
        let h = &self.inp.figure_box.half;
        (0..h.len()).filter(|&i| h[i] > 0.0)
    }

    /// Every residual at the coordinates `x`: the shifts, then the deviations.
    fn residuals_at(&self, x: &[f64], out: &mut Vec<f64>) -> bool {
        out.clear();
        out.extend(self.free().map(|i| self.shift(x, i)));
        self.deviations(x, out) && out.iter().all(|v| v.is_finite())
    }
}

impl LpProblem for ViewsFit<'_, '_> {
    fn residuals(&self, p: &[f64], out: &mut Vec<f64>) -> bool {
        self.residuals_at(&self.views(p), out)
    }

    /// The central differences of the Lᵖ residuals with step 10⁻⁷·max(1, |pⱼ|), entry for
    /// entry. A probe re-projects its own frame only; another frame's shift is the one at
    /// `p` (finite there), so its entry (g − g)/2h is formed from that one value.
    fn lp_jacobian(&self, p: &[f64], raw: &[f64], power: f64, jt: &mut DMatrix<f64>) -> bool {
        let (n, m) = (p.len(), raw.len());
        if jt.shape() != (n, m) {
            *jt = DMatrix::zeros(n, m);
        }
        let free: Vec<usize> = self.free().collect();
        let base: Vec<f64> = raw.iter().map(|v| lp_value(*v, power)).collect();
        let at = self.views(p);
        let mut x = at.clone();
        let (mut up, mut down) = (Vec::with_capacity(m), Vec::with_capacity(m));
        for j in 0..n {
            let h = 1e-7 * p[j].abs().max(1.0);
            let f = j / PARAMS;
            let frame = f * COORDS..(f + 1) * COORDS;
            for (out, value) in [(&mut up, p[j] + h), (&mut down, p[j] - h)] {
                let mut w = [0.0; PARAMS];
                w.copy_from_slice(&p[f * PARAMS..(f + 1) * PARAMS]);
                w[j % PARAMS] = value;
                self.view(&w, &mut x[frame.clone()]);
                if !self.residuals_at(&x, out) || out.len() != m {
                    return false;
                }
            }
            x[frame.clone()].copy_from_slice(&at[frame.clone()]);
            for (i, (u, d)) in up.iter().zip(&down).enumerate() {
                let (gu, gd) = match free.get(i) {
                    Some(c) if !frame.contains(c) => (base[i], base[i]),
                    _ => (lp_value(*u, power), lp_value(*d, power)),
                };
                jt[(j, i)] = (gu - gd) / (2.0 * h);
            }
        }
        true
    }
}
