//! Tests of `orthocheck_core::derivations::degenerate`.

use orthocheck_core::derivations::degenerate::*;
use orthocheck_core::derivations::solver::{Degenerate, SquaredLengths};
use orthocheck_core::model::Scene;

#[test]
fn each_case_in_its_order() {
    let scene = Scene::random(4, 3, 5);
    let mut t = scene.tracks();
    assert_eq!(classify(&SquaredLengths::from_tracks(&t), 3), None);
    // a point listed twice
    for f in &mut t.frames {
        f[3] = f[1];
    }
    assert_eq!(
        classify(&SquaredLengths::from_tracks(&t), 3),
        Some(Degenerate::DuplicatedPoints {
            first: 2,
            second: 4
        })
    );
    // nearly the same point (one ulp away)
    for f in &mut t.frames {
        f[3].x = f[1].x + f[1].x.abs() * f64::EPSILON;
    }
    assert!(matches!(
        classify(&SquaredLengths::from_tracks(&t), 3),
        Some(Degenerate::CoincidentPoints { .. } | Degenerate::DuplicatedPoints { .. })
    ));
    // frame 3 a copy of frame 2: identical
    let mut t = scene.tracks();
    t.frames[2] = t.frames[1].clone();
    let d = classify(&SquaredLengths::from_tracks(&t), 3).unwrap();
    assert_eq!(
        d,
        Degenerate::IdenticalFrames {
            first: 2,
            second: 3
        }
    );
    assert_eq!(refine_frames(d, &t), d);
    // frame 3 = frame 2 turned in the image plane
    let (s, c) = 0.4f64.sin_cos();
    t.frames[2] = t.frames[1]
        .iter()
        .map(|p| nalgebra::Vector2::new(c * p.x - s * p.y + 1.0, s * p.x + c * p.y))
        .collect();
    let d = classify(&SquaredLengths::from_tracks(&t), 3).unwrap();
    assert_eq!(
        refine_frames(d, &t),
        Degenerate::InPlaneMotion {
            first: 2,
            second: 3
        }
    );
    // with a fourth distinct frame the pair is no longer fatal for a three-frame solver
    let mut t4 = Scene::random(4, 4, 6).tracks();
    t4.frames[3] = t4.frames[2].clone();
    assert_eq!(classify(&SquaredLengths::from_tracks(&t4), 3), None);
    assert!(classify(&SquaredLengths::from_tracks(&t4), 4).is_some());
}

#[test]
fn collinear_bodies_with_many_points() {
    let mut t = Scene::random(5, 3, 7).tracks();
    for f in &mut t.frames {
        let (a, d) = (f[0], f[1] - f[0]);
        for (j, p) in f.iter_mut().enumerate() {
            *p = a + d * (0.5 + j as f64);
        }
    }
    assert_eq!(
        classify(&SquaredLengths::from_tracks(&t), 3),
        Some(Degenerate::Collinear)
    );
}
