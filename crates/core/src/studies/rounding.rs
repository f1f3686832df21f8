//! Witness searches with tolerances from the printed precision, and the acceptance region of
//! such a search (its power): how far a printed target may move before the search fails.

use nalgebra::DMatrix;

pub use crate::derivations::rounding::{
    monte_carlo, quantile, witness, witness_step, witness_with, RoundingBox, Witness,
};

/// Shifts of a mutant target, in units of the target's own tolerance (half a unit of its last
/// printed digit), tried in turn on each side until the search fails.
pub const LADDER: [f64; 8] = [1.0, 3.0, 10.0, 30.0, 100.0, 1e3, 1e4, 1e5];

/// Weight of the shift (in units of the box) appended to the residuals by
/// [`reproduce_gauged`]: it makes the linearised system full rank where the targets leave
/// some coordinates free (a frame's translation, an in-plane turn) and the targets outnumber
/// the coordinates, and costs at most this fraction of one tolerance inside the box, so it
/// never decides whether a target is met.
const SHIFT_WEIGHT: f64 = 1e-2;

/// The difference step of [`reproduce_gauged`], in units of the box: residuals divided by
/// half units of six-digit numbers are ~10⁸ times their own rounding, so the default step
/// (10⁻⁷) would bury the Jacobian in noise; they are polynomials of low degree, so a step of
/// 10⁻³ of the box leaves a truncation error far below one tolerance.
const GAUGED_STEP: f64 = 1e-3;

fn finite(r: Option<Vec<f64>>) -> Option<Vec<f64>> {
    r.filter(|r| r.iter().all(|v| v.is_finite()))
}

/// A point of the box where every residual, already divided by its own tolerance, is at most
/// 1 in magnitude; `None` when the search finds none inside the box (or a residual stops
/// being finite on the way). For fewer targets than coordinates: the minimum-norm steps find
/// the nearest point.
pub fn reproduce(b: &RoundingBox, scaled: &dyn Fn(&[f64]) -> Option<Vec<f64>>) -> Option<Witness> {
    witness(b, &|x| finite(scaled(x)), 1.0).filter(inside)
}

/// [`reproduce`] for more targets than free coordinates, with directions the targets do not
/// see: the shift, weighted by `SHIFT_WEIGHT`, joins the residuals.
pub fn reproduce_gauged(
    b: &RoundingBox,
    scaled: &dyn Fn(&[f64]) -> Option<Vec<f64>>,
) -> Option<Witness> {
    let free: Vec<usize> = (0..b.center.len()).filter(|&i| b.half[i] > 0.0).collect();
    let with_shift = |x: &[f64]| {
        let mut r = finite(scaled(x))?;
        r.extend(
            free.iter()
                .map(|&i| SHIFT_WEIGHT * (x[i] - b.center[i]) / b.half[i]),
        );
        Some(r)
    };
    witness_step(b, &with_shift, 1.0, GAUGED_STEP).filter(inside)
}

/// Scaled residuals in groups, each moved by a few coordinates only (a printed row by the
/// two frames it compares): [`reproduce_grouped`] probes a coordinate by re-evaluating only
/// the groups it moves.
pub trait GroupedResiduals {
    /// Number of groups.
    fn groups(&self) -> usize;
    /// Group `g`'s scaled residuals at the coordinates `x`, appended to `out`.
    fn group(&self, g: usize, x: &[f64], out: &mut Vec<f64>);
    /// Whether changing coordinate `i` alone can change group `g`.
    fn moves(&self, i: usize, g: usize) -> bool;
}

/// All of a grouped residual's groups at `x`, in order.
fn all_groups(res: &dyn GroupedResiduals, x: &[f64]) -> Vec<f64> {
    let mut out = Vec::new();
    for g in 0..res.groups() {
        res.group(g, x, &mut out);
    }
    out
}

/// The shift residual of coordinate `i` at `x`.
fn shift_of(b: &RoundingBox, x: &[f64], i: usize) -> f64 {
    SHIFT_WEIGHT * (x[i] - b.center[i]) / b.half[i]
}

/// [`reproduce_gauged`] of every group in order.
pub fn reproduce_grouped(b: &RoundingBox, res: &dyn GroupedResiduals) -> Option<Witness> {
    let free: Vec<usize> = (0..b.center.len()).filter(|&i| b.half[i] > 0.0).collect();
    let with_shift = |x: &[f64]| {
        let mut r = finite(Some(all_groups(res, x)))?;
        r.extend(free.iter().map(|&i| shift_of(b, x, i)));
        Some(r)
    };
    let jac = |u: &[f64]| grouped_jacobian(b, &free, res, u);
    witness_with(b, &with_shift, Some(&jac), 1.0, GAUGED_STEP).filter(inside)
}

/// The central differences [`witness_step`] takes of [`reproduce_gauged`]'s residuals at
/// the scaled unknowns `u`, entry for entry: a probe of coordinate `i` changes only the groups
/// `i` moves and its own shift, so only those are evaluated; every other entry is
/// (v − v)/2h = +0 for the finite v at `u`. `None` where a probe is undefined.
fn grouped_jacobian(
    b: &RoundingBox,
    free: &[usize],
    res: &dyn GroupedResiduals,
    u: &[f64],
) -> Option<DMatrix<f64>> {
    let mut x = b.center.clone();
    for (k, &i) in free.iter().enumerate() {
        x[i] += u[k] * b.half[i];
    }
    // each group's first row, and the number of rows
    let mut starts = Vec::with_capacity(res.groups() + 1);
    let mut probe = Vec::new();
    for g in 0..res.groups() {
        starts.push(probe.len());
        res.group(g, &x, &mut probe);
    }
    starts.push(probe.len());
    let scaled = probe.len();
    let mut jac = DMatrix::zeros(scaled + free.len(), free.len());
    let (mut up, mut down) = (x.clone(), x.clone());
    for (k, &i) in free.iter().enumerate() {
        let h = GAUGED_STEP * u[k].abs().max(1.0);
        up[i] = b.center[i] + (u[k] + h) * b.half[i];
        down[i] = b.center[i] + (u[k] - h) * b.half[i];
        for g in (0..res.groups()).filter(|&g| res.moves(i, g)) {
            probe.clear();
            res.group(g, &up, &mut probe);
            let n = probe.len();
            res.group(g, &down, &mut probe);
            if n != starts[g + 1] - starts[g] || probe.iter().any(|v| !v.is_finite()) {
                return None;
            }
            for (row, (fu, fd)) in (starts[g]..).zip(probe[..n].iter().zip(&probe[n..])) {
                jac[(row, k)] = (fu - fd) / (2.0 * h);
            }
        }
        jac[(scaled + k, k)] = (shift_of(b, &up, i) - shift_of(b, &down, i)) / (2.0 * h);
        (up[i], down[i]) = (x[i], x[i]);
    }
    Some(jac)
}

/// Whether a witness lies in the box and meets every tolerance.
pub fn inside(w: &Witness) -> bool {
    w.shift_ratio <= 1.0 && w.residual <= 1.0
}

/// How far one printed target may be moved (in units of its tolerance) with the search still
/// succeeding: per side, the largest shift of [`LADDER`] accepted and the first rejected.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Acceptance {
    /// Largest shift accepted below and above the printed value (0 when even 1 fails).
    pub accepted: [f64; 2],
    /// First shift rejected below and above (`None`: accepted up to the ladder's end).
    pub rejected: [Option<f64>; 2],
}

impl Acceptance {
    /// The widest rejected shift on either side: the search accepts nothing beyond it
    /// (infinite when one side never fails).
    pub fn outer(&self) -> f64 {
        self.rejected
            .iter()
            .map(|r| r.unwrap_or(f64::INFINITY))
            .fold(0.0, f64::max)
    }

    /// The acceptance interval of a target printed as `value` with tolerance `unit`: from
    /// the first rejected shift below to the first rejected above (the search found nothing
    /// beyond them; the region lies inside).
    pub fn interval(&self, value: f64, unit: f64) -> (f64, f64) {
        let r = |k: usize| self.rejected[k].unwrap_or(f64::INFINITY);
        (value - r(0) * unit, value + r(1) * unit)
    }
}

/// Run `accepts(shift)` up the ladder on each side (shift < 0 below, > 0 above) until it fails.
pub fn acceptance(accepts: &dyn Fn(f64) -> bool) -> Acceptance {
    let mut a = Acceptance {
        accepted: [0.0; 2],
        rejected: [None; 2],
    };
    for (k, sign) in [-1.0, 1.0].into_iter().enumerate() {
        for s in LADDER {
            if accepts(sign * s) {
                a.accepted[k] = s;
            } else {
                a.rejected[k] = Some(s);
                break;
            }
        }
    }
    a
}

/// The 5, 50 and 95 % quantiles of `v` (0 for no data).
pub fn spread(mut v: Vec<f64>) -> [f64; 3] {
    v.sort_by(f64::total_cmp);
    [0.05, 0.5, 0.95].map(|q| quantile(&v, q).unwrap_or(0.0))
}

/// Per component, the [`spread`] of solution `k` over a cloud of paired roots.
pub fn cloud_spread(cloud: &[Vec<[f64; 3]>], k: usize) -> [[f64; 3]; 3] {
    std::array::from_fn(|e| spread(cloud.iter().map(|m| m[k][e]).collect()))
}
