//! Tests of `orthocheck_core::derivations::p3f3`.

use nalgebra::Vector2;
use nalgebra::{Rotation3, Vector3};
use orthocheck_core::derivations::p3f3::*;
use orthocheck_core::derivations::solver::{Degenerate, SquaredLengths};
use orthocheck_core::model::{Body, Motion, Scene};

fn lengths(scene: &Scene) -> SquaredLengths {
    SquaredLengths::from_tracks(&scene.tracks())
}

#[test]
fn recovers_the_truth_and_all_reconstructions_reproject() {
    let scene = Scene::random(3, 3, 21);
    let out = solve(&lengths(&scene)).unwrap();
    let truth = [0, 1, 2].map(|e| {
        let (i, j) = [(0, 1), (1, 2), (2, 0)][e];
        scene.body.squared_distance(i, j)
    });
    let found = out
        .feasible()
        .find(|s| (0..3).all(|e| (s.squared_edges[e] - truth[e]).abs() < 1e-9 * truth[e]))
        .expect("truth among the feasible roots");
    let sq = [
        found.squared_edges[0],
        found.squared_edges[1],
        found.squared_edges[2],
    ];
    let recs = reconstructions(&scene.tracks(), &sq).unwrap();
    assert_eq!(recs.len(), 4);
    assert!(recs.iter().all(|r| r.reprojection_error < 1e-6));
}

#[test]
fn collinear_points_are_a_typed_outcome() {
    let body = Body::new(vec![
        Vector3::new(0.0, 0.0, 0.0),
        Vector3::new(1.0, 2.0, 3.0),
        Vector3::new(2.0, 4.0, 6.0),
    ]);
    let mut scene = Scene::random(3, 3, 2);
    scene.body = body;
    let out = solve(&lengths(&scene)).unwrap();
    assert_eq!(out.degenerate, Some(Degenerate::Collinear));
    assert!(out.solutions.is_empty());
}

#[test]
fn identical_frames_up_to_in_plane_rotation_are_detected() {
    let mut scene = Scene::random(3, 3, 3);
    let r = scene.motions[1].rotation;
    scene.motions[2] = Motion {
        rotation: Rotation3::from_axis_angle(&Vector3::z_axis(), 0.7) * r,
        translation: Vector2::new(0.3, -0.2),
    };
    let out = solve(&lengths(&scene)).unwrap();
    assert!(matches!(
        out.degenerate,
        Some(Degenerate::IdenticalFrames {
            first: 2,
            second: 3
        })
    ));
    assert!(out
        .solutions
        .iter()
        .all(|s| s.squared_edges.iter().all(|v| v.is_finite())));
}

#[test]
fn wrong_counts_are_errors() {
    let l = SquaredLengths::new(
        orthocheck_core::model::default_names(3),
        vec![vec![1.0, 1.0, 1.0]; 4],
    )
    .unwrap();
    assert!(solve(&l).is_err());
}

mod validation_tests {
    use num_rational::BigRational;
    use orthocheck_core::derivations::p3f3::*;

    #[test]
    fn exact_and_float_routes_agree_on_a_random_scene() {
        let scene = orthocheck_core::model::Scene::random(3, 3, 8);
        let t = scene.tracks();
        let l: [[BigRational; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|e| {
                let (a, b) = [(0, 1), (1, 2), (2, 0)][e];
                let d = t.frames[i][a] - t.frames[i][b];
                let x = BigRational::from_float(d.x).unwrap();
                let y = BigRational::from_float(d.y).unwrap();
                &x * &x + &y * &y
            })
        });
        let v = validate(&l);
        assert!(v.same_count, "{v:?}");
        assert_eq!(v.exact.as_ref().map(Vec::len), Some(v.solver.len()));
        // the float route loses at most the conditioning of the quadratic; here well below 1e-9
        assert!(v.max_relative_disagreement < 1e-9, "{v:?}");
    }
}
