//! Bundle adjustment: Levenberg–Marquardt on the orthographic reprojection error over the
//! points, the rotations (a local update R·exp(\[δ\]×), three parameters) and the image
//! translations (two), with the normal equations reduced by the Schur complement on the 3 × 3
//! point blocks to a dense 5k × 5k camera system, accumulated by matrix products over chunks
//! of points and factored by a blocked Cholesky (`algebra::cholesky`). The damping is λI
//! for the first [`PLAIN_ITERATIONS`], then λ·diag(JᵀJ).
//!
//! After every step, each point its views fix is moved to its least-squares position for
//! the new cameras before the cost is compared (embedded point iterations: Jeong, Nistér,
//! Steedly, Szeliski & Kweon, "Pushing the envelope of modern methods for bundle
//! adjustment", 2012). Under an orthographic camera that position is exact, since a point's
//! images are linear in it, and it costs one 3 × 3 solve per point. Where points are seen
//! in few frames it shortens the descent along their weakly fixed depths: on 100,000 points
//! each in 2 of 100 frames, Ceres' cost after 1,200 iterations is reached in 287 instead of
//! more than 10,000 (docs/architecture.md).
//!
//! The gauge (a common rotation, a common 3-D shift) is fixed by holding frame 1's rotation
//! and re-centring the points after every step (an exact change of gauge that moves no
//! image); the shift along frame 1's viewing direction that remains is held by the damping.
//!
//! Own loop rather than the `levenberg-marquardt` crate: that crate solves the dense normal
//! equations of a generic problem and cannot use the block structure that makes 100 points
//! in 20 frames cost milliseconds.

use nalgebra::{
    DMatrix, DVector, Matrix2x3, Matrix3, Rotation3, SMatrix, SVector, Vector2, Vector3,
};

pub use super::covariance::FrameStd;
use super::{Error, Observations, Reconstruction, Units};
use crate::algebra::cholesky::{cholesky_lower, cholesky_solve};
use crate::algebra::damping::Damping;
use crate::algebra::psd3_nonsingular;

/// Levenberg–Marquardt iterations by default: [`PLAIN_ITERATIONS`] damped by λI, the rest
/// damped by λ·diag(JᵀJ).
pub const MAX_ITERATIONS: usize = 200;

/// Iterations damped by λI (every parameter alike, λ from the largest curvature) before the
/// damping is scaled by each parameter's own curvature, λ·diag(JᵀJ) (Marquardt's scaling,
/// Ceres' default); as many as the pipeline's screening of other starts
/// (`pipeline::starts::SCREEN_ITERATIONS`). Where points are
/// seen in few frames their curvature is far below the cameras', and λI moves them slowly:
/// 1,000 points each in 2 of 30 frames end at a cost of 2.13 × 10⁻³ after 200 iterations of
/// λI, at 3.55 × 10⁻⁴ after 20 of λI and 180 scaled (with the points re-solved after each
/// step; without, 0.624 and 1.05 × 10⁻³). On the turntable family (measured before the
/// re-solve) λI alone reaches the optimum in more scenes than the scaled damping alone; 20
/// first, then scaled, reaches as many as 100 first (docs/limits.md).
pub const PLAIN_ITERATIONS: usize = 20;

/// The bounds of a diagonal entry of JᵀJ in the scaled damping (Ceres' `min_lm_diagonal`
/// and `max_lm_diagonal`): the floor keeps the damping positive on a parameter no
/// observation moves (frame 1's rotation), in the unit coordinates the adjustment works in.
const SCALED_DIAGONAL: (f64, f64) = (1e-6, 1e32);

/// The scaled damping's first λ: Ceres' first trust region radius, 10⁴, inverted.
const SCALED_START: f64 = 1e-4;
/// Rejected steps in a row after which no step can lower the cost (the damping has grown by
/// 2^(n(n+1)/2)).
const MAX_REJECTIONS: usize = 40;

type Mat5 = SMatrix<f64, 5, 5>;
type Mat5x3 = SMatrix<f64, 5, 3>;
type Vec5 = SVector<f64, 5>;

/// Options of [`bundle_adjust`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BundleOptions {
    /// Accepted iterations at most.
    pub max_iterations: usize,
    /// Huber's loss on each observation's residual norm, with this corner (input units),
    /// minimised by iteratively reweighted least squares: weight 1 within the corner, k/‖r‖
    /// beyond it; `None`: least squares.
    pub huber: Option<f64>,
    /// Whether to compute each point's and frame's standard errors at the optimum
    /// ([`BundleReport::points_std`], [`BundleReport::frames_std`]); they cost about as much
    /// as the adjustment itself.
    pub standard_errors: bool,
    /// Iterations damped by λI before the damping is scaled by diag(JᵀJ)
    /// ([`PLAIN_ITERATIONS`]); `max_iterations` or more: λI throughout, 0: scaled throughout.
    pub plain_iterations: usize,
    /// Whether each point is moved to its least-squares position for the cameras after
    /// every step (embedded point iterations, see the module's documentation); `false`:
    /// the points take their share of the step alone, as in plain Levenberg–Marquardt.
    pub embedded_points: bool,
}

impl Default for BundleOptions {
    fn default() -> Self {
        BundleOptions {
            max_iterations: MAX_ITERATIONS,
            huber: None,
            standard_errors: true,
            plain_iterations: PLAIN_ITERATIONS,
            embedded_points: true,
        }
    }
}

impl BundleOptions {
    /// The bundle options of the pipeline's options.
    pub fn with(o: &super::Options) -> Self {
        BundleOptions {
            max_iterations: o.max_iterations,
            ..BundleOptions::default()
        }
    }
}

/// How the adjustment went.
#[derive(Clone, Debug, PartialEq)]
pub struct BundleReport {
    /// Accepted iterations.
    pub iterations: usize,
    /// ½ Σ ‖residual‖² (input units squared) at the start and after each accepted step.
    pub costs: Vec<f64>,
    /// Whether it stopped because no step could lower the cost beyond rounding (rather than
    /// at the iteration limit).
    pub converged: bool,
    /// The iterations damped by λI before the damping was scaled by diag(JᵀJ), when it was
    /// (see [`PLAIN_ITERATIONS`]).
    pub scaled_after: Option<usize>,
    /// The standard error of each point's three coordinates (input units; the points
    /// centred, in frame 1's camera coordinates), from the normal equations at the optimum
    /// (`sfm::covariance`); `None` when they are singular or no residual degree of freedom
    /// is left.
    pub points_std: Option<Vec<Vector3<f64>>>,
    /// The standard errors of each frame's rotation (radians, relative to the first frame's)
    /// and translation (input units, the points centred), with the points'; `None` with them.
    pub frames_std: Option<Vec<FrameStd>>,
    /// Why there are no standard errors, when they were asked for and could not be given.
    pub no_standard_errors: Option<&'static str>,
}

/// A refined reconstruction and its report.
#[derive(Clone, Debug, PartialEq)]
pub struct Adjusted {
    /// The refined reconstruction.
    pub reconstruction: Reconstruction,
    /// How the adjustment went.
    pub report: BundleReport,
}

/// The work of one iteration: Σ over points of (frames seeing it)², the size of the Schur
/// complement's accumulation.
pub fn work(obs: &Observations) -> usize {
    let mut per_point = vec![0usize; obs.names.len()];
    for (_, j, _) in obs.seen() {
        per_point[j] += 1;
    }
    per_point.iter().map(|n| n * n).sum()
}

/// The parameters: one camera per frame, one point per name.
#[derive(Clone, Debug)]
pub(super) struct State {
    pub(super) rot: Vec<Matrix3<f64>>,
    trans: Vec<Vector2<f64>>,
    pub(super) pts: Vec<Vector3<f64>>,
}

impl State {
    fn rows(&self, f: usize) -> Matrix2x3<f64> {
        self.rot[f].fixed_rows::<2>(0).into_owned()
    }

    fn residual(&self, f: usize, j: usize, y: &Vector2<f64>) -> Vector2<f64> {
        self.rows(f) * self.pts[j] + self.trans[f] - y
    }

    /// Each point its views fix moved to its least-squares position for the cameras,
    /// weighted by Huber's weights at its residuals here (one reweighting: the weighted
    /// quadratic touches ρ from above here, so the point's cost does not rise); the others
    /// left where they are.
    fn points_resolved(self, by_point: &ByPoint, huber: Option<f64>) -> State {
        let mut s = self;
        // each frame's rows C and CᵀC once, not once per image
        let rows: Vec<Matrix2x3<f64>> = (0..s.rot.len()).map(|f| s.rows(f)).collect();
        let squares: Vec<Matrix3<f64>> = rows.iter().map(|c| c.transpose() * c).collect();
        for (j, list) in by_point.iter().enumerate() {
            let mut v = Matrix3::zeros();
            let mut b = Vector3::zeros();
            for (f, y) in list {
                let c = &rows[*f];
                // least squares needs no residual for its weight
                let w = match huber {
                    Some(_) => weight((c * s.pts[j] + s.trans[*f] - y).norm_squared(), huber),
                    None => 1.0,
                };
                v += squares[*f] * w;
                b += c.transpose() * (y - s.trans[*f]) * w;
            }
            // V sums 2 × 3 products of unit rows: its entries round to about ε times their
            // size (as in `gaps::intersect`)
            if psd3_nonsingular(&v, 3.0)
                && let Some(x) = v.cholesky().map(|ch| ch.solve(&b))
            {
                s.pts[j] = x;
            }
        }
        s
    }

    /// The step δ applied: R·exp([δ_R]×), t + δ_t, X + δ_X.
    fn moved(&self, dc: &[Vec5], dp: &[Vector3<f64>]) -> State {
        let mut s = self.clone();
        for (f, d) in dc.iter().enumerate() {
            let w = Vector3::new(d[0], d[1], d[2]);
            s.rot[f] *= Rotation3::new(w).into_inner();
            s.trans[f] += Vector2::new(d[3], d[4]);
        }
        for (x, d) in s.pts.iter_mut().zip(dp) {
            *x += d;
        }
        s
    }

    /// The points' centroid moved to the origin, the translations compensating: an exact
    /// change of gauge that moves no image.
    fn recentred(mut self) -> State {
        let c = self.pts.iter().sum::<Vector3<f64>>() / self.pts.len().max(1) as f64;
        for x in &mut self.pts {
            *x -= c;
        }
        let shifts: Vec<Vector2<f64>> = (0..self.rot.len()).map(|f| self.rows(f) * c).collect();
        for (t, shift) in self.trans.iter_mut().zip(shifts) {
            *t += shift;
        }
        self
    }

    fn norm(&self) -> f64 {
        let a: f64 = self.trans.iter().map(|t| t.norm_squared()).sum();
        let b: f64 = self.pts.iter().map(|x| x.norm_squared()).sum();
        (a + b + self.rot.len() as f64).sqrt()
    }
}

/// Observations grouped by point: (frame, image).
type ByPoint = Vec<Vec<(usize, Vector2<f64>)>>;

/// Σ ρ(‖r‖): ρ(s) = s²/2 (least squares), or Huber's s²/2 within the corner k and
/// k s − k²/2 beyond it.
fn cost(by_point: &ByPoint, s: &State, huber: Option<f64>) -> f64 {
    let mut c = 0.0;
    for (j, list) in by_point.iter().enumerate() {
        for (f, y) in list {
            let sq = s.residual(*f, j, y).norm_squared();
            c += match huber {
                Some(k) if sq > k * k => 2.0 * k * sq.sqrt() - k * k,
                _ => sq,
            };
        }
    }
    c / 2.0
}

/// The weight of a residual of squared norm `sq` in the reweighted normal equations: 1
/// within Huber's corner, k/‖r‖ beyond it (the weighted quadratic then touches ρ from above
/// at the current residual, so a step that lowers it lowers ρ).
fn weight(sq: f64, huber: Option<f64>) -> f64 {
    match huber {
        Some(k) if sq > k * k => k / sq.sqrt(),
        _ => 1.0,
    }
}

/// The normal equations JᵀJ, Jᵀr in blocks.
pub(super) struct Normal {
    pub(super) u: Vec<Mat5>,
    gc: Vec<Vec5>,
    pub(super) v: Vec<Matrix3<f64>>,
    gp: Vec<Vector3<f64>>,
    /// Per point, per observation: the camera–point block J_cᵀ J_p.
    pub(super) w: Vec<Vec<Mat5x3>>,
}

/// The camera Jacobian of one residual: [−C [X]× | I₂], zero rotation columns for frame 1
/// (its rotation is the gauge).
pub(super) fn camera_jacobian(
    c: &Matrix2x3<f64>,
    x: &Vector3<f64>,
    fixed: bool,
) -> SMatrix<f64, 2, 5> {
    let mut j = SMatrix::<f64, 2, 5>::zeros();
    if !fixed {
        let rot = -(c * x.cross_matrix());
        j.fixed_view_mut::<2, 3>(0, 0).copy_from(&rot);
    }
    j[(0, 3)] = 1.0;
    j[(1, 4)] = 1.0;
    j
}

fn normal(by_point: &ByPoint, s: &State, huber: Option<f64>) -> Normal {
    let k = s.rot.len();
    let mut n = Normal {
        u: vec![Mat5::zeros(); k],
        gc: vec![Vec5::zeros(); k],
        v: vec![Matrix3::zeros(); by_point.len()],
        gp: vec![Vector3::zeros(); by_point.len()],
        w: Vec::with_capacity(by_point.len()),
    };
    for (j, list) in by_point.iter().enumerate() {
        let mut wj = Vec::with_capacity(list.len());
        for (f, y) in list {
            let c = s.rows(*f);
            let r = s.residual(*f, j, y);
            let w = weight(r.norm_squared(), huber);
            let jc = camera_jacobian(&c, &s.pts[j], *f == 0);
            n.u[*f] += jc.transpose() * jc * w;
            n.gc[*f] += jc.transpose() * r * w;
            n.v[j] += c.transpose() * c * w;
            n.gp[j] += c.transpose() * r * w;
            wj.push(jc.transpose() * c * w);
        }
        n.w.push(wj);
    }
    n
}

/// Points whose Schur terms are accumulated together (one matrix product when their frames
/// make it cheaper than block by block).
pub(super) const CHUNK: usize = 64;
/// Rows of the camera system per matrix product when a chunk's points span every frame: the
/// lower triangle is computed panel by panel, about half the products of the whole square.
const PANEL: usize = 128;
/// How much faster a multiply-add is taken to run in a large matrix product than in the
/// 5 × 3 · 3 × 5 block products of the scattered accumulation: a chosen factor, not a
/// measured one (it only moves time, never the result beyond rounding).
pub(super) const DENSE_GAIN: usize = 4;

/// One point's share of the damped step: M = L⁻¹ for L Lᵀ = V + λD (D its damping's shape),
/// and per image the camera–point block Z = W Mᵀ (so that W (V + λD)⁻¹ Wᵀ = Z Zᵀ).
struct PointTerms {
    m: Matrix3<f64>,
    z: Vec<Mat5x3>,
}

/// A damped step: the cameras' and the points' shares.
struct Step {
    dc: Vec<Vec5>,
    dp: Vec<Vector3<f64>>,
}

/// The damping's shape on a block `m` of JᵀJ (a camera's 5 × 5 or a point's 3 × 3): I, or
/// its diagonal within [`SCALED_DIAGONAL`] when `scaled`.
fn shape<const N: usize>(m: &SMatrix<f64, N, N>, scaled: bool) -> SMatrix<f64, N, N> {
    if scaled {
        SMatrix::from_diagonal(
            &m.diagonal()
                .map(|d| d.clamp(SCALED_DIAGONAL.0, SCALED_DIAGONAL.1)),
        )
    } else {
        SMatrix::identity()
    }
}

/// The damped step: (JᵀJ + λD) δ = −Jᵀr (D = I, or diag(JᵀJ) when `scaled`) by the Schur
/// complement on the point blocks; the camera system's lower triangle is accumulated and
/// factored by a blocked Cholesky.
fn solve(n: &Normal, by_point: &ByPoint, lambda: f64, scaled: bool) -> Option<Step> {
    let k = n.u.len();
    let mut s = DMatrix::<f64>::zeros(5 * k, 5 * k);
    let mut rhs = DVector::<f64>::zeros(5 * k);
    for (f, (u, g)) in n.u.iter().zip(&n.gc).enumerate() {
        s.fixed_view_mut::<5, 5>(5 * f, 5 * f)
            .copy_from(&(u + shape(u, scaled) * lambda));
        rhs.fixed_rows_mut::<5>(5 * f).copy_from(&-g);
    }
    let mut terms = Vec::with_capacity(by_point.len());
    for (j, list) in by_point.iter().enumerate() {
        let l = (n.v[j] + shape(&n.v[j], scaled) * lambda)
            .cholesky()?
            .unpack();
        let m = l.try_inverse()?;
        let h = m * n.gp[j];
        let z: Vec<Mat5x3> = n.w[j].iter().map(|w| w * m.transpose()).collect();
        for ((f, _), za) in list.iter().zip(&z) {
            let mut r = rhs.fixed_rows_mut::<5>(5 * f);
            r += za * h;
        }
        terms.push(PointTerms { m, z });
    }
    for start in (0..by_point.len()).step_by(CHUNK) {
        let end = (start + CHUNK).min(by_point.len());
        subtract_chunk(&mut s, &by_point[start..end], &terms[start..end]);
    }
    let l = cholesky_lower(s)?;
    let dc_all = cholesky_solve(&l, &rhs)?;
    let dc: Vec<Vec5> = (0..k)
        .map(|f| dc_all.fixed_rows::<5>(5 * f).into_owned())
        .collect();
    let dp = by_point
        .iter()
        .zip(&terms)
        .enumerate()
        .map(|(j, (list, t))| {
            let mut g = -n.gp[j];
            for (a, (f, _)) in list.iter().enumerate() {
                g -= n.w[j][a].transpose() * dc[*f];
            }
            t.m.transpose() * (t.m * g)
        })
        .collect();
    Some(Step { dc, dp })
}

/// S −= Σ Z Zᵀ over a chunk of points, into S's lower triangle (image lists in frame order):
/// one matrix product over the frames the chunk sees when that costs less than the
/// scattered 5 × 5 blocks, block by block otherwise (short tracks in many frames).
fn subtract_chunk(
    s: &mut DMatrix<f64>,
    lists: &[Vec<(usize, Vector2<f64>)>],
    terms: &[PointTerms],
) {
    let k = s.nrows() / 5;
    let mut pos = vec![usize::MAX; k];
    for (f, _) in lists.iter().flatten() {
        pos[*f] = 0;
    }
    let frames: Vec<usize> = (0..k).filter(|&f| pos[f] == 0).collect();
    for (i, &f) in frames.iter().enumerate() {
        pos[f] = i;
    }
    let r = frames.len();
    let dense = 25 * r * r * 3 * lists.len() / 2;
    let scattered: usize = lists.iter().map(|l| 75 * l.len() * (l.len() + 1) / 2).sum();
    if dense > DENSE_GAIN * scattered {
        for (list, t) in lists.iter().zip(terms) {
            for (a, (fa, _)) in list.iter().enumerate() {
                for (b, (fb, _)) in list.iter().enumerate().take(a + 1) {
                    let mut blk = s.fixed_view_mut::<5, 5>(5 * fa, 5 * fb);
                    blk -= t.z[a] * t.z[b].transpose();
                }
            }
        }
        return;
    }
    let mut zc = DMatrix::<f64>::zeros(5 * r, 3 * lists.len());
    for (i, (list, t)) in lists.iter().zip(terms).enumerate() {
        for ((f, _), za) in list.iter().zip(&t.z) {
            zc.fixed_view_mut::<5, 3>(5 * pos[*f], 3 * i).copy_from(za);
        }
    }
    let zt = zc.transpose();
    if r == k {
        for i0 in (0..5 * k).step_by(PANEL) {
            let len = PANEL.min(5 * k - i0);
            s.view_mut((i0, 0), (len, i0 + len)).gemm(
                -1.0,
                &zc.rows(i0, len),
                &zt.columns(0, i0 + len),
                1.0,
            );
        }
        return;
    }
    let prod = &zc * &zt;
    for (a, &fa) in frames.iter().enumerate() {
        for (b, &fb) in frames.iter().enumerate().take(a + 1) {
            let mut blk = s.fixed_view_mut::<5, 5>(5 * fa, 5 * fb);
            blk -= prod.fixed_view::<5, 5>(5 * a, 5 * b);
        }
    }
}

/// The reduction the damped model predicts: ½ δᵀ(λDδ − g), D the damping's shape.
fn predicted(n: &Normal, st: &Step, lambda: f64, scaled: bool) -> f64 {
    let c: f64 = st
        .dc
        .iter()
        .zip(&n.gc)
        .zip(&n.u)
        .map(|((d, g), u)| d.dot(&(shape(u, scaled) * d * lambda - g)))
        .sum();
    let p: f64 = st
        .dp
        .iter()
        .zip(&n.gp)
        .zip(&n.v)
        .map(|((d, g), v)| d.dot(&(shape(v, scaled) * d * lambda - g)))
        .sum();
    (c + p) / 2.0
}

/// Each point's and frame's standard errors at the optimum `state` (`sfm::covariance`), in
/// input units, into `report`; or why there are none.
fn standard_errors(
    by_point: &ByPoint,
    state: &State,
    huber: Option<f64>,
    scale: f64,
    report: &mut BundleReport,
) {
    let frames_of: Vec<Vec<usize>> = by_point
        .iter()
        .map(|l| l.iter().map(|(f, _)| *f).collect())
        .collect();
    let at_optimum = normal(by_point, state, huber);
    let squares = cost(by_point, state, None);
    match super::covariance::standard_errors(&at_optimum, &frames_of, state, squares) {
        Ok(e) => {
            report.points_std = Some(e.points.into_iter().map(|x| x * scale).collect());
            report.frames_std = Some(
                e.frames
                    .into_iter()
                    .map(|f| FrameStd {
                        translation: f.translation * scale,
                        ..f
                    })
                    .collect(),
            );
        }
        Err(why) => report.no_standard_errors = Some(why),
    }
}

/// Refine `start` (a reconstruction of `obs`' points and frames, in its units) by
/// Levenberg–Marquardt with Nielsen's damping update, damped by λI and, after
/// `plain_iterations` (see [`PLAIN_ITERATIONS`]), by λ·diag(JᵀJ). It stops when a step lowers the cost
/// by no more than its rounding (4ε·cost: the cost is a sum of squares, each rounded to about
/// ε) or moves no parameter beyond rounding (4ε·‖x‖), or at the iteration limit.
pub fn bundle_adjust(
    obs: &Observations,
    start: &Reconstruction,
    options: &BundleOptions,
) -> Result<Adjusted, Error> {
    if start.points.len() != obs.names.len() || start.frames.len() != obs.frames.len() {
        return Err(Error::Numerical(format!(
            "the start has {} points in {} frames, the observations {} in {}",
            start.points.len(),
            start.frames.len(),
            obs.names.len(),
            obs.frames.len()
        )));
    }
    let units = Units::of(obs)?;
    let unit_obs = units.to_unit(obs);
    let mut unit_start = start.clone();
    units.forward(&mut unit_start);
    let mut by_point: ByPoint = vec![Vec::new(); obs.names.len()];
    for (f, j, y) in unit_obs.seen() {
        by_point[j].push((f, y));
    }
    let state = State {
        rot: unit_start.frames.iter().map(|f| f.rotation).collect(),
        trans: unit_start.frames.iter().map(|f| f.translation).collect(),
        pts: unit_start.points.clone(),
    };
    let huber = options.huber.map(|k| k / units.scale);
    if huber.is_some_and(|k| !(k.is_finite() && k > 0.0)) {
        return Err(Error::InvalidOption(
            "Huber's corner must be a positive number of image units".into(),
        ));
    }
    let (state, mut report) = levenberg_marquardt(&by_point, state, options, huber)?;
    if options.standard_errors {
        standard_errors(&by_point, &state, huber, units.scale, &mut report);
    }
    let s2 = units.scale * units.scale;
    report.costs.iter_mut().for_each(|c| *c *= s2);
    let mut rec = unit_start;
    for (f, frame) in rec.frames.iter_mut().enumerate() {
        frame.rotation = state.rot[f];
        frame.translation = state.trans[f];
    }
    rec.points = state.pts;
    units.back(&mut rec);
    rec.method.push(method_line(options, &report));
    if !report.converged {
        rec.warnings.push(format!(
            "bundle adjustment stopped at its iteration limit ({}) before it converged: the body may not be the least-squares one",
            options.max_iterations
        ));
    }
    if !rec.is_finite() {
        return Err(Error::Numerical(
            "bundle adjustment produced a non-finite value".into(),
        ));
    }
    Ok(Adjusted {
        reconstruction: rec,
        report,
    })
}

/// The `method` line of an adjustment run with `options` that went as `report` says.
fn method_line(options: &BundleOptions, report: &BundleReport) -> String {
    format!(
        "bundle adjustment (levenberg-marquardt, schur complement{}{}): {} iterations{}{}",
        if options.embedded_points {
            ", points re-solved after each step"
        } else {
            ""
        },
        options.huber.map_or(String::new(), |k| format!(
            ", huber loss with its corner at {} image units, by reweighting",
            crate::numfmt::sig(k)
        )),
        report.iterations,
        report.scaled_after.map_or(String::new(), |n| format!(
            " (the damping scaled by diag(JᵀJ) after {n})"
        )),
        if report.converged {
            ""
        } else {
            ", iteration limit reached"
        }
    )
}

/// Damped steps from `state` until one lowers the cost (`damping` updated by Nielsen's
/// rule): that step's state, cost and length. With the points re-solved, the reduction
/// exceeds the step's predicted one (the gain ratio runs high and λ falls by its cap), and
/// the length is the step's, not the re-solved points' move.
/// `None` when none can beyond rounding: a rejected step whose predicted reduction is
/// within the cost's rounding (4ε·cost) or whose length is within the parameters' (4ε·‖x‖)
/// ends the search, as does [`MAX_REJECTIONS`] in a row (more damping only shortens the
/// step further).
fn trial(
    n: &Normal,
    by_point: &ByPoint,
    state: &State,
    c: f64,
    damping: &mut Damping,
    rule: Rule,
) -> Option<(State, f64, f64)> {
    for _ in 0..MAX_REJECTIONS {
        if let Some(st) = solve(n, by_point, damping.lambda, rule.scaled) {
            let mut next = state.moved(&st.dc, &st.dp);
            if rule.embedded {
                next = next.points_resolved(by_point, rule.huber);
            }
            let next = next.recentred();
            let nc = cost(by_point, &next, rule.huber);
            let pred = predicted(n, &st, damping.lambda, rule.scaled);
            let step = (st.dc.iter().map(|d| d.norm_squared()).sum::<f64>()
                + st.dp.iter().map(|d| d.norm_squared()).sum::<f64>())
            .sqrt();
            if nc.is_finite() && nc < c && pred > 0.0 {
                damping.accepted((c - nc) / pred);
                return Some((next, nc, step));
            }
            if pred <= 4.0 * f64::EPSILON * c || step <= 4.0 * f64::EPSILON * state.norm() {
                return None;
            }
        }
        damping.rejected();
    }
    None
}

/// How a phase of the loop steps: Huber's corner (unit coordinates), the damping's shape
/// (λ·diag(JᵀJ) when `scaled`, else λI) and whether points are re-solved after each step.
#[derive(Clone, Copy)]
struct Rule {
    huber: Option<f64>,
    scaled: bool,
    embedded: bool,
}

/// The damped Gauss–Newton loop: damped by λI for at most `plain_iterations`, then by
/// λ·diag(JᵀJ) up to `max_iterations` in all (both of `options`; `huber` in unit
/// coordinates).
fn levenberg_marquardt(
    by_point: &ByPoint,
    mut state: State,
    options: &BundleOptions,
    huber: Option<f64>,
) -> Result<(State, BundleReport), Error> {
    let max_iterations = options.max_iterations;
    let c = cost(by_point, &state, huber);
    let mut report = BundleReport {
        iterations: 0,
        costs: vec![c],
        converged: false,
        scaled_after: None,
        points_std: None,
        frames_std: None,
        no_standard_errors: None,
    };
    let plain = max_iterations.min(options.plain_iterations);
    let mut rule = Rule {
        huber,
        scaled: false,
        embedded: options.embedded_points,
    };
    if plain > 0 {
        state = descend(by_point, state, &mut report, plain, rule);
    }
    let left = report.costs.last().is_some_and(|&c| c > 0.0);
    if !report.converged && left && report.iterations < max_iterations {
        report.scaled_after = Some(report.iterations);
        rule.scaled = true;
        state = descend(by_point, state, &mut report, max_iterations, rule);
    }
    let c = report.costs.last().copied().unwrap_or(f64::NAN);
    if c == 0.0 {
        report.converged = true;
    }
    if !c.is_finite() {
        return Err(Error::Numerical(
            "the reprojection cost became non-finite".into(),
        ));
    }
    Ok((state, report))
}

/// Damped steps from `state` (the cost is the report's last) until none lowers the cost
/// beyond rounding or the report counts `until` iterations; damped by λI from 10⁻³ of the
/// largest diagonal entry of JᵀJ, or when the rule is `scaled` by λ·diag(JᵀJ) from
/// [`SCALED_START`].
fn descend(
    by_point: &ByPoint,
    mut state: State,
    report: &mut BundleReport,
    until: usize,
    rule: Rule,
) -> State {
    let mut c = report.costs.last().copied().unwrap_or(f64::NAN);
    let mut damping = if rule.scaled {
        Damping::with_lambda(SCALED_START)
    } else {
        let first = normal(by_point, &state, rule.huber);
        let diag = first
            .u
            .iter()
            .map(|u| u.diagonal().max())
            .chain(first.v.iter().map(|v| v.diagonal().max()));
        Damping::from_diagonal_max(diag.fold(f64::MIN_POSITIVE, f64::max))
    };
    while report.iterations < until && c > 0.0 {
        let n = normal(by_point, &state, rule.huber);
        let Some((next, nc, step)) = trial(&n, by_point, &state, c, &mut damping, rule) else {
            report.converged = true;
            break;
        };
        let small = c - nc <= 4.0 * f64::EPSILON * c || step <= 4.0 * f64::EPSILON * state.norm();
        state = next;
        c = nc;
        report.iterations += 1;
        report.costs.push(c);
        if small {
            report.converged = true;
            break;
        }
    }
    state
}
