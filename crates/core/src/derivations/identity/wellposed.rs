//! Whether two frames can come from one rigid body seen from distinct views: identical
//! frames, in-plane motions, mirrors, scaled copies and non-rigid data, named before any
//! question about the body is answered.

use super::*;

/// Two frames the identity and membership tests cannot use as they are.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum TwoFrameDegenerate {
    /// Fewer than four points: three correspondences fix no epipolar line.
    TooFewPoints,
    /// Two points of a frame coincide.
    CoincidentPoints,
    /// The frames differ by an in-plane motion only: every distance is kept, the views are
    /// the same, and every point is on its epipolar line whatever the assignment.
    IdenticalFrames,
    /// Frame 2 is a mirror image of frame 1 (up to an in-plane motion): the same viewing line
    /// seen from the other side, so again the same view.
    Mirror,
    /// Frame 2 is a scaled copy of frame 1 (up to an in-plane motion): orthographic views of
    /// one rigid body have one scale, so no rigid body gives these frames.
    ScaledFrames,
    /// No rigid body seen orthographically gives these frames: they fit no affine epipolar
    /// geometry of two views at equal scale. Real cameras break it too where their
    /// perspective or non-square pixels exceed the tracks' noise: 5 of the Oxford dinosaur's
    /// 35 pairs of consecutive frames are refused (docs/limits.md).
    NotRigid,
    /// The best assignment leaves the epipolar geometry undetermined (a planar body).
    Planar,
}

impl std::fmt::Display for TwoFrameDegenerate {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            TwoFrameDegenerate::TooFewPoints => "fewer than four points",
            TwoFrameDegenerate::CoincidentPoints => "two points of a frame coincide",
            TwoFrameDegenerate::IdenticalFrames => {
                "the frames differ by an in-plane motion only: the two views are the same"
            }
            TwoFrameDegenerate::Mirror => {
                "frame 2 is a mirror image of frame 1: the same viewing line from the other side, the two views are the same"
            }
            TwoFrameDegenerate::ScaledFrames => {
                "frame 2 is a scaled copy of frame 1: orthographic views of one rigid body have one scale, no rigid body gives these frames"
            }
            TwoFrameDegenerate::NotRigid => {
                "no rigid body gives these frames as orthographic views: they fit no epipolar geometry of two orthographic views at equal scale (a real camera's perspective or non-square pixels, beyond the tracks' noise, break it too)"
            }
            TwoFrameDegenerate::Planar => {
                "the body is planar: the epipolar geometry is undetermined and several assignments may fit"
            }
        })
    }
}

/// The largest distance of a point from the frames' centroids, the size rounding is judged by.
fn size_of(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> f64 {
    let c = |f: &[Vector2<f64>]| f.iter().sum::<Vector2<f64>>() / f.len().max(1) as f64;
    let (c1, c2) = (c(f1), c(f2));
    f1.iter()
        .map(|p| (p - c1).norm())
        .chain(f2.iter().map(|q| (q - c2).norm()))
        .fold(f64::MIN_POSITIVE, f64::max)
}

/// The affine map A of frame 2 onto frame 1 (centred, least squares: Σqpᵀ (Σppᵀ)⁻¹) and the
/// condition number of Σppᵀ; `None` when frame 1's points are collinear.
fn affine_map(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> Option<(nalgebra::Matrix2<f64>, f64)> {
    let n = f1.len().max(1) as f64;
    let c1 = f1.iter().sum::<Vector2<f64>>() / n;
    let c2 = f2.iter().sum::<Vector2<f64>>() / n;
    let mut pp = nalgebra::Matrix2::zeros();
    let mut qp = nalgebra::Matrix2::zeros();
    for (p, q) in f1.iter().zip(f2) {
        let (p, q) = (p - c1, q - c2);
        pp += p * p.transpose();
        qp += q * p.transpose();
    }
    let sv = pp.singular_values();
    let cond = sv.max() / sv.min();
    Some((qp * pp.try_inverse()?, cond))
}

/// Frames related by an affine map A (the epipolar geometry undetermined): two orthographic
/// views of a planar body have A = M₂M₁⁻¹ with each Mᵢ a 2×2 matrix of singular values 1 and
/// |cos θᵢ|, possible exactly when A's singular values s₁ ≥ s₂ straddle 1 (s₂ ≤ 1 ≤ s₁).
/// Both above or both below 1 (a scaled copy) is no rigid body. Tolerance: 64ε·κ(Σppᵀ),
/// the relative rounding the normal equations of A can leave.
fn affine_degeneracy(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> TwoFrameDegenerate {
    let Some((a, cond)) = affine_map(f1, f2) else {
        return TwoFrameDegenerate::Planar;
    };
    let tol = crate::algebra::NEGLIGIBLE_ULPS * f64::EPSILON * cond;
    let sv = a.singular_values();
    let (s1, s2) = (sv.max(), sv.min());
    if s2 <= 1.0 + tol && s1 >= 1.0 - tol {
        TwoFrameDegenerate::Planar
    } else if (s1 - s2) <= tol * s1 {
        TwoFrameDegenerate::ScaledFrames
    } else {
        TwoFrameDegenerate::NotRigid
    }
}

/// What makes two frames unusable (or weaker) for the tests, if anything; `planar` is
/// judged for the correspondence given. Order: too few points, coincident points, the same
/// view (in-plane motion, mirror), an affine relation (a planar body, or a scaled copy or
/// other affine image no rigid body gives).
pub fn degeneracy(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> Option<TwoFrameDegenerate> {
    let n = f1.len();
    if n < 4 || f2.len() != n {
        return Some(TwoFrameDegenerate::TooFewPoints);
    }
    let size = f1
        .iter()
        .chain(f2)
        .map(|p| p.norm())
        .fold(f64::MIN_POSITIVE, f64::max);
    let tiny = crate::algebra::NEGLIGIBLE_ULPS * f64::EPSILON * size;
    for f in [f1, f2] {
        for i in 0..n {
            for j in i + 1..n {
                if (f[i] - f[j]).norm() <= tiny {
                    return Some(TwoFrameDegenerate::CoincidentPoints);
                }
            }
        }
    }
    // each squared distance judged against the frames' size squared: a short distance carries
    // the rounding of the coordinates, not of itself
    let size2 = 4.0 * size_of(f1, f2).powi(2);
    let same = (0..n).all(|i| {
        (i + 1..n).all(|j| {
            let (a, b) = (
                (f1[i] - f1[j]).norm_squared(),
                (f2[i] - f2[j]).norm_squared(),
            );
            crate::algebra::negligible(a - b, size2)
        })
    });
    if same {
        // the orthogonal map between congruent frames: a rotation or a reflection
        let mirror = affine_map(f1, f2).is_some_and(|(a, _)| a.determinant() < 0.0);
        return Some(if mirror {
            TwoFrameDegenerate::Mirror
        } else {
            TwoFrameDegenerate::IdenticalFrames
        });
    }
    (!epipolar(f1, f2).determined).then(|| affine_degeneracy(f1, f2))
}

/// [`degeneracy`], then whether one rigid body can give the two frames at all: the centred
/// rows (x₁, y₁, x₂, y₂) must have a null vector (the affine epipolar constraint; automatic
/// for four points) with a² + b² = c² + d² (equal scale). Rounding allowance: the null
/// vector of the Gram matrix G moves by at most ‖δG‖/(λ₁ − λ₀) with ‖δG‖ ≤ 64ε·λ₃ (Davis–
/// Kahan), and the form a² + b² − c² − d² of a unit vector by at most twice that; the
/// smallest eigenvalue itself must be below what rounding leaves ([`epipolar`]'s zero).
pub fn rigidity(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> Option<TwoFrameDegenerate> {
    if let Some(d) = degeneracy(f1, f2) {
        return Some(d);
    }
    let e = epipolar(f1, f2);
    let [l0, l1, _, l3] = e.eigenvalues;
    let u = crate::algebra::NEGLIGIBLE_ULPS * f64::EPSILON;
    let rounding = u * size_of(f1, f2);
    let zero = (4.0 * f1.len() as f64 * rounding * rounding).max(u * l3);
    let scale_allowance = 2.0 * u * l3 / (l1 - l0).max(f64::MIN_POSITIVE);
    (l0 > zero || e.scale_residual.abs() > scale_allowance).then_some(TwoFrameDegenerate::NotRigid)
}

/// The level at which [`members_rigid`] refuses members by their own noise: the chance that
/// normal errors give a rigid body's members an F ratio beyond it. Nominal: F(1, ν) holds
/// for small noise, and members chosen for small residuals inflate the ratio; none of
/// `membership_calibration`'s 12,000 rigid scenes was refused (docs/limits.md).
pub const RIGID_LEVEL: f64 = 1e-6;

/// Whether the members of a membership decision are views of one rigid body at equal scale.
///
/// They are, unless their epipolar geometry's equal-scale residual exceeds what rounding
/// leaves ([`rigidity`]'s allowance) and one of two rules says noise cannot explain it:
/// - the noise that `tolerance` (the relative epipolar distance a member may have) admits,
///   carried to the residual by a worst-case bound;
/// - with m ≥ 5 members, their own noise: the least squares Σ (v·row)² over unit vectors v
///   of equal scale exceed the free least by more than F(1, m − 4) times the free least's
///   variance allows at [`RIGID_LEVEL`] (m − 4 residual degrees of freedom: the centre and
///   the unit vector take four).
///
/// `None` when they are rigid; the degenerate case otherwise.
pub fn members_rigid(
    f1: &[Vector2<f64>],
    f2: &[Vector2<f64>],
    members: &[bool],
    tolerance: f64,
) -> Option<TwoFrameDegenerate> {
    let pick = |f: &[Vector2<f64>]| -> Vec<Vector2<f64>> {
        f.iter()
            .zip(members)
            .filter(|(_, m)| **m)
            .map(|(p, _)| *p)
            .collect()
    };
    let (g1, g2) = (pick(f1), pick(f2));
    if g1.len() < 4 {
        return None;
    }
    let e = epipolar(&g1, &g2);
    let [l0, l1, _, l3] = e.eigenvalues;
    let gap = (l1 - l0).max(f64::MIN_POSITIVE);
    let rounding = 2.0 * crate::algebra::NEGLIGIBLE_ULPS * f64::EPSILON * l3 / gap;
    if !e.determined || e.scale_residual.abs() <= rounding {
        return None;
    }
    let beyond_bound = e.scale_residual.abs() > tolerance_bound(&g2, &e, tolerance);
    let nu = g1.len() - 4;
    let beyond_level = nu > 0 && {
        let gram = crate::derivations::two_frames::centred_gram(&g1, &g2);
        let (free, equal) = equal_scale_least(&gram, l3);
        let t = crate::algebra::student::two_sided_quantile(1.0 - RIGID_LEVEL, nu as u32);
        // F = (equal − free) / (free / ν) beyond t², both least squares known to the
        // eigensolver's rounding r = 64ε·λ₃ (and `free` taken as at least r)
        let r = crate::algebra::NEGLIGIBLE_ULPS * f64::EPSILON * l3;
        (equal - free - r) * nu as f64 > t * t * free.max(r)
    };
    // either rule refuses: the bound never refused a rigid body in the calibration, and the
    // test adds what the members' own noise shows
    (beyond_bound || beyond_level).then_some(TwoFrameDegenerate::NotRigid)
}

/// The equal-scale residual the noise that `tolerance` admits can cause: a member's distance
/// `tolerance` is |v·row| / ‖(c, d)‖ / size, so the rows' noise is about σ = tolerance ×
/// ‖(c, d)‖ × size per coordinate; it moves the Gram matrix by at most 2‖A‖‖ΔA‖ ≤
/// 4√(l₃ n) σ, the null vector by that over the gap (Davis–Kahan), and q = vᵀDv by twice
/// that (‖D‖ = 1).
fn tolerance_bound(
    g2: &[Vector2<f64>],
    e: &crate::derivations::two_frames::Epipolar,
    tolerance: f64,
) -> f64 {
    let [l0, l1, _, l3] = e.eigenvalues;
    let gap = (l1 - l0).max(f64::MIN_POSITIVE);
    let [_, _, c, d] = e.coefficients;
    let m2 = g2.iter().sum::<Vector2<f64>>() / g2.len() as f64;
    let size = g2.iter().map(|q| (q - m2).norm()).fold(0.0, f64::max);
    let sigma = tolerance * (c * c + d * d).sqrt() * size;
    8.0 * (l3 * g2.len() as f64).sqrt() * sigma / gap
}

/// The least vᵀGv over unit vectors v, free and of equal scale (vᵀDv = 0, D = diag(1, 1,
/// −1, −1)), as (free, equal). The equal-scale least is the dual's maximum over η of the
/// least eigenvalue φ(η) of G − ηD (a concave function, whose slope is −vᵀDv at its least
/// eigenvector v), found by bisection on the slope's sign in [−λ₃, λ₃] (`top` = λ₃, G's
/// largest eigenvalue; beyond, φ falls below φ(0)). Two quadratic forms on the sphere leave
/// no duality gap (Brickman), so the maximum is the constrained least.
fn equal_scale_least(g: &nalgebra::Matrix4<f64>, top: f64) -> (f64, f64) {
    let d = nalgebra::Matrix4::from_diagonal(&nalgebra::Vector4::new(1.0, 1.0, -1.0, -1.0));
    let least = |eta: f64| -> (f64, f64) {
        let eig = (g - d * eta).symmetric_eigen();
        let i = eig.eigenvalues.imin();
        let v = eig.eigenvectors.column(i);
        (eig.eigenvalues[i], (v.transpose() * d * v)[(0, 0)])
    };
    let free = least(0.0).0;
    let top = top.max(f64::MIN_POSITIVE);
    let (mut lo, mut hi) = (-top, top);
    let mut best = free;
    // φ'(η) = −q(η): q < 0 means φ still rises to the right
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        let (phi, q) = least(mid);
        best = best.max(phi);
        if q < 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    (free, best)
}

/// Two frames of points in unknown correspondence that are the same view (congruent: an
/// in-plane motion or a mirror) or a scaled copy: the sorted pairwise squared distances of
/// frame 2 are λ² times frame 1's, within rounding. Correspondence-free, O(n² log n).
pub fn similar_frames(f1: &[Vector2<f64>], f2: &[Vector2<f64>]) -> Option<TwoFrameDegenerate> {
    let sorted = |f: &[Vector2<f64>]| {
        let mut d: Vec<f64> = (0..f.len())
            .flat_map(|i| (i + 1..f.len()).map(move |j| (f[i] - f[j]).norm_squared()))
            .collect();
        d.sort_by(f64::total_cmp);
        d
    };
    let (d1, d2) = (sorted(f1), sorted(f2));
    let (s1, s2): (f64, f64) = (d1.iter().sum(), d2.iter().sum());
    if d1.len() != d2.len() || s1 == 0.0 || s2 == 0.0 {
        return None;
    }
    let l2 = s2 / s1;
    // judged against the largest squared distance (the coordinates' rounding sets the noise)
    let big = d2.last().copied().unwrap_or(0.0) + l2 * d1.last().copied().unwrap_or(0.0);
    let similar = d1
        .iter()
        .zip(&d2)
        .all(|(a, b)| crate::algebra::negligible(b - l2 * a, big));
    if !similar {
        return None;
    }
    Some(if crate::algebra::negligible(l2 - 1.0, 1.0 + l2) {
        TwoFrameDegenerate::IdenticalFrames
    } else {
        TwoFrameDegenerate::ScaledFrames
    })
}
