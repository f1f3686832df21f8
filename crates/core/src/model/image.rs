//! Image-plane geometry shared by the two-frame tests.

use nalgebra::Vector2;

/// The distance of `x` from the line through `a` and `b`; the distance from `a` when the two
/// coincide (a degenerate line is a point).
///
/// # Example
/// ```
/// use nalgebra::Vector2;
/// use orthocheck_core::model::point_line_distance;
/// let d = point_line_distance(Vector2::new(0.0, 2.0), Vector2::zeros(), Vector2::new(3.0, 0.0));
/// assert_eq!(d, 2.0);
/// ```
pub fn point_line_distance(x: Vector2<f64>, a: Vector2<f64>, b: Vector2<f64>) -> f64 {
    let dir = b - a;
    let off = x - a;
    let n = dir.norm();
    if n == 0.0 {
        off.norm()
    } else {
        (dir.x * off.y - dir.y * off.x).abs() / n
    }
}

/// The image size: the largest distance of a point from the centroid.
pub fn image_size(f: &[Vector2<f64>]) -> f64 {
    let m = f.iter().sum::<Vector2<f64>>() / f.len().max(1) as f64;
    f.iter()
        .map(|p| (p - m).norm())
        .fold(f64::MIN_POSITIVE, f64::max)
}
