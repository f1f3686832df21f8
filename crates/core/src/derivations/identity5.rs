//! §5.3: five points make the identity test linear. The frame-1 ray through S meets the
//! plane PQT at S_a and the plane QRP at S_b; their affine coordinates in those planes are
//! read off frame 1 (projection keeps affine combinations), so their frame-2 images follow
//! from frame 2 alone, and S₂ must lie on the line S₂ₐS₂_b. No quadratic is involved.

use nalgebra::{Matrix2, Vector2};

/// Affine coordinates (α, β) of `x` in the frame (o; u, v): x = o + α u + β v.
fn affine(
    o: Vector2<f64>,
    u: Vector2<f64>,
    v: Vector2<f64>,
    x: Vector2<f64>,
) -> Option<Vector2<f64>> {
    Matrix2::from_columns(&[u, v])
        .try_inverse()
        .map(|m| m * (x - o))
}

/// The distance of S₂ from the line S₂ₐS₂_b, for frames of P, Q, R, T, S (in that order);
/// `None` when a plane's image is degenerate (collinear points).
///
/// # Example
/// ```
/// use orthocheck_core::derivations::identity5::line_distance;
/// let t = orthocheck_core::model::Scene::random(5, 2, 3).tracks();
/// let f = |i: usize| std::array::from_fn(|j| t.frames[i][j]);
/// assert!(line_distance(&f(0), &f(1)).unwrap() < 1e-9);
/// ```
pub fn line_distance(f1: &[Vector2<f64>; 5], f2: &[Vector2<f64>; 5]) -> Option<f64> {
    let [p1, q1, r1, t1, s1] = *f1;
    let [p2, q2, r2, t2, s2] = *f2;
    // S_a in the plane PQT, in terms of TP and TQ; S_b in QRP, in terms of RP and RQ
    let a = affine(t1, p1 - t1, q1 - t1, s1)?;
    let b = affine(r1, p1 - r1, q1 - r1, s1)?;
    let sa = t2 + a.x * (p2 - t2) + a.y * (q2 - t2);
    let sb = r2 + b.x * (p2 - r2) + b.y * (q2 - r2);
    Some(crate::model::point_line_distance(s2, sa, sb))
}
