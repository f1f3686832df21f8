//! §2's example under the rounding of its figure: the roots at the printed coordinates, a
//! witness point of the ±half-unit box that reproduces both printed solutions, how far those
//! targets may move before the same search fails, the roots over the box (Monte Carlo), and
//! whether the body itself projects into the box.

use num_rational::BigRational;

use crate::algebra::{Interval, NEGLIGIBLE_ULPS};
use crate::derivations::p3f3::{
    match_solutions, real_solutions_from_coordinates, validate, Validation,
};
use crate::derivations::twofold::FrameCoefficients;
use crate::studies::rounding::{
    acceptance, cloud_spread, monte_carlo, reproduce, Acceptance, RoundingBox, Witness,
};

/// What the study needs: the figure's box and what the paper printed, as numbers.
#[derive(Clone, Debug)]
pub struct ExampleData<'a> {
    /// Flat coordinates (frame, point, x/y) and their half-widths.
    pub figure_box: &'a RoundingBox,
    /// The printed solutions (a², b², c²).
    pub targets: &'a [[f64; 3]],
    /// Half a unit of each printed component.
    pub target_half: &'a [[f64; 3]],
    /// The body table's squares.
    pub body: [f64; 3],
    /// Half a unit of each printed square.
    pub body_half: [f64; 3],
    /// Monte Carlo samples.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
}

/// The numbers of the study.
#[derive(Clone, Debug)]
pub struct ExampleStudy {
    /// Real roots at the printed coordinates, ordered by c².
    pub at_printed: Vec<[f64; 3]>,
    /// Those roots paired with the printed solutions (`None`: fewer real roots).
    pub matched: Option<Vec<[f64; 3]>>,
    /// A point of the box whose roots reproduce every printed component within its half unit.
    pub witness: Option<Witness>,
    /// Squared projections per frame at the witness.
    pub witness_projections: Option<Vec<[f64; 3]>>,
    /// The independent routes (exact elimination over ℚ, closed form, companion) at it.
    pub witness_routes: Option<Validation>,
    /// Per printed solution and component: how far the target may move (in half units) with
    /// the same search still finding a witness.
    pub acceptance: Vec<[Acceptance; 3]>,
    /// Samples with two real roots, each paired with the printed solutions.
    pub cloud: Vec<Vec<[f64; 3]>>,
    /// Per printed solution and component: 5 %, 50 %, 95 % of the paired root over the box.
    pub spread: Vec<[[f64; 3]; 3]>,
    /// Squared projections (PQ², QR², RP²) per frame at the printed coordinates.
    pub projections: Vec<[f64; 3]>,
    /// Per edge, the longest projection over the box, enclosed by interval arithmetic.
    pub longest_projection: [Interval; 3],
    /// Eq. p3f3sqr of each frame at the body's squares, relative to the size of its terms.
    pub body_residual: Vec<f64>,
    /// A point of the box that is an exact projection of the body (to rounding).
    pub body_fit: Option<Witness>,
    /// Per body square: how far it may move (in its half units) and still project into the box.
    pub body_acceptance: [Acceptance; 3],
}

fn frame_lengths(x: &[f64]) -> Vec<[f64; 3]> {
    (0..x.len() / 6)
        .map(|i| {
            let pts: Vec<[f64; 2]> = (0..3)
                .map(|j| [x[6 * i + 2 * j], x[6 * i + 2 * j + 1]])
                .collect();
            let l = crate::model::squared_lengths(&pts);
            [l[0], l[1], l[2]]
        })
        .collect()
}

/// Residuals of the roots at `x` against `targets`, in units of the half units.
fn scaled_roots(x: &[f64], targets: &[[f64; 3]], half: &[[f64; 3]]) -> Option<Vec<f64>> {
    let m = match_solutions(&real_solutions_from_coordinates(x), targets)?;
    Some(
        m.iter()
            .zip(targets.iter().zip(half))
            .flat_map(|(s, (t, h))| (0..3).map(move |e| (s[e] - t[e]) / h[e]))
            .collect(),
    )
}

/// Eq. p3f3sqr of each frame at `body`, in units of its rounding: 64ε × the sum of the
/// magnitudes of its terms bounds the error of evaluating it (a dozen products and sums).
fn scaled_body(x: &[f64], body: [f64; 3]) -> Vec<f64> {
    frame_lengths(x)
        .iter()
        .map(|l| {
            let f = FrameCoefficients::new(*l);
            let [a, b, c] = body;
            f.eval(a, b, c) / (NEGLIGIBLE_ULPS * f64::EPSILON * f.terms(a, b, c))
        })
        .collect()
}

fn mutant_acceptance(
    figure_box: &RoundingBox,
    targets: &[[f64; 3]],
    half: &[[f64; 3]],
) -> Vec<[Acceptance; 3]> {
    (0..targets.len())
        .map(|k| {
            std::array::from_fn(|e| {
                acceptance(&|shift| {
                    let mut moved = targets.to_vec();
                    moved[k][e] += shift * half[k][e];
                    reproduce(figure_box, &|x| scaled_roots(x, &moved, half)).is_some()
                })
            })
        })
        .collect()
}

fn longest_projection(figure_box: &RoundingBox) -> [Interval; 3] {
    let frames = figure_box.center.len() / 6;
    std::array::from_fn(|e| {
        let (a, b) = [(0, 1), (1, 2), (2, 0)][e];
        (0..frames)
            .map(|i| {
                let c = |j: usize, d: usize| {
                    let k = 6 * i + 2 * j + d;
                    Interval::around(figure_box.center[k], figure_box.half[k])
                };
                (c(a, 0) - c(b, 0)).square() + (c(a, 1) - c(b, 1)).square()
            })
            .reduce(|m, v| Interval {
                lo: m.lo.max(v.lo),
                hi: m.hi.max(v.hi),
            })
            .unwrap_or(Interval::point(0.0))
    })
}

/// Run the study.
pub fn study(inp: &ExampleData) -> ExampleStudy {
    let figure_box = inp.figure_box;
    let at_printed = real_solutions_from_coordinates(&figure_box.center);
    let witness = reproduce(figure_box, &|x| {
        scaled_roots(x, inp.targets, inp.target_half)
    });
    let witness_routes = witness.as_ref().map(|w| {
        let exact: [[BigRational; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|e| {
                BigRational::from_float(frame_lengths(&w.point)[i][e]).unwrap_or_default()
            })
        });
        validate(&exact)
    });
    let cloud: Vec<Vec<[f64; 3]>> = monte_carlo(figure_box, inp.trials, inp.seed, |x| {
        match_solutions(&real_solutions_from_coordinates(x), inp.targets)
    })
    .into_iter()
    .flatten()
    .collect();
    let body = inp.body;
    let body_fit = reproduce(figure_box, &|x| Some(scaled_body(x, body)));
    let body_acceptance = std::array::from_fn(|e| {
        acceptance(&|shift| {
            let mut moved = body;
            moved[e] += shift * inp.body_half[e];
            reproduce(figure_box, &|x| Some(scaled_body(x, moved))).is_some()
        })
    });
    ExampleStudy {
        matched: match_solutions(&at_printed, inp.targets),
        at_printed,
        witness_projections: witness.as_ref().map(|w| frame_lengths(&w.point)),
        witness,
        witness_routes,
        acceptance: mutant_acceptance(figure_box, inp.targets, inp.target_half),
        spread: (0..inp.targets.len())
            .map(|k| cloud_spread(&cloud, k))
            .collect(),
        cloud,
        projections: frame_lengths(&figure_box.center),
        longest_projection: longest_projection(figure_box),
        body_residual: frame_lengths(&figure_box.center)
            .iter()
            .map(|l| {
                let f = FrameCoefficients::new(*l);
                f.eval(body[0], body[1], body[2]) / f.terms(body[0], body[1], body[2])
            })
            .collect(),
        body_fit,
        body_acceptance,
    }
}
