//! Tests of `orthocheck_core::derivations::p4f3`.

use nalgebra::Vector3;
use nalgebra::{Rotation3, Vector2};
use orthocheck_core::derivations::p4f3::lsq::solve_least_squares;
use orthocheck_core::derivations::p4f3::*;
use orthocheck_core::derivations::solver::edges;
use orthocheck_core::derivations::solver::{Degenerate, SquaredLengths};
use orthocheck_core::model::{Body, Motion, Scene};

use crate::truth;

fn max_rel(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs() / y)
        .fold(0.0, f64::max)
}

#[test]
fn edge_index_follows_the_edge_order() {
    for (k, &(i, j)) in edges(9).iter().enumerate() {
        assert_eq!(edge_index(i, j), k);
        assert_eq!(edge_index(j, i), k);
    }
}

#[test]
fn both_forms_recover_generic_scenes_and_fit_them() {
    let scene = Scene::random(4, 3, 31);
    let l = SquaredLengths::from_tracks(&scene.tracks());
    let out = solve(&l).unwrap();
    let s = &out.solutions[0];
    assert!(s.feasibility.is_feasible(), "{out:?}");
    assert!(max_rel(&s.squared_edges, &truth(&scene)) < 1e-9);
    let fit = fit(&scene.tracks(), &s.squared_edges);
    assert!(fit.residual < 1e-9, "{}", fit.residual);
    let scene = Scene::random(7, 5, 32);
    let out = solve_least_squares(&SquaredLengths::from_tracks(&scene.tracks())).unwrap();
    assert!(out.solutions[0].feasibility.is_feasible(), "{out:?}");
    assert!(max_rel(&out.solutions[0].squared_edges, &truth(&scene)) < 1e-9);
    assert!(out.condition.is_some());
}

#[test]
fn a_planar_body_and_special_motions_are_typed_outcomes() {
    let mut scene = Scene::random(4, 3, 33);
    for x in &mut scene.body.points {
        x.z = 0.3 * x.x - 0.2 * x.y;
    }
    scene.body = Body::new(scene.body.points.clone());
    let out = solve(&SquaredLengths::from_tracks(&scene.tracks())).unwrap();
    assert_eq!(out.degenerate, Some(Degenerate::Coplanar), "{out:?}");
    let mut turn = Scene::random(4, 3, 34);
    for i in 1..3 {
        turn.motions[i] = Motion {
            rotation: Rotation3::from_axis_angle(&Vector3::z_axis(), 0.5 * i as f64),
            translation: Vector2::new(0.1, 0.2),
        };
    }
    // frames 2 and 3 differ by an in-plane turn only: the same view, named before the rank
    let out = solve(&SquaredLengths::from_tracks(&turn.tracks())).unwrap();
    assert_eq!(
        out.degenerate,
        Some(Degenerate::IdenticalFrames {
            first: 1,
            second: 2
        }),
        "{out:?}"
    );
    assert!(out.solutions.is_empty());
}

#[test]
fn realization_rejects_impossible_distances() {
    // PQ = QR = 1 but RP = 3: the triangle inequality fails
    let r = realize(&[1.0, 1.0, 9.0, 1.0, 1.0, 1.0], 4);
    assert!(!r.realizable);
}

#[test]
fn cayley_menger_and_heron_of_a_unit_corner() {
    use num_rational::BigRational;
    let r = |n: i64| BigRational::from_integer(n.into());
    // P at the origin, Q, R, T on the axes at distance 1 (edges PQ, QR, RP, TP, TQ, TR):
    // V = 1/6, so 288 V² = 8
    let corner = [r(1), r(2), r(1), r(1), r(2), r(2)];
    assert_eq!(cayley_menger(&corner), r(8));
    // a planar set (T in the plane of P, Q, R) has a zero determinant
    let planar = [r(1), r(2), r(1), r(2), r(1), r(1)];
    assert_eq!(cayley_menger(&planar), r(0));
    // the right triangle with legs 1, 1: 16 A² = 4
    assert_eq!(heron16(&r(1), &r(1), &r(2)), r(4));
    // sides 1, 1, 4 (lengths 1, 1, 2) are degenerate: 16 A² = 0
    assert_eq!(heron16(&r(1), &r(1), &r(4)), r(0));
}
