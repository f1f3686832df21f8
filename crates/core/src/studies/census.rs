//! Censuses over seeded random scenes: how many solutions the paper's solvers leave (§2.2,
//! §3, §4), and what their degenerate configurations do.

use nalgebra::{DMatrix, Rotation3, Vector2, Vector3};

use crate::algebra::svd_rank_above;
use crate::derivations::p3f3::{self, forward_error_bound, reconstructions, validate};
use crate::derivations::solver::{edges, Degenerate, Solution, SquaredLengths, REPROJECTION_EXACT};
use crate::derivations::{p3f4, p4f3};
use crate::model::{Body, Motion, Scene};

/// Solution counts over seeded generic scenes (three points, three frames).
#[derive(Clone, Debug, serde::Serialize)]
pub struct P3f3CensusCase {
    /// Scenes solved.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
    /// Scenes with 0, 1, 2 feasible edge solutions.
    pub feasible_counts: [usize; 3],
    /// Scenes whose true squared edges were among the feasible solutions, within the
    /// first-order rounding bound [`forward_error_bound`].
    pub truth_found: usize,
    /// Largest relative error of the true solution's recovery.
    pub max_truth_error: f64,
    /// Structure-and-motion solutions behind one edge solution (depth-sign combinations that
    /// reproject), counted up to the global mirror reversal; the same in every scene checked.
    pub motions_per_edge_solution: Vec<usize>,
    /// Largest relative disagreement of the independent routes ([`validate`]) with the
    /// solver, over the first scenes (at most 200: the exact route is slow).
    pub max_route_disagreement: f64,
    /// Scenes validated, and how many of them every route found the same number of roots.
    pub routes_checked: (usize, usize),
    /// Outcome for a collinear body.
    pub collinear: Option<Degenerate>,
    /// Outcome for two frames identical up to an in-plane rotation.
    pub identical_frames: Option<Degenerate>,
}

/// Solve `trials` seeded random scenes and two degenerate ones.
pub fn p3f3(trials: usize, seed: u64) -> P3f3CensusCase {
    let mut c = P3f3CensusCase {
        trials,
        seed,
        feasible_counts: [0; 3],
        truth_found: 0,
        max_truth_error: 0.0,
        motions_per_edge_solution: Vec::new(),
        max_route_disagreement: 0.0,
        routes_checked: (0, 0),
        collinear: None,
        identical_frames: None,
    };
    for t in 0..trials {
        let scene = Scene::random(3, 3, seed.wrapping_add(t as u64));
        let tracks = scene.tracks();
        let Ok(out) = p3f3::solve(&SquaredLengths::from_tracks(&tracks)) else {
            continue;
        };
        let feasible: Vec<&Solution> = out.feasible().collect();
        c.feasible_counts[feasible.len().min(2)] += 1;
        let truth = [(0, 1), (1, 2), (2, 0)].map(|(i, j)| scene.body.squared_distance(i, j));
        let l: [[f64; 3]; 3] = std::array::from_fn(|i| {
            let f = &SquaredLengths::from_tracks(&tracks).frames[i];
            [f[0], f[1], f[2]]
        });
        let err = |s: &Solution| {
            (0..3)
                .map(|e| (s.squared_edges[e] - truth[e]).abs())
                .fold(0.0, f64::max)
        };
        if let Some(best) = feasible.iter().min_by(|a, b| err(a).total_cmp(&err(b))) {
            let e = err(best);
            // found when the error is within what rounding can explain at this solution
            if e <= forward_error_bound(&l, &truth) {
                c.truth_found += 1;
            }
            let scale = truth.iter().fold(0.0_f64, |a, b| a.max(*b));
            c.max_truth_error = c.max_truth_error.max(e / scale);
        }
        if t < 200 {
            use num_rational::BigRational;
            let exact: [[BigRational; 3]; 3] = std::array::from_fn(|i| {
                std::array::from_fn(|e| BigRational::from_float(l[i][e]).unwrap_or_default())
            });
            let v = validate(&exact);
            c.max_route_disagreement = c.max_route_disagreement.max(v.max_relative_disagreement);
            c.routes_checked.0 += 1;
            c.routes_checked.1 += usize::from(v.same_count);
        }
        if t < 20 {
            for s in &feasible {
                let sq = [s.squared_edges[0], s.squared_edges[1], s.squared_edges[2]];
                let n = reconstructions(&tracks, &sq)
                    .map(|r| {
                        r.iter()
                            .filter(|x| x.reprojection_error < REPROJECTION_EXACT)
                            .count()
                    })
                    .unwrap_or(0);
                if !c.motions_per_edge_solution.contains(&n) {
                    c.motions_per_edge_solution.push(n);
                }
            }
        }
    }
    degenerate_p3f3(&mut c, seed);
    c
}
/// The two degenerate cases §2.2 names: a collinear body, two frames identical up to an
/// in-plane rotation.
fn degenerate_p3f3(c: &mut P3f3CensusCase, seed: u64) {
    let mut collinear = Scene::random(3, 3, seed);
    let d = collinear.body.points[1] - collinear.body.points[0];
    collinear.body = Body::new(vec![
        collinear.body.points[0],
        collinear.body.points[0] + d,
        collinear.body.points[0] + 2.5 * d,
    ]);
    c.collinear = p3f3::solve(&SquaredLengths::from_tracks(&collinear.tracks()))
        .ok()
        .and_then(|o| o.degenerate);
    let mut same = Scene::random(3, 3, seed);
    same.motions[2] = Motion {
        rotation: Rotation3::from_axis_angle(&Vector3::z_axis(), 1.1) * same.motions[1].rotation,
        translation: same.motions[1].translation,
    };
    c.identical_frames = p3f3::solve(&SquaredLengths::from_tracks(&same.tracks()))
        .ok()
        .and_then(|o| o.degenerate);
}

/// Uniqueness over seeded generic scenes, and the special motions.
#[derive(Clone, Debug, serde::Serialize)]
pub struct P3f4CensusCase {
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
pub fn p3f4(trials: usize, frames: usize, seed: u64) -> P3f4CensusCase {
    use nalgebra::Unit;
    let mut c = P3f4CensusCase {
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
        let Ok(out) = p3f4::solve(&SquaredLengths::from_tracks(&scene.tracks())) else {
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
        let sys = p3f4::system(&l);
        crate::algebra::svd_rank_above(&sys.m, sys.noise_m).rank
    };
    c.viewing_axis_rank = rank_for(nalgebra::Vector3::z_axis());
    c.fixed_axis_rank = rank_for(Unit::new_normalize(nalgebra::Vector3::new(0.3, -0.8, 0.5)));
    c
}

/// Uniqueness of the paper's system over seeded generic scenes, and its degenerate cases.
#[derive(Clone, Debug, serde::Serialize)]
pub struct P4f3CensusCase {
    /// Scenes.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
    /// Scenes with a unique feasible, realizable solution.
    pub unique: usize,
    /// Scenes whose solution is the truth within its rounding bound.
    pub truth_found: usize,
    /// Largest relative error against the truth.
    pub max_truth_error: f64,
    /// Median condition number.
    pub median_condition: f64,
    /// Planar bodies tried, and the ranks of the paper's system found for them.
    pub planar_trials: usize,
    /// Distinct ranks of the paper's 6×6 system for planar bodies.
    pub planar_ranks: Vec<usize>,
    /// Distinct ranks of the system over all four triangles for planar bodies.
    pub planar_ranks_all_triangles: Vec<usize>,
    /// The outcome the solver names for planar bodies.
    pub planar_outcome: Option<Degenerate>,
    /// Rank for motions about the viewing axis only.
    pub viewing_axis_rank: usize,
}

/// Solve `trials` seeded generic scenes of four points in three frames, then planar bodies
/// and motions about the viewing axis.
pub fn p4f3(trials: usize, seed: u64) -> P4f3CensusCase {
    let mut c = P4f3CensusCase {
        trials,
        seed,
        unique: 0,
        truth_found: 0,
        max_truth_error: 0.0,
        median_condition: f64::INFINITY,
        planar_trials: 0,
        planar_ranks: Vec::new(),
        planar_ranks_all_triangles: Vec::new(),
        planar_outcome: None,
        viewing_axis_rank: 0,
    };
    let truth = |s: &Scene| -> Vec<f64> {
        edges(4)
            .iter()
            .map(|&(i, j)| s.body.squared_distance(i, j))
            .collect()
    };
    let mut conds = Vec::new();
    for t in 0..trials {
        let scene = Scene::random(4, 3, seed.wrapping_add(t as u64));
        let Ok(out) = p4f3::solve(&SquaredLengths::from_tracks(&scene.tracks())) else {
            continue;
        };
        conds.extend(out.condition);
        let Some(s) = out.solutions.first() else {
            continue;
        };
        if s.feasibility.is_feasible() {
            c.unique += 1;
        }
        let tr = truth(&scene);
        let abs = s
            .squared_edges
            .iter()
            .zip(&tr)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        if abs <= s.error_bound.unwrap_or(0.0) {
            c.truth_found += 1;
        }
        let scale = tr.iter().fold(0.0_f64, |a, b| a.max(*b));
        c.max_truth_error = c.max_truth_error.max(abs / scale);
    }
    conds.sort_by(f64::total_cmp);
    c.median_condition = conds.get(conds.len() / 2).copied().unwrap_or(f64::INFINITY);
    degenerate_p4f3(&mut c, trials, seed);
    c
}

/// Planar bodies (z an affine function of x and y) and motions about the viewing axis.
fn degenerate_p4f3(c: &mut P4f3CensusCase, trials: usize, seed: u64) {
    // planar bodies: z an affine function of x and y
    c.planar_trials = trials.clamp(1, 200);
    for t in 0..c.planar_trials {
        let mut scene = Scene::random(4, 3, seed.wrapping_add(t as u64));
        for x in &mut scene.body.points {
            x.z = 0.4 * x.x - 0.7 * x.y + 0.1;
        }
        let l = SquaredLengths::from_tracks(&scene.tracks());
        let (noise_m, _) = p4f3::noise(&l, 6);
        let lf: [[f64; 6]; 3] = std::array::from_fn(|i| std::array::from_fn(|e| l.frames[i][e]));
        let (a, _) = p4f3::paper_system(&lf);
        let m = DMatrix::from_fn(6, 6, |i, j| a[(i, j)]);
        let r = svd_rank_above(&m, noise_m).rank;
        if !c.planar_ranks.contains(&r) {
            c.planar_ranks.push(r);
        }
        let (g, _) = p4f3::general_system(&l);
        let r = svd_rank_above(&g, noise_m).rank;
        if !c.planar_ranks_all_triangles.contains(&r) {
            c.planar_ranks_all_triangles.push(r);
        }
        if t == 0 {
            c.planar_outcome = p4f3::solve(&l).ok().and_then(|o| o.degenerate);
        }
    }
    let mut turn = Scene::random(4, 3, seed);
    for i in 1..3 {
        turn.motions[i] = Motion {
            rotation: Rotation3::from_axis_angle(&Vector3::z_axis(), 0.6 * i as f64),
            translation: nalgebra::Vector2::new(0.2, -0.1),
        };
    }
    let l = SquaredLengths::from_tracks(&turn.tracks());
    let (noise_m, _) = p4f3::noise(&l, 6);
    let (g, _) = p4f3::general_system(&l);
    c.viewing_axis_rank = svd_rank_above(&g, noise_m).rank;
}
