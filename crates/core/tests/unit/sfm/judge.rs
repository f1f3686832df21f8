//! Tests of `orthocheck_core::sfm::judge`.

use nalgebra::Vector2;
use orthocheck_core::model::Scene;
use orthocheck_core::sfm::judge::*;
use orthocheck_core::sfm::threshold::Mix;
use orthocheck_core::sfm::{Frame, Observations};

/// The true cameras of a scene.
fn cameras(s: &Scene) -> Vec<Option<Frame>> {
    s.motions
        .iter()
        .map(|m| {
            Some(Frame {
                rotation: m.rotation.into_inner(),
                translation: m.translation,
            })
        })
        .collect()
}

#[test]
fn an_outlying_image_is_dropped_and_its_point_kept() {
    let s = Scene::random(6, 8, 2);
    let mut o = Observations::from_tracks(&s.tracks());
    if let Some(y) = o.frames[3][4].as_mut() {
        *y += Vector2::new(0.3, -0.2);
    }
    let j = judge(&views(&o), 8, &cameras(&s), (1e-6, Mix::UNIFORM));
    assert_eq!(j.kept, [0, 1, 2, 3, 4, 5]);
    assert_eq!(j.dropped.len(), 1);
    assert_eq!((j.dropped[0].point, j.dropped[0].frame), (4, 3));
    assert!(j.dropped[0].residual.is_some_and(|r| r > 0.1));
    assert!(!j.inlier[3][4] && j.inlier[2][4]);
    let kept = j.observations(&o);
    assert_eq!(kept.count(), o.count() - 1);
}

#[test]
fn a_wrong_track_is_rejected_whole() {
    let s = Scene::random(6, 5, 4);
    let mut o = Observations::from_tracks(&s.tracks());
    for (f, row) in o.frames.iter_mut().enumerate() {
        row[2] = Some(Vector2::new(0.7 * f as f64 - 1.0, (f * f) as f64 * 0.3));
    }
    let j = judge(&views(&o), 5, &cameras(&s), (1e-3, Mix::UNIFORM));
    assert_eq!(j.kept, [0, 1, 3, 4, 5]);
    assert_eq!(j.dropped.len(), 5);
    assert!(j.dropped.iter().all(|d| d.point == 2));
}
