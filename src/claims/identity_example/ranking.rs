//! §5.2's example ranked: every assignment by the paper's distance and by the epipolar
//! residual, and the true assignment's distances with their rounding bound.

use nalgebra::Vector2;

use super::author_program::Example;
use crate::algebra::permutations4;
use crate::derivations::identity::{paper_tests, smallest_c};
use crate::derivations::rounding::first_order_bound;
use crate::derivations::two_frames::epipolar_with_rounding;
use crate::model::image_size;
use crate::studies::identity::{distance_level, paper_distance};

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
