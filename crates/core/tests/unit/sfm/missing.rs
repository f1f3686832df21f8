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

#[test]
fn a_run_stops_when_its_work_is_spent_and_says_so() {
    let (views, _) = turntable();
    let chained = missing::chained_start(&views, 36).unwrap();
    let model = missing::Work::of(&views, 36);
    // enough for two steps with one trial each, not for a third
    let mut work = 2.5 * (model.normal + model.trial);
    let f = missing::varpro_within(&views, chained.clone(), missing::MAX_ITERATIONS, &mut work)
        .unwrap();
    assert!(f.out_of_work && !f.converged && f.iterations <= 2, "{f:?}");
    let w = missing::stop_warning(&f).unwrap();
    assert!(
        w.starts_with("variable projection stopped at its work limit (docs/limits.md) after"),
        "{w}"
    );
    assert!(work >= 0.0 && work < model.normal + model.trial);
    // unmetered, the same start converges: the meter, not the data, stopped it
    let free = missing::varpro(&views, chained.clone(), missing::MAX_ITERATIONS).unwrap();
    assert!(free.converged && !free.out_of_work && free.iterations > 2);
    assert_eq!(missing::stop_warning(&free), None);
    // stopped by the iteration limit instead, and said so
    let one = missing::varpro(&views, chained, 1).unwrap();
    assert!(!one.converged && !one.out_of_work);
    let w = missing::stop_warning(&one).unwrap();
    assert!(w.contains("its iteration limit after 1 iterations"), "{w}");
}

#[test]
fn tracks_whose_least_run_exceeds_the_work_limit_are_refused_before_the_work() {
    use orthocheck_core::sfm::{Error, Observations};
    // 2,000 points each in 30 of 100 frames: 20 steps cost 1.07e10 multiply-adds by the model
    let t = Turntable {
        points: 2_000,
        frames: 100,
        window: 30,
        elevation: 0.5,
        noise: None,
        seed: 3,
    };
    let (_, obs) = t.generate();
    let err = missing::reconstruct(&Observations { ..obs }, 1).unwrap_err();
    assert!(
        matches!(&err, Error::TooLarge(m) if m.contains("2000 points in 100 frames")
            && m.contains("more than the limit of 1.0e10")),
        "{err}"
    );
    // 1,800 such points pass the model's check, 9.96e9 (the test does not run them)
    let fewer = Turntable { points: 1_800, ..t }.generate().1;
    let least = missing::Work::of(&judge::views(&fewer), 100).least();
    assert!(least <= orthocheck_core::limits::VARPRO_WORK, "{least}");
}
