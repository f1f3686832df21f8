//! Tests of `orthocheck_core::derivations::identity`.

use nalgebra::{Vector2, Vector3};
use orthocheck_core::derivations::identity::membership::membership;
use orthocheck_core::derivations::identity::wellposed::*;
use orthocheck_core::derivations::identity::*;
use orthocheck_core::model::Scene;

#[test]
fn degenerate_frames_are_named() {
    let t = Scene::random(3, 2, 1).tracks();
    assert_eq!(
        degeneracy(&t.frames[0], &t.frames[1]),
        Some(TwoFrameDegenerate::TooFewPoints)
    );
    let mut s = Scene::random(5, 2, 2);
    s.motions[1].rotation = nalgebra::Rotation3::from_axis_angle(&Vector3::z_axis(), 0.4);
    let t = s.tracks();
    assert_eq!(
        degeneracy(&t.frames[0], &t.frames[1]),
        Some(TwoFrameDegenerate::IdenticalFrames)
    );
    let mut s = Scene::random(5, 2, 3);
    for x in &mut s.body.points {
        x.z = 0.5 * x.x - 0.3 * x.y;
    }
    let t = s.tracks();
    assert_eq!(
        degeneracy(&t.frames[0], &t.frames[1]),
        Some(TwoFrameDegenerate::Planar)
    );
    let mut s = Scene::random(5, 2, 4);
    s.body.points[4] = s.body.points[1];
    let t = s.tracks();
    assert_eq!(
        degeneracy(&t.frames[0], &t.frames[1]),
        Some(TwoFrameDegenerate::CoincidentPoints)
    );
    let t = Scene::random(6, 2, 5).tracks();
    assert_eq!(degeneracy(&t.frames[0], &t.frames[1]), None);
}

#[test]
fn the_full_correspondence_and_membership() {
    let s = Scene::random(7, 2, 9);
    let t = s.tracks();
    let perm = [3, 0, 6, 1, 5, 2, 4];
    let shuffled: Vec<Vector2<f64>> = (0..7)
        .map(|j| t.frames[1][perm.iter().position(|p| *p == j).unwrap_or(0)])
        .collect();
    let best = full_correspondence(&t.frames[0], &shuffled).unwrap();
    let found: Vec<usize> = best.frame2_indices.clone();
    for (i, &j) in found.iter().enumerate() {
        assert_eq!(shuffled[j], t.frames[1][i]);
    }
    // an outsider: move one point of frame 2 off its epipolar line
    let mut f2 = t.frames[1].clone();
    f2[5] += Vector2::new(0.3, -0.2);
    let m = membership(&t.frames[0], &f2, 1e-9);
    assert!(!m[5].0);
    assert!(m
        .iter()
        .enumerate()
        .all(|(i, (inside, _))| *inside == (i != 5)));
}
