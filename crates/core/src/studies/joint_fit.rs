//! §4's figure against §4's table: the linear system built from the figure's printed
//! coordinates and solved, and one exact configuration (a body with the table's edges and
//! three orthographic cameras) fitted jointly to the figure and to every printed coefficient.

use nalgebra::{DMatrix, Rotation3, Vector2, Vector3};

use crate::algebra::{central_jacobian, complete_rotation, orthonormal_rows};
use crate::derivations::p4f3::solve_points;
use crate::studies::printed_matrix::{identify_rows, row_at, RowMatch};
use crate::studies::rounding::RoundingBox;

pub mod jacobian;
pub mod lp;

pub use lp::{lp_minimax, lp_minimax_with, ResidualJacobian, Residuals};

/// Points per frame of §4's example.
pub const POINTS: usize = 4;

fn frames_of(x: &[f64]) -> Vec<Vec<[f64; 2]>> {
    (0..x.len() / (2 * POINTS))
        .map(|f| {
            (0..POINTS)
                .map(|j| [x[2 * (POINTS * f + j)], x[2 * (POINTS * f + j) + 1]])
                .collect()
        })
        .collect()
}

/// The system built from the figure's printed coordinates, solved.
#[derive(Clone, Debug)]
pub struct FigureSystem {
    /// Its solution x₁ … x₆ (`None`: singular).
    pub x: Option<[f64; 6]>,
    /// (figure solution − printed x) / printed x.
    pub relative: Vec<f64>,
    /// First-order bound of each xᵢ's change over the figure's rounding box,
    /// Σₖ |∂xᵢ/∂cₖ| · hₖ, relative to the printed x.
    pub relative_bound: Vec<f64>,
    /// Per printed row and column: (figure's coefficient − printed) / half unit; 0 on the
    /// structural zeros.
    pub coefficient_half_units: Vec<[f64; 7]>,
    /// How each printed row arises (triangle, frame pair, factor).
    pub matches: Vec<RowMatch>,
}

/// Solve the paper's system at the figure's printed coordinates and compare it with the
/// printed x and the printed rows (half units `half`, 0 on structural zeros).
pub fn figure_system(
    figure_box: &RoundingBox,
    printed_x: &[f64],
    rows: &[[f64; 7]],
    half: &[[f64; 7]],
) -> FigureSystem {
    let x = solve_points(&frames_of(&figure_box.center));
    let relative = x.map_or_else(Vec::new, |x| {
        x.iter().zip(printed_x).map(|(a, p)| (a - p) / p).collect()
    });
    let f = |c: &[f64]| solve_points(&frames_of(c)).map(|v| v.to_vec());
    // the solution is a rational function of the coordinates: a step of 10⁻⁶ of the box
    // width leaves a truncation error far below the box's own effect
    let relative_bound = central_jacobian(&f, &figure_box.center, |k, _| {
        1e-6 * figure_box.half[k].max(1e-3)
    })
    .map_or_else(Vec::new, |j| {
        (0..j.nrows())
            .map(|i| {
                (0..j.ncols())
                    .map(|k| j[(i, k)].abs() * figure_box.half[k])
                    .sum::<f64>()
                    / printed_x[i].abs()
            })
            .collect()
    });
    let matches = identify_rows(rows, &frames_of(&figure_box.center));
    let coefficient_half_units = coefficient_deviation(&figure_box.center, rows, half, &matches);
    FigureSystem {
        x,
        relative,
        relative_bound,
        coefficient_half_units,
        matches,
    }
}

/// Per row and column: (recomputed − printed) / half unit at flat image coordinates `x`.
fn coefficient_deviation(
    x: &[f64],
    rows: &[[f64; 7]],
    half: &[[f64; 7]],
    matches: &[RowMatch],
) -> Vec<[f64; 7]> {
    matches
        .iter()
        .zip(rows.iter().zip(half))
        .map(|(m, (p, h))| {
            let r = row_at(x, POINTS, m);
            std::array::from_fn(|j| {
                if h[j] > 0.0 {
                    (r[j] - p[j]) / h[j]
                } else {
                    0.0
                }
            })
        })
        .collect()
}

/// The tetrahedron P, Q, R, T with squared edges PQ, QR, RP, TP, TQ, TR: P at the origin,
/// Q on the x axis, R in the xy plane, T above it; `None` when the edges admit no body.
pub fn tetrahedron(s: &[f64]) -> Option<[Vector3<f64>; 4]> {
    let a = s[0].sqrt();
    let rx = (s[2] + s[0] - s[1]) / (2.0 * a);
    let ry2 = s[2] - rx * rx;
    let tx = (s[3] + s[0] - s[4]) / (2.0 * a);
    if !(a > 0.0 && ry2 > 0.0) {
        return None;
    }
    let ry = ry2.sqrt();
    let ty = ((s[3] + s[2] - s[5]) / 2.0 - rx * tx) / ry;
    let tz2 = s[3] - tx * tx - ty * ty;
    (tz2 >= 0.0).then(|| {
        [
            Vector3::zeros(),
            Vector3::new(a, 0.0, 0.0),
            Vector3::new(rx, ry, 0.0),
            Vector3::new(tx, ty, tz2.sqrt()),
        ]
    })
}

/// What the joint fit is fitted to.
#[derive(Clone, Debug)]
pub struct JointInput<'a> {
    /// The figure's coordinates and their half-widths.
    pub figure: &'a RoundingBox,
    /// The printed rows (x₁ … x₆, constant).
    pub rows: &'a [[f64; 7]],
    /// Half a unit of each printed entry; 0 on a structural zero.
    pub half: &'a [[f64; 7]],
    /// Per squared edge, the interval of true values its printed length and square allow.
    pub edges: &'a [(f64, f64)],
}

/// One exact configuration fitted to everything printed.
#[derive(Clone, Debug)]
pub struct JointFit {
    /// The fitted squared edges.
    pub squares: Vec<f64>,
    /// Per image coordinate: (exact projection − printed) / half-width.
    pub figure_half_units: Vec<f64>,
    /// Per printed entry: (coefficient of the exact projections − printed) / half unit; 0
    /// on the structural zeros.
    pub coefficient_half_units: Vec<[f64; 7]>,
    /// Per squared edge: its offset from the centre of its allowed interval, in half-widths.
    pub edge_half_units: Vec<f64>,
    /// Each camera's viewing direction (third row of its rotation).
    pub views: Vec<[f64; 3]>,
    /// The largest of all the scaled deviations above.
    pub worst: f64,
}

/// A configuration unpacked: squared edges, the three frames' image points, the views.
pub type Unpacked = (Vec<f64>, Vec<Vec<[f64; 2]>>, Vec<[f64; 3]>);

/// The squared edges at parameters `p`: each edge offset is in half-widths of its interval.
fn squares_at(inp: &JointInput, p: &[f64]) -> Vec<f64> {
    inp.edges
        .iter()
        .zip(p)
        .map(|((lo, hi), u)| (lo + hi) / 2.0 + u * (hi - lo) / 2.0)
        .collect()
}

/// The flat image coordinates of the configuration `p` (as [`unpack`] projects them) into
/// `x`; `false` when the edges span no body.
fn project_into(inp: &JointInput, p: &[f64], x: &mut Vec<f64>) -> bool {
    x.clear();
    let Some(body) = tetrahedron(&squares_at(inp, p)) else {
        return false;
    };
    for c in p[6..].chunks(5) {
        let r = Rotation3::new(Vector3::new(c[0], c[1], c[2]));
        let m = r.matrix();
        for b in &body {
            let y = m * b;
            x.extend([y.x + c[3], y.y + c[4]]);
        }
    }
    true
}

/// The configuration at parameters `p`: 6 edge offsets (in half-widths of their intervals),
/// then per camera a rotation vector and a 2-D translation; `None` when the edges span no
/// body.
pub fn unpack(inp: &JointInput, p: &[f64]) -> Option<Unpacked> {
    let squares = squares_at(inp, p);
    let body = tetrahedron(&squares)?;
    let mut frames = Vec::new();
    let mut views = Vec::new();
    for c in p[6..].chunks(5) {
        let r = Rotation3::new(Vector3::new(c[0], c[1], c[2]));
        let m = r.matrix();
        frames.push(
            body.iter()
                .map(|x| {
                    let y = m * x;
                    [y.x + c[3], y.y + c[4]]
                })
                .collect(),
        );
        views.push([m[(2, 0)], m[(2, 1)], m[(2, 2)]]);
    }
    Some((squares, frames, views))
}

fn flat(frames: &[Vec<[f64; 2]>]) -> Vec<f64> {
    frames.iter().flatten().flatten().copied().collect()
}

/// Every scaled deviation of the configuration `p`: figure, nonzero coefficients, edges.
pub fn scaled(inp: &JointInput, matches: &[RowMatch], p: &[f64]) -> Option<Vec<f64>> {
    let mut r = Vec::new();
    scaled_into(inp, matches, p, &mut r).then_some(r)
}

/// [`scaled`] into `out`; `false` where it is `None`. The image coordinates are projected
/// into `out` itself, read for the coefficients and then turned into their own deviations.
fn scaled_into(inp: &JointInput, matches: &[RowMatch], p: &[f64], out: &mut Vec<f64>) -> bool {
    if !project_into(inp, p, out) {
        return false;
    }
    let n = out.len();
    for (m, (row, h)) in matches.iter().zip(inp.rows.iter().zip(inp.half)) {
        let r = row_at(&out[..n], POINTS, m);
        for j in (0..7).filter(|j| h[*j] > 0.0) {
            out.push((r[j] - row[j]) / h[j]);
        }
    }
    for ((a, c), h) in out[..n]
        .iter_mut()
        .zip(&inp.figure.center)
        .zip(&inp.figure.half)
    {
        *a = (*a - c) / h;
    }
    out.extend(p[..6].iter().copied());
    out.iter().all(|v| v.is_finite())
}

/// The joint fit as a problem of the Lᵖ stages: [`scaled`] and its analytic Jacobian.
struct JointProblem<'a, 'b> {
    inp: &'a JointInput<'b>,
    matches: &'a [RowMatch],
}

impl lp::LpProblem for JointProblem<'_, '_> {
    fn residuals(&self, p: &[f64], out: &mut Vec<f64>) -> bool {
        scaled_into(self.inp, self.matches, p, out)
    }

    fn lp_jacobian(&self, p: &[f64], raw: &[f64], power: f64, jt: &mut DMatrix<f64>) -> bool {
        jacobian::scaled_jacobian_into(self.inp, self.matches, p, jt)
            && lp::chain_rule(jt, raw, power)
    }
}

/// The start: the body at the centre of its intervals, each camera the nearest orthographic
/// camera to the affine camera mapping it onto the printed frame.
fn start(inp: &JointInput) -> Option<Vec<f64>> {
    let mut p = vec![0.0; 6];
    let squares: Vec<f64> = inp.edges.iter().map(|(lo, hi)| (lo + hi) / 2.0).collect();
    let body = tetrahedron(&squares)?;
    let xc = body.iter().sum::<Vector3<f64>>() / POINTS as f64;
    let xs = DMatrix::from_fn(3, POINTS, |i, j| body[j][i] - xc[i]);
    for fr in frames_of(&inp.figure.center) {
        let yc = fr
            .iter()
            .fold(Vector2::zeros(), |s, c| s + Vector2::new(c[0], c[1]))
            / POINTS as f64;
        let ys = DMatrix::from_fn(2, POINTS, |i, j| fr[j][i] - yc[i]);
        let m = &ys * xs.clone().pseudo_inverse(f64::EPSILON).ok()?;
        let c = orthonormal_rows(&nalgebra::Matrix2x3::from_fn(|i, j| m[(i, j)]));
        let r = Rotation3::from_matrix_unchecked(complete_rotation(&c));
        let w = r.scaled_axis();
        let t = yc - (r.matrix() * xc).xy();
        p.extend([w.x, w.y, w.z, t.x, t.y]);
    }
    Some(p)
}

/// Fit one exact configuration to the figure, the printed rows and the edge intervals by
/// Lᵖ stages from least squares to p = 64, starting from `p0` (or the affine start).
pub fn joint_fit(inp: &JointInput, p0: Option<&[f64]>) -> Option<(JointFit, Vec<f64>)> {
    let frames = frames_of(&inp.figure.center);
    let matches = identify_rows(inp.rows, &frames);
    let p0 = match p0 {
        Some(p) => p.to_vec(),
        None => start(inp)?,
    };
    let problem = JointProblem {
        inp,
        matches: &matches,
    };
    let p = lp::lp_minimax_problem(&problem, &p0)?;
    let (squares, fr, views) = unpack(inp, &p)?;
    let x = flat(&fr);
    let figure_half_units: Vec<f64> = x
        .iter()
        .zip(&inp.figure.center)
        .zip(&inp.figure.half)
        .map(|((a, c), h)| (a - c) / h)
        .collect();
    let coefficient_half_units = coefficient_deviation(&x, inp.rows, inp.half, &matches);
    let edge_half_units = p[..6].to_vec();
    let worst = figure_half_units
        .iter()
        .chain(coefficient_half_units.iter().flatten())
        .chain(&edge_half_units)
        .fold(0.0, |m: f64, v| m.max(v.abs()));
    Some((
        JointFit {
            squares,
            figure_half_units,
            coefficient_half_units,
            edge_half_units,
            views,
            worst,
        },
        p,
    ))
}

/// One mutant of the joint fit: a printed entry moved, and the worst deviation the same fit
/// then reaches.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JointMutant {
    /// Row (0-based).
    pub row: usize,
    /// Column (0-based; 6 is the constant).
    pub column: usize,
    /// Signed shift in half units.
    pub shift: f64,
    /// The worst scaled deviation of the refitted configuration.
    pub worst: f64,
}

/// The same fit, warm-started at `p`, for every nonzero entry moved alone by ± each shift.
/// The refits are independent: they run in parallel and are collected in a fixed order.
pub fn joint_mutants(inp: &JointInput, p: &[f64], shifts: &[f64]) -> Vec<JointMutant> {
    use rayon::prelude::*;
    let mut moves = Vec::new();
    for (i, h) in inp.half.iter().enumerate() {
        for j in (0..7).filter(|j| h[*j] > 0.0) {
            for shift in shifts.iter().flat_map(|m| [-m, *m]) {
                moves.push((i, j, shift));
            }
        }
    }
    moves
        .into_par_iter()
        .map(|(i, j, shift)| {
            let mut rows = inp.rows.to_vec();
            rows[i][j] += shift * inp.half[i][j];
            let moved = JointInput {
                rows: &rows,
                ..inp.clone()
            };
            let worst = joint_fit(&moved, Some(p)).map_or(f64::INFINITY, |f| f.0.worst);
            JointMutant {
                row: i,
                column: j,
                shift,
                worst,
            }
        })
        .collect()
}
