//! Tests of `orthocheck_core::model::image`.

use nalgebra::Vector2;
use orthocheck_core::model::image::*;

#[test]
fn on_off_and_degenerate() {
    let (a, b) = (Vector2::new(1.0, 1.0), Vector2::new(3.0, 3.0));
    assert_eq!(point_line_distance(Vector2::new(5.0, 5.0), a, b), 0.0);
    assert!((point_line_distance(Vector2::new(1.0, 3.0), a, b) - 2f64.sqrt()).abs() < 1e-15);
    assert_eq!(point_line_distance(Vector2::new(4.0, 5.0), a, a), 5.0);
}
