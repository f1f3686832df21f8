//! Tests of `orthocheck_core::sfm::missing`: variable projection from the chained pairs
//! reaches the optimum that a start at the truth reaches, and never ends above alternating
//! least squares from the same start.

use nalgebra::Matrix2x4;
use orthocheck_core::sfm::turntable::Turntable;
use orthocheck_core::sfm::{judge, missing, Units};

/// The unit views of a 90 %-missing turntable and its true cameras in the same units.
fn turntable() -> (Vec<judge::Images>, missing::Cameras) {
    let t = Turntable {
        points: 117,
        frames: 36,
        window: 4,
        elevation: 30f64.to_radians(),
        noise: Some(0.001),
        seed: 1,
    };
    let (scene, obs) = t.generate();
    let units = Units::of(&obs).unwrap();
    let views = judge::views(&units.to_unit(&obs));
    let truth = scene
        .motions
        .iter()
        .map(|m| {
            let r = m.rotation.matrix();
            Matrix2x4::from_fn(|a, c| match c {
                3 => (m.translation[a] - units.centre[a]) / units.scale,
                _ => r[(a, c)] / units.scale,
            })
        })
        .collect();
    (views, truth)
}

#[test]
fn the_chained_start_reaches_the_optimum_of_the_truth() {
    let (views, truth) = turntable();
    let chained = missing::chained_start(&views, 36).expect("every frame shares 4 points");
    let from_chain = missing::varpro(&views, chained.clone(), missing::MAX_ITERATIONS).unwrap();
    let from_truth = missing::varpro(&views, truth, missing::MAX_ITERATIONS).unwrap();
    assert!(from_chain.converged && from_truth.converged);
    // each cost is a sum of n squares, rounded by at most γₙ of itself, and each run stops
    // once a step gains at most 4ε of it
    let n = views.iter().map(Vec::len).sum::<usize>() * 2;
    let gamma = n as f64 * f64::EPSILON / (1.0 - n as f64 * f64::EPSILON);
    let tol = 2.0 * (gamma + 4.0 * f64::EPSILON) * from_truth.cost;
    assert!((from_chain.cost - from_truth.cost).abs() <= tol);
    // every point is placed, and alternating least squares from the chain ends no lower
    assert!(from_chain.points.iter().all(Option::is_some));
    let als = missing::als(&views, chained, 200).unwrap();
    assert!(als.cost >= from_chain.cost - tol);
}

#[test]
fn a_point_seen_once_is_named() {
    use orthocheck_core::sfm::{Error, Observations};
    let t = Turntable {
        points: 12,
        frames: 6,
        window: 3,
        elevation: 0.5,
        noise: None,
        seed: 3,
    };
    let (_, mut obs) = t.generate();
    let seen: Vec<usize> = (0..6).filter(|&f| obs.frames[f][0].is_some()).collect();
    for &f in &seen[1..] {
        obs.frames[f][0] = None;
    }
    let err = missing::reconstruct(&Observations { ..obs }, 1).unwrap_err();
    assert!(
        matches!(&err, Error::Unreachable(m) if m.contains("[P1]")),
        "{err}"
    );
}
