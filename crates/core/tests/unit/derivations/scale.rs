//! Tests of `orthocheck_core::derivations::scale`.

use nalgebra::Vector2;
use orthocheck_core::derivations::scale::*;
use orthocheck_core::model::Tracks;

fn tracks(k: f64, shift: f64) -> Tracks {
    let f = |a: f64| {
        vec![
            Vector2::new(shift + 0.1 * k, shift - 0.3 * k * a),
            Vector2::new(shift + 0.7 * k * a, shift + 0.2 * k),
            Vector2::new(shift - 0.4 * k, shift + 0.5 * k),
        ]
    };
    Tracks::new(
        vec!["P".into(), "Q".into(), "R".into()],
        vec![f(1.0), f(2.0)],
    )
    .unwrap()
}

#[test]
fn unit_size_and_exact_power_of_two_scales() {
    let n = normalise(&tracks(1e-100, 0.0)).unwrap();
    let big = n
        .tracks
        .frames
        .iter()
        .flatten()
        .fold(0.0_f64, |m, p| m.max(p.x.abs()).max(p.y.abs()));
    assert!((1.0..2.0).contains(&big), "{big}");
    assert_eq!(n.scale.log2().fract(), 0.0);
    let n = normalise(&tracks(1e80, 1e80)).unwrap();
    assert!(n.scale > 1e79 && n.scale < 1e81);
}

#[test]
fn sizes_beyond_the_range_are_typed_errors_on_both_sides() {
    assert!(normalise(&tracks(1e149, 0.0)).is_ok());
    assert!(normalise(&tracks(1e160, 0.0)).is_err());
    assert!(normalise(&tracks(1e-149, 0.0)).is_ok());
    assert!(normalise(&tracks(1e-160, 0.0)).is_err());
    let e = normalise(&tracks(1e300, 0.0)).unwrap_err().to_string();
    assert!(e.contains("orders of magnitude"), "{e}");
}
