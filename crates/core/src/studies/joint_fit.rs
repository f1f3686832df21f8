//! §4's figure against §4's table: the linear system built from the figure's printed
//! coordinates and solved, and one exact configuration (a body with the table's edges and
//! three orthographic cameras) fitted jointly to the figure and to every printed coefficient.

use nalgebra::{DMatrix, DVector, Rotation3, Vector2, Vector3};

use crate::algebra::{central_jacobian, complete_rotation, orthonormal_rows};
use crate::derivations::p4f3::solve_points;
use crate::studies::printed_matrix::{identify_rows, row_at, RowMatch};
use crate::studies::rounding::RoundingBox;

pub mod jacobian;

/// Points per frame of §4's example.
pub const POINTS: usize = 4;

/// The exponents of the Lᵖ stages of the joint fit: least squares first, then ever closer to
/// the largest residual (p = 64 weighs a residual 1.1 times another by 1.1⁶⁴ ≈ 450).
const STAGES: [f64; 6] = [2.0, 4.0, 8.0, 16.0, 32.0, 64.0];

/// Levenberg–Marquardt steps per stage.
const STEPS: usize = 200;

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
    let (_, frames, _) = unpack(inp, p)?;
    let x = flat(&frames);
    let mut r: Vec<f64> = x
        .iter()
        .zip(&inp.figure.center)
        .zip(&inp.figure.half)
        .map(|((a, c), h)| (a - c) / h)
        .collect();
    for (row, h) in coefficient_deviation(&x, inp.rows, inp.half, matches)
        .iter()
        .zip(inp.half)
    {
        r.extend((0..7).filter(|j| h[*j] > 0.0).map(|j| row[j]));
    }
    r.extend(p[..6].iter().copied());
    r.iter().all(|v| v.is_finite()).then_some(r)
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

/// Residuals of a parameter vector (`None`: undefined there).
pub type Residuals<'a> = &'a dyn Fn(&[f64]) -> Option<Vec<f64>>;

/// The Jacobian of [`Residuals`] (`None`: undefined there).
pub type ResidualJacobian<'a> = &'a dyn Fn(&[f64]) -> Option<DMatrix<f64>>;

/// Minimise the largest |rᵢ| of `f` from `x0`: the Lᵖ stages of `STAGES`, least squares
/// first, with central-difference Jacobians. `None` when `f` is undefined at the start.
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
    let mut p = x0.to_vec();
    for power in STAGES {
        p = lp_stage(f, jac, &p, power)?;
    }
    Some(p)
}

/// The Jacobian of g = sign(r)|r|^(p/2) at `x` (residuals `r` there): from `jac` by the
/// chain rule, ∂gᵢ = (p/2)|rᵢ|^(p/2 − 1) ∂rᵢ, or by central differences of `g`.
fn lp_jacobian(
    g: Residuals,
    jac: Option<ResidualJacobian>,
    x: &[f64],
    r: &[f64],
    power: f64,
) -> Option<DMatrix<f64>> {
    let Some(jac) = jac else {
        return central_jacobian(g, x, |_, xj| 1e-7 * xj.abs().max(1.0));
    };
    let mut j = jac(x)?;
    for (i, mut row) in j.row_iter_mut().enumerate() {
        row *= power / 2.0 * r[i].abs().powf(power / 2.0 - 1.0);
    }
    j.iter().all(|v| v.is_finite()).then_some(j)
}

/// Levenberg–Marquardt on Σ gᵢ², gᵢ = sign(rᵢ)|rᵢ|^(p/2): the Lᵖ norm of the residuals.
fn lp_stage(
    f: Residuals,
    jac: Option<ResidualJacobian>,
    x0: &[f64],
    power: f64,
) -> Option<Vec<f64>> {
    let lp = |r: Vec<f64>| -> Vec<f64> {
        r.iter()
            .map(|v| v.signum() * v.abs().powf(power / 2.0))
            .collect()
    };
    let g = |x: &[f64]| f(x).map(lp);
    let cost = |r: &[f64]| r.iter().map(|v| v * v).sum::<f64>();
    let mut x = x0.to_vec();
    let mut raw = f(&x)?;
    let mut r = lp(raw.clone());
    let mut c = cost(&r);
    let mut lambda = 1e-3;
    for _ in 0..STEPS {
        let Some(j) = lp_jacobian(&g, jac, &x, &raw, power) else {
            break;
        };
        let jt = j.transpose();
        let jtj = &jt * &j;
        let grad = &jt * DVector::from_vec(r.clone());
        let mut improved = false;
        while lambda < 1e12 {
            let mut a = jtj.clone();
            for k in 0..a.nrows() {
                a[(k, k)] += lambda * jtj[(k, k)].max(1e-12);
            }
            let Some(dx) = a.cholesky().map(|ch| ch.solve(&grad)) else {
                lambda *= 10.0;
                continue;
            };
            let trial: Vec<f64> = x.iter().zip(dx.iter()).map(|(a, d)| a - d).collect();
            if let Some(rawt) = f(&trial) {
                let rt = lp(rawt.clone());
                let ct = cost(&rt);
                if ct < c {
                    (x, r, c, raw) = (trial, rt, ct, rawt);
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
    Some(x)
}

/// Fit one exact configuration to the figure, the printed rows and the edge intervals by
/// Lᵖ stages from least squares to p = 64, starting from `p0` (or the affine start).
pub fn joint_fit(inp: &JointInput, p0: Option<&[f64]>) -> Option<(JointFit, Vec<f64>)> {
    let frames = frames_of(&inp.figure.center);
    let matches = identify_rows(inp.rows, &frames);
    let f = |p: &[f64]| scaled(inp, &matches, p);
    let p0 = match p0 {
        Some(p) => p.to_vec(),
        None => start(inp)?,
    };
    let jac = |p: &[f64]| jacobian::scaled_jacobian(inp, &matches, p);
    let p = lp_minimax_with(&f, Some(&jac), &p0)?;
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
