//! §5.2–5.3 over seeded random scenes: the paper's four-point test, the equal-scale epipolar
//! check, five points, and the controls (wrong assignments, a point moved off the rigid body)
//! that the same tests must reject.

use nalgebra::Vector2;

use crate::algebra::{permutations, sqrt_rounding};
use crate::derivations::identity::{epipolar_residual, paper_tests, rank_quadruples, smallest_c};
use crate::derivations::identity5::line_distance;
use crate::model::{image_size, Scene};

/// The rounding level of the paper's distance, relative to the image size: three depths
/// √(e² − eᵢ²) enter it, each with the absolute error √(64ε)·e of a square root of a
/// cancelling difference.
pub fn distance_level() -> f64 {
    3.0 * sqrt_rounding()
}

/// The paper's distance for one assignment at one c: the smaller over the signs of b and of
/// frame 2's depths (the paper's rule), relative to `size`; infinite when no b is real.
pub fn paper_distance(f1: &[Vector2<f64>; 4], f2: &[Vector2<f64>; 4], c: f64, size: f64) -> f64 {
    paper_tests(f1, f2, c)
        .iter()
        .map(|t| t.distance / size)
        .fold(f64::INFINITY, f64::min)
}

/// What the census found.
#[derive(Clone, Debug, Default)]
pub struct IdentityCensus {
    /// Scenes with an admissible c.
    pub tested: usize,
    /// Largest distance (relative) of T₂ from its line, true assignment, every c tried.
    pub true_max: f64,
    /// Smallest distance (relative) of the best wrong assignment, over the scenes.
    pub wrong_min: f64,
    /// Scenes where T₂ moved off the rigid body (by `shift` of the image size) still came
    /// out on its line (should be none).
    pub nonrigid_accepted: usize,
    /// Scenes where the true assignment ranks first by the paper's distance.
    pub paper_first: usize,
    /// … by the epipolar residual.
    pub epi_first: usize,
    /// … where both tests name the same first assignment.
    pub same_first: usize,
    /// The epipolar residual of the runner-up, per scene, sorted.
    pub runner_up: Vec<f64>,
    /// Lines of wrong assignments at larger c found again at the smallest c / all of them.
    pub lines_found_again: (usize, usize),
    /// Wrong assignments whose smallest distance changed with c / tried.
    pub min_changed: (usize, usize),
    /// Five points: scenes where the true assignment ranks first of 120.
    pub five_first: usize,
    /// Five points: largest distance of S₂ from its line for the true assignment.
    pub five_true_max: f64,
    /// Five points: smallest distance of the best wrong assignment.
    pub five_wrong_min: f64,
    /// Five points: scenes where S₂ moved off the body still came out on its line.
    pub five_nonrigid_accepted: usize,
}

/// Lines of wrong assignments at other c matched to the smallest c (as sets: the roots of b
/// swap places as c moves); returns (found, total).
fn lines_again(
    f1: &[Vector2<f64>; 4],
    g: &[Vector2<f64>; 4],
    cg: f64,
    factors: &[f64],
) -> (usize, usize) {
    let runs: Vec<Vec<_>> = factors.iter().map(|k| paper_tests(f1, g, cg * k)).collect();
    let level = distance_level();
    let (mut found, mut total) = (0, 0);
    for other in runs.iter().skip(1) {
        for w in other {
            let d = runs[0]
                .iter()
                .map(|v| {
                    (v.distance - w.distance).abs()
                        / v.distance.max(w.distance).max(f64::MIN_POSITIVE)
                })
                .fold(f64::INFINITY, f64::min);
            if d.is_finite() {
                total += 1;
                found += usize::from(d <= level);
            }
        }
    }
    (found, total)
}

/// The seeded census: `trials` random bodies of five points in two frames (seed + k), c at
/// `factors` × its smallest admissible value, and the control shift `shift` (relative to the
/// image size) of T₂ and S₂ off the body.
pub fn census(trials: usize, seed: u64, factors: &[f64], shift: f64) -> IdentityCensus {
    let mut out = IdentityCensus {
        wrong_min: f64::INFINITY,
        five_wrong_min: f64::INFINITY,
        ..Default::default()
    };
    let level = distance_level();
    let truth4 = vec![0, 1, 2, 3];
    for t in 0..trials {
        let tr = Scene::random(5, 2, seed.wrapping_add(t as u64)).tracks();
        let f1: [Vector2<f64>; 4] = std::array::from_fn(|i| tr.frames[0][i]);
        let f2: [Vector2<f64>; 4] = std::array::from_fn(|i| tr.frames[1][i]);
        let s = image_size(&tr.frames[1]);
        let Some(c0) = smallest_c(&f1, &f2) else {
            continue;
        };
        out.tested += 1;
        for &k in factors {
            out.true_max = out.true_max.max(paper_distance(&f1, &f2, c0 * k, s));
        }
        // the control: T₂ moved across the image by `shift` of its size
        let mut moved = f2;
        moved[3] += Vector2::new(shift * s, shift * s) / std::f64::consts::SQRT_2;
        out.nonrigid_accepted += usize::from(paper_distance(&f1, &moved, c0, s) <= level);
        let factor0 = factors.first().copied().unwrap_or(1.0);
        let paper = rank_quadruples(&f1[..], &f2[..], |a, g| {
            smallest_c(a, g).map_or(f64::INFINITY, |c| paper_distance(a, g, c * factor0, s))
        });
        let epi = rank_quadruples(&f1[..], &f2[..], |a, g| epipolar_residual(a, g));
        out.paper_first += usize::from(paper[0].frame2_indices == truth4);
        out.epi_first += usize::from(epi[0].frame2_indices == truth4);
        out.same_first += usize::from(paper[0].frame2_indices == epi[0].frame2_indices);
        out.runner_up.push(epi.get(1).map_or(0.0, |x| x.residual));
        if let Some(w) = paper.iter().find(|a| a.frame2_indices != truth4) {
            out.wrong_min = out.wrong_min.min(w.residual);
        }
        for a in paper.iter().skip(1).take(5) {
            let g: [Vector2<f64>; 4] = std::array::from_fn(|i| f2[a.frame2_indices[i]]);
            let Some(cg) = smallest_c(&f1, &g) else {
                continue;
            };
            let (f, n) = lines_again(&f1, &g, cg, factors);
            out.lines_found_again.0 += f;
            out.lines_found_again.1 += n;
            let mins: Vec<f64> = factors
                .iter()
                .map(|k| paper_distance(&f1, &g, cg * k, s))
                .collect();
            let changed = mins
                .iter()
                .any(|m| (m - mins[0]).abs() > level * m.abs().max(mins[0].abs()));
            out.min_changed.0 += usize::from(changed);
            out.min_changed.1 += 1;
        }
        five(&tr.frames[0], &tr.frames[1], s, shift, &mut out);
    }
    out.runner_up.sort_by(f64::total_cmp);
    out
}

fn five(f1: &[Vector2<f64>], f2: &[Vector2<f64>], s: f64, shift: f64, out: &mut IdentityCensus) {
    let level = distance_level();
    let g1: [Vector2<f64>; 5] = std::array::from_fn(|i| f1[i]);
    let mut best = (f64::INFINITY, Vec::new());
    let mut wrong = f64::INFINITY;
    let truth: Vec<usize> = (0..5).collect();
    for perm in permutations(5) {
        let g2: [Vector2<f64>; 5] = std::array::from_fn(|i| f2[perm[i]]);
        let d = line_distance(&g1, &g2).unwrap_or(f64::INFINITY) / s;
        if perm == truth {
            out.five_true_max = out.five_true_max.max(d);
            let mut moved = g2;
            moved[4] += Vector2::new(shift * s, shift * s) / std::f64::consts::SQRT_2;
            let dm = line_distance(&g1, &moved).unwrap_or(f64::INFINITY) / s;
            out.five_nonrigid_accepted += usize::from(dm <= level);
        } else {
            wrong = wrong.min(d);
        }
        if d < best.0 {
            best = (d, perm);
        }
    }
    out.five_wrong_min = out.five_wrong_min.min(wrong);
    out.five_first += usize::from(best.1 == truth);
}
