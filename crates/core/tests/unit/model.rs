//! Tests of `orthocheck_core::model`.

use nalgebra::Vector2;
use num_rational::BigRational;
use num_traits::{One, Zero};
mod image;

use approx::assert_relative_eq;
use orthocheck_core::model::*;

#[test]
fn cayley_is_orthogonal() {
    let v = [
        BigRational::new(1.into(), 2.into()),
        BigRational::new((-3).into(), 4.into()),
        BigRational::new(2.into(), 1.into()),
    ];
    let r = cayley(&v);
    for i in 0..3 {
        for j in 0..3 {
            let dot: BigRational = (0..3).map(|k| &r[i][k] * &r[j][k]).sum();
            let want = if i == j {
                BigRational::one()
            } else {
                BigRational::zero()
            };
            assert_eq!(dot, want);
        }
    }
}

#[test]
fn random_scene_is_seeded_and_rigid() {
    let a = Scene::random(4, 3, 11);
    assert_eq!(a, Scene::random(4, 3, 11));
    assert_ne!(a, Scene::random(4, 3, 12));
    for m in &a.motions {
        assert_relative_eq!(m.rotation.matrix().determinant(), 1.0, epsilon = 1e-12);
    }
    let t = a.tracks();
    // a projection never lengthens an edge
    assert!(t.squared_length(1, 0, 1) <= a.body.squared_distance(0, 1) + 1e-12);
}

#[test]
fn tracks_reject_bad_counts_and_nan() {
    let names = default_names(2);
    assert!(Tracks::new(names.clone(), vec![]).is_err());
    assert!(Tracks::new(names.clone(), vec![vec![Vector2::zeros()]]).is_err());
    let nan = vec![vec![Vector2::zeros(), Vector2::new(f64::NAN, 0.0)]];
    assert!(Tracks::new(names, nan).is_err());
}
