//! §2.2: three points, three frames — the closed-form solver along the paper's route.
//!
//! Solves the three twofold-squared equations F₁ = F₂ = F₃ = 0 (eq. p3f3sqr) in x = a²,
//! y = b², z = c²: the differences F₁ − F₃ and F₂ − F₃ are linear, so a² = A_c c² + A_Cst and
//! b² = B_c c² + B_Cst; substituted into F₃ they leave a quadratic in c². Every root is
//! returned, real or complex, and judged by the paper's feasibility rules.

use nalgebra::{Matrix3, Rotation3, Vector3};
use num_complex::Complex64;

use super::solver::{feasibility, Degenerate, Solution, SolverOutput, SquaredLengths};
use super::twofold::FrameCoefficients;
use crate::algebra::{negligible, quadratic_roots};
use crate::error::{Error, Result};
use crate::model::Tracks;

pub mod exact;
pub mod route;
pub use exact::{
    exact_elimination, exact_elimination_parts, exact_equations, validate, Validation,
};

/// The unknowns as affine functions of the free one, t: v = slope·t + intercept.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Elimination {
    /// Index of the free unknown (2 = c², the paper's choice).
    pub free: usize,
    /// Slopes (A_c, B_c, 1 for the paper's choice).
    pub slope: [f64; 3],
    /// Intercepts (A_Cst, B_Cst, 0).
    pub intercept: [f64; 3],
    /// Quadratic in t: `q[0] + q[1] t + q[2] t²`.
    pub quadratic: [f64; 3],
}

/// The allocation-free result of [`solve_core`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Core {
    /// Candidate squared edges (a², b², c²), real parts.
    pub squares: [[f64; 3]; 2],
    /// Imaginary parts.
    pub imag: [[f64; 3]; 2],
    /// Number of candidates (0, 1 or 2).
    pub count: usize,
    /// Whether each candidate passes the feasibility rules.
    pub feasible: [bool; 2],
    /// The degenerate case, if any.
    pub degenerate: Option<Degenerate>,
    /// The elimination used (absent when the input is degenerate before it).
    pub elimination: Option<Elimination>,
}

/// Projected squared lengths (PQ, QR, RP) in three frames → all roots with feasibility.
///
/// # Example
/// ```
/// use orthocheck_core::derivations::p3f3::solve_core;
/// use orthocheck_core::derivations::solver::SquaredLengths;
/// use orthocheck_core::model::Scene;
/// let scene = Scene::random(3, 3, 4);
/// let l = SquaredLengths::from_tracks(&scene.tracks());
/// let core = solve_core(&[0, 1, 2].map(|i| [l.frames[i][0], l.frames[i][1], l.frames[i][2]]));
/// let truth = scene.body.squared_distance(0, 1);
/// assert!((0..core.count).any(|k| (core.squares[k][0] - truth).abs() < 1e-9 * truth));
/// ```
pub fn solve_core(l: &[[f64; 3]; 3]) -> Core {
    let mut core = Core {
        squares: [[0.0; 3]; 2],
        imag: [[0.0; 3]; 2],
        count: 0,
        feasible: [false; 2],
        degenerate: None,
        elimination: None,
    };
    let f = [
        FrameCoefficients::new(l[0]),
        FrameCoefficients::new(l[1]),
        FrameCoefficients::new(l[2]),
    ];
    if f.iter().all(|fi| negligible(fi.k, fi.scale * fi.scale)) {
        core.degenerate = Some(Degenerate::Collinear);
        return core;
    }
    let Some(elim) = eliminate(&f, l, &mut core) else {
        return core;
    };
    core.elimination = Some(elim);
    let [q0, q1, q2] = elim.quadratic;
    // Σᵢⱼ |sᵢ Mᵢⱼ sⱼ| = (Σ|sᵢ|)², the scale of the leading coefficient sᵀMs
    let s = elim.slope;
    let mag2 = (s[0].abs() + s[1].abs() + s[2].abs()).powi(2);
    let roots: [Complex64; 2];
    if negligible(q2, mag2) {
        if q1 == 0.0 {
            core.degenerate = Some(Degenerate::Indeterminate);
            return core;
        }
        core.degenerate = Some(Degenerate::VanishingLeadingCoefficient);
        roots = [Complex64::new(-q0 / q1, 0.0); 2];
        core.count = 1;
    } else {
        let (r, _) = quadratic_roots(q2, q1, q0);
        roots = r;
        core.count = 2;
        if r[0].im != 0.0 {
            core.degenerate = Some(Degenerate::NoRealRoot);
        }
    }
    for (k, t) in roots.iter().take(core.count).enumerate() {
        for v in 0..3 {
            core.squares[k][v] = elim.slope[v] * t.re + elim.intercept[v];
            core.imag[k][v] = elim.slope[v] * t.im;
        }
        if t.im == 0.0 {
            // a real root: polish, then the paper's rules
            let v = polish(&f, core.squares[k]);
            core.squares[k] = v;
            core.feasible[k] =
                super::solver::first_violation(&v, l.iter().map(|f| &f[..])).is_none();
        }
    }
    core
}

/// One Newton step on the three original equations. The paper's route (Cramer's rule, then
/// a quadratic) can lose digits when the two roots are close; the step restores the accuracy
/// the equations themselves allow (quadratic convergence from the route's answer).
fn polish(f: &[FrameCoefficients; 3], v: [f64; 3]) -> [f64; 3] {
    let [x, y, z] = v;
    let mut r = Vector3::zeros();
    let mut at_noise = true;
    for (i, fi) in f.iter().enumerate() {
        r[i] = fi.eval(x, y, z);
        // a residual within the rounding noise of evaluating Fᵢ (the noise measure of
        // [`forward_error_bound`]): a Newton step would only move the answer by noise
        at_noise &= negligible(r[i], fi.terms(x, y, z));
    }
    if at_noise {
        return v;
    }
    // Newton step J d = r by the adjugate: J⁻¹ has the columns j₁×j₂, j₂×j₀, j₀×j₁ over det
    let row = |fi: &FrameCoefficients| Vector3::from(fi.slope(v));
    let (j0, j1, j2) = (row(&f[0]), row(&f[1]), row(&f[2]));
    let c0 = j1.cross(&j2);
    let det = j0.dot(&c0);
    if det == 0.0 || !det.is_finite() {
        return v;
    }
    let d = (c0 * r[0] + j2.cross(&j0) * r[1] + j0.cross(&j1) * r[2]) / det;
    [x - d[0], y - d[1], z - d[2]]
}

/// Solve the two difference equations for two unknowns in terms of the third, the paper's
/// way (free c²) unless its denominator vanishes; then substitute into F₃.
fn eliminate(
    f: &[FrameCoefficients; 3],
    l: &[[f64; 3]; 3],
    core: &mut Core,
) -> Option<Elimination> {
    let (d1, k1) = f[0].difference(&f[2]);
    let (d2, k2) = f[1].difference(&f[2]);
    // A difference whose coefficients are rounding noise: two frames with equal lengths.
    let vanishes = |d: &[f64; 3], a: &FrameCoefficients, b: &FrameCoefficients| {
        let m = 2.0 * (a.scale + b.scale);
        negligible(d[0], m) && negligible(d[1], m) && negligible(d[2], m)
    };
    if vanishes(&d1, &f[0], &f[2]) || vanishes(&d2, &f[1], &f[2]) {
        core.degenerate = Some(identical_frames(l).unwrap_or(Degenerate::DependentDifferences));
        return None;
    }
    // minor for the pair (u, v) with the third unknown free
    let minor = |u: usize, v: usize| {
        (
            d1[u] * d2[v] - d2[u] * d1[v],
            (d1[u] * d2[v]).abs() + (d2[u] * d1[v]).abs(),
        )
    };
    // the paper's choice (c² free) when its denominator is usable, else the largest minor
    let (det, mag) = minor(0, 1);
    let best = if !negligible(det, mag) {
        Some((0, 1, 2, det))
    } else {
        [(0, 2, 1), (1, 2, 0)]
            .iter()
            .map(|&(u, v, w)| (u, v, w, minor(u, v)))
            .filter(|(_, _, _, (det, mag))| !negligible(*det, *mag))
            .map(|(u, v, w, (det, _))| (u, v, w, det))
            .max_by(|a, b| a.3.abs().total_cmp(&b.3.abs()))
    };
    let Some((u, v, w, det)) = best else {
        core.degenerate = Some(identical_frames(l).unwrap_or(Degenerate::DependentDifferences));
        return None;
    };
    if w != 2 {
        core.degenerate = Some(Degenerate::PaperDenominatorVanishes);
    }
    // d1[u] X + d1[v] Y = −d1[w] t − k1, likewise for d2; Cramer's rule as printed.
    let mut slope = [0.0; 3];
    let mut intercept = [0.0; 3];
    let inv = 1.0 / det;
    slope[u] = ((-d1[w]) * d2[v] - (-d2[w]) * d1[v]) * inv;
    intercept[u] = ((-k1) * d2[v] - (-k2) * d1[v]) * inv;
    slope[v] = (d1[u] * (-d2[w]) - d2[u] * (-d1[w])) * inv;
    intercept[v] = (d1[u] * (-k2) - d2[u] * (-k1)) * inv;
    slope[w] = 1.0;
    // With M the matrix of x² + y² + z² − 2xy − 2xz − 2yz,
    // F₃(slope·t + intercept) = sᵀMs t² + (2 sᵀMc + 2(α,β,γ)·s) t + cᵀMc + 2(α,β,γ)·c + K
    let lin = [2.0 * f[2].alpha, 2.0 * f[2].beta, 2.0 * f[2].gamma];
    // aᵀMb with M = 2I − 11ᵀ
    let form = |a: &[f64; 3], b: &[f64; 3]| -> f64 {
        2.0 * (a[0] * b[0] + a[1] * b[1] + a[2] * b[2])
            - (a[0] + a[1] + a[2]) * (b[0] + b[1] + b[2])
    };
    let dot = |a: &[f64; 3], b: &[f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let quadratic = [
        form(&intercept, &intercept) + dot(&lin, &intercept) + f[2].k,
        2.0 * form(&slope, &intercept) + dot(&lin, &slope),
        form(&slope, &slope),
    ];
    Some(Elimination {
        free: w,
        slope,
        intercept,
        quadratic,
    })
}

/// Two frames whose projected squared lengths agree up to rounding.
fn identical_frames(l: &[[f64; 3]; 3]) -> Option<Degenerate> {
    for (i, j) in [(0, 1), (0, 2), (1, 2)] {
        if (0..3).all(|e| negligible(l[i][e] - l[j][e], l[i][e] + l[j][e])) {
            return Some(Degenerate::IdenticalFrames {
                first: i + 1,
                second: j + 1,
            });
        }
    }
    None
}

/// Largest |Fᵢ| at a (possibly complex) solution, relative to its squared scale.
fn residual(l: &[[f64; 3]; 3], re: &[f64; 3], im: &[f64; 3]) -> f64 {
    let v: Vec<Complex64> = (0..3).map(|i| Complex64::new(re[i], im[i])).collect();
    let scale = v.iter().map(|z| z.norm()).fold(f64::MIN_POSITIVE, f64::max);
    l.iter()
        .map(|li| {
            let f = FrameCoefficients::new(*li);
            let (x, y, z) = (v[0], v[1], v[2]);
            let val = x * x + y * y + z * z - 2.0 * x * y - 2.0 * x * z - 2.0 * y * z
                + f.k
                + 2.0 * f.alpha * x
                + 2.0 * f.beta * y
                + 2.0 * f.gamma * z;
            val.norm() / (scale * scale)
        })
        .fold(0.0, f64::max)
}

/// The p3f3 solver in the shared calling convention: exactly three points and three frames.
pub fn solve(input: &SquaredLengths) -> Result<SolverOutput> {
    if input.names.len() != 3 || input.frames.len() != 3 {
        return Err(Error::InvalidInput(format!(
            "p3f3 needs 3 points in 3 frames, got {} points in {} frames",
            input.names.len(),
            input.frames.len()
        )));
    }
    if let Some(d) = super::degenerate::classify(input, 3) {
        return Ok(SolverOutput::degenerate("p3f3", input, d));
    }
    let l: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|e| input.frames[i][e]));
    let core = solve_core(&l);
    let solutions = (0..core.count)
        .map(|k| Solution {
            squared_edges: core.squares[k].to_vec(),
            imaginary: core.imag[k].to_vec(),
            feasibility: feasibility(&core.squares[k], &core.imag[k], input),
            residual: residual(&l, &core.squares[k], &core.imag[k]),
            error_bound: (core.imag[k] == [0.0; 3])
                .then(|| forward_error_bound(&l, &core.squares[k])),
        })
        .collect();
    Ok(SolverOutput {
        method: "p3f3".into(),
        edges: input.edge_names(),
        solutions,
        degenerate: core.degenerate,
        condition: None,
    })
}

/// One structure-and-motion solution behind an edge-length solution.
#[derive(Clone, Debug, PartialEq)]
pub struct Reconstruction {
    /// P, Q, R in frame 1's camera coordinates (P at the origin).
    pub points: [Vector3<f64>; 3],
    /// Rotation of frame 1's coordinates into each frame's (the first is the identity).
    pub rotations: Vec<Rotation3<f64>>,
    /// Depth sign chosen in each frame (+1 or −1; frame 1 is the reference).
    pub depth_signs: Vec<i8>,
    /// Largest reprojection error, relative to the largest edge.
    pub reprojection_error: f64,
}

/// Frames of three points whose depth-sign patterns [`reconstructions`] lists one by one
/// (2^(k−1) of them); beyond, [`motion_summary`] counts them in closed form.
pub const MAX_LISTED_FRAMES: usize = 16;

/// Frames of three points whose structure-and-motion solutions [`motion_summary`] can count:
/// 2^(k−1) must fit in 64 bits (and twice it, with the mirror reversal, in 128).
pub const MAX_COUNTED_FRAMES: usize = 64;

/// P, Q, R in frame `i`'s camera coordinates for depth sign `s`: the depth differences are
/// ±√(e² − eᵢ²) with the sign pattern of the relation that holds (the smallest
/// |s_a√A + s_b√B + s_c√C|), up to the global sign `s`.
fn camera(f: &[nalgebra::Vector2<f64>], squares: &[f64; 3], s: f64) -> Option<[Vector3<f64>; 3]> {
    let proj = [0, 1, 2].map(|e| {
        let (a, b) = [(0, 1), (1, 2), (2, 0)][e];
        (f[a] - f[b]).norm_squared()
    });
    let roots: [f64; 3] = std::array::from_fn(|e| (squares[e] - proj[e]).max(0.0).sqrt());
    let patterns = [[1.0, 1.0, -1.0], [1.0, -1.0, 1.0], [-1.0, 1.0, 1.0]];
    let r = |p: &[f64; 3]| (p[0] * roots[0] + p[1] * roots[1] + p[2] * roots[2]).abs();
    let best = patterns.iter().min_by(|p, q| r(p).total_cmp(&r(q)))?;
    let zq = s * best[0] * roots[0];
    let zr = zq + s * best[1] * roots[1];
    let o = f[0];
    Some([
        Vector3::new(0.0, 0.0, 0.0),
        Vector3::new(f[1].x - o.x, f[1].y - o.y, zq),
        Vector3::new(f[2].x - o.x, f[2].y - o.y, zr),
    ])
}

/// Per later frame and depth sign (+1, −1): the rotation taking frame 1's body onto that
/// frame's, and the frame's reprojection error relative to the largest edge. A pattern's
/// error is the largest of its frames' errors, so every count and best choice over the
/// 2^(k−1) patterns follows from these 2(k − 1) numbers.
#[allow(clippy::type_complexity)]
fn per_frame(
    tracks: &Tracks,
    squares: &[f64; 3],
) -> Result<Option<([Vector3<f64>; 3], Vec<[(Rotation3<f64>, f64); 2]>)>> {
    if tracks.points() != 3 {
        return Err(Error::InvalidInput("reconstruction needs 3 points".into()));
    }
    let scale = squares.iter().fold(0.0_f64, |a, b| a.max(*b)).sqrt();
    let Some(first) = camera(&tracks.frames[0], squares, 1.0) else {
        return Ok(None);
    };
    let mut frames = Vec::with_capacity(tracks.frames.len());
    for f in &tracks.frames[1..] {
        let mut pair = [(Rotation3::identity(), 0.0); 2];
        for (slot, s) in pair.iter_mut().zip([1.0, -1.0]) {
            let Some(target) = camera(f, squares, s) else {
                return Ok(None);
            };
            let r = kabsch(&first, &target);
            let err = (0..3)
                .map(|j| {
                    let (y, t) = (r * first[j], target[j]);
                    ((y.x - t.x).powi(2) + (y.y - t.y).powi(2)).sqrt() / scale
                })
                .fold(0.0, f64::max);
            *slot = (r, err);
        }
        frames.push(pair);
    }
    Ok(Some((first, frames)))
}

/// All structure-and-motion solutions behind one feasible edge solution: in each frame the
/// depth differences are ±√(e² − eᵢ²) with the sign pattern of the relation that holds, and
/// the whole pattern may flip (a reflection of that frame's triangle through the image plane).
/// A planar triangle can be rotated onto its mirror image, so every combination of flips is a
/// rigid motion: 2^k solutions, 2^(k−1) up to the global mirror reversal. Listed one by one
/// for at most [`MAX_LISTED_FRAMES`] frames (an error beyond: use [`motion_summary`]).
pub fn reconstructions(tracks: &Tracks, squares: &[f64; 3]) -> Result<Vec<Reconstruction>> {
    let k = tracks.frames.len();
    if k > MAX_LISTED_FRAMES {
        return Err(Error::InvalidInput(format!(
            "{k} frames: listing all 2^{} depth-sign patterns is refused beyond {MAX_LISTED_FRAMES} frames",
            k - 1
        )));
    }
    let Some((first, frames)) = per_frame(tracks, squares)? else {
        return Ok(Vec::new());
    };
    Ok((0..1usize << (k - 1))
        .map(|mask| {
            let mut signs = vec![1i8];
            let mut rotations = vec![Rotation3::identity()];
            let mut err: f64 = 0.0;
            for (i, pair) in frames.iter().enumerate() {
                let b = mask >> i & 1;
                signs.push(if b == 1 { -1 } else { 1 });
                rotations.push(pair[b].0);
                err = err.max(pair[b].1);
            }
            Reconstruction {
                points: first,
                rotations,
                depth_signs: signs,
                reprojection_error: err,
            }
        })
        .collect())
}

/// The structure-and-motion solutions behind one edge solution, counted without listing them.
#[derive(Clone, Debug, PartialEq)]
pub struct MotionSummary {
    /// The pattern of least reprojection error (each frame's better sign).
    pub best: Reconstruction,
    /// Patterns whose every frame reprojects within `threshold`: the product over frames of
    /// the signs that do (0, 1 or 2 each), i.e. 0 or a power of two up to 2^(k−1).
    pub reprojecting: u64,
}

/// [`reconstructions`] in closed form: linear in the frames, for up to [`MAX_COUNTED_FRAMES`].
pub fn motion_summary(
    tracks: &Tracks,
    squares: &[f64; 3],
    threshold: f64,
) -> Result<Option<MotionSummary>> {
    let k = tracks.frames.len();
    if k > MAX_COUNTED_FRAMES {
        return Err(Error::InvalidInput(format!(
            "{k} frames of three points: their 2^{} structure-and-motion solutions are counted for at most {MAX_COUNTED_FRAMES} frames",
            k - 1
        )));
    }
    let Some((first, frames)) = per_frame(tracks, squares)? else {
        return Ok(None);
    };
    let mut signs = vec![1i8];
    let mut rotations = vec![Rotation3::identity()];
    let mut err: f64 = 0.0;
    let mut count: u64 = 1;
    for pair in &frames {
        let b = usize::from(pair[1].1 < pair[0].1);
        signs.push(if b == 1 { -1 } else { 1 });
        rotations.push(pair[b].0);
        err = err.max(pair[b].1);
        // at most 63 doublings (k ≤ 64): no overflow
        count *= pair.iter().filter(|(_, e)| *e <= threshold).count() as u64;
    }
    Ok(Some(MotionSummary {
        best: Reconstruction {
            points: first,
            rotations,
            depth_signs: signs,
            reprojection_error: err,
        },
        reprojecting: count,
    }))
}

/// The proper rotation that best maps `from` onto `to` (shared Procrustes kernel).
pub(crate) use crate::algebra::kabsch;

/// Real solutions (a², b², c²) of three frames given as flat image coordinates
/// `[x, y]` of P, Q, R per frame (18 numbers), ordered by c².
pub fn real_solutions_from_coordinates(coords: &[f64]) -> Vec<[f64; 3]> {
    let (s, n) = real_solutions_at(coords);
    s[..n].to_vec()
}

/// [`real_solutions_from_coordinates`] without allocating: the solutions and their number.
pub fn real_solutions_at(coords: &[f64]) -> ([[f64; 3]; 2], usize) {
    // PQ, QR, RP of each frame, as `model::squared_lengths` computes them
    let l: [[f64; 3]; 3] = std::array::from_fn(|i| {
        let p = |j: usize| [coords[6 * i + 2 * j], coords[6 * i + 2 * j + 1]];
        [(0, 1), (1, 2), (2, 0)].map(|(a, b)| {
            let (a, b) = (p(a), p(b));
            (a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)
        })
    });
    let core = solve_core(&l);
    let mut out = [[0.0; 3]; 2];
    let mut n = 0;
    for k in (0..core.count).filter(|&k| core.imag[k].iter().all(|v| *v == 0.0)) {
        out[n] = core.squares[k];
        n += 1;
    }
    // the stable sort by c² of two
    if n == 2 && out[0][2].total_cmp(&out[1][2]).is_gt() {
        out.swap(0, 1);
    }
    (out, n)
}

/// Pair each target with a distinct solution, minimising the largest component difference;
/// `None` when there are fewer solutions than targets (at most two of each here).
pub fn match_solutions(solutions: &[[f64; 3]], targets: &[[f64; 3]]) -> Option<Vec<[f64; 3]>> {
    match_solutions_at(solutions, targets).map(|(m, n)| m[..n].to_vec())
}

/// [`match_solutions`] without allocating: the paired solutions and their number.
pub fn match_solutions_at(
    solutions: &[[f64; 3]],
    targets: &[[f64; 3]],
) -> Option<([[f64; 3]; 2], usize)> {
    let dist = |a: &[f64; 3], b: &[f64; 3]| (0..3).map(|i| (a[i] - b[i]).abs()).fold(0.0, f64::max);
    match (solutions.len(), targets.len()) {
        (_, 0) => Some(([[0.0; 3]; 2], 0)),
        (n, 1) if n >= 1 => solutions
            .iter()
            .min_by(|a, b| dist(a, &targets[0]).total_cmp(&dist(b, &targets[0])))
            .map(|s| ([*s, [0.0; 3]], 1)),
        (2, 2) => {
            let straight = dist(&solutions[0], &targets[0]).max(dist(&solutions[1], &targets[1]));
            let crossed = dist(&solutions[1], &targets[0]).max(dist(&solutions[0], &targets[1]));
            Some(if straight <= crossed {
                ([solutions[0], solutions[1]], 2)
            } else {
                ([solutions[1], solutions[0]], 2)
            })
        }
        _ => None,
    }
}

/// First-order bound on the absolute error of a solution `v` = (a², b², c²) caused by
/// rounding: ‖J⁻¹‖∞ · max_i 64ε·Tᵢ, where J = ∂Fᵢ/∂v and Tᵢ sums the absolute values of
/// the terms of Fᵢ. Infinite where J is singular (a double root).
pub fn forward_error_bound(l: &[[f64; 3]; 3], v: &[f64; 3]) -> f64 {
    let [x, y, z] = *v;
    let mut j = Matrix3::zeros();
    let mut worst: f64 = 0.0;
    for (i, li) in l.iter().enumerate() {
        let f = FrameCoefficients::new(*li);
        j[(i, 0)] = 2.0 * (x - y - z + f.alpha);
        j[(i, 1)] = 2.0 * (y - x - z + f.beta);
        j[(i, 2)] = 2.0 * (z - x - y + f.gamma);
        worst = worst.max(crate::algebra::NEGLIGIBLE_ULPS * f64::EPSILON * f.terms(x, y, z));
    }
    match j.try_inverse() {
        Some(inv) => {
            let norm = (0..3)
                .map(|r| (0..3).map(|c| inv[(r, c)].abs()).sum::<f64>())
                .fold(0.0, f64::max);
            norm * worst
        }
        None => f64::INFINITY,
    }
}
