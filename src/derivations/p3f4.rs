//! §3: three points, four or more frames — the linear solver.
//!
//! Subtracting frame 1's twofold-squared equation from frame i's (i = 2, 3, 4, …) leaves
//! 2(αᵢ − α₁)a² + 2(βᵢ − β₁)b² + 2(γᵢ − γ₁)c² = −(Kᵢ − K₁), linear in (a², b², c²).
//! Four frames give a square system; more frames are solved by least squares.

use nalgebra::{DMatrix, DVector, Matrix3, Vector3};

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

/// The linear system: one row per later frame.
/// Also returns a bound on the Frobenius norm of the rounding error of the matrix entries.
fn system(input: &SquaredLengths) -> (DMatrix<f64>, DVector<f64>, f64) {
    let tri = |i: usize| [input.frames[i][0], input.frames[i][1], input.frames[i][2]];
    let f1 = FrameCoefficients::new(tri(0));
    let n = input.frames.len() - 1;
    let mut m = DMatrix::zeros(n, 3);
    let mut rhs = DVector::zeros(n);
    let mut noise2 = 0.0;
    for i in 1..=n {
        let fi = FrameCoefficients::new(tri(i));
        // each entry 2(αᵢ − α₁) is formed from terms bounded by the two frames' scales
        noise2 += 3.0 * (NEGLIGIBLE_ULPS * f64::EPSILON * 2.0 * (fi.scale + f1.scale)).powi(2);
        let (d, k) = fi.difference(&f1);
        for c in 0..3 {
            m[(i - 1, c)] = d[c];
        }
        rhs[i - 1] = -k;
    }
    (m, rhs, noise2.sqrt())
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
    let (m, rhs, noise) = system(input);
    let rank = svd_rank_above(&m, noise);
    let mut out = SolverOutput {
        method: "p3f4".into(),
        edges: input.edge_names(),
        solutions: Vec::new(),
        degenerate: None,
        condition: rank.condition,
    };
    if rank.rank < 3 {
        out.degenerate = Some(Degenerate::SpecialMotion { rank: rank.rank });
        return Ok(out);
    }
    let x = m
        .clone()
        .svd(true, true)
        .solve(&rhs, rank.tolerance)
        .map_err(|e| Error::Numerical(e.to_string()))?;
    let squares = vec![x[0], x[1], x[2]];
    let r = &m * &x - &rhs;
    let scale = squares.iter().fold(f64::MIN_POSITIVE, |a, b| a.max(b.abs()));
    out.solutions.push(Solution {
        feasibility: feasibility(&squares, &[0.0; 3], input),
        residual: r.amax() / (scale * scale),
        imaginary: vec![0.0; 3],
        squared_edges: squares,
    });
    Ok(out)
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
        approx::assert_relative_eq!(s.squared_edges[2], scene.body.squared_distance(2, 0), max_relative = 1e-9);
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
        assert!(matches!(out.degenerate, Some(Degenerate::SpecialMotion { rank: 0 })));
        assert!(out.solutions.is_empty());
    }
}
