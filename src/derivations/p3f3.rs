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
use crate::algebra::{negligible, quadratic};
use crate::error::{Error, Result};
use crate::model::Tracks;

/// The quadratic form of F: x² + y² + z² − 2xy − 2xz − 2yz.
const M: [[f64; 3]; 3] = [[1.0, -1.0, -1.0], [-1.0, 1.0, -1.0], [-1.0, -1.0, 1.0]];

/// The unknowns as affine functions of the free one, t: v = slope·t + intercept.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Elimination {
    /// Index of the free unknown (2 = c², the paper's choice).
    pub free: usize,
    /// Slopes (A_c, B_c, 1 for the paper's choice).
    pub slope: [f64; 3],
    /// Intercepts (A_Cst, B_Cst, 0).
    pub intercept: [f64; 3],
    /// Quadratic in t: q[0] + q[1] t + q[2] t².
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
/// use orthocheck::derivations::p3f3::solve_core;
/// use orthocheck::derivations::solver::SquaredLengths;
/// use orthocheck::model::Scene;
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
    let mag2: f64 = (0..3)
        .flat_map(|i| (0..3).map(move |j| (i, j)))
        .map(|(i, j)| (elim.slope[i] * elim.slope[j] * M[i][j]).abs())
        .sum();
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
        let r = quadratic(q2, q1, q0);
        roots = [r[0], r[1]];
        core.count = 2;
        if r[0].im != 0.0 {
            core.degenerate = Some(Degenerate::NoRealRoot);
        }
    }
    let max_proj = [0, 1, 2].map(|e| l[0][e].max(l[1][e]).max(l[2][e]));
    for (k, t) in roots.iter().take(core.count).enumerate() {
        for v in 0..3 {
            core.squares[k][v] = elim.slope[v] * t.re + elim.intercept[v];
            core.imag[k][v] = elim.slope[v] * t.im;
        }
        core.feasible[k] = core.imag[k].iter().all(|v| *v == 0.0)
            && (0..3).all(|v| core.squares[k][v] >= 0.0 && core.squares[k][v] >= max_proj[v]);
    }
    core
}

/// Solve the two difference equations for two unknowns in terms of the third, the paper's
/// way (free c²) unless its denominator vanishes; then substitute into F₃.
fn eliminate(f: &[FrameCoefficients; 3], l: &[[f64; 3]; 3], core: &mut Core) -> Option<Elimination> {
    let (d1, k1) = f[0].difference(&f[2]);
    let (d2, k2) = f[1].difference(&f[2]);
    // A difference whose coefficients are rounding noise: two frames with equal lengths.
    let vanishes = |d: &[f64; 3], a: &FrameCoefficients, b: &FrameCoefficients| {
        d.iter().all(|x| negligible(*x, 2.0 * (a.scale + b.scale)))
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
    let pairs = [(0, 1, 2), (0, 2, 1), (1, 2, 0)];
    let usable: Vec<(usize, usize, usize, f64)> = pairs
        .iter()
        .map(|&(u, v, w)| (u, v, w, minor(u, v)))
        .filter(|(_, _, _, (det, mag))| !negligible(*det, *mag))
        .map(|(u, v, w, (det, _))| (u, v, w, det))
        .collect();
    let Some(&(u, v, w, det)) = usable
        .iter()
        .find(|p| p.2 == 2)
        .or_else(|| usable.iter().max_by(|a, b| a.3.abs().total_cmp(&b.3.abs())))
    else {
        core.degenerate = Some(identical_frames(l).unwrap_or(Degenerate::DependentDifferences));
        return None;
    };
    if w != 2 {
        core.degenerate = Some(Degenerate::PaperDenominatorVanishes);
    }
    // d1[u] X + d1[v] Y = −d1[w] t − k1, likewise for d2; Cramer's rule as printed.
    let mut slope = [0.0; 3];
    let mut intercept = [0.0; 3];
    slope[u] = ((-d1[w]) * d2[v] - (-d2[w]) * d1[v]) / det;
    intercept[u] = ((-k1) * d2[v] - (-k2) * d1[v]) / det;
    slope[v] = (d1[u] * (-d2[w]) - d2[u] * (-d1[w])) / det;
    intercept[v] = (d1[u] * (-k2) - d2[u] * (-k1)) / det;
    slope[w] = 1.0;
    // F₃(slope·t + intercept) = sᵀMs t² + (2 sᵀMc + 2(α,β,γ)·s) t + cᵀMc + 2(α,β,γ)·c + K
    let lin = [2.0 * f[2].alpha, 2.0 * f[2].beta, 2.0 * f[2].gamma];
    let form = |a: &[f64; 3], b: &[f64; 3]| -> f64 {
        (0..3)
            .map(|i| (0..3).map(|j| a[i] * M[i][j] * b[j]).sum::<f64>())
            .sum()
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
    let l: [[f64; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|e| input.frames[i][e]));
    let core = solve_core(&l);
    let solutions = (0..core.count)
        .map(|k| Solution {
            squared_edges: core.squares[k].to_vec(),
            imaginary: core.imag[k].to_vec(),
            feasibility: feasibility(&core.squares[k], &core.imag[k], input),
            residual: residual(&l, &core.squares[k], &core.imag[k]),
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

/// All structure-and-motion solutions behind one feasible edge solution: in each frame the
/// depth differences are ±√(e² − eᵢ²) with the sign pattern of the relation that holds, and
/// the whole pattern may flip (a reflection of that frame's triangle through the image plane).
/// A planar triangle can be rotated onto its mirror image, so every combination of flips is a
/// rigid motion: 2^k solutions, 2^(k−1) up to the global mirror reversal.
pub fn reconstructions(tracks: &Tracks, squares: &[f64; 3]) -> Result<Vec<Reconstruction>> {
    if tracks.points() != 3 {
        return Err(Error::InvalidInput("reconstruction needs 3 points".into()));
    }
    let k = tracks.frames.len();
    let scale = squares.iter().fold(0.0_f64, |a, b| a.max(*b)).sqrt();
    // camera-frame coordinates of P, Q, R in frame i for depth sign s
    let camera = |i: usize, s: f64| -> Option<[Vector3<f64>; 3]> {
        let f = &tracks.frames[i];
        let proj = [0, 1, 2].map(|e| {
            let (a, b) = [(0, 1), (1, 2), (2, 0)][e];
            (f[a] - f[b]).norm_squared()
        });
        let roots: Vec<f64> = (0..3).map(|e| (squares[e] - proj[e]).max(0.0).sqrt()).collect();
        // the pattern with the smallest |s_a√A + s_b√B + s_c√C|, up to a global sign
        let patterns = [[1.0, 1.0, -1.0], [1.0, -1.0, 1.0], [-1.0, 1.0, 1.0]];
        let best = patterns.iter().min_by(|p, q| {
            let r = |p: &[f64; 3]| (p[0] * roots[0] + p[1] * roots[1] + p[2] * roots[2]).abs();
            r(p).total_cmp(&r(q))
        })?;
        let zq = s * best[0] * roots[0];
        let zr = zq + s * best[1] * roots[1];
        let o = f[0];
        Some([
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(f[1].x - o.x, f[1].y - o.y, zq),
            Vector3::new(f[2].x - o.x, f[2].y - o.y, zr),
        ])
    };
    let Some(first) = camera(0, 1.0) else {
        return Ok(Vec::new());
    };
    let mut out = Vec::new();
    for mask in 0..(1u32 << (k - 1)) {
        let mut signs = vec![1i8];
        let mut rotations = vec![Rotation3::identity()];
        let mut err: f64 = 0.0;
        for i in 1..k {
            let s = if mask >> (i - 1) & 1 == 1 { -1.0 } else { 1.0 };
            signs.push(s as i8);
            let Some(target) = camera(i, s) else {
                return Ok(Vec::new());
            };
            let r = kabsch(&first, &target);
            for j in 0..3 {
                let y = r * first[j];
                let t = target[j];
                err = err.max(((y.x - t.x).powi(2) + (y.y - t.y).powi(2)).sqrt() / scale);
            }
            rotations.push(r);
        }
        out.push(Reconstruction {
            points: first,
            rotations,
            depth_signs: signs,
            reprojection_error: err,
        });
    }
    Ok(out)
}

/// The proper rotation that best maps `from` onto `to` (both with the first point at the origin).
fn kabsch(from: &[Vector3<f64>; 3], to: &[Vector3<f64>; 3]) -> Rotation3<f64> {
    let h: Matrix3<f64> = (0..3).map(|j| to[j] * from[j].transpose()).sum();
    let svd = h.svd(true, true);
    let (Some(u), Some(vt)) = (svd.u, svd.v_t) else {
        return Rotation3::identity();
    };
    let d = (u * vt).determinant().signum();
    let fix = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, d));
    Rotation3::from_matrix_unchecked(u * fix * vt)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Body, Motion, Scene};
    use nalgebra::Vector2;

    fn lengths(scene: &Scene) -> SquaredLengths {
        SquaredLengths::from_tracks(&scene.tracks())
    }

    #[test]
    fn recovers_the_truth_and_all_reconstructions_reproject() {
        let scene = Scene::random(3, 3, 21);
        let out = solve(&lengths(&scene)).unwrap();
        let truth = [0, 1, 2].map(|e| {
            let (i, j) = [(0, 1), (1, 2), (2, 0)][e];
            scene.body.squared_distance(i, j)
        });
        let found = out
            .feasible()
            .find(|s| (0..3).all(|e| (s.squared_edges[e] - truth[e]).abs() < 1e-9 * truth[e]))
            .expect("truth among the feasible roots");
        let sq = [found.squared_edges[0], found.squared_edges[1], found.squared_edges[2]];
        let recs = reconstructions(&scene.tracks(), &sq).unwrap();
        assert_eq!(recs.len(), 4);
        assert!(recs.iter().all(|r| r.reprojection_error < 1e-6));
    }

    #[test]
    fn collinear_points_are_a_typed_outcome() {
        let body = Body::new(vec![
            Vector3::new(0.0, 0.0, 0.0),
            Vector3::new(1.0, 2.0, 3.0),
            Vector3::new(2.0, 4.0, 6.0),
        ]);
        let mut scene = Scene::random(3, 3, 2);
        scene.body = body;
        let out = solve(&lengths(&scene)).unwrap();
        assert_eq!(out.degenerate, Some(Degenerate::Collinear));
        assert!(out.solutions.is_empty());
    }

    #[test]
    fn identical_frames_up_to_in_plane_rotation_are_detected() {
        let mut scene = Scene::random(3, 3, 3);
        let r = scene.motions[1].rotation;
        scene.motions[2] = Motion {
            rotation: Rotation3::from_axis_angle(&Vector3::z_axis(), 0.7) * r,
            translation: Vector2::new(0.3, -0.2),
        };
        let out = solve(&lengths(&scene)).unwrap();
        assert!(matches!(
            out.degenerate,
            Some(Degenerate::IdenticalFrames { first: 2, second: 3 })
        ));
        assert!(out.solutions.iter().all(|s| s.squared_edges.iter().all(|v| v.is_finite())));
    }

    #[test]
    fn wrong_counts_are_errors() {
        let l = SquaredLengths::new(crate::model::default_names(3), vec![vec![1.0, 1.0, 1.0]; 4]).unwrap();
        assert!(solve(&l).is_err());
    }
}
