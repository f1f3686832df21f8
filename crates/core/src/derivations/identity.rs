//! §5.2: point identity and rigid-body membership from two frames of four points.
//!
//! The paper's test: choose the length c of RP, get b² from the Appendix A quadratic (both
//! signs) and a² from the frame difference, build the triangle PQR in 3-D, intersect the
//! first frame's viewing ray through T with the plane RPQ (T_a) and with that plane shifted
//! along RP × RQ (T_b), project both into the second frame and measure the distance of T₂
//! from the line T₂ₐT₂_b. That line is T's epipolar line; the independent check is the affine
//! epipolar constraint with the equal scale of orthographic views (module `two_frames`).

use nalgebra::{Matrix3, Vector2, Vector3};

use super::p3f3::kabsch;
use super::twofold::FrameCoefficients;
use crate::derivations::two_frames::epipolar;

pub mod hungarian;
pub mod membership;
pub mod wellposed;
pub use hungarian::hungarian;
pub use membership::{membership, robust_tolerance, Judged, Tolerance, MEMBER_LEVEL};
pub use wellposed::*;

/// The paper's test for one value of c and one choice of signs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaperTest {
    /// c (the chosen length of RP).
    pub c: f64,
    /// The sign in the formula for b² (+1 or −1).
    pub sign_b: f64,
    /// The relative depth sign of the triangle in frame 2 (+1 or −1).
    pub sign_frame2: f64,
    /// b² and a² that follow.
    pub b2: f64,
    /// a².
    pub a2: f64,
    /// T_a and T_b in the triangle's coordinates (R; RP, RQ, RP × RQ), the debug output's
    /// "PaK" and "PbK".
    pub ta_coords: Vector3<f64>,
    /// T_b's.
    pub tb_coords: Vector3<f64>,
    /// T_a and T_b in frame 2's camera coordinates (image x, y and depth): "Pa", "Pb".
    pub ta2: Vector3<f64>,
    /// T_b in frame 2.
    pub tb2: Vector3<f64>,
    /// The distance of the observed T₂ from the line T₂ₐT₂_b.
    pub distance: f64,
    /// The depths of P, Q, R in frame 2 (P at 0).
    pub depths2: [f64; 3],
}

/// The depths of a triangle P, Q, R in one frame (P at depth 0) from its squared edges and
/// projections: the sign pattern whose signed sum of √(e² − eᵢ²) is closest to zero, times
/// `sign`. `None` if an edge is shorter than its projection.
fn depths(sq: [f64; 3], proj: [f64; 3], sign: f64) -> Option<[f64; 3]> {
    let r: Vec<f64> = (0..3)
        .map(|e| {
            let d = sq[e] - proj[e];
            // rounding may leave −64ε(e² + eᵢ²) for an edge parallel to the image
            (d >= 0.0 || crate::algebra::negligible(d, sq[e] + proj[e])).then(|| d.max(0.0).sqrt())
        })
        .collect::<Option<_>>()?;
    let patterns = [[1.0, 1.0, -1.0], [1.0, -1.0, 1.0], [-1.0, 1.0, 1.0]];
    let best = patterns.iter().min_by(|a, b| {
        let s = |p: &[f64; 3]| (p[0] * r[0] + p[1] * r[1] + p[2] * r[2]).abs();
        s(a).total_cmp(&s(b))
    })?;
    let zq = sign * best[0] * r[0];
    Some([0.0, zq, zq + sign * best[1] * r[1]])
}

fn squared(f: &[Vector2<f64>; 4]) -> [f64; 3] {
    [
        (f[0] - f[1]).norm_squared(),
        (f[1] - f[2]).norm_squared(),
        (f[2] - f[0]).norm_squared(),
    ]
}

/// The Appendix A quadratic as a function of c²: F₁ − F₂ gives a² = p b² + q c² + r;
/// substituted into F₁, A b⁴ + B b² + C = 0. The function returns (A, B, C, p, s) with
/// a² = p b² + s; `None` when F₁ − F₂ has no a² term. The frames' coefficients are computed
/// once, for scans over c².
fn quadratic_in(
    f1: &[Vector2<f64>; 4],
    f2: &[Vector2<f64>; 4],
) -> Option<impl Fn(f64) -> [f64; 5]> {
    let (g1, g2) = (
        FrameCoefficients::new(squared(f1)),
        FrameCoefficients::new(squared(f2)),
    );
    let (d, k) = g1.difference(&g2);
    if d[0] == 0.0 {
        return None;
    }
    Some(move |c2: f64| {
        let (p, s) = (-d[1] / d[0], (-d[2] * c2 - k) / d[0]);
        let a = p * p - 2.0 * p + 1.0;
        let b =
            2.0 * p * s - 2.0 * s - 2.0 * c2 - 2.0 * p * c2 + 2.0 * g1.alpha * p + 2.0 * g1.beta;
        let c = s * s + c2 * c2 - 2.0 * s * c2 + g1.k + 2.0 * g1.alpha * s + 2.0 * g1.gamma * c2;
        [a, b, c, p, s]
    })
}

/// Δ_b = B² − 4AC of the Appendix A quadratic at c², in floating point (NaN when the
/// quadratic does not exist).
pub fn float_delta_b(f1: &[Vector2<f64>; 4], f2: &[Vector2<f64>; 4], c2: f64) -> f64 {
    quadratic_in(f1, f2).map_or(f64::NAN, |q| {
        let [a, b, c, _, _] = q(c2);
        b * b - 4.0 * a * c
    })
}

/// b² from the Appendix A quadratic at a given c² (both roots when real) and the a² that go
/// with them: F₁ − F₂ gives a² = p b² + q c² + r; substituted into F₁, A b⁴ + B b² + C = 0.
pub fn b_squared(
    f1: &[Vector2<f64>; 4],
    f2: &[Vector2<f64>; 4],
    c2: f64,
) -> Option<[(f64, f64); 2]> {
    b_squared_in(f1, f2)?(c2)
}

/// [`b_squared`] as a function of c², the frames' coefficients computed once (`None` when
/// F₁ − F₂ has no a² term).
pub fn b_squared_in(
    f1: &[Vector2<f64>; 4],
    f2: &[Vector2<f64>; 4],
) -> Option<impl Fn(f64) -> Option<[(f64, f64); 2]>> {
    let q = quadratic_in(f1, f2)?;
    Some(move |c2: f64| {
        let [a, b, c, p, s] = q(c2);
        let disc = b * b - 4.0 * a * c;
        if disc < 0.0 || a == 0.0 {
            return None;
        }
        let root = |sign: f64| {
            let y = (-b + sign * disc.sqrt()) / (2.0 * a);
            (y, p * y + s)
        };
        Some([root(-1.0), root(1.0)])
    })
}

/// The paper's test for frames of P, Q, R, T (in that order) at one c, for each sign of b
/// and each relative depth sign of frame 2: the tests that are geometrically possible.
pub fn paper_tests(f1: &[Vector2<f64>; 4], f2: &[Vector2<f64>; 4], c: f64) -> Vec<PaperTest> {
    let mut out = Vec::new();
    let Some(roots) = b_squared(f1, f2, c * c) else {
        return out;
    };
    let (p1, p2) = (squared(f1), squared(f2));
    for (k, &(b2, a2)) in roots.iter().enumerate() {
        let sq = [a2, b2, c * c];
        for sign_frame2 in [1.0, -1.0] {
            let (Some(mut z1), Some(z2)) = (depths(sq, p1, 1.0), depths(sq, p2, sign_frame2))
            else {
                continue;
            };
            // frame 1's mirror convention: P not below R (the two mirror images give the same
            // set of lines over the frame-2 signs; this one matches the author's printout)
            if z1[0] < z1[2] {
                z1 = z1.map(|z| -z);
            }
            let x1: [Vector3<f64>; 3] =
                std::array::from_fn(|i| Vector3::new(f1[i].x, f1[i].y, z1[i]));
            let x2: [Vector3<f64>; 3] =
                std::array::from_fn(|i| Vector3::new(f2[i].x, f2[i].y, z2[i]));
            let o1: [Vector3<f64>; 3] = std::array::from_fn(|i| x1[i] - x1[0]);
            let o2: [Vector3<f64>; 3] = std::array::from_fn(|i| x2[i] - x2[0]);
            let rot = kabsch(&o1, &o2);
            // the triangle's frame at R: RP, RQ, RP × RQ
            let (rp, rq) = (x1[0] - x1[2], x1[1] - x1[2]);
            let basis = Matrix3::from_columns(&[rp, rq, rp.cross(&rq)]);
            let Some(inv) = basis.try_inverse() else {
                continue;
            };
            // T(z) = (T₁, z): coordinates affine in z; solve γ = 0 and γ = 1
            let at = |z: f64| inv * (Vector3::new(f1[3].x, f1[3].y, z) - x1[2]);
            let (g0, g1) = (at(0.0), at(1.0) - at(0.0));
            if g1.z == 0.0 {
                continue;
            }
            let za = -g0.z / g1.z;
            let zb = (1.0 - g0.z) / g1.z;
            let (ta, tb) = (
                Vector3::new(f1[3].x, f1[3].y, za),
                Vector3::new(f1[3].x, f1[3].y, zb),
            );
            let to2 = |x: Vector3<f64>| rot * (x - x1[0]) + x2[0];
            let (ta2, tb2) = (to2(ta), to2(tb));
            let distance = crate::model::point_line_distance(f2[3], ta2.xy(), tb2.xy());
            out.push(PaperTest {
                c,
                sign_b: if k == 0 { -1.0 } else { 1.0 },
                sign_frame2,
                b2,
                a2,
                ta_coords: at(za),
                tb_coords: at(zb),
                ta2,
                tb2,
                distance,
                depths2: z2,
            });
        }
    }
    out
}

/// 1.001ⁱ as `powi` gives it, tabulated once: [`smallest_c`] scans the same grid for every
/// assignment of every scene.
fn grid_step(i: i32) -> f64 {
    static STEPS: std::sync::LazyLock<Vec<f64>> =
        std::sync::LazyLock::new(|| (0..SMALLEST_C_STEPS).map(|i| 1.001_f64.powi(i)).collect());
    STEPS[i as usize]
}

/// The grid of [`smallest_c`]: 1.001⁴⁶¹⁰ ≈ 100, so up to 100 times the projection.
const SMALLEST_C_STEPS: i32 = 4610;

/// The smallest c the paper allows, to a relative step of 10⁻³: RP at least its longest
/// projection, then the first c on the grid start·1.001ⁱ for which some b is real with a and b
/// at least their longest projections. `None` if none up to 100 times the projection.
pub fn smallest_c(f1: &[Vector2<f64>; 4], f2: &[Vector2<f64>; 4]) -> Option<f64> {
    let (p1, p2) = (squared(f1), squared(f2));
    let start = p1[2].max(p2[2]).sqrt();
    let at = b_squared_in(f1, f2)?;
    (0..SMALLEST_C_STEPS)
        .map(|i| start * grid_step(i))
        .find(|&c| {
            at(c * c).is_some_and(|roots| {
                roots
                    .iter()
                    .any(|&(b2, a2)| b2 >= p1[1].max(p2[1]) && a2 >= p1[0].max(p2[0]))
            })
        })
}

/// The equal-scale residual |a² + b² − c² − d²| of the affine epipolar constraint of four
/// correspondences: zero for two views of one rigid body (the four correspondences always
/// satisfy the affine constraint alone).
pub fn epipolar_residual(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> f64 {
    epipolar(f1, f2).scale_residual.abs()
}

/// One assignment of frame-2 points to frame-1 points, with its residual.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Assignment {
    /// `frame2_indices[i]` is the frame-2 index of frame-1 point i.
    pub frame2_indices: Vec<usize>,
    /// The residual (smaller is better).
    pub residual: f64,
}

/// An assignment ordered by residual (total order), then by indices: the ranking's order.
#[derive(PartialEq)]
struct Ranked(Assignment);

impl Eq for Ranked {}

impl PartialOrd for Ranked {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Ranked {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        self.0
            .residual
            .total_cmp(&other.0.residual)
            .then_with(|| self.0.frame2_indices.cmp(&other.0.frame2_indices))
    }
}

/// The `top` best assignments kept while visiting: a max-heap of at most `top` entries, so
/// memory is linear in what is kept, not in what is tried.
#[derive(Default)]
struct TopN {
    heap: std::collections::BinaryHeap<Ranked>,
    tried: usize,
}

impl TopN {
    fn push(mut self, a: Assignment, top: usize) -> Self {
        self.tried += 1;
        if top == 0 {
            return self;
        }
        let r = Ranked(a);
        if self.heap.len() < top {
            self.heap.push(r);
        } else if self.heap.peek().is_some_and(|worst| r < *worst) {
            self.heap.pop();
            self.heap.push(r);
        }
        self
    }

    fn merge(mut self, other: TopN, top: usize) -> Self {
        let tried = self.tried + other.tried;
        for r in other.heap {
            self = self.push(r.0, top);
        }
        self.tried = tried;
        self
    }

    fn into_sorted(self) -> (Vec<Assignment>, usize) {
        let v = self
            .heap
            .into_sorted_vec()
            .into_iter()
            .map(|r| r.0)
            .collect();
        (v, self.tried)
    }
}

/// The `top` best of every ordered choice of four frame-2 points for frame-1 points 0‥3,
/// n(n−1)(n−2)(n−3) of them, ranked by `residual` (best first, ties by indices), and how many
/// were tried. Memory O(top) per thread.
pub fn rank_quadruples_top(
    f1: &[Vector2<f64>],
    f2: &[Vector2<f64>],
    residual: impl Fn(&[Vector2<f64>; 4], &[Vector2<f64>; 4]) -> f64 + Sync,
    top: usize,
) -> (Vec<Assignment>, usize) {
    rank_quadruples_reporting(f1, f2, residual, top, &|| {})
}

/// [`rank_quadruples_top`], calling `done` as each choice of the first frame-2 point is
/// finished (n calls in all, from any thread): the progress of a long ranking.
fn rank_quadruples_reporting(
    f1: &[Vector2<f64>],
    f2: &[Vector2<f64>],
    residual: impl Fn(&[Vector2<f64>; 4], &[Vector2<f64>; 4]) -> f64 + Sync,
    top: usize,
    done: &(dyn Fn() + Sync),
) -> (Vec<Assignment>, usize) {
    use rayon::prelude::*;
    let n = f2.len();
    if f1.len() < 4 || n < 4 {
        return (Vec::new(), 0);
    }
    let first: [Vector2<f64>; 4] = std::array::from_fn(|i| f1[i]);
    (0..n)
        .into_par_iter()
        .fold(TopN::default, |mut acc, a| {
            for b in (0..n).filter(|b| *b != a) {
                for c in (0..n).filter(|c| *c != a && *c != b) {
                    for d in (0..n).filter(|d| *d != a && *d != b && *d != c) {
                        let g = [f2[a], f2[b], f2[c], f2[d]];
                        let x = Assignment {
                            frame2_indices: vec![a, b, c, d],
                            residual: residual(&first, &g),
                        };
                        acc = acc.push(x, top);
                    }
                }
            }
            done();
            acc
        })
        .reduce(TopN::default, |x, y| x.merge(y, top))
        .into_sorted()
}

/// Every ordered choice of four frame-2 points for frame-1 points 0‥3, n(n−1)(n−2)(n−3) of
/// them, ranked by `residual` (best first, ties by indices). Memory grows with n⁴: for small
/// n; [`rank_quadruples_top`] keeps only the best.
pub fn rank_quadruples(
    f1: &[Vector2<f64>],
    f2: &[Vector2<f64>],
    residual: impl Fn(&[Vector2<f64>; 4], &[Vector2<f64>; 4]) -> f64 + Sync,
) -> Vec<Assignment> {
    rank_quadruples_top(f1, f2, residual, usize::MAX).0
}

/// The best full correspondence: the best four-point assignment fixes the epipolar geometry;
/// every other frame-1 point takes the frame-2 point nearest its epipolar line (an optimal
/// assignment of the rest by those distances). The score is the RMS epipolar distance over
/// all points, relative to the image size.
pub fn full_correspondence(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> Option<Assignment> {
    if f1.len() < 4 || f2.len() != f1.len() {
        return None;
    }
    let best = rank_quadruples_top(f1, f2, |a, b| epipolar_residual(a, b), 1)
        .0
        .into_iter()
        .next()?;
    extend_to_full(f1, f2, &best.frame2_indices)
}

/// [`full_correspondence`] from the best four-point assignment `chosen`, already found.
fn extend_to_full(
    f1: &[Vector2<f64>],
    f2: &[Vector2<f64>],
    chosen: &[usize],
) -> Option<Assignment> {
    let n = f1.len();
    if n < 4 || f2.len() != n || chosen.len() != 4 {
        return None;
    }
    let g1: Vec<Vector2<f64>> = (0..4).map(|i| f1[i]).collect();
    let g2: Vec<Vector2<f64>> = chosen.iter().map(|&j| f2[j]).collect();
    let e = epipolar(&g1, &g2);
    let [a, b, c, d] = e.coefficients;
    let m1 = g1.iter().sum::<Vector2<f64>>() / 4.0;
    let m2 = g2.iter().sum::<Vector2<f64>>() / 4.0;
    let norm = (c * c + d * d).sqrt().max(f64::MIN_POSITIVE);
    // distance of frame-2 point q from the epipolar line of frame-1 point p
    let dist = |p: &Vector2<f64>, q: &Vector2<f64>| {
        (a * (p.x - m1.x) + b * (p.y - m1.y) + c * (q.x - m2.x) + d * (q.y - m2.y)).abs() / norm
    };
    let rest1: Vec<usize> = (4..n).collect();
    let rest2: Vec<usize> = (0..n).filter(|j| !chosen.contains(j)).collect();
    let cost: Vec<Vec<f64>> = rest1
        .iter()
        .map(|&i| {
            rest2
                .iter()
                .map(|&j| dist(&f1[i], &f2[j]).powi(2))
                .collect()
        })
        .collect();
    let matched = hungarian(&cost);
    let mut indices = chosen.to_vec();
    indices.extend(matched.iter().map(|&k| rest2[k]));
    let size = f2
        .iter()
        .map(|q| (q - m2).norm())
        .fold(f64::MIN_POSITIVE, f64::max);
    let rms = ((0..n)
        .map(|i| dist(&f1[i], &f2[indices[i]]).powi(2))
        .sum::<f64>()
        / n as f64)
        .sqrt();
    Some(Assignment {
        frame2_indices: indices,
        residual: rms / size,
    })
}

/// The test `identify` ranks assignments by.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum IdentifyMethod {
    /// The equal-scale residual of the affine epipolar constraint of four points.
    Epipolar,
    /// The paper's four-point test (Appendix A quadratic, T_a, T_b).
    Four,
    /// The five-point line (§5.3).
    Five,
}

/// What `identify` reports.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Identified {
    /// The test used.
    pub method: IdentifyMethod,
    /// The best assignments of frame-1 points 0‥3 (0‥4 for five), best first.
    pub assignments: Vec<Assignment>,
    /// How many assignments were tried.
    pub tried: usize,
    /// The best full correspondence of all points, with its RMS epipolar distance.
    pub full: Option<Assignment>,
    /// A degenerate case, if any (judged for the best full correspondence).
    pub degenerate: Option<TwoFrameDegenerate>,
}

/// Rank the assignments of frame-2 points to frame-1 points by `method`, keep the `top`
/// best, and extend the best to a full correspondence.
pub fn identify(
    f1: &[Vector2<f64>],
    f2: &[Vector2<f64>],
    method: IdentifyMethod,
    top: usize,
) -> crate::error::Result<Identified> {
    identify_reporting(f1, f2, method, top, &|| {})
}

/// [`identify`], calling `done` once for each frame-2 point the ranking has tried as the
/// first of its choices: `f2.len()` calls in all, from any thread (a progress bar's ticks).
pub fn identify_reporting(
    f1: &[Vector2<f64>],
    f2: &[Vector2<f64>],
    method: IdentifyMethod,
    top: usize,
    done: &(dyn Fn() + Sync),
) -> crate::error::Result<Identified> {
    let need = if method == IdentifyMethod::Five { 5 } else { 4 };
    if f1.len() < need || f2.len() != f1.len() {
        return Err(crate::error::Error::InvalidInput(format!(
            "{} points: the {} test needs at least {need} in each frame, the same number in both",
            f1.len(),
            match method {
                IdentifyMethod::Five => "five-point",
                _ => "four-point",
            }
        )));
    }
    if let Some(d @ (TwoFrameDegenerate::CoincidentPoints | TwoFrameDegenerate::TooFewPoints)) =
        degeneracy(f1, f2)
    {
        return Err(crate::error::Error::InvalidInput(d.to_string()));
    }
    // the same view (or a scaled copy) under every assignment: no question to answer
    if let Some(d) = similar_frames(f1, f2) {
        let d = match d {
            TwoFrameDegenerate::IdenticalFrames => "the frames are the same view (an in-plane motion or a mirror of each other, under some assignment): every assignment fits".to_string(),
            d => d.to_string(),
        };
        return Err(crate::error::Error::InvalidInput(d));
    }
    let size = f2
        .iter()
        .map(|p| p.norm())
        .fold(f64::MIN_POSITIVE, f64::max);
    let (ranked, tried) = match method {
        IdentifyMethod::Epipolar => {
            rank_quadruples_reporting(f1, f2, |a, b| epipolar_residual(a, b), top, done)
        }
        IdentifyMethod::Four => rank_quadruples_reporting(
            f1,
            f2,
            |a, b| {
                smallest_c(a, b).map_or(f64::INFINITY, |c| {
                    paper_tests(a, b, c)
                        .iter()
                        .map(|t| t.distance / size)
                        .fold(f64::INFINITY, f64::min)
                })
            },
            top,
            done,
        ),
        IdentifyMethod::Five => rank_quintuples(f1, f2, top, done),
    };
    // the epipolar ranking already found the four points the full correspondence starts from
    let full = match (method, ranked.first()) {
        (IdentifyMethod::Epipolar, Some(best)) => extend_to_full(f1, f2, &best.frame2_indices),
        _ => full_correspondence(f1, f2),
    };
    let degenerate = full.as_ref().and_then(|a| {
        let g2: Vec<Vector2<f64>> = a.frame2_indices.iter().map(|&j| f2[j]).collect();
        rigidity(f1, &g2)
    });
    Ok(Identified {
        method,
        assignments: ranked,
        tried,
        full,
        degenerate,
    })
}

/// The `top` best ordered choices of five frame-2 points for frame-1 points 0‥4, by the
/// five-point line distance (relative to the image size), and how many were tried; memory
/// O(top) per thread; `done` as in [`identify_reporting`].
fn rank_quintuples(
    f1: &[Vector2<f64>],
    f2: &[Vector2<f64>],
    top: usize,
    done: &(dyn Fn() + Sync),
) -> (Vec<Assignment>, usize) {
    use rayon::prelude::*;
    let n = f2.len();
    let first: [Vector2<f64>; 5] = std::array::from_fn(|i| f1[i]);
    let size = f2
        .iter()
        .map(|p| p.norm())
        .fold(f64::MIN_POSITIVE, f64::max);
    fn rec(k: usize, n: usize, idx: &mut [usize; 5], visit: &mut dyn FnMut(&[usize; 5])) {
        if k == 5 {
            visit(idx);
            return;
        }
        for j in 0..n {
            if !idx[..k].contains(&j) {
                idx[k] = j;
                rec(k + 1, n, idx, visit);
            }
        }
    }
    (0..n)
        .into_par_iter()
        .fold(TopN::default, |acc, a| {
            let mut acc = Some(acc);
            let mut idx = [a, 0, 0, 0, 0];
            rec(1, n, &mut idx, &mut |c| {
                let g: [Vector2<f64>; 5] = std::array::from_fn(|i| f2[c[i]]);
                let x = Assignment {
                    frame2_indices: c.to_vec(),
                    residual: super::identity5::line_distance(&first, &g)
                        .map_or(f64::INFINITY, |d| d / size),
                };
                acc = acc.take().map(|t| t.push(x, top));
            });
            done();
            acc.unwrap_or_default()
        })
        .reduce(TopN::default, |x, y| x.merge(y, top))
        .into_sorted()
}
