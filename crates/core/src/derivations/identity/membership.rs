//! Which points of two frames are one rigid body: membership by the affine epipolar
//! geometry, started from the least-median four-point subset, and its default tolerance from
//! the data's own noise.

use super::*;

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

/// Four-point subsets tried by [`robust_tolerance`]: all of them up to this many, else this
/// many drawn with a fixed seed (the same input gives the same tolerance).
const LMEDS_SUBSETS: usize = 500;

/// The default tolerance of [`membership()`], from the data's own noise, with the degrees
/// of freedom of the fit accounted for.
///
/// 1. Least median of squares (Rousseeuw): the epipolar geometry of every four-point subset
///    (or `LMEDS_SUBSETS` of them) fitted exactly, the subset whose h-th smallest distance
///    over all points (h = ⌊(n + 4)/2⌋) is least kept; σ₀ = 1.4826 (1 + 5/(n − 3)) × that
///    distance; the points within [`REWEIGHT`] σ₀ are the first members.
/// 2. The constraint refitted to the members by least squares; σ̂² = Σ d² / (m − 4) over
///    the m members (the fit takes four parameters from their distances); the tolerance is
///    t · σ̂ with t the two-sided [`MEMBER_LEVEL`] point of Student's t with m − 4 degrees of
///    freedom (σ̂ is known only to that factor: few members, a wide tolerance); the points
///    within it are the members, and step 2 repeats until they no longer change.
///
/// At least 2¹⁰ ε (exact data); with five points or fewer (no residual freedom beyond one)
/// the floor.
pub fn robust_tolerance(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> f64 {
    let floor = 1024.0 * f64::EPSILON;
    let n = f1.len();
    if n <= FIT_PARAMETERS + 1 {
        return floor;
    }
    let h = (n + EPIPOLAR_DOF).div_ceil(2).clamp(EPIPOLAR_DOF + 2, n);
    let d = epipolar_distances(f1, f2, &least_median_subset(f1, f2));
    let mut sorted = d.clone();
    sorted.sort_by(f64::total_cmp);
    let sigma0 = MAD_TO_SIGMA * (1.0 + 5.0 / (n - EPIPOLAR_DOF) as f64) * sorted[h - 1];
    let mut members: Vec<bool> = d.iter().map(|x| *x <= REWEIGHT * sigma0).collect();
    let mut tolerance = f64::NAN;
    for _ in 0..n {
        let m = members.iter().filter(|x| **x).count();
        if m <= FIT_PARAMETERS {
            break;
        }
        let d = epipolar_distances(f1, f2, &members);
        let nu = m - FIT_PARAMETERS;
        let squares: f64 = d
            .iter()
            .zip(&members)
            .filter(|(_, m)| **m)
            .map(|(x, _)| x * x)
            .sum();
        let t = crate::algebra::student::two_sided_quantile(MEMBER_LEVEL, nu as u32);
        tolerance = t * (squares / nu as f64).sqrt();
        let next = within(&d, &members, tolerance);
        if next == members {
            break;
        }
        members = next;
    }
    if tolerance.is_finite() {
        tolerance.max(floor)
    } else {
        floor
    }
}

/// Every four-point subset of `n` points, or [`LMEDS_SUBSETS`] of them drawn with seed 0.
fn four_point_subsets(n: usize) -> Vec<[usize; 4]> {
    let all = n * (n - 1) * (n - 2) * (n - 3) / 24;
    if all <= LMEDS_SUBSETS {
        let mut out = Vec::with_capacity(all);
        for a in 0..n {
            for b in a + 1..n {
                for c in b + 1..n {
                    for d in c + 1..n {
                        out.push([a, b, c, d]);
                    }
                }
            }
        }
        return out;
    }
    let mut rng = crate::model::rng(0);
    (0..LMEDS_SUBSETS)
        .map(|_| {
            let v = rand::seq::index::sample(&mut rng, n, 4).into_vec();
            [v[0], v[1], v[2], v[3]]
        })
        .collect()
}

/// Every point's epipolar distance (relative to frame 2's size) from the geometry fitted to
/// the points `inside`.
fn epipolar_distances(f1: &[Vector2<f64>], f2: &[Vector2<f64>], inside: &[bool]) -> Vec<f64> {
    let idx: Vec<usize> = (0..f1.len()).filter(|&i| inside[i]).collect();
    let g1: Vec<Vector2<f64>> = idx.iter().map(|&i| f1[i]).collect();
    let g2: Vec<Vector2<f64>> = idx.iter().map(|&i| f2[i]).collect();
    let e = epipolar(&g1, &g2);
    let [a, b, c, d] = e.coefficients;
    let m1 = g1.iter().sum::<Vector2<f64>>() / g1.len().max(1) as f64;
    let m2 = g2.iter().sum::<Vector2<f64>>() / g2.len().max(1) as f64;
    let size = f2
        .iter()
        .map(|q| (q - m2).norm())
        .fold(f64::MIN_POSITIVE, f64::max);
    let norm = (c * c + d * d).sqrt().max(f64::MIN_POSITIVE);
    (0..f1.len())
        .map(|i| {
            (a * (f1[i].x - m1.x)
                + b * (f1[i].y - m1.y)
                + c * (f2[i].x - m2.x)
                + d * (f2[i].y - m2.y))
                .abs()
                / norm
                / size
        })
        .collect()
}

/// Rigid-body membership with known correspondences. The epipolar geometry is fitted to all
/// points; when some point lies beyond `tolerance` (relative to the image size), the fit
/// starts instead from the four-point subset of least h-th distance (as in
/// [`robust_tolerance`]: a foreign point cannot drag it), its points within `tolerance` are
/// refitted until the members no longer change. Returns each point's membership and its
/// final distance.
pub fn membership(f1: &[Vector2<f64>], f2: &[Vector2<f64>], tolerance: f64) -> Vec<(bool, f64)> {
    let n = f1.len();
    let all = epipolar_distances(f1, f2, &vec![true; n]);
    if n <= EPIPOLAR_DOF + 1 || all.iter().all(|d| *d <= tolerance) {
        return all.iter().map(|d| (*d <= tolerance, *d)).collect();
    }
    let mut inside = least_median_subset(f1, f2);
    let mut dist = epipolar_distances(f1, f2, &inside);
    // each round refits on the points within the tolerance; the members settle in a few
    for _ in 0..n {
        let next = within(&dist, &inside, tolerance);
        if next == inside || next.iter().filter(|m| **m).count() <= EPIPOLAR_DOF {
            break;
        }
        inside = next;
        dist = epipolar_distances(f1, f2, &inside);
    }
    let judged = within(&dist, &inside, tolerance);
    judged.into_iter().zip(dist).collect()
}

/// The points within the tolerance of the fit to `inside`: a point of the fit is judged by
/// its residual, one outside it by its distance from a line it did not help fit, whose
/// variance is larger by the fit's mean leverage: (1 + 4/m) for m fitted points (a
/// prediction interval), so that a member once set apart is judged alike.
fn within(dist: &[f64], inside: &[bool], tolerance: f64) -> Vec<bool> {
    let m = inside.iter().filter(|x| **x).count().max(1);
    let outside = tolerance * (1.0 + FIT_PARAMETERS as f64 / m as f64).sqrt();
    dist.iter()
        .zip(inside)
        .map(|(d, i)| *d <= if *i { tolerance } else { outside })
        .collect()
}

/// The four-point subset whose exact epipolar fit has the least h-th smallest distance over
/// all points (h = ⌊(n + 4)/2⌋), as a membership mask.
fn least_median_subset(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> Vec<bool> {
    let n = f1.len();
    let h = (n + EPIPOLAR_DOF).div_ceil(2).clamp(EPIPOLAR_DOF + 2, n);
    let mut best = (f64::INFINITY, vec![true; n]);
    for q in four_point_subsets(n) {
        let mut inside = vec![false; n];
        q.iter().for_each(|&i| inside[i] = true);
        let mut d = epipolar_distances(f1, f2, &inside);
        d.sort_by(f64::total_cmp);
        if d[h - 1] < best.0 {
            best = (d[h - 1], inside);
        }
    }
    best.1
}
