//! §3: three points, four or more frames — the linear solver.
//!
//! Subtracting frame 1's twofold-squared equation from frame i's (i = 2, 3, 4, …) leaves
//! 2(αᵢ − α₁)a² + 2(βᵢ − β₁)b² + 2(γᵢ − γ₁)c² = −(Kᵢ − K₁), linear in (a², b², c²).
//! Four frames give a square system; more frames are solved by least squares.

use nalgebra::{DMatrix, DVector, Matrix3, Rotation3, Vector2, Vector3};

use super::solver::{feasibility, Degenerate, Solution, SolverOutput, SquaredLengths};
use super::twofold::FrameCoefficients;
use crate::algebra::{svd_rank_above, NEGLIGIBLE_ULPS};
use crate::error::{Error, Result};

/// Four frames of projected squared lengths (PQ, QR, RP) → (a², b², c²) and whether it is
/// feasible; `None` when the 3×3 system is singular.
///
/// # Example
/// ```
/// use orthocheck::derivations::{p3f4::solve_core, solver::SquaredLengths};
/// use orthocheck::model::Scene;
/// let scene = Scene::random(3, 4, 9);
/// let l = SquaredLengths::from_tracks(&scene.tracks());
/// let (x, feasible) = solve_core(&[0, 1, 2, 3].map(|i| [l.frames[i][0], l.frames[i][1], l.frames[i][2]])).unwrap();
/// approx::assert_relative_eq!(x[0], scene.body.squared_distance(0, 1), max_relative = 1e-9);
/// assert!(feasible);
/// ```
pub fn solve_core(l: &[[f64; 3]; 4]) -> Option<([f64; 3], bool)> {
    let f1 = FrameCoefficients::new(l[0]);
    let mut m = Matrix3::zeros();
    let mut rhs = Vector3::zeros();
    for i in 1..4 {
        let (d, k) = FrameCoefficients::new(l[i]).difference(&f1);
        for c in 0..3 {
            m[(i - 1, c)] = d[c];
        }
        rhs[i - 1] = -k;
    }
    let x = m.lu().solve(&rhs)?;
    let x = [x[0], x[1], x[2]];
    let feasible = (0..3).all(|e| x[e] >= 0.0 && l.iter().all(|f| x[e] >= f[e]));
    Some((x, feasible))
}

/// The linear system, one row per later frame, with bounds on the Frobenius norm of the
/// rounding error of its matrix and of its right-hand side.
struct System {
    m: DMatrix<f64>,
    rhs: DVector<f64>,
    noise_m: f64,
    noise_rhs: f64,
}

fn system(input: &SquaredLengths) -> System {
    let tri = |i: usize| [input.frames[i][0], input.frames[i][1], input.frames[i][2]];
    let f1 = FrameCoefficients::new(tri(0));
    let n = input.frames.len() - 1;
    let mut m = DMatrix::zeros(n, 3);
    let mut rhs = DVector::zeros(n);
    let (mut noise_m, mut noise_rhs) = (0.0, 0.0);
    let u = NEGLIGIBLE_ULPS * f64::EPSILON;
    for i in 1..=n {
        let fi = FrameCoefficients::new(tri(i));
        // entries 2(αᵢ − α₁) come from terms bounded by the frames' scales, Kᵢ − K₁ by squares
        noise_m += 3.0 * (u * 2.0 * (fi.scale + f1.scale)).powi(2);
        noise_rhs += (u * 2.0 * (fi.scale.powi(2) + f1.scale.powi(2))).powi(2);
        let (d, k) = fi.difference(&f1);
        for c in 0..3 {
            m[(i - 1, c)] = d[c];
        }
        rhs[i - 1] = -k;
    }
    System {
        m,
        rhs,
        noise_m: noise_m.sqrt(),
        noise_rhs: noise_rhs.sqrt(),
    }
}

/// The p3f4 solver in the shared calling convention: three points, four or more frames.
pub fn solve(input: &SquaredLengths) -> Result<SolverOutput> {
    if input.names.len() != 3 || input.frames.len() < 4 {
        return Err(Error::InvalidInput(format!(
            "p3f4 needs 3 points in at least 4 frames, got {} points in {} frames",
            input.names.len(),
            input.frames.len()
        )));
    }
    let sys = system(input);
    let rank = svd_rank_above(&sys.m, sys.noise_m);
    let mut out = SolverOutput {
        method: "p3f4".into(),
        edges: input.edge_names(),
        solutions: Vec::new(),
        degenerate: None,
        condition: rank.condition,
    };
    if rank.rank < 3 {
        out.degenerate = Some(Degenerate::SpecialMotion {
            rank: rank.rank,
            unknowns: 3,
        });
        return Ok(out);
    }
    // Least squares by Householder QR (rank 3 is established): backward stable, and more
    // accurate here than nalgebra's SVD solve, which lost ~1e-10 on well-conditioned systems.
    let qr = sys.m.clone().qr();
    let qtb = qr.q().transpose() * &sys.rhs;
    let x = qr
        .r()
        .solve_upper_triangular(&qtb)
        .ok_or_else(|| Error::Numerical("singular triangular factor".into()))?;
    let squares = vec![x[0], x[1], x[2]];
    let r = &sys.m * &x - &sys.rhs;
    let scale = squares
        .iter()
        .fold(f64::MIN_POSITIVE, |a, b| a.max(b.abs()));
    let smin = rank.singular_values.last().copied().unwrap_or(0.0);
    out.solutions.push(Solution {
        feasibility: feasibility(&squares, &[0.0; 3], input),
        residual: r.amax() / (scale * scale),
        error_bound: Some((sys.noise_m * x.norm() + sys.noise_rhs) / smin),
        imaginary: vec![0.0; 3],
        squared_edges: squares,
    });
    Ok(out)
}

/// Uniqueness over seeded generic scenes, and the special motions.
#[derive(Clone, Debug, serde::Serialize)]
pub struct Census {
    /// Scenes solved.
    pub trials: usize,
    /// Frames per scene.
    pub frames: usize,
    /// Seed.
    pub seed: u64,
    /// Scenes with a unique (rank-3) solution.
    pub unique: usize,
    /// Scenes whose unique solution is the truth within its rounding error bound.
    pub truth_found: usize,
    /// Largest relative error against the truth.
    pub max_truth_error: f64,
    /// Median condition number of the linear system.
    pub median_condition: f64,
    /// Rank for rotations about the viewing axis only.
    pub viewing_axis_rank: usize,
    /// Rank for rotations about one fixed, generic axis.
    pub fixed_axis_rank: usize,
}

/// Solve `trials` seeded random scenes with `frames` frames, plus two special motions.
pub fn census(trials: usize, frames: usize, seed: u64) -> Census {
    use crate::model::{Motion, Scene};
    use nalgebra::Unit;
    let mut c = Census {
        trials,
        frames,
        seed,
        unique: 0,
        truth_found: 0,
        max_truth_error: 0.0,
        median_condition: 0.0,
        viewing_axis_rank: 0,
        fixed_axis_rank: 0,
    };
    let mut conds = Vec::new();
    for t in 0..trials {
        let scene = Scene::random(3, frames, seed.wrapping_add(t as u64));
        let Ok(out) = solve(&SquaredLengths::from_tracks(&scene.tracks())) else {
            continue;
        };
        if let Some(s) = out.solutions.first() {
            c.unique += 1;
            let truth = [(0, 1), (1, 2), (2, 0)].map(|(i, j)| scene.body.squared_distance(i, j));
            let abs = (0..3)
                .map(|e| (s.squared_edges[e] - truth[e]).abs())
                .fold(0.0, f64::max);
            if abs <= s.error_bound.unwrap_or(0.0) {
                c.truth_found += 1;
            }
            let scale = truth.iter().fold(0.0_f64, |a, b| a.max(*b));
            c.max_truth_error = c.max_truth_error.max(abs / scale);
        }
        conds.extend(out.condition);
    }
    conds.sort_by(f64::total_cmp);
    c.median_condition = conds.get(conds.len() / 2).copied().unwrap_or(f64::INFINITY);
    let rank_for = |axis: Unit<nalgebra::Vector3<f64>>| {
        let mut scene = Scene::random(3, frames, seed);
        for i in 1..frames {
            scene.motions[i] = Motion {
                rotation: Rotation3::from_axis_angle(&axis, 0.4 * i as f64),
                translation: Vector2::zeros(),
            };
        }
        let l = SquaredLengths::from_tracks(&scene.tracks());
        let sys = system(&l);
        crate::algebra::svd_rank_above(&sys.m, sys.noise_m).rank
    };
    c.viewing_axis_rank = rank_for(nalgebra::Vector3::z_axis());
    c.fixed_axis_rank = rank_for(Unit::new_normalize(nalgebra::Vector3::new(0.3, -0.8, 0.5)));
    c
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::{Motion, Scene};
    use nalgebra::{Rotation3, Vector2, Vector3 as V3};

    #[test]
    fn least_squares_with_many_frames_is_exact_on_exact_data() {
        let scene = Scene::random(3, 7, 13);
        let out = solve(&SquaredLengths::from_tracks(&scene.tracks())).unwrap();
        let s = &out.solutions[0];
        assert!(s.feasibility.is_feasible());
        approx::assert_relative_eq!(
            s.squared_edges[2],
            scene.body.squared_distance(2, 0),
            max_relative = 1e-9
        );
        assert!(out.condition.is_some());
    }

    #[test]
    fn rotation_about_the_viewing_axis_only_is_too_special() {
        let mut scene = Scene::random(3, 4, 5);
        for i in 1..4 {
            scene.motions[i] = Motion {
                rotation: Rotation3::from_axis_angle(&V3::z_axis(), 0.3 * i as f64),
                translation: Vector2::zeros(),
            };
        }
        let out = solve(&SquaredLengths::from_tracks(&scene.tracks())).unwrap();
        assert!(matches!(
            out.degenerate,
            Some(Degenerate::SpecialMotion { rank: 0, .. })
        ));
        assert!(out.solutions.is_empty());
    }
}
