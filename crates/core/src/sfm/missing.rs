//! The affine factorisation of tracks with most entries missing (turntable sequences: each
//! point seen in a few consecutive frames), by variable projection.
//!
//! The model: image y = M_f X + t_f, U_f = [M_f | t_f] per frame. Given the cameras, every
//! point is its own small least-squares problem, so the points are eliminated and only the
//! cameras are searched (variable projection: Okatani & Deguchi 2007; Hong & Fitzgibbon
//! 2015, "Secrets of matrix factorization"), by Levenberg–Marquardt on Kaufman's Jacobian
//! J = (I − P) G (G the Jacobian with the points held, P the projection onto a point's
//! columns of M). Its normal matrix needs no J: JᵀJ = GᵀG − (AᵀG)ᵀ H⁻¹ (AᵀG), block
//! diagonal plus a rank-3 term per point, and Jᵀr = Gᵀr (the residual is orthogonal to A).
//! After each step the stacked M is replaced by the Q of its QR factorisation (the points
//! absorb R): an exact change of the affine gauge that keeps the search well scaled.
//!
//! Starts: the chained partial reconstructions ([`chained_start`]: the affine factorisation
//! of every two consecutive frames' common points, chained through the frame and the points
//! consecutive pairs share), or seeded random cameras. Alternating least squares ([`als`]) is the baseline it is
//! measured against (`examples` of the benchmarks, docs/limits.md).

use nalgebra::{
    DMatrix, DVector, Matrix2x3, Matrix2x4, Matrix3, Matrix4, SMatrix, Vector2, Vector3, Vector4,
};
use rand::Rng;

use super::gaps::intersect;
use super::judge::{self, Images};
use super::{Error, Frame, Observations, Reconstruction, Units};
use crate::algebra::cholesky::{cholesky_lower, cholesky_solve};
use crate::algebra::damping::Damping;
use crate::algebra::{complete_rotation, orthonormal_rows};
use crate::model::rng;

/// Iterations at most of either method from one start.
pub const MAX_ITERATIONS: usize = 500;
/// Rejected steps in a row after which no step lowers the cost.
const MAX_REJECTIONS: usize = 40;
/// Steps the work limit must allow from one start before a run begins: fewer could not
/// converge even from the chained start (it took 5–10 on the sequences of docs/limits.md).
pub const MIN_STEPS: usize = 20;

type Mat8 = SMatrix<f64, 8, 8>;
type Mat3x8 = SMatrix<f64, 3, 8>;

/// Every frame's affine camera [M_f | t_f].
pub type Cameras = Vec<Matrix2x4<f64>>;
/// A pair's two affine cameras and its common points (index, local position).
type Pair = ([Matrix2x4<f64>; 2], Vec<(usize, Vector3<f64>)>);

/// A factorisation and how it was reached.
#[derive(Clone, Debug, PartialEq)]
pub struct Factorised {
    /// The cameras.
    pub cameras: Cameras,
    /// The points, eliminated from the cameras (`None` where the cameras do not fix one).
    pub points: Vec<Option<Vector3<f64>>>,
    /// ½ Σ ‖r‖² over the observations.
    pub cost: f64,
    /// Accepted iterations.
    pub iterations: usize,
    /// Whether it stopped because no step lowered the cost beyond rounding.
    pub converged: bool,
    /// Whether it stopped because its share of the work limit was spent.
    pub out_of_work: bool,
}

/// Variable projection's cost model, in multiply-adds: what one step's normal equations cost
/// (the rank-3 term of each point, about 200 per pair of its frames) and what one trial step
/// costs (the (8k)³/3 factorisation and a cost evaluation, about 60 per observation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Work {
    /// One step's normal equations.
    pub normal: f64,
    /// One trial step.
    pub trial: f64,
}

impl Work {
    /// The model at these tracks (frames seen by each point) in `frames` frames.
    pub fn of(views: &[Images], frames: usize) -> Work {
        let pairs: f64 = views.iter().map(|v| (v.len() * v.len()) as f64).sum();
        let seen: f64 = views.iter().map(|v| v.len() as f64).sum();
        Work {
            normal: 200.0 * pairs,
            trial: (8.0 * frames as f64).powi(3) / 3.0 + 60.0 * seen,
        }
    }

    /// The least work a run must be allowed: [`MIN_STEPS`] steps, each with one trial.
    pub fn least(&self) -> f64 {
        MIN_STEPS as f64 * (self.normal + self.trial)
    }
}

/// A point's normal equations H X = b through the cameras: H = Σ M_fᵀM_f, b = Σ M_fᵀ(y − t_f).
fn point_system(cams: &[Matrix2x4<f64>], images: &Images) -> (Matrix3<f64>, Vector3<f64>) {
    let mut h = Matrix3::zeros();
    let mut b = Vector3::zeros();
    for (f, y) in images {
        let m = cams[*f].fixed_columns::<3>(0);
        h += m.transpose() * m;
        b += m.transpose() * (y - cams[*f].column(3));
    }
    (h, b)
}

/// The point that best fits its images through the cameras; `None` when they do not fix it.
pub fn eliminate(cams: &[Matrix2x4<f64>], images: &Images) -> Option<Vector3<f64>> {
    let (h, b) = point_system(cams, images);
    h.cholesky().map(|c| c.solve(&b))
}

/// ½ Σ ‖r‖² with every point eliminated; `None` when some point is not fixed.
pub fn cost(cams: &[Matrix2x4<f64>], views: &[Images]) -> Option<f64> {
    let mut c = 0.0;
    for v in views {
        let x = eliminate(cams, v)?.push(1.0);
        c += v
            .iter()
            .map(|(f, y)| (cams[*f] * x - y).norm_squared())
            .sum::<f64>();
    }
    Some(c / 2.0)
}

/// Seeded random cameras: every entry uniform in [−1, 1].
pub fn random_start(frames: usize, seed: u64) -> Cameras {
    let mut g = rng(seed);
    (0..frames)
        .map(|_| Matrix2x4::from_fn(|_, _| g.random_range(-1.0..1.0)))
        .collect()
}

/// The normal equations of Kaufman's Jacobian at the cameras: JᵀJ's lower triangle and Jᵀr;
/// `None` when some point is not fixed.
fn normal(cams: &[Matrix2x4<f64>], views: &[Images]) -> Option<(DMatrix<f64>, DVector<f64>)> {
    let k = cams.len();
    let mut n = DMatrix::zeros(8 * k, 8 * k);
    let mut g = DVector::zeros(8 * k);
    for v in views {
        let (h, b) = point_system(cams, v);
        let l = h.cholesky()?.unpack();
        let x = l
            .transpose()
            .solve_upper_triangular(&l.solve_lower_triangular(&b)?)?;
        let xh = x.push(1.0);
        let outer = xh * xh.transpose();
        let linv = l.try_inverse()?;
        let mut z: Vec<Mat3x8> = Vec::with_capacity(v.len());
        for (f, y) in v {
            let r = cams[*f] * xh - y;
            let mut blk = n.fixed_view_mut::<8, 8>(8 * f, 8 * f);
            blk += block_diag(&outer);
            let mut gf = g.fixed_rows_mut::<8>(8 * f);
            gf.fixed_rows_mut::<4>(0).axpy(r.x, &xh, 1.0);
            gf.fixed_rows_mut::<4>(4).axpy(r.y, &xh, 1.0);
            // AᵀG for this frame: [m₀ ⊗ Xhᵀ | m₁ ⊗ Xhᵀ], then L⁻¹ of it
            let m = cams[*f].fixed_columns::<3>(0);
            let mut atg = Mat3x8::zeros();
            atg.fixed_columns_mut::<4>(0)
                .copy_from(&(m.row(0).transpose() * xh.transpose()));
            atg.fixed_columns_mut::<4>(4)
                .copy_from(&(m.row(1).transpose() * xh.transpose()));
            z.push(linv * atg);
        }
        for (a, (fa, _)) in v.iter().enumerate() {
            for (b, (fb, _)) in v.iter().enumerate().take(a + 1) {
                let mut blk = n.fixed_view_mut::<8, 8>(8 * fa, 8 * fb);
                blk -= z[a].transpose() * z[b];
            }
        }
    }
    Some((n, g))
}

/// diag(B, B) for the 4 × 4 block B.
fn block_diag(b: &Matrix4<f64>) -> Mat8 {
    let mut out = Mat8::zeros();
    out.fixed_view_mut::<4, 4>(0, 0).copy_from(b);
    out.fixed_view_mut::<4, 4>(4, 4).copy_from(b);
    out
}

/// The cameras with the stacked M replaced by the Q of its QR factorisation (the affine
/// gauge: the points absorb R, no image moves); `None` when M has lost rank.
fn normalised(cams: &[Matrix2x4<f64>]) -> Option<Cameras> {
    let k = cams.len();
    let m = DMatrix::from_fn(2 * k, 3, |i, c| cams[i / 2][(i % 2, c)]);
    let qr = m.qr();
    let r = qr.r();
    if r.diagonal()
        .iter()
        .any(|d| !d.is_finite() || d.abs() <= f64::EPSILON * r.norm())
    {
        return None;
    }
    let q = qr.q();
    Some(
        (0..k)
            .map(|f| {
                let mut u = cams[f];
                for row in 0..2 {
                    for c in 0..3 {
                        u[(row, c)] = q[(2 * f + row, c)];
                    }
                }
                u
            })
            .collect(),
    )
}

/// Variable projection from `start` (see the module); `None` when the start does not fix
/// every point.
pub fn varpro(views: &[Images], start: Cameras, max_iterations: usize) -> Option<Factorised> {
    let mut unmetered = f64::INFINITY;
    varpro_within(views, start, max_iterations, &mut unmetered)
}

/// [`varpro`] metered: each step's normal equations and each trial take their [`Work`] from
/// `work` (multiply-adds left), and the run stops, `out_of_work`, before a step it cannot pay.
pub fn varpro_within(
    views: &[Images],
    start: Cameras,
    max_iterations: usize,
    work: &mut f64,
) -> Option<Factorised> {
    let model = Work::of(views, start.len());
    let mut cams = normalised(&start)?;
    let mut c = cost(&cams, views)?;
    let mut damping = None;
    let (mut iterations, mut converged, mut out_of_work) = (0, false, false);
    while iterations < max_iterations && c > 0.0 {
        if *work < model.normal + model.trial {
            out_of_work = true;
            break;
        }
        *work -= model.normal;
        let (n, g) = normal(&cams, views)?;
        let d = damping.get_or_insert_with(|| Damping::from_diagonal_max(n.diagonal().max()));
        let step = trial(views, &cams, c, (&n, &g), d, (work, model.trial));
        let Some((nx, nc)) = step.accepted else {
            converged = !step.out_of_work;
            out_of_work = step.out_of_work;
            break;
        };
        let small = c - nc <= 4.0 * f64::EPSILON * c;
        cams = nx;
        c = nc;
        iterations += 1;
        if small {
            converged = true;
            break;
        }
    }
    // an exact fit ends the loop with nothing left to lower
    let mut f = finish(cams, views, c, iterations, converged || c == 0.0);
    f.out_of_work = out_of_work;
    Some(f)
}

/// A trial's outcome: the accepted cameras and cost, or none, and whether the work ran out.
struct Trial {
    accepted: Option<(Cameras, f64)>,
    out_of_work: bool,
}

/// Damped steps (`damping` updated by Nielsen's rule) until one lowers the cost: its cameras
/// and cost. None when none can beyond rounding (a rejected step's predicted gain within 4ε
/// of the cost, or [`MAX_REJECTIONS`] in a row), or when `work` cannot pay the next trial.
fn trial(
    views: &[Images],
    cams: &[Matrix2x4<f64>],
    c: f64,
    (n, g): (&DMatrix<f64>, &DVector<f64>),
    damping: &mut Damping,
    (work, each): (&mut f64, f64),
) -> Trial {
    let none = |out_of_work| Trial {
        accepted: None,
        out_of_work,
    };
    for _ in 0..MAX_REJECTIONS {
        if *work < each {
            return none(true);
        }
        *work -= each;
        let mut damped = n.clone();
        for i in 0..damped.nrows() {
            damped[(i, i)] += damping.lambda;
        }
        if let Some(d) = cholesky_lower(damped).and_then(|l| cholesky_solve(&l, &-g)) {
            let pred = 0.5 * d.dot(&(&d * damping.lambda - g));
            let next = normalised(&stepped(cams, &d));
            let nc = next.as_ref().and_then(|nx| cost(nx, views));
            if let (Some(nx), Some(nc)) = (next, nc)
                && nc < c
                && pred > 0.0
            {
                damping.accepted((c - nc) / pred);
                return Trial {
                    accepted: Some((nx, nc)),
                    out_of_work: false,
                };
            }
            if pred <= 4.0 * f64::EPSILON * c {
                return none(false);
            }
        }
        damping.rejected();
    }
    none(false)
}

/// The cameras moved by the step δ (8 entries per frame, row by row).
fn stepped(cams: &[Matrix2x4<f64>], d: &DVector<f64>) -> Cameras {
    cams.iter()
        .enumerate()
        .map(|(f, u)| u + Matrix2x4::from_row_slice(&d.as_slice()[8 * f..8 * f + 8]))
        .collect()
}

fn finish(
    cams: Cameras,
    views: &[Images],
    cost: f64,
    iterations: usize,
    converged: bool,
) -> Factorised {
    let points = views.iter().map(|v| eliminate(&cams, v)).collect();
    Factorised {
        cameras: cams,
        points,
        cost,
        iterations,
        converged,
        out_of_work: false,
    }
}

/// Alternating least squares, the baseline: every point from the cameras, then every camera
/// from the points it sees, until an iteration lowers the cost by no more than its rounding;
/// `None` when the start does not fix every point or a frame sees too few points.
pub fn als(views: &[Images], start: Cameras, max_iterations: usize) -> Option<Factorised> {
    let k = start.len();
    let mut cams = start;
    let mut c = cost(&cams, views)?;
    let (mut iterations, mut converged) = (0, false);
    while iterations < max_iterations && c > 0.0 {
        let mut xx = vec![Matrix4::zeros(); k];
        let mut yx = vec![Matrix2x4::zeros(); k];
        for v in views {
            let xh: Vector4<f64> = eliminate(&cams, v)?.push(1.0);
            for (f, y) in v {
                xx[*f] += xh * xh.transpose();
                yx[*f] += y * xh.transpose();
            }
        }
        let next: Option<Cameras> = xx
            .iter()
            .zip(&yx)
            .map(|(a, b)| {
                a.cholesky()
                    .map(|ch| (ch.solve(&b.transpose())).transpose())
            })
            .collect();
        let next = normalised(&next?)?;
        let nc = cost(&next, views)?;
        iterations += 1;
        let small = c - nc <= 4.0 * f64::EPSILON * c;
        cams = next;
        c = nc.min(c);
        if small {
            converged = true;
            break;
        }
    }
    Some(finish(cams, views, c, iterations, converged))
}

/// The chained partial reconstructions: each frame (in the tracks' order) paired with the
/// latest of the [`CHAIN_BACK`] frames before it that shares at least four points with it,
/// the pair factorised from those points (the registered 4 × n block's rank 3), and carried
/// into the first pair's affine frame by the map G (X_local = A X + c) that the placed frame
/// and the points already placed fix together (linear least squares in G's 12 entries).
/// `None` when no such partner exists.
pub fn chained_start(views: &[Images], frames: usize) -> Option<Cameras> {
    let mut cams: Vec<Option<Matrix2x4<f64>>> = vec![None; frames];
    let mut pts: Vec<Option<Vector3<f64>>> = vec![None; views.len()];
    for next in 1..frames {
        // the latest placed frame (of the last CHAIN_BACK) that shares four points with it
        let (known, (local, common)) = (1..=CHAIN_BACK.min(next))
            .map(|back| next - back)
            .find_map(|known| pair_factorisation(views, [known, next]).map(|p| (known, p)))?;
        let (a, c) = match cams[known] {
            None => {
                cams[known] = Some(local[0]);
                (Matrix3::identity(), Vector3::zeros())
            }
            Some(placed) => chain_map(placed, &local[0], &common, &pts)?,
        };
        let g = Matrix4::from_fn(|i, j| match (i, j) {
            (3, 3) => 1.0,
            (3, _) => 0.0,
            (_, 3) => c[i],
            _ => a[(i, j)],
        });
        cams[next] = Some(local[1] * g);
        let ainv = a.try_inverse()?;
        for (j, x) in common {
            pts[j].get_or_insert(ainv * (x - c));
        }
    }
    cams.into_iter().collect()
}

/// G's A and c from the shared frame (U_local G = U_global: 8 equations) and the placed
/// common points (A X + c = X_local: 3 each).
fn chain_map(
    global: Matrix2x4<f64>,
    local: &Matrix2x4<f64>,
    common: &[(usize, Vector3<f64>)],
    pts: &[Option<Vector3<f64>>],
) -> Option<(Matrix3<f64>, Vector3<f64>)> {
    // unknowns θ = (A row-major, c); rows of the system accumulated as normal equations
    let mut nn = SMatrix::<f64, 12, 12>::zeros();
    let mut rhs = SMatrix::<f64, 12, 1>::zeros();
    let mut add = |row: SMatrix<f64, 12, 1>, v: f64| {
        nn += row * row.transpose();
        rhs += row * v;
    };
    for r in 0..2 {
        for j in 0..3 {
            let mut row = SMatrix::<f64, 12, 1>::zeros();
            for i in 0..3 {
                row[3 * i + j] = local[(r, i)];
            }
            add(row, global[(r, j)]);
        }
        let mut row = SMatrix::<f64, 12, 1>::zeros();
        for i in 0..3 {
            row[9 + i] = local[(r, i)];
        }
        add(row, global[(r, 3)] - local[(r, 3)]);
    }
    for (j, xl) in common {
        let Some(xg) = pts[*j] else { continue };
        for i in 0..3 {
            let mut row = SMatrix::<f64, 12, 1>::zeros();
            for m in 0..3 {
                row[3 * i + m] = xg[m];
            }
            row[9 + i] = 1.0;
            add(row, xl[i]);
        }
    }
    // one frame and three points leave the depth's shear free (A + d aᵀ, c + β d with
    // aᵀX + β = 0 at the points): the least-norm map, a start the search then corrects
    let theta = nn
        .svd(true, true)
        .solve(&rhs, 12.0 * f64::EPSILON * nn.norm())
        .ok()?;
    let a = Matrix3::from_fn(|i, j| theta[3 * i + j]);
    Some((a, Vector3::new(theta[9], theta[10], theta[11])))
}

/// One pair's affine cameras and its common points' local positions: the registered 4 × n
/// block's rank-3 factorisation (W ≈ (U S) Vᵀ), the translations the images' centroids.
fn pair_factorisation(views: &[Images], fr: [usize; 2]) -> Option<Pair> {
    let common: Vec<(usize, [Vector2<f64>; 2])> = views
        .iter()
        .enumerate()
        .filter_map(|(j, v)| {
            let at = |f: usize| v.iter().find(|(g, _)| *g == f).map(|(_, y)| *y);
            Some((j, [at(fr[0])?, at(fr[1])?]))
        })
        .collect();
    if common.len() < 4 {
        return None;
    }
    let n = common.len() as f64;
    let cent: [Vector2<f64>; 2] =
        std::array::from_fn(|i| common.iter().map(|c| c.1[i]).sum::<Vector2<f64>>() / n);
    let w = DMatrix::from_fn(4, common.len(), |r, j| {
        (common[j].1[r / 2] - cent[r / 2])[r % 2]
    });
    let svd = w.svd(true, true);
    let (u, vt) = (svd.u?, svd.v_t?);
    let s = &svd.singular_values;
    let mut order: Vec<usize> = (0..s.len()).collect();
    order.sort_by(|&a, &b| s[b].total_cmp(&s[a]));
    let top = &order[..3];
    if s[top[2]] <= f64::EPSILON * s[top[0]] * 4.0 {
        return None;
    }
    let cams = std::array::from_fn(|i| {
        let mut cam = Matrix2x4::zeros();
        for r in 0..2 {
            for (c, &o) in top.iter().enumerate() {
                cam[(r, c)] = u[(2 * i + r, o)] * s[o];
            }
            cam[(r, 3)] = cent[i][r];
        }
        cam
    });
    let local = common
        .iter()
        .enumerate()
        .map(|(col, (j, _))| (*j, Vector3::from_fn(|c, _| vt[(top[c], col)])))
        .collect();
    Some((cams, local))
}

/// How far back a frame's partner in the chain may be (a pair of consecutive frames that
/// shares fewer than four points is bridged by an earlier frame).
pub const CHAIN_BACK: usize = 3;

/// Seeded random starts tried when the chain of windows breaks (the best is kept).
pub const RANDOM_STARTS: usize = 8;

/// The reconstruction of tracks with gaps by variable projection (see the module): from the
/// chained start, or the best of [`RANDOM_STARTS`] seeded random starts when the chain breaks;
/// then the metric upgrade, and every point intersected from its frames' cameras.
pub fn reconstruct(obs: &Observations, seed: u64) -> Result<Reconstruction, Error> {
    obs.check_counts()?;
    let k = obs.frames.len();
    if k > crate::limits::VARPRO_FRAMES {
        return Err(Error::Unreachable(format!(
            "variable projection: {k} frames, more than its limit of {} (see docs/limits.md)",
            crate::limits::VARPRO_FRAMES
        )));
    }
    let units = Units::of(obs)?;
    let unit = units.to_unit(obs);
    let views = judge::views(&unit);
    let few: Vec<&str> = views
        .iter()
        .zip(&unit.names)
        .filter(|(v, _)| v.len() < 2)
        .map(|(_, n)| n.as_str())
        .collect();
    if !few.is_empty() {
        return Err(Error::Unreachable(format!(
            "{} point(s) seen in fewer than 2 frames cannot be placed (the pipeline drops them first): [{}]",
            few.len(),
            few.join(", ")
        )));
    }
    let least = Work::of(&views, k).least();
    if least > crate::limits::VARPRO_WORK {
        return Err(Error::TooLarge(format!(
            "variable projection: {MIN_STEPS} steps over {} points in {k} frames ({} observations) cost {least:.2e} multiply-adds, more than the limit of {:.1e} (see docs/limits.md)",
            views.len(),
            views.iter().map(Vec::len).sum::<usize>(),
            crate::limits::VARPRO_WORK
        )));
    }
    if let Some((first, second)) = super::factor::same_view(&views) {
        return Err(Error::Degenerate(super::Degenerate::InPlaneMotion {
            first,
            second,
        }));
    }
    let (fact, start) = factorise(&views, unit.frames.len(), seed)?;
    let mut rec = metric_of(&fact, &views, &unit.names)?;
    rec.method.insert(
        0,
        format!(
            "variable projection (affine factorisation with missing entries) from {start}: {} iterations{}",
            fact.iterations,
            match (fact.converged, fact.out_of_work) {
                (true, _) => "",
                (false, true) => ", work limit reached (docs/limits.md)",
                (false, false) => ", iteration limit reached",
            }
        ),
    );
    rec.warnings.extend(stop_warning(&fact));
    rec.align_to_first();
    rec.centre();
    units.back(&mut rec);
    Ok(rec)
}

/// The warning of a factorisation that stopped before it converged: at the work limit or
/// the iteration limit; `None` when it converged.
pub fn stop_warning(f: &Factorised) -> Option<String> {
    let limit = match (f.converged, f.out_of_work) {
        (true, _) => return None,
        (false, true) => "its work limit (docs/limits.md)".to_string(),
        (false, false) => "its iteration limit".to_string(),
    };
    Some(format!(
        "variable projection stopped at {limit} after {} iterations, before it converged: the affine factorisation, and so the body, may not be the least-squares one",
        f.iterations
    ))
}

/// The affine factorisation and the name of its start, within the work limit
/// ([`crate::limits::VARPRO_WORK`]): the chained start may spend all of it, and the random
/// starts share what it left.
fn factorise(views: &[Images], k: usize, seed: u64) -> Result<(Factorised, String), Error> {
    let mut work = crate::limits::VARPRO_WORK;
    if let Some(f) =
        chained_start(views, k).and_then(|s| varpro_within(views, s, MAX_ITERATIONS, &mut work))
    {
        return Ok((
            f,
            "the chained partial reconstructions (every two consecutive frames)".into(),
        ));
    }
    let mut best: Option<Factorised> = None;
    for i in 0..RANDOM_STARTS as u64 {
        let mut share = work / (RANDOM_STARTS as u64 - i) as f64;
        work -= share;
        let start = random_start(k, seed.wrapping_add(i));
        if let Some(f) = varpro_within(views, start, MAX_ITERATIONS, &mut share) {
            best = match best {
                Some(b) if b.cost <= f.cost => Some(b),
                _ => Some(f),
            };
        }
        work += share;
    }
    best.map(|f| {
        (
            f,
            format!("the best of {RANDOM_STARTS} seeded random starts (the chain of frame pairs broke)"),
        )
    })
    .ok_or_else(|| {
        Error::Unreachable(format!(
            "variable projection: no start (the chain of frame pairs, {RANDOM_STARTS} random ones) fixes every point"
        ))
    })
}

/// The metric reconstruction of an affine factorisation: the upgrade Q of the stacked M,
/// each frame's nearest rotation rows to M_f Q, every point intersected from them.
fn metric_of(
    fact: &Factorised,
    views: &[Images],
    names: &[String],
) -> Result<Reconstruction, Error> {
    let k = fact.cameras.len();
    let m = DMatrix::from_fn(2 * k, 3, |i, c| fact.cameras[i / 2][(i % 2, c)]);
    let up = super::metric::upgrade(&m)?;
    let frames: Vec<Frame> = fact
        .cameras
        .iter()
        .map(|u| {
            let mq: Matrix2x3<f64> = u.fixed_columns::<3>(0) * up.q;
            Frame {
                rotation: complete_rotation(&orthonormal_rows(&mq)),
                translation: u.column(3).into_owned(),
            }
        })
        .collect();
    let known: Vec<Option<Frame>> = frames.iter().copied().map(Some).collect();
    let points = views
        .iter()
        .map(|v| intersect(&known, v))
        .collect::<Option<Vec<_>>>()
        .ok_or_else(|| {
            Error::Numerical("a point's cameras do not fix it after the metric upgrade".into())
        })?;
    Ok(Reconstruction {
        names: names.to_vec(),
        points,
        frames,
        method: vec![if up.clipped {
            "metric upgrade: L not positive definite, nearest positive definite by eigenvalue clipping".into()
        } else {
            "metric upgrade: cholesky".into()
        }],
        conditioning: None,
        warnings: up
            .clipped
            .then(|| super::metric::CLIPPED.to_string())
            .into_iter()
            .collect(),
    })
}
