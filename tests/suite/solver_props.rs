use nalgebra::{Rotation3, Vector2, Vector3};
use orthocheck::derivations::solver::{Degenerate, SquaredLengths};
use orthocheck::derivations::{p3f3, p3f4, p4f3};
use orthocheck::model::{Body, Motion, Scene};
use proptest::prelude::*;

fn truth(scene: &Scene) -> [f64; 3] {
    [(0, 1), (1, 2), (2, 0)].map(|(i, j)| scene.body.squared_distance(i, j))
}

fn relative_error(s: &[f64], t: &[f64; 3]) -> f64 {
    (0..3)
        .map(|e| (s[e] - t[e]).abs() / t[e])
        .fold(0.0, f64::max)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 512, rng_seed: proptest::test_runner::RngSeed::Fixed(11), ..ProptestConfig::default() })]

    #[test]
    fn p3f3_finds_the_truth_among_the_feasible_roots(seed in any::<u64>()) {
        let scene = Scene::random(3, 3, seed);
        let out = p3f3::solve(&SquaredLengths::from_tracks(&scene.tracks())).unwrap();
        let t = truth(&scene);
        let best = out
            .feasible()
            .map(|s| relative_error(&s.squared_edges, &t))
            .fold(f64::INFINITY, f64::min);
        prop_assert!(best < 1e-9, "seed {seed}: best {best}, {out:?}");
        prop_assert!(out.feasible().count() <= 2);
    }

    #[test]
    fn p3f4_is_unique_and_true(seed in any::<u64>(), frames in 4usize..9) {
        let scene = Scene::random(3, frames, seed);
        let out = p3f4::solve(&SquaredLengths::from_tracks(&scene.tracks())).unwrap();
        prop_assert_eq!(out.solutions.len(), 1);
        let s = &out.solutions[0];
        prop_assert!(s.feasibility.is_feasible());
        prop_assert!(relative_error(&s.squared_edges, &truth(&scene)) < 1e-9);
    }

    #[test]
    fn degenerate_scenes_give_their_typed_outcome_and_no_nan(seed in any::<u64>(), t in 0.5f64..3.0, angle in 0.1f64..3.0) {
        // collinear body
        let mut line = Scene::random(3, 3, seed);
        let (p, d) = (line.body.points[0], line.body.points[1] - line.body.points[0]);
        line.body = Body::new(vec![p, p + d, p + t * d]);
        let out = p3f3::solve(&SquaredLengths::from_tracks(&line.tracks())).unwrap();
        prop_assert_eq!(out.degenerate, Some(Degenerate::Collinear));
        // frame 3 = frame 2 turned in the image plane and shifted
        let mut same = Scene::random(3, 3, seed);
        same.motions[2] = Motion {
            rotation: Rotation3::from_axis_angle(&Vector3::z_axis(), angle) * same.motions[1].rotation,
            translation: Vector2::new(t, -t),
        };
        let out = p3f3::solve(&SquaredLengths::from_tracks(&same.tracks())).unwrap();
        prop_assert_eq!(out.degenerate, Some(Degenerate::IdenticalFrames { first: 2, second: 3 }));
        for s in &out.solutions {
            prop_assert!(s.squared_edges.iter().chain(&s.imaginary).all(|v| v.is_finite()));
        }
        // four frames all turned about the viewing axis only: rank 0
        let mut flat = Scene::random(3, 4, seed);
        for i in 1..4 {
            flat.motions[i].rotation = Rotation3::from_axis_angle(&Vector3::z_axis(), angle * i as f64);
        }
        let out = p3f4::solve(&SquaredLengths::from_tracks(&flat.tracks())).unwrap();
        let special = matches!(out.degenerate, Some(Degenerate::SpecialMotion { .. }));
        prop_assert!(special, "{:?}", out.degenerate);
        prop_assert!(out.solutions.is_empty());
    }

    #[test]
    fn p4f3_and_least_squares_recover_generic_bodies(seed in any::<u64>(), points in 4usize..8, frames in 3usize..6) {
        let scene = Scene::random(4, 3, seed);
        let out = p4f3::solve(&SquaredLengths::from_tracks(&scene.tracks())).unwrap();
        prop_assert_eq!(out.solutions.len(), 1);
        prop_assert!(out.solutions[0].feasibility.is_feasible(), "{:?}", out);
        prop_assert!(all_edges_within(&scene, &out.solutions[0].squared_edges, 1e-9));
        let scene = Scene::random(points, frames, seed);
        let out = p4f3::solve_least_squares(&SquaredLengths::from_tracks(&scene.tracks())).unwrap();
        prop_assert!(out.solutions[0].feasibility.is_feasible(), "{:?}", out);
        prop_assert!(all_edges_within(&scene, &out.solutions[0].squared_edges, 1e-9));
    }

    #[test]
    fn a_planar_body_is_a_typed_outcome(seed in any::<u64>(), a in -1.0f64..1.0, b in -1.0f64..1.0) {
        let mut scene = Scene::random(4, 3, seed);
        for x in &mut scene.body.points {
            x.z = a * x.x + b * x.y;
        }
        let out = p4f3::solve(&SquaredLengths::from_tracks(&scene.tracks())).unwrap();
        prop_assert_eq!(out.degenerate, Some(Degenerate::Coplanar));
        prop_assert!(out.solutions.is_empty());
    }
}

fn all_edges_within(scene: &Scene, squares: &[f64], tol: f64) -> bool {
    let e = orthocheck::derivations::solver::edges(scene.body.points.len());
    e.len() == squares.len()
        && e.iter().zip(squares).all(|(&(i, j), s)| {
            let t = scene.body.squared_distance(i, j);
            (s - t).abs() <= tol * t
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 64, rng_seed: proptest::test_runner::RngSeed::Fixed(13), ..ProptestConfig::default() })]

    #[test]
    fn the_true_assignment_ranks_first_with_a_margin(seed in any::<u64>(), shift in 0usize..6) {
        use orthocheck::derivations::identity::{rank_quadruples, epipolar_residual};
        let t = Scene::random(6, 2, seed).tracks();
        // frame 2 rotated in order by `shift`
        let f2: Vec<_> = (0..6).map(|k| t.frames[1][(k + shift) % 6]).collect();
        let ranked = rank_quadruples(&t.frames[0], &f2, |a, b| epipolar_residual(a, b));
        let truth: Vec<usize> = (0..4).map(|i| (i + 6 - shift) % 6).collect();
        prop_assert_eq!(&ranked[0].frame2_indices, &truth);
        // a clear margin: the runner-up is worse by orders of magnitude
        prop_assert!(ranked[1].residual > 1e3 * ranked[0].residual.max(1e-15), "{:?}", &ranked[..2]);
    }

    #[test]
    fn every_member_of_the_two_frame_family_reprojects(seed in any::<u64>(), points in 4usize..12, beta in 0.05f64..3.09) {
        let t = Scene::random(points, 2, seed).tracks();
        let m = orthocheck::derivations::two_frames::family(&t.frames[0], &t.frames[1], &[beta]).unwrap();
        prop_assert!(m[0].reprojection < 1e-9, "{}", m[0].reprojection);
    }
}
