//! Which points of two frames are one rigid body: membership by the affine epipolar
//! geometry, started from the least-median three-point fit of equal scale, and its default
//! tolerance from the data's own noise.

use super::*;
use crate::algebra::mix::Mix;

/// The share of true members the default tolerance may reject: each member is judged at
/// the two-sided 99 % point of its distance's distribution.
pub const MEMBER_LEVEL: f64 = 0.99;

/// The consistency factor of the median absolute residual for a normal distribution
/// (1/Φ⁻¹(3/4)): σ ≈ 1.4826 × the median of |residual|.
const MAD_TO_SIGMA: f64 = 1.482_602_218_505_602;

/// Degrees of freedom of the affine epipolar constraint (four coefficients up to scale):
/// four points fit it exactly.
const EPIPOLAR_DOF: usize = 3;

/// Parameters a fit of the constraint takes from its points' distances: the line's normal
/// (three) and its offset through the centroid (one).
const FIT_PARAMETERS: usize = 4;

/// Rousseeuw's reweighting cut: after least median of squares, the points within 2.5
/// robust standard deviations start the least-squares refit.
pub const REWEIGHT: f64 = 2.5;

/// Three-point subsets tried by the least-median start: all of them up to this many, else
/// this many drawn with a fixed seed (the same input gives the same tolerance).
const LMEDS_SUBSETS: usize = 500;

/// Members at least, for the mix of the two noise scales to be estimated (it takes a degree
/// of freedom; below, one scale). Chosen by `membership_calibration` (docs/limits.md): from
/// 6 members the extra degree costs the far foreign points of the smallest scenes (80–83 %
/// found instead of 98–99 %), from 14 the relative noise of 10–13 members stays unmodelled
/// (0.69 % of the 10–19 members rejected instead of 0.55 %).
pub const MIX_MIN_MEMBERS: usize = 10;

/// How far a member's epipolar distance (relative to the image size) may go, point by point.
///
/// An image coordinate x is taken to carry noise of variance σ² ((1 − λ) + λ x²/u²): one
/// scale across the image (λ = 0, a tracker's pixel noise) or growing with the distance from
/// the image's origin (λ = 1, noise relative to the coordinates), u² the members' mean of
/// the coordinates' squares as the epipolar line weighs them, so both parts are of one size.
/// A point's distance then has standard deviation σ w, with w² = (1 − λ) + λ s/u² and s its
/// coordinates' squares weighed by the line's coefficients; it is a member when its distance
/// is at most `base` × w.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    /// The largest distance of a member of weight 1.
    pub base: f64,
    /// λ, the share of the noise that grows with the coordinates.
    pub relative: f64,
    /// u², the unit of the coordinates' squares.
    pub unit: f64,
}

impl Tolerance {
    /// One tolerance for every point (λ = 0): what `--tolerance` gives.
    pub fn uniform(base: f64) -> Tolerance {
        Tolerance {
            base,
            relative: 0.0,
            unit: 1.0,
        }
    }

    /// The weight w of a point whose coordinates' squares, weighed by the line, are `spread`
    /// ([`Mix::weight`]).
    fn weight(&self, spread: f64) -> f64 {
        Mix {
            relative: self.relative,
            unit: self.unit,
        }
        .weight(spread)
    }

    /// Every point's own tolerance, for the distances of a fit.
    fn of(&self, fit: &Distances) -> Vec<f64> {
        fit.spread
            .iter()
            .map(|s| self.base * self.weight(*s))
            .collect()
    }

    /// The largest of the members' tolerances (what the rigidity check may take as their
    /// noise); `base` when there are none.
    pub fn largest(&self, judged: &[Judged]) -> f64 {
        judged
            .iter()
            .filter(|j| j.member)
            .map(|j| j.tolerance)
            .reduce(f64::max)
            .unwrap_or(self.base)
    }
}

/// The mix of most likelihood for the members' distances ([`Mix::most_likely`]), as (λ, u²).
fn noise_mix(fit: &Distances, members: &[bool]) -> (f64, f64) {
    let inside: Vec<(f64, f64)> = fit
        .d
        .iter()
        .zip(&fit.spread)
        .zip(members)
        .filter(|(_, m)| **m)
        .map(|((d, s), _)| (*d, *s))
        .collect();
    let mix = Mix::most_likely(&inside);
    (mix.relative, mix.unit)
}

/// The default tolerance of [`membership()`], from the data's own noise, with the degrees
/// of freedom of the fit accounted for.
///
/// 1. Least median of squares (Rousseeuw): the epipolar geometries of equal scale through
///    every three-point subset (or `LMEDS_SUBSETS` of them), the one whose h-th smallest
///    distance over all points (h = ⌊(n + 4)/2⌋) is least kept; σ₀ = 1.4826 (1 + 5/(n − 3))
///    × that distance; the points within [`REWEIGHT`] σ₀ are the first members.
/// 2. The constraint refitted to the members by least squares; with at least
///    [`MIX_MIN_MEMBERS`] members, the mix λ of the two noise scales ([`Tolerance`]) of most
///    likelihood for their distances (else λ = 0); σ̂² = Σ (d/w)² / ν over the m members,
///    ν = m − 4 (the fit takes four parameters from their distances), one fewer when λ was
///    estimated; the tolerance of weight 1 is t · σ̂ with t the two-sided [`MEMBER_LEVEL`]
///    point of Student's t with ν degrees of freedom (σ̂ is known only to that factor: few
///    members, a wide tolerance); the points within their own tolerances are the members,
///    and step 2 repeats until they no longer change.
///
/// At least 2¹⁰ ε (exact data); with five points or fewer (no residual freedom beyond one)
/// the floor, the same for every point.
pub fn robust_tolerance(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> Tolerance {
    let floor = Tolerance::uniform(1024.0 * f64::EPSILON);
    let n = f1.len();
    if n <= FIT_PARAMETERS + 1 {
        return floor;
    }
    let h = median_rank(n);
    let d = least_median_fit(f1, f2).0.d;
    let mut sorted = d.clone();
    sorted.sort_by(f64::total_cmp);
    let sigma0 = MAD_TO_SIGMA * (1.0 + 5.0 / (n - EPIPOLAR_DOF) as f64) * sorted[h - 1];
    let mut members: Vec<bool> = d.iter().map(|x| *x <= REWEIGHT * sigma0).collect();
    let mut tolerance: Option<Tolerance> = None;
    for _ in 0..n {
        let m = members.iter().filter(|x| **x).count();
        if m <= FIT_PARAMETERS {
            break;
        }
        let fit = epipolar_distances(f1, f2, &members);
        // a second scale takes one more degree of freedom: only where the fit leaves enough
        let mixed = m >= MIX_MIN_MEMBERS;
        let (relative, unit) = if mixed {
            noise_mix(&fit, &members)
        } else {
            (0.0, 1.0)
        };
        let mut t = Tolerance {
            base: 1.0,
            relative,
            unit,
        };
        let nu = m - FIT_PARAMETERS - usize::from(mixed);
        let squares: f64 = (0..n)
            .filter(|&i| members[i])
            .map(|i| (fit.d[i] / t.weight(fit.spread[i])).powi(2))
            .sum();
        t.base = crate::algebra::student::two_sided_quantile(MEMBER_LEVEL, nu as u32)
            * (squares / nu as f64).sqrt();
        let next = within(&fit.d, &members, &t.of(&fit), t.base);
        tolerance = Some(t);
        if next == members {
            break;
        }
        members = next;
    }
    match tolerance {
        Some(t) if t.base.is_finite() && t.base >= floor.base => t,
        Some(t) if t.base.is_finite() => Tolerance {
            base: floor.base,
            ..t
        },
        _ => floor,
    }
}

/// The rank h = ⌈(n + 3)/2⌉ (at least 5, at most n) of the distance least median of squares
/// minimises over n ≥ 5 points. It counts the affine constraint's three degrees of freedom,
/// as Rousseeuw's ⌊(n + p + 1)/2⌋ does p, although the start of equal scale has two: more
/// points must fit, the safer side, and the calibration in docs/limits.md is of this rank.
fn median_rank(n: usize) -> usize {
    (n + EPIPOLAR_DOF)
        .div_ceil(2)
        .clamp(EPIPOLAR_DOF + 2, n.max(EPIPOLAR_DOF + 2))
}

/// Every three-point subset of `n` points, or [`LMEDS_SUBSETS`] of them drawn with seed 0.
fn three_point_subsets(n: usize) -> Vec<[usize; 3]> {
    let all = n * n.saturating_sub(1) * n.saturating_sub(2) / 6;
    if all <= LMEDS_SUBSETS {
        let mut out = Vec::with_capacity(all);
        for a in 0..n {
            for b in a + 1..n {
                for c in b + 1..n {
                    out.push([a, b, c]);
                }
            }
        }
        return out;
    }
    let mut rng = crate::model::rng(0);
    (0..LMEDS_SUBSETS)
        .map(|_| {
            let v = rand::seq::index::sample(&mut rng, n, 3).into_vec();
            [v[0], v[1], v[2]]
        })
        .collect()
}

/// The epipolar geometries of equal scale, a² + b² = c² + d², through three points: the
/// constraint's null space of their two difference rows is two-dimensional, and the form
/// vanishes on it twice or nowhere (then the vector nearest equal scale). No fit when the
/// rows are nearly dependent (the points coincide or are collinear in both frames alike):
/// the second singular value below ε^(1/4) of the first, where the null space's vectors
/// would carry errors of more than √ε (the Gram matrix's eigenvalues are the singular
/// values squared).
fn equal_scale_fits(f1: &[Vector2<f64>], f2: &[Vector2<f64>], q: [usize; 3]) -> Vec<[f64; 4]> {
    let row = |i: usize| nalgebra::Vector4::new(f1[i].x, f1[i].y, f2[i].x, f2[i].y);
    let (r1, r2) = (row(q[1]) - row(q[0]), row(q[2]) - row(q[0]));
    let eig = nalgebra::SymmetricEigen::new(r1 * r1.transpose() + r2 * r2.transpose());
    let mut order = [0usize, 1, 2, 3];
    order.sort_by(|&i, &j| eig.eigenvalues[i].total_cmp(&eig.eigenvalues[j]));
    if eig.eigenvalues[order[2]] <= f64::EPSILON.sqrt() * eig.eigenvalues[order[3]] {
        return Vec::new();
    }
    let v1: nalgebra::Vector4<f64> = eig.eigenvectors.column(order[0]).into();
    let v2: nalgebra::Vector4<f64> = eig.eigenvectors.column(order[1]).into();
    crate::derivations::two_frames::equal_scale_in_span(&v1, &v2)
        .into_iter()
        .map(|v| [v[0], v[1], v[2], v[3]])
        .collect()
}

/// The points' distances from one fitted epipolar geometry.
struct Distances {
    /// Every point's epipolar distance, relative to frame 2's size.
    d: Vec<f64>,
    /// Every point's coordinates' squares weighed by the line's coefficients,
    /// (a²x₁² + b²y₁² + c²x₂² + d²y₂²) / (a² + b² + c² + d²): how relative noise reaches its
    /// distance.
    spread: Vec<f64>,
}

/// Every point's epipolar distance (relative to frame 2's size) from the geometry fitted to
/// the points `inside`.
fn epipolar_distances(f1: &[Vector2<f64>], f2: &[Vector2<f64>], inside: &[bool]) -> Distances {
    let idx: Vec<usize> = (0..f1.len()).filter(|&i| inside[i]).collect();
    let g1: Vec<Vector2<f64>> = idx.iter().map(|&i| f1[i]).collect();
    let g2: Vec<Vector2<f64>> = idx.iter().map(|&i| f2[i]).collect();
    let m1 = g1.iter().sum::<Vector2<f64>>() / g1.len().max(1) as f64;
    let m2 = g2.iter().sum::<Vector2<f64>>() / g2.len().max(1) as f64;
    distances_from(f1, f2, epipolar(&g1, &g2).coefficients, [m1, m2])
}

/// Every point's distance from the line of coefficients (a, b, c, d) through the centres
/// `[m1, m2]`, relative to frame 2's size, with the points' spreads under it.
fn distances_from(
    f1: &[Vector2<f64>],
    f2: &[Vector2<f64>],
    e: [f64; 4],
    centres: [Vector2<f64>; 2],
) -> Distances {
    let [a, b, c, d] = e;
    let all = (a * a + b * b + c * c + d * d).max(f64::MIN_POSITIVE);
    let spread = (0..f1.len())
        .map(|i| {
            let (p, q) = (f1[i], f2[i]);
            (a * a * p.x * p.x + b * b * p.y * p.y + c * c * q.x * q.x + d * d * q.y * q.y) / all
        })
        .collect();
    let mut dist = Vec::with_capacity(f1.len());
    line_distances(f1, f2, e, centres, &mut dist);
    Distances { d: dist, spread }
}

/// [`distances_from`]'s distances alone, into `out` (cleared first).
fn line_distances(
    f1: &[Vector2<f64>],
    f2: &[Vector2<f64>],
    [a, b, c, d]: [f64; 4],
    [m1, m2]: [Vector2<f64>; 2],
    out: &mut Vec<f64>,
) {
    let size = f2
        .iter()
        .map(|q| (q - m2).norm())
        .fold(f64::MIN_POSITIVE, f64::max);
    let norm = (c * c + d * d).sqrt().max(f64::MIN_POSITIVE);
    out.clear();
    out.extend((0..f1.len()).map(|i| {
        (a * (f1[i].x - m1.x) + b * (f1[i].y - m1.y) + c * (f2[i].x - m2.x) + d * (f2[i].y - m2.y))
            .abs()
            / norm
            / size
    }));
}

/// One point's membership.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Judged {
    /// Whether it belongs to the body.
    pub member: bool,
    /// Its epipolar distance, relative to the image size.
    pub distance: f64,
    /// The largest distance it could have had as a member: its own tolerance (see
    /// [`Tolerance`]), wider by the fit's own error for a point outside the fit.
    pub tolerance: f64,
}

/// Rigid-body membership with known correspondences. The epipolar geometry is fitted to all
/// points; when some point lies beyond its tolerance (relative to the image size), the fit
/// starts instead from the least-median fit of equal scale (as in [`robust_tolerance`]: a
/// foreign point cannot drag it), and its points within their tolerances are refitted until
/// the members no longer change. Returns each point's membership, its final distance and
/// its tolerance.
pub fn membership(f1: &[Vector2<f64>], f2: &[Vector2<f64>], tolerance: &Tolerance) -> Vec<Judged> {
    let n = f1.len();
    let all = epipolar_distances(f1, f2, &vec![true; n]);
    let tol = tolerance.of(&all);
    let judge = |fit: &Distances, inside: &[bool], tol: &[f64]| -> Vec<Judged> {
        fit.d
            .iter()
            .zip(thresholds(inside, tol, tolerance.base))
            .map(|(d, t)| Judged {
                member: *d <= t,
                distance: *d,
                tolerance: t,
            })
            .collect()
    };
    if n <= EPIPOLAR_DOF + 1 || all.d.iter().zip(&tol).all(|(d, t)| d <= t) {
        return judge(&all, &vec![true; n], &tol);
    }
    let (mut fit, mut inside) = least_median_fit(f1, f2);
    // each round refits on the points within the tolerance; the members settle in a few
    for _ in 0..n {
        let next = within(&fit.d, &inside, &tolerance.of(&fit), tolerance.base);
        if next == inside || next.iter().filter(|m| **m).count() <= EPIPOLAR_DOF {
            break;
        }
        inside = next;
        fit = epipolar_distances(f1, f2, &inside);
    }
    if inside.iter().filter(|m| **m).count() <= EPIPOLAR_DOF {
        fit = nearest_four(f1, f2, &fit, &mut inside);
    }
    let tol = tolerance.of(&fit);
    judge(&fit, &inside, &tol)
}

/// Three members, the start's, say nothing (an epipolar geometry of equal scale passes
/// through any three points): the nearest point outside joins them, and the four are fitted
/// exactly, so that the rigidity check has four points to judge (four points of no rigid
/// body are rarely of equal scale).
fn nearest_four(
    f1: &[Vector2<f64>],
    f2: &[Vector2<f64>],
    fit: &Distances,
    inside: &mut [bool],
) -> Distances {
    let next = (0..inside.len())
        .filter(|&i| !inside[i])
        .min_by(|&i, &j| fit.d[i].total_cmp(&fit.d[j]));
    if let Some(i) = next {
        inside[i] = true;
    }
    epipolar_distances(f1, f2, inside)
}

/// Each point's threshold under the fit to `inside`, from its own tolerance t_i = base ×
/// w_i: a point of the fit is judged by its residual (t_i), one outside it by its distance
/// from a line it did not help fit, whose variance is larger by the fit's own error: the
/// mean leverage 4/m of m fitted points at the members' mean weight (1), so
/// √(t_i² + base² · 4/m) (a prediction interval; with one scale, t √(1 + 4/m)), and a
/// member once set apart is judged alike.
fn thresholds(inside: &[bool], tolerance: &[f64], base: f64) -> Vec<f64> {
    // a leverage is at most 1: the three points of the start count as four
    let m = inside.iter().filter(|x| **x).count().max(FIT_PARAMETERS);
    let fit = base * base * FIT_PARAMETERS as f64 / m as f64;
    inside
        .iter()
        .zip(tolerance)
        .map(|(i, t)| if *i { *t } else { (t * t + fit).sqrt() })
        .collect()
}

/// The points within their thresholds ([`thresholds`]) of the fit to `inside`.
fn within(dist: &[f64], inside: &[bool], tolerance: &[f64], base: f64) -> Vec<bool> {
    dist.iter()
        .zip(thresholds(inside, tolerance, base))
        .map(|(d, t)| *d <= t)
        .collect()
}

/// Least median of squares under equal scale: of the epipolar geometries of equal scale
/// through three points ([`equal_scale_fits`], every subset of [`three_point_subsets`]),
/// the one of least h-th smallest distance over all points (h = ⌊(n + 4)/2⌋). Returns its
/// distances and its three points as a mask.
///
/// Equal scale is what one rigid body's two orthographic views obey. A fit without it (four
/// points, four parameters) can pass through a foreign point and three members and still
/// come near another member by chance; such a start then sets true members apart, and the
/// rigidity check refuses the scene (`membership_calibration`, docs/limits.md).
fn least_median_fit(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> (Distances, Vec<bool>) {
    let n = f1.len();
    let h = median_rank(n);
    let mut best: Option<(f64, [f64; 4], [usize; 3])> = None;
    let mut d = Vec::with_capacity(n);
    for q in three_point_subsets(n) {
        let centres = centres_of(f1, f2, q);
        for e in equal_scale_fits(f1, f2, q) {
            line_distances(f1, f2, e, centres, &mut d);
            let (_, kth, _) = d.select_nth_unstable_by(h - 1, f64::total_cmp);
            if best.is_none_or(|b| kth.total_cmp(&b.0).is_lt()) {
                best = Some((*kth, e, q));
            }
        }
    }
    let mut inside = vec![false; n];
    match best {
        Some((_, e, q)) => {
            q.iter().for_each(|&i| inside[i] = true);
            (distances_from(f1, f2, e, centres_of(f1, f2, q)), inside)
        }
        // every triple tried dependent: the least-squares fit of all points
        None => (epipolar_distances(f1, f2, &vec![true; n]), vec![true; n]),
    }
}

/// The centres of three points' images in the two frames.
fn centres_of(f1: &[Vector2<f64>], f2: &[Vector2<f64>], q: [usize; 3]) -> [Vector2<f64>; 2] {
    let mean = |f: &[Vector2<f64>]| q.iter().map(|&i| f[i]).sum::<Vector2<f64>>() / 3.0;
    [mean(f1), mean(f2)]
}
