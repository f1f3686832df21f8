//! A three-point example under the rounding of its figure (§2's), restricted to projections a
//! rigid body can produce: per frame, the exact orthographic views of the printed body (P at the origin)
//! that round to the printed coordinates; the roots of the paper's quadratic over them; and
//! the quadratic's discriminant at the printed data, which says how well the data fix the
//! roots.

use rand::Rng;

use nalgebra::Vector3;

use crate::algebra::{central_jacobian, kabsch};
use crate::derivations::p3f3::{match_solutions, real_solutions_from_coordinates, solve_core};
use crate::model::rng;
use crate::studies::joint_fit::lp::lp_minimax_problem;
use crate::studies::rounding::{
    acceptance, cloud_spread, inside, spread, Acceptance, RoundingBox, Witness,
};

mod fit;

/// Bisection steps when solving a frame's last coordinate: 60 halvings of a box of width
/// 0.01 leave far less than one ulp.
const BISECTIONS: usize = 60;

/// Sub-intervals scanned for sign changes of the rigidity condition across the box.
const SCAN: usize = 16;

/// Draws per frame before a sample is given up (the acceptance is reported).
const ATTEMPTS: usize = 100;

fn lengths(x: &[f64]) -> [[f64; 3]; 3] {
    std::array::from_fn(|i| {
        let pts: Vec<[f64; 2]> = (0..3)
            .map(|j| [x[6 * i + 2 * j], x[6 * i + 2 * j + 1]])
            .collect();
        let l = crate::model::squared_lengths(&pts);
        [l[0], l[1], l[2]]
    })
}

/// The quadratic α t² + β t + γ of the paper's route (t = c²) at flat coordinates `x`, as
/// [γ, β, α]; `None` when the route is degenerate there.
pub fn quadratic(x: &[f64]) -> Option<[f64; 3]> {
    solve_core(&lengths(x)).elimination.map(|e| e.quadratic)
}

/// The discriminant β² − 4αγ at `x`.
fn discriminant(x: &[f64]) -> Option<f64> {
    quadratic(x).map(|[g, b, a]| b * b - 4.0 * a * g)
}

/// The rigidity condition of one frame: with P at the origin, Q = (qx, qy, z_Q) with
/// z_Q = √(a² − |q|²) ≥ 0 (the mirror through the image plane is the same view), and
/// R = (rx, ry, s·√(c² − |r|²)), the view is exact iff |R − Q|² = b². `None` outside the
/// sphere of either depth.
pub fn rigidity(body: [f64; 3], q: [f64; 2], r: [f64; 2], s: f64) -> Option<f64> {
    let zq2 = body[0] - q[0] * q[0] - q[1] * q[1];
    let zr2 = body[2] - r[0] * r[0] - r[1] * r[1];
    if zq2 < 0.0 || zr2 < 0.0 {
        return None;
    }
    let dz = s * zr2.sqrt() - zq2.sqrt();
    Some(dz * dz + (r[0] - q[0]).powi(2) + (r[1] - q[1]).powi(2) - body[1])
}

/// Every ry in [lo, hi] where the frame is an exact view (either sign of R's depth), by a
/// scan for sign changes and bisection.
pub fn solve_ry(body: [f64; 3], q: [f64; 2], rx: f64, lo: f64, hi: f64) -> Vec<f64> {
    let mut out = Vec::new();
    scan_ry(body, q, rx, lo, hi, &mut |y| {
        out.push(y);
        false
    });
    out
}

/// The first ry that [`solve_ry`] lists, without the scan beyond it.
pub fn first_ry(body: [f64; 3], q: [f64; 2], rx: f64, lo: f64, hi: f64) -> Option<f64> {
    let mut first = None;
    scan_ry(body, q, rx, lo, hi, &mut |y| {
        first = Some(y);
        true
    });
    first
}

/// [`solve_ry`]'s roots in its order, each handed to `found` until it returns `true`.
fn scan_ry(
    body: [f64; 3],
    q: [f64; 2],
    rx: f64,
    lo: f64,
    hi: f64,
    found: &mut dyn FnMut(f64) -> bool,
) {
    for s in [1.0, -1.0] {
        let f = |y: f64| rigidity(body, q, [rx, y], s);
        for k in 0..SCAN {
            let (mut a, mut b) = (
                lo + (hi - lo) * k as f64 / SCAN as f64,
                lo + (hi - lo) * (k + 1) as f64 / SCAN as f64,
            );
            let (Some(mut fa), Some(fb)) = (f(a), f(b)) else {
                continue;
            };
            if fa * fb > 0.0 {
                continue;
            }
            for _ in 0..BISECTIONS {
                let m = 0.5 * (a + b);
                let Some(fm) = f(m) else { break };
                if fa * fm <= 0.0 {
                    b = m;
                } else {
                    (a, fa) = (m, fm);
                }
            }
            if found(0.5 * (a + b)) {
                return;
            }
        }
    }
}

/// What the restricted analysis needs.
#[derive(Clone, Debug)]
pub struct RestrictedDesign<'a> {
    /// The figure's coordinates (P, Q, R per frame; P exact) and their half-widths.
    pub figure_box: &'a RoundingBox,
    /// The printed body's squares (a², b², c²).
    pub body: [f64; 3],
    /// The printed solutions.
    pub targets: &'a [[f64; 3]],
    /// Half a unit of each printed component.
    pub target_half: &'a [[f64; 3]],
    /// Samples.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
}

/// The discriminant of the paper's quadratic at the printed data.
#[derive(Clone, Copy, Debug)]
pub struct Discriminant {
    /// [γ, β, α] of α t² + β t + γ, t = c².
    pub quadratic: [f64; 3],
    /// β² − 4αγ.
    pub value: f64,
    /// Δ / β²: how near the two roots are to a double root (0: a double root).
    pub relative: f64,
    /// √Δ / |α|: the two roots' separation in c².
    pub separation: f64,
    /// Σₖ |∂Δ/∂cₖ| hₖ over the figure's rounding box, in units of Δ (> 1: the printed
    /// digits do not decide Δ's sign).
    pub worst_change: f64,
    /// Per root (ordered by c²) and component: Σₖ |∂v/∂cₖ| hₖ, the linear worst-case change
    /// over the box.
    pub root_change: [[f64; 3]; 2],
}

/// The restricted analysis.
#[derive(Clone, Debug)]
pub struct Restricted {
    /// The discriminant at the printed data.
    pub discriminant: Option<Discriminant>,
    /// Per frame: the draws that gave an exact view inside the box, and all draws.
    pub accepted: [(usize, usize); 3],
    /// Samples made of three exact views.
    pub samples: usize,
    /// Samples with two real roots.
    pub two_real: usize,
    /// Per printed solution and component: the 5, 50 and 95 % quantiles of the paired root
    /// over the samples (a sample's spread, not a bound).
    pub spread: Vec<[[f64; 3]; 3]>,
    /// The smallest discriminant over the samples, and its 5, 50 and 95 % quantiles.
    pub discriminant_spread: (f64, [f64; 3]),
    /// Unrestricted box: samples with no real root, of all.
    pub unrestricted_no_real: (usize, usize),
    /// Unrestricted box: per printed solution and component, the quantiles of the root.
    pub unrestricted_spread: Vec<[[f64; 3]; 3]>,
    /// Per printed solution and component: how far the target may move (in half units) with
    /// the witness search still finding exact views that reproduce every printed digit.
    pub acceptance: Vec<[Acceptance; 3]>,
    /// The exact views (one rotation of the body per frame) nearest to rounding to the figure
    /// and reproducing every printed component: the largest coordinate shift (half-widths)
    /// and component deviation (half units); a witness when both are at most 1.
    pub witness: Option<Witness>,
}

fn discriminant_at(figure_box: &RoundingBox) -> Option<Discriminant> {
    let q = quadratic(&figure_box.center)?;
    let [g, b, a] = q;
    let value = b * b - 4.0 * a * g;
    // Δ is a polynomial of the coordinates: a step of 10⁻⁶ of the box keeps the truncation
    // error far below the box's own effect
    let step = |k: usize, _| 1e-6 * figure_box.half[k].max(1e-3);
    let worst = |j: nalgebra::DMatrix<f64>, i: usize| {
        (0..j.ncols())
            .map(|k| j[(i, k)].abs() * figure_box.half[k])
            .sum::<f64>()
    };
    let dj = central_jacobian(
        &|x: &[f64]| discriminant(x).map(|d| vec![d]),
        &figure_box.center,
        step,
    )?;
    let roots = |x: &[f64]| {
        let r = real_solutions_from_coordinates(x);
        (r.len() == 2).then(|| r.iter().flatten().copied().collect::<Vec<f64>>())
    };
    let rj = central_jacobian(&roots, &figure_box.center, step)?;
    Some(Discriminant {
        quadratic: q,
        value,
        relative: value / (b * b),
        separation: value.max(0.0).sqrt() / a.abs(),
        worst_change: worst(dj, 0) / value.abs(),
        root_change: std::array::from_fn(|k| std::array::from_fn(|e| worst(rj.clone(), 3 * k + e))),
    })
}

/// One exact view of frame `f` drawn in the box: (q, rx) uniform, ry solved.
fn draw_frame<R: Rng>(inp: &RestrictedDesign, f: usize, g: &mut R) -> Option<[f64; 4]> {
    let (c, h) = (
        &inp.figure_box.center[6 * f..6 * f + 6],
        &inp.figure_box.half[6 * f..6 * f + 6],
    );
    let u = |g: &mut R, k: usize| c[k] + g.random_range(-h[k]..=h[k]);
    let (qx, qy, rx) = (u(g, 2), u(g, 3), u(g, 4));
    first_ry(inp.body, [qx, qy], rx, c[5] - h[5], c[5] + h[5]).map(|y| [qx, qy, rx, y])
}

/// Per solution and component, the quantiles of the paired roots of `cloud`.
fn spreads(cloud: &[Vec<[f64; 3]>], n: usize) -> Vec<[[f64; 3]; 3]> {
    (0..n).map(|k| cloud_spread(cloud, k)).collect()
}

/// The triangle P, Q, R of squared edges PQ, QR, RP: P at the origin, Q on the x axis.
fn triangle(body: [f64; 3]) -> Option<[Vector3<f64>; 3]> {
    let a = body[0].sqrt();
    let rx = (body[2] + body[0] - body[1]) / (2.0 * a);
    let ry2 = body[2] - rx * rx;
    (a > 0.0 && ry2 > 0.0).then(|| {
        [
            Vector3::zeros(),
            Vector3::new(a, 0.0, 0.0),
            Vector3::new(rx, ry2.sqrt(), 0.0),
        ]
    })
}

/// Per frame, the rotation taking the body's triangle onto the exact view at flat
/// coordinates `x` (P at the origin), depths lifted from rigidity.
fn rotations_of(inp: &RestrictedDesign, tri: &[Vector3<f64>; 3], x: &[f64]) -> Option<Vec<f64>> {
    let mut p = Vec::new();
    for f in 0..x.len() / 6 {
        let (q, r) = ([x[6 * f + 2], x[6 * f + 3]], [x[6 * f + 4], x[6 * f + 5]]);
        let s = [1.0, -1.0]
            .into_iter()
            .filter_map(|s| rigidity(inp.body, q, r, s).map(|v| (s, v.abs())))
            .min_by(|a, b| a.1.total_cmp(&b.1))?
            .0;
        let zq = (inp.body[0] - q[0] * q[0] - q[1] * q[1]).max(0.0).sqrt();
        let zr = s * (inp.body[2] - r[0] * r[0] - r[1] * r[1]).max(0.0).sqrt();
        let to = [
            Vector3::zeros(),
            Vector3::new(q[0], q[1], zq),
            Vector3::new(r[0], r[1], zr),
        ];
        let w = kabsch(tri, &to).scaled_axis();
        p.extend([w.x, w.y, w.z]);
    }
    Some(p)
}

/// Exact views of the body (one rotation per frame) fitted so that their coordinates round
/// to the figure and their roots to every printed digit: the largest of the coordinates'
/// shifts (in half-widths) and the components' deviations (in half units) minimised.
fn restricted_witness(inp: &RestrictedDesign, seed_views: &[f64]) -> Option<Witness> {
    let tri = triangle(inp.body)?;
    let shifts = |x: &[f64]| -> Vec<f64> {
        x.iter()
            .zip(&inp.figure_box.center)
            .zip(&inp.figure_box.half)
            .filter(|(_, h)| **h > 0.0)
            .map(|((v, c), h)| (v - c) / h)
            .collect()
    };
    let deviations = |x: &[f64]| -> Option<Vec<f64>> {
        let m = match_solutions(&real_solutions_from_coordinates(x), inp.targets)?;
        Some(
            m.iter()
                .zip(inp.targets.iter().zip(inp.target_half))
                .flat_map(|(s, (t, h))| (0..3).map(move |e| (s[e] - t[e]) / h[e]))
                .collect(),
        )
    };
    let fit = fit::ViewsFit { inp, tri };
    let p = lp_minimax_problem(&fit, &rotations_of(inp, &tri, seed_views)?)?;
    let x = fit.views(&p);
    let worst = |v: &[f64]| v.iter().fold(0.0, |m: f64, r| m.max(r.abs()));
    Some(Witness {
        shift_ratio: worst(&shifts(&x)),
        residual: worst(&deviations(&x)?),
        point: x,
    })
}

/// Per solution and component, the ladder of the witness search: the target moved by each
/// rung (in its half units), the search from the same start. The ladders are independent:
/// they run in parallel and are collected in order.
fn witness_acceptance(inp: &RestrictedDesign, start: &[f64]) -> Vec<[Acceptance; 3]> {
    use rayon::prelude::*;
    let ladders: Vec<Acceptance> = (0..inp.targets.len() * 3)
        .into_par_iter()
        .map(|c| {
            let (k, e) = (c / 3, c % 3);
            acceptance(&|shift| {
                let mut moved = inp.targets.to_vec();
                moved[k][e] += shift * inp.target_half[k][e];
                let design = RestrictedDesign {
                    targets: &moved,
                    ..inp.clone()
                };
                restricted_witness(&design, start).is_some_and(|w| inside(&w))
            })
        })
        .collect();
    ladders.chunks(3).map(|c| [c[0], c[1], c[2]]).collect()
}

/// The largest deviation of paired roots from the printed solutions, in half units.
fn scaled_miss(m: &[[f64; 3]], inp: &RestrictedDesign) -> f64 {
    m.iter()
        .zip(inp.targets.iter().zip(inp.target_half))
        .flat_map(|(s, (t, h))| (0..3).map(move |e| ((s[e] - t[e]) / h[e]).abs()))
        .fold(0.0, f64::max)
}

/// Run the analysis.
pub fn restricted(inp: &RestrictedDesign) -> Restricted {
    let mut g = rng(inp.seed);
    let frames = inp.figure_box.center.len() / 6;
    let mut accepted = [(0, 0); 3];
    let mut cloud = Vec::new();
    let (mut samples, mut discriminants) = (0, Vec::new());
    // the seeded start of the witness: the sample whose roots come nearest the printed ones
    let mut nearest: Option<(f64, Vec<f64>)> = None;
    'trial: for _ in 0..inp.trials {
        let mut x = inp.figure_box.center.clone();
        for (f, acc) in accepted.iter_mut().enumerate().take(frames) {
            let mut view = None;
            for _ in 0..ATTEMPTS {
                acc.1 += 1;
                view = draw_frame(inp, f, &mut g);
                if view.is_some() {
                    acc.0 += 1;
                    break;
                }
            }
            let Some(v) = view else { continue 'trial };
            x[6 * f + 2..6 * f + 6].copy_from_slice(&v);
        }
        samples += 1;
        discriminants.extend(discriminant(&x));
        if let Some(m) = match_solutions(&real_solutions_from_coordinates(&x), inp.targets) {
            let miss = scaled_miss(&m, inp);
            if nearest.as_ref().is_none_or(|(b, _)| miss < *b) {
                nearest = Some((miss, x.clone()));
            }
            cloud.push(m);
        }
    }
    let plain: Vec<Option<Vec<[f64; 3]>>> =
        crate::studies::rounding::monte_carlo(inp.figure_box, inp.trials, inp.seed, |x| {
            match_solutions(&real_solutions_from_coordinates(x), inp.targets)
        });
    let no_real = plain.iter().filter(|m| m.is_none()).count();
    let plain: Vec<Vec<[f64; 3]>> = plain.into_iter().flatten().collect();
    let witness = nearest.and_then(|(_, x)| restricted_witness(inp, &x));
    // the ladder starts where the unmoved search ended: each rung is a small step from it
    let start = witness.as_ref().map(|w| w.point.clone());
    Restricted {
        discriminant: discriminant_at(inp.figure_box),
        accepted,
        samples,
        two_real: cloud.len(),
        spread: spreads(&cloud, inp.targets.len()),
        // no sample: 0, which no positive bound passes
        discriminant_spread: (
            discriminants
                .iter()
                .copied()
                .reduce(f64::min)
                .unwrap_or(0.0),
            spread(discriminants),
        ),
        unrestricted_no_real: (no_real, inp.trials),
        unrestricted_spread: spreads(&plain, inp.targets.len()),
        acceptance: start
            .as_ref()
            .map_or_else(Vec::new, |x| witness_acceptance(inp, x)),
        witness,
    }
}
