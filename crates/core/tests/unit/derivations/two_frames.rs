//! Tests of `orthocheck_core::derivations::two_frames`.

use nalgebra::{Rotation3, Vector3};
use orthocheck_core::derivations::two_frames::*;

#[test]
fn every_member_of_the_family_reprojects_and_they_differ() {
    let scene = orthocheck_core::model::Scene::random(6, 2, 4);
    let t = scene.tracks();
    let m = family(&t.frames[0], &t.frames[1], &[0.3, 1.0, 2.0]).unwrap();
    assert!(
        m.iter().all(|x| x.reprojection < 1e-12),
        "{:?}",
        m.iter().map(|x| x.reprojection).collect::<Vec<_>>()
    );
    let (d, _) = shape_difference(&m[0].points, &m[2].points);
    assert!(d > 1e-3);
    // the true body is a member, up to a shift in depth
    let r = scene.motions[1].rotation;
    let beta = (r.matrix()[(2, 2)]).acos();
    let truth = family(&t.frames[0], &t.frames[1], &[beta]).unwrap();
    let (d, _) = shape_difference(&truth[0].points, &scene.body.points);
    assert!(d < 1e-9, "{d}");
}

#[test]
fn a_constructed_counterexample_is_rebuilt() {
    // the construction run forwards: axis n ⟂ x through P, view u₂ ⟂ n, a turn about n;
    // Q′ on the line through Q along x that meets the turned line q₂′ (in the plane ⟂ n)
    let (p, q, r) = (
        Vector3::zeros(),
        Vector3::new(1.0, 0.7, -0.4),
        Vector3::new(-0.3, 1.2, 0.9),
    );
    let u1 = Vector3::x();
    let n = Vector3::new(0.0, 0.6, 0.8);
    let u2 = (u1 * 0.5 + n.cross(&u1) * 0.8).normalize();
    let rot = Rotation3::from_axis_angle(&nalgebra::Unit::new_normalize(n), 0.9);
    let moved = |x: Vector3<f64>| {
        // x + s u₁ = rot(x) + t rot(u₂): both sides lie in the plane ⟂ n through x
        let (a, b) = (u1, rot * u2);
        let d = rot * (x - p) + p - x;
        let m = nalgebra::Matrix3x2::from_columns(&[a, -b]);
        let st = (m.transpose() * m).try_inverse().unwrap() * m.transpose() * d;
        x + a * st[0]
    };
    let c = counterexample([p, q, r, moved(q), moved(r)]).unwrap();
    assert!(c.image_mismatch < 1e-12, "{c:?}");
    assert!((c.rebuilt[0] - moved(q)).norm() < 1e-9 && (c.rebuilt[1] - moved(r)).norm() < 1e-9);
    assert!((c.sides[0] - c.sides_prime[0]).abs() > 1e-3);
}
