//! Tests of `orthocheck_core::sfm::groups`: what cannot take part is dropped with its reason,
//! to a fixed point, and frames that share too few points are never one group.

use orthocheck_core::model::{rng, Scene};
use orthocheck_core::sfm::groups::{partition, LINK};
use orthocheck_core::sfm::{Observations, MIN_FRAMES, MIN_POINTS};
use rand::Rng;

/// A random scene's images where `seen(frame, point)` holds.
fn seen_where(p: usize, k: usize, seen: impl Fn(usize, usize) -> bool) -> Observations {
    Observations::seen_where(&Scene::random(p, k, 5).tracks(), seen)
}

#[test]
fn a_point_seen_once_is_dropped_and_the_rest_is_one_group() {
    // P1 only in frame 2; every other point everywhere
    let obs = seen_where(8, 4, |f, j| j != 0 || f == 1);
    let p = partition(&obs);
    assert_eq!(p.groups.len(), 1);
    assert_eq!(p.groups[0].frames, [0, 1, 2, 3]);
    assert_eq!(p.groups[0].points, [1, 2, 3, 4, 5, 6, 7]);
    assert_eq!(p.dropped_points.len(), 1);
    assert_eq!(p.dropped_points[0].name, "P");
    assert_eq!(
        p.dropped_points[0].why,
        "seen in 1 frame (frame 2): at least 2 are needed"
    );
    assert!(p.dropped_frames.is_empty());
}

#[test]
fn drops_cascade_until_nothing_more_drops() {
    // T and S (indices 3, 4) are seen in frame 4 only: dropping them leaves frame 4 with 3
    // of its 5 points, so it goes, and then R (index 2), seen in frames 1 and 4, keeps 1
    // frame and goes too
    let obs = seen_where(9, 4, |f, j| match f {
        3 => j <= 4,
        0 => j != 3 && j != 4,
        _ => j >= 5 || j <= 1,
    });
    let p = partition(&obs);
    let frames: Vec<usize> = p.dropped_frames.iter().map(|d| d.frame).collect();
    assert_eq!(frames, [4]);
    assert!(
        p.dropped_frames[0].why.contains("of its 5 points kept"),
        "{:?}",
        p.dropped_frames
    );
    let names: Vec<&str> = p.dropped_points.iter().map(|d| d.name.as_str()).collect();
    assert_eq!(names, ["R", "T", "S"]);
    assert!(p.dropped_points[0]
        .why
        .contains("1 of its 2 frames is kept (frame 1)"));
    assert_eq!(p.groups.len(), 1);
    assert_eq!(p.groups[0].frames, [0, 1, 2]);
    assert_eq!(p.groups[0].points, [0, 1, 5, 6, 7, 8]);
}

#[test]
fn two_groups_with_nothing_in_common_are_two_groups() {
    // frames 1–3 see points 1–4, frames 4–6 points 5–8
    let obs = seen_where(8, 6, |f, j| (f < 3) == (j < 4));
    let p = partition(&obs);
    assert_eq!(p.groups.len(), 2);
    assert_eq!(p.groups[0].frames, [0, 1, 2]);
    assert_eq!(p.groups[0].points, [0, 1, 2, 3]);
    assert_eq!(p.groups[1].frames, [3, 4, 5]);
    assert_eq!(p.groups[1].points, [4, 5, 6, 7]);
    assert!(p.dropped_points.is_empty() && p.dropped_frames.is_empty());
}

#[test]
fn three_shared_points_do_not_link_and_belong_to_both_groups() {
    // points 1–3 seen everywhere, 4–6 in frames 1–3, 7–9 in frames 4–6
    let obs = seen_where(9, 6, |f, j| j < 3 || (f < 3) == (j < 6));
    let p = partition(&obs);
    assert_eq!(p.groups.len(), 2);
    assert_eq!(p.groups[0].points, [0, 1, 2, 3, 4, 5]);
    assert_eq!(p.groups[1].points, [0, 1, 2, 6, 7, 8]);
    // a fourth shared point links them
    let linked = seen_where(9, 6, |f, j| j < 4 || (f < 3) == (j < 6));
    assert_eq!(partition(&linked).groups.len(), 1);
}

#[test]
fn a_pair_of_frames_apart_is_dropped_and_named() {
    // frames 1–3 share points 1–5; frames 4 and 5 share points 6–10 with each other only
    let obs = seen_where(10, 5, |f, j| (f < 3) == (j < 5));
    let p = partition(&obs);
    assert_eq!(p.groups.len(), 1);
    assert_eq!(p.groups[0].frames, [0, 1, 2]);
    let frames: Vec<usize> = p.dropped_frames.iter().map(|d| d.frame).collect();
    assert_eq!(frames, [4, 5]);
    assert!(p.dropped_frames[0]
        .why
        .starts_with("linked to frame 5 only"));
    assert!(p.dropped_frames[0]
        .why
        .contains("two frames never determine the body"));
    assert_eq!(p.dropped_points.len(), 5);
    assert!(p.dropped_points[0]
        .why
        .starts_with("none of its 2 frames is kept"));
}

/// On random gap patterns the partition is a fixed point of its rules: every group has at
/// least 3 frames, every frame of a group sees at least 4 of its points, each of its points
/// is seen in 2 of its frames, frames of different groups share fewer than 4 kept points,
/// and everything not in a group is listed as dropped.
#[test]
fn the_partition_is_a_fixed_point_of_its_rules() {
    let mut g = rng(11);
    for trial in 0..200 {
        let (p, k) = (g.random_range(4..30), g.random_range(3..12));
        let share: f64 = g.random_range(0.1..0.9);
        let mask: Vec<Vec<bool>> = (0..k)
            .map(|_| (0..p).map(|_| g.random_range(0.0..1.0) < share).collect())
            .collect();
        let obs = seen_where(p, k, |f, j| mask[f][j]);
        let part = partition(&obs);
        let mut group_of = vec![None; k];
        let mut placed = vec![false; p];
        for (i, grp) in part.groups.iter().enumerate() {
            assert!(grp.frames.len() >= MIN_FRAMES, "trial {trial}");
            for &f in &grp.frames {
                assert!(group_of[f].is_none());
                group_of[f] = Some(i);
                let n = grp.points.iter().filter(|&&j| mask[f][j]).count();
                assert!(n >= MIN_POINTS, "trial {trial}: frame {f} sees {n}");
            }
            for &j in &grp.points {
                placed[j] = true;
                let n = grp.frames.iter().filter(|&&f| mask[f][j]).count();
                assert!(n >= 2, "trial {trial}: point {j} in {n} frames");
            }
        }
        for a in 0..k {
            for b in a + 1..k {
                if let (Some(x), Some(y)) = (group_of[a], group_of[b])
                    && x != y
                {
                    let shared = (0..p)
                        .filter(|&j| placed[j] && mask[a][j] && mask[b][j])
                        .count();
                    assert!(
                        shared < LINK,
                        "trial {trial}: frames {a}, {b} share {shared}"
                    );
                }
            }
        }
        let dropped_f = part.dropped_frames.len();
        let dropped_p = part.dropped_points.len();
        assert_eq!(dropped_f, group_of.iter().filter(|g| g.is_none()).count());
        assert_eq!(dropped_p, placed.iter().filter(|&&x| !x).count());
        assert!(part
            .dropped_frames
            .iter()
            .all(|d| group_of[d.frame - 1].is_none() && !d.why.is_empty()));
    }
}
