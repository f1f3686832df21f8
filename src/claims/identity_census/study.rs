//! §5.2–5.3 over seeded random scenes, and the ranking of §5.2's example: the paper's
//! four-point test, the equal-scale epipolar check, five points, and the controls (wrong
//! assignments, a point moved off the rigid body) that the same tests must reject.

use nalgebra::Vector2;

use crate::algebra::{permutations, permutations4, sqrt_rounding};
use crate::claims::identity_example::author_program::Example;
use crate::derivations::identity::{epipolar_residual, paper_tests, rank_quadruples, smallest_c};
use crate::derivations::identity5::line_distance;
use crate::derivations::rounding::first_order_bound;
use crate::derivations::two_frames::epipolar_with_rounding;
use crate::model::Scene;

/// The rounding level of the paper's distance, relative to the image size: three depths
/// √(e² − eᵢ²) enter it, each with the absolute error √(64ε)·e of a square root of a
/// cancelling difference.
pub fn distance_level() -> f64 {
    3.0 * sqrt_rounding()
}

/// The image size: the largest distance of a point from the centroid.
pub fn image_size(f: &[Vector2<f64>]) -> f64 {
    let m = f.iter().sum::<Vector2<f64>>() / f.len().max(1) as f64;
    f.iter()
        .map(|p| (p - m).norm())
        .fold(f64::MIN_POSITIVE, f64::max)
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

/// §5.2's example: every assignment ranked by the paper's distance (at its smallest c) and
/// by the epipolar residual; the true assignment's distances with their rounding bound.
#[derive(Clone, Debug)]
pub struct ExampleRanking {
    /// (assignment, paper's distance), best first; `None` when no c is admissible: that
    /// assignment has no real line, so no distance (not an infinite one), and ranks last.
    pub by_paper: Vec<([usize; 4], Option<f64>)>,
    /// (assignment, equal-scale epipolar residual), best first.
    pub by_epipolar: Vec<([usize; 4], f64)>,
    /// The true assignment's distances, one per variant (signs of b and of frame 2's depths).
    pub true_distances: Vec<f64>,
    /// The largest rounding bound of those distances: the first-order effect of the frames'
    /// ±half over the 16 coordinates, plus the floating-point level times the image size.
    pub true_bound: f64,
}

/// Rank §5.2's example at c = `factor` × each assignment's smallest admissible c (away from
/// the bound, where Δ_b = 0 and b is ill-conditioned); `truth` is the assignment the table
/// decides.
pub fn rank_example(ex: &Example, truth: &[usize; 4], factor: f64) -> ExampleRanking {
    let g1 = ex.paper_order(&ex.frame1, truth);
    let size = image_size(&ex.frame2);
    let mut by_paper = Vec::new();
    let mut by_epipolar = Vec::new();
    for asg in permutations4() {
        let g2 = ex.frame2_recentred(&asg);
        let d = smallest_c(&g1, &g2).map(|c| paper_distance(&g1, &g2, c * factor, 1.0));
        by_paper.push((asg, d));
        let e = epipolar_with_rounding(&g1, &g2, ex.coord_half)
            .scale_residual
            .abs();
        by_epipolar.push((asg, e));
    }
    // no line ranks after every distance, as an infinite one did
    by_paper.sort_by(|a, b| match (a.1, b.1) {
        (Some(x), Some(y)) => x.total_cmp(&y),
        (x, y) => x.is_none().cmp(&y.is_none()),
    });
    by_epipolar.sort_by(|a, b| a.1.total_cmp(&b.1));
    let g2 = ex.frame2_recentred(truth);
    let (mut true_distances, mut true_bound) = (Vec::new(), 0.0_f64);
    if let Some(c) = smallest_c(&g1, &g2).map(|c| c * factor) {
        let x: Vec<f64> = g1.iter().chain(&g2).flat_map(|p| [p.x, p.y]).collect();
        let half = vec![ex.coord_half; 16];
        for t in paper_tests(&g1, &g2, c) {
            true_distances.push(t.distance);
            let f = |y: &[f64]| {
                let a: [Vector2<f64>; 4] =
                    std::array::from_fn(|i| Vector2::new(y[2 * i], y[2 * i + 1]));
                let b: [Vector2<f64>; 4] =
                    std::array::from_fn(|i| Vector2::new(y[8 + 2 * i], y[9 + 2 * i]));
                paper_tests(&a, &b, c)
                    .into_iter()
                    .find(|u| u.sign_b == t.sign_b && u.sign_frame2 == t.sign_frame2)
                    .map(|u| vec![u.distance])
            };
            let b = first_order_bound(&f, &x, &half).map_or(f64::INFINITY, |b| b[0]);
            true_bound = true_bound.max(b + distance_level() * size);
        }
    }
    ExampleRanking {
        by_paper,
        by_epipolar,
        true_distances,
        true_bound,
    }
}
