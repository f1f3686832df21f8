//! §4's example: the edge table's consistency, the body behind it projected into the
//! figure's rounding box, the printed solution against the printed matrix, and the
//! conditioning of the paper's system at the paper's own scene.

use nalgebra::{DMatrix, Rotation3, Vector2, Vector3};
use num_rational::BigRational;
use num_traits::ToPrimitive;

use crate::algebra::{complete_rotation, exact_solve, svd_rank, NEGLIGIBLE_ULPS};
use crate::derivations::noise::{run_level, stream, LevelResult, Study, StudySolver};
use crate::derivations::p4f3::{
    first_order_spread, fit, paper_system, realize, view_residual, Realization,
};
use crate::model::{Body, Motion, NoiseModel, Tracks};
use crate::studies::rounding::{acceptance, reproduce, Acceptance, RoundingBox, Witness};

/// The interval of true squares both a printed length (± `hl`) and its printed square (± `hs`)
/// allow: `(lo, hi)`, empty when lo > hi.
pub fn common_square(length: f64, hl: f64, square: f64, hs: f64) -> (f64, f64) {
    (
        (length - hl).powi(2).max(square - hs),
        (length + hl).powi(2).min(square + hs),
    )
}

fn frames_of(x: &[f64], points: usize) -> Vec<Vec<[f64; 2]>> {
    (0..x.len() / (2 * points))
        .map(|f| {
            (0..points)
                .map(|j| [x[2 * (points * f + j)], x[2 * (points * f + j) + 1]])
                .collect()
        })
        .collect()
}

/// The rounding unit of the view residuals of `body`: the affine camera solves a 3×3 system
/// in XXᵀ, so its error is at most about κ(XXᵀ) · 64ε · (body size) (condition × unit
/// roundoff × size). It depends on the body only: a search computes it once.
fn view_unit(body: &[Vector3<f64>]) -> Option<f64> {
    let p = body.len();
    let centre = body.iter().sum::<Vector3<f64>>() / p as f64;
    let xxt: nalgebra::Matrix3<f64> = body
        .iter()
        .map(|v| (v - centre) * (v - centre).transpose())
        .sum();
    let cond = svd_rank(&DMatrix::from_fn(3, 3, |i, j| xxt[(i, j)])).condition?;
    let size = body.iter().map(|v| (v - centre).norm()).fold(1.0, f64::max);
    Some(cond * NEGLIGIBLE_ULPS * f64::EPSILON * size)
}

/// The view residuals of `body` at flat coordinates `x`, in units of their rounding `unit`
/// ([`view_unit`]).
fn scaled_views(x: &[f64], body: &[Vector3<f64>], unit: f64) -> Option<Vec<f64>> {
    let r: Vec<f64> = frames_of(x, body.len())
        .iter()
        .flat_map(|f| view_residual(body, f))
        .map(|v| v / unit)
        .collect();
    r.iter().all(|v| v.is_finite()).then_some(r)
}

/// A point of the box where the views of `body` are exact to their rounding.
fn views_witness(figure_box: &RoundingBox, body: &[Vector3<f64>]) -> Option<Witness> {
    let unit = view_unit(body)?;
    reproduce(figure_box, &|x| scaled_views(x, body, unit))
}

/// The body of the table projected into the figure's box, and how far each square may move.
#[derive(Clone, Debug)]
pub struct FigureFit {
    /// The body realized from the printed squares.
    pub realization: Realization,
    /// Largest view residual at the printed coordinates (absolute).
    pub misfit_at_printed: f64,
    /// A point of the box where the body's views are exact (to their rounding).
    pub witness: Option<Witness>,
    /// Per square: the same search for the body with that square moved (in its half units).
    pub acceptance: Vec<Acceptance>,
}

/// Fit the body of `squares` into the box; `half` is each square's half unit.
pub fn figure_fit(figure_box: &RoundingBox, squares: &[f64], half: &[f64]) -> FigureFit {
    let realization = realize(squares, 4);
    let body = realization.points.clone();
    let misfit_at_printed = frames_of(&figure_box.center, 4)
        .iter()
        .flat_map(|f| view_residual(&body, f))
        .fold(0.0, |a: f64, v| a.max(v.abs()));
    let witness = views_witness(figure_box, &body);
    let acceptance = (0..squares.len())
        .map(|e| {
            acceptance(&|shift| {
                let mut moved = squares.to_vec();
                moved[e] += shift * half[e];
                reproduces(figure_box, &moved)
            })
        })
        .collect();
    FigureFit {
        realization,
        misfit_at_printed,
        witness,
        acceptance,
    }
}

/// Whether the body of `squares` exists and the search finds exact views of it inside the
/// box: the test of every acceptance and of a named alternative body.
pub fn reproduces(figure_box: &RoundingBox, squares: &[f64]) -> bool {
    let r = realize(squares, 4);
    r.realizable && views_witness(figure_box, &r.points).is_some()
}

/// The printed solution against the printed matrix.
#[derive(Clone, Debug)]
pub struct SolutionCheck {
    /// Per row, the residual A x + b of the printed x.
    pub residuals: Vec<f64>,
    /// Per row, the bound Σ|xⱼ|δaᵢⱼ + Σ|aᵢⱼ|δxⱼ + δbᵢ from the printed half units.
    pub residual_bounds: Vec<f64>,
    /// The exact solution of the printed matrix over ℚ, as floats.
    pub exact: Option<Vec<f64>>,
    /// Per unknown, |A⁻¹|(|δA||x| + |δb|) + the printed x's half unit.
    pub bounds: Vec<f64>,
    /// Condition number of the printed matrix.
    pub condition: Option<f64>,
}

/// CaseCheck the printed `x` (half units `xh`) against printed rows `a` (exact values `aq`,
/// half units `ah`; the last column is the constant).
pub fn solution_check(
    aq: &[Vec<BigRational>],
    ah: &[[f64; 7]],
    x: &[f64],
    xh: &[f64],
) -> SolutionCheck {
    let a: Vec<Vec<f64>> = aq
        .iter()
        .map(|r| r.iter().map(|q| q.to_f64().unwrap_or(0.0)).collect())
        .collect();
    let residuals = a
        .iter()
        .map(|r| (0..6).map(|j| r[j] * x[j]).sum::<f64>() + r[6])
        .collect();
    let residual_bounds = a
        .iter()
        .zip(ah)
        .map(|(r, h)| {
            (0..6)
                .map(|j| x[j].abs() * h[j] + r[j].abs() * xh[j])
                .sum::<f64>()
                + h[6]
        })
        .collect();
    let lhs: Vec<Vec<BigRational>> = aq.iter().map(|r| r[..6].to_vec()).collect();
    let rhs: Vec<BigRational> = aq.iter().map(|r| -r[6].clone()).collect();
    let exact =
        exact_solve(&lhs, &rhs).map(|v| v.iter().map(|q| q.to_f64().unwrap_or(0.0)).collect());
    let af = DMatrix::from_fn(6, 6, |i, j| a[i][j]);
    // first-order bound of the solution's change over the matrix's rounding
    let db: Vec<f64> = ah
        .iter()
        .map(|h| h[6] + (0..6).map(|j| h[j] * x[j].abs()).sum::<f64>())
        .collect();
    let bounds = match af.clone().try_inverse() {
        Some(inv) => (0..6)
            .map(|i| (0..6).map(|k| inv[(i, k)].abs() * db[k]).sum::<f64>() + xh[i])
            .collect(),
        None => vec![f64::INFINITY; 6],
    };
    SolutionCheck {
        residuals,
        residual_bounds,
        exact,
        bounds,
        condition: svd_rank(&af).condition,
    }
}

/// The conditioning of the paper's system at the paper's scene.
#[derive(Clone, Debug)]
pub struct Conditioning {
    /// Condition number of the 6×6 system at the scene.
    pub condition: Option<f64>,
    /// Per level: ε, the first-order relative σ per squared edge, the Monte Carlo result.
    pub levels: Vec<(f64, Option<[f64; 6]>, LevelResult)>,
    /// The same first-order σ for the measured projected squares of frame 1 (the control:
    /// a quantity read directly off the image, not through the solve), relative to ε.
    pub direct_amplification: f64,
}

/// The scene: the body and each frame's camera fitted to the exact views at `point`.
pub fn conditioning(
    point: &[f64],
    squares: &[f64],
    levels: &[f64],
    trials: usize,
    seed: u64,
) -> Conditioning {
    let fr = frames_of(point, 4);
    let tracks = Tracks {
        names: crate::model::default_names(4),
        frames: fr
            .iter()
            .map(|f| f.iter().map(|c| Vector2::new(c[0], c[1])).collect())
            .collect(),
    };
    let fitted = fit(&tracks, squares);
    let motions: Vec<Motion> = fitted
        .cameras
        .iter()
        .map(|c| Motion {
            rotation: Rotation3::from_matrix_unchecked(complete_rotation(c)),
            translation: Vector2::zeros(),
        })
        .collect();
    let scene_frames: Vec<Vec<[f64; 2]>> = motions
        .iter()
        .map(|m| {
            let o = m.project(&fitted.points[0]);
            fitted
                .points
                .iter()
                .map(|x| {
                    let y = m.project(x) - o;
                    [y.x, y.y]
                })
                .collect()
        })
        .collect();
    let l: [[f64; 6]; 3] = std::array::from_fn(|f| {
        let s = crate::model::squared_lengths(&scene_frames[f]);
        std::array::from_fn(|e| s[e])
    });
    let (a, _) = paper_system(&l);
    let condition = svd_rank(&DMatrix::from_fn(6, 6, |i, j| a[(i, j)])).condition;
    let study = Study {
        solver: StudySolver::P4f3,
        body: Body::new(fitted.points.clone()),
        frames: 3,
        trials,
        seed,
        motions: Some(motions),
    };
    let levels = levels
        .iter()
        .enumerate()
        .map(|(i, &eps)| {
            let mut res = run_level(
                &study,
                NoiseModel::RelativeCoordinate { eps },
                stream(i, 0),
                &|_| {},
            );
            res.model = format!("{} at the paper's scene", res.model);
            (eps, first_order_spread(&scene_frames, eps), res)
        })
        .collect();
    Conditioning {
        condition,
        levels,
        direct_amplification: direct_amplification(&scene_frames[0]),
    }
}

/// First-order relative σ of each projected square of one frame under c → c(1 + uε), u
/// uniform in [−1, 1], divided by ε; the largest over the edges.
fn direct_amplification(frame: &[[f64; 2]]) -> f64 {
    let flat: Vec<f64> = frame.iter().flatten().copied().collect();
    let f = |c: &[f64]| {
        let pts: Vec<[f64; 2]> = c.chunks(2).map(|p| [p[0], p[1]]).collect();
        Some(crate::model::squared_lengths(&pts))
    };
    let Some(j) = crate::algebra::central_jacobian(&f, &flat, |_, c| 1e-6 * c.abs()) else {
        return f64::INFINITY;
    };
    let l = f(&flat).unwrap_or_default();
    (0..l.len())
        .map(|e| {
            ((0..flat.len())
                .map(|k| (j[(e, k)] * flat[k]).powi(2))
                .sum::<f64>()
                / 3.0)
                .sqrt()
                / l[e]
        })
        .fold(0.0, f64::max)
}
