//! Tests of `orthocheck_core::derivations::p3f4`.

use nalgebra::{Rotation3, Vector2, Vector3 as V3};
use orthocheck_core::algebra::svd_rank_above;
use orthocheck_core::derivations::p3f4::*;
use orthocheck_core::derivations::solver::{Degenerate, SquaredLengths};
use orthocheck_core::model::{Motion, Scene};

#[test]
fn least_squares_with_many_frames_is_exact_on_exact_data() {
    let scene = Scene::random(3, 7, 13);
    let out = solve(&SquaredLengths::from_tracks(&scene.tracks())).unwrap();
    let s = &out.solutions[0];
    assert!(s.feasibility.is_feasible());
    approx::assert_relative_eq!(
        s.squared_edges[2],
        scene.body.squared_distance(2, 0),
        max_relative = 1e-9
    );
    assert!(out.condition.is_some());
}

#[test]
fn rotation_about_the_viewing_axis_only_is_the_same_view() {
    let mut scene = Scene::random(3, 4, 5);
    for i in 1..4 {
        scene.motions[i] = Motion {
            rotation: Rotation3::from_axis_angle(&V3::z_axis(), 0.3 * i as f64),
            translation: Vector2::zeros(),
        };
    }
    let out = solve(&SquaredLengths::from_tracks(&scene.tracks())).unwrap();
    // frames 2‥4 differ by in-plane turns only: two distinct views, four needed
    assert_eq!(
        out.degenerate,
        Some(Degenerate::IdenticalFrames {
            first: 1,
            second: 2
        })
    );
    assert!(out.solutions.is_empty());
    // the system itself has rank 0 there (the special motion of §3)
    let sys = system(&SquaredLengths::from_tracks(&scene.tracks()));
    assert_eq!(svd_rank_above(&sys.m, sys.noise_m).rank, 0);
}
