//! `reconstruct` on tracks that cannot all take part: points seen once and starved frames
//! dropped and listed, frames that split into groups reconstructed apart, and a warning
//! printed with the whole result and exit 1.

use std::path::Path;

use orthocheck::input::observations_to_yaml;
use orthocheck::model::Scene;
use orthocheck::sfm::turntable::Turntable;
use orthocheck::sfm::{reconstruct, Observations, Options};

use crate::sfm::shape_error;

fn orthocheck(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_orthocheck"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs")
}

/// `reconstruct --input file` with more arguments.
fn run(file: &Path, more: &[&str]) -> std::process::Output {
    let mut args = vec!["reconstruct", "--input", file.to_str().unwrap()];
    args.extend_from_slice(more);
    orthocheck(&args)
}

#[test]
fn a_turntable_with_tracks_seen_once_reconstructs_and_lists_them() {
    let t = Turntable {
        points: 117,
        frames: 36,
        window: 4,
        elevation: 30f64.to_radians(),
        noise: Some(0.001),
        seed: 1,
    };
    let (scene, mut obs) = t.generate();
    // every tenth track cut to its first image
    let cut: Vec<usize> = (0..117).step_by(10).collect();
    for &j in &cut {
        let first = (0..36).find(|&f| obs.frames[f][j].is_some()).unwrap();
        for f in (0..36).filter(|&f| f != first) {
            obs.frames[f][j] = None;
        }
    }
    let out = reconstruct(&obs, &Options::default()).unwrap();
    let names: Vec<&str> = out.dropped_points.iter().map(|d| d.name.as_str()).collect();
    let expected: Vec<String> = cut.iter().map(|j| obs.names[*j].clone()).collect();
    assert_eq!(names, expected);
    assert!(out
        .dropped_points
        .iter()
        .all(|d| d.why.starts_with("seen in 1 frame (frame ")));
    assert!(out.dropped_frames.is_empty());
    let c = out.into_single().unwrap();
    assert_eq!(c.reconstruction.points.len(), 117 - cut.len());
    let truth: Vec<_> = (0..117)
        .filter(|j| !cut.contains(j))
        .map(|j| scene.body.points[j])
        .collect();
    let e = shape_error(&c.reconstruction, &truth);
    assert!(e <= 0.03, "relative shape error {e}");
    // the command line lists them in JSON and in text, and exits 0
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("cut.yaml");
    std::fs::write(&file, observations_to_yaml(&obs)).unwrap();
    let json = run(&file, &["--json"]);
    assert_eq!(
        json.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&json.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    let listed = v["dropped_points"].as_array().unwrap();
    assert_eq!(listed.len(), cut.len());
    assert_eq!(listed[0]["name"], obs.names[0].as_str());
    assert!(listed[0]["why"].as_str().unwrap().contains("at least 2"));
    assert_eq!(v["dropped_frames"], serde_json::json!([]));
    assert_eq!(v["warnings"], serde_json::json!([]));
    assert_eq!(v["points"].as_object().unwrap().len(), 117 - cut.len());
    let text = String::from_utf8(run(&file, &[]).stdout).unwrap();
    assert!(
        text.starts_with(&format!("dropped point {}: seen in 1 frame", obs.names[0])),
        "{text}"
    );
}

/// Two groups of 3 frames × 4 points with nothing in common.
fn two_groups() -> Observations {
    Observations::seen_where(&Scene::random(8, 6, 17).tracks(), |f, j| (f < 3) == (j < 4))
}

#[test]
fn frames_that_share_too_few_points_are_never_one_body() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("two.yaml");
    std::fs::write(&file, observations_to_yaml(&two_groups())).unwrap();
    let out = run(&file, &["--json"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!(v.get("points").is_none(), "one body printed: {v}");
    let parts = v["components"].as_array().unwrap();
    assert_eq!(parts.len(), 2);
    for (c, (frames, names)) in parts.iter().zip([
        ([1, 2, 3], ["P", "Q", "R", "T"]),
        ([4, 5, 6], ["S", "P6", "P7", "P8"]),
    ]) {
        let numbers: Vec<u64> = c["frames"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f["frame"].as_u64().unwrap())
            .collect();
        assert_eq!(numbers, frames);
        let points = c["points"].as_object().unwrap();
        assert!(names.iter().all(|n| points.contains_key(*n)) && points.len() == 4);
        assert!(c["rms"].as_f64().unwrap() < 1e-9);
    }
    let text = String::from_utf8(run(&file, &[]).stdout).unwrap();
    assert!(text.contains("form 2 groups"), "{text}");
    assert!(
        text.contains("group 1 of 2 (frames 1–3), 4 points:"),
        "{text}"
    );
    assert!(
        text.contains("group 2 of 2 (frames 4–6), 4 points:"),
        "{text}"
    );
    assert!(text.contains("points (frame 4's camera coordinates, centred; ± standard errors):"));
    // most entries missing, each point in two frames only: no two frames share four points,
    // and nothing can take part (exit 2, each frame's reason given)
    let sparse =
        Observations::seen_where(&Scene::random(12, 5, 7).tracks(), |f, p| (f + p) % 5 < 2);
    let file = dir.path().join("sparse.yaml");
    std::fs::write(&file, observations_to_yaml(&sparse)).unwrap();
    let out = run(&file, &[]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("no frame can take part: all 5 frames were dropped (frame 1: "),
        "{err}"
    );
    assert!(out.stdout.is_empty());
}

#[test]
fn a_warning_is_printed_with_the_whole_result_and_exits_1() {
    // 201 frames: beyond bundle adjustment's frame limit, so it is skipped, with a warning
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("long.yaml");
    let obs = Observations::from_tracks(&Scene::random(5, 201, 4).tracks());
    std::fs::write(&file, observations_to_yaml(&obs)).unwrap();
    let out = run(&file, &["--json"]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.contains("the result was printed with 1 warning(s): it may be wrong")
            && err.contains("bundle adjustment was skipped"),
        "{err}"
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["frames"].as_array().unwrap().len(), 201);
    assert_eq!(v["points"].as_object().unwrap().len(), 5);
    let w = v["warnings"].as_array().unwrap();
    assert_eq!(w.len(), 1);
    assert!(w[0]
        .as_str()
        .unwrap()
        .starts_with("bundle adjustment was skipped (201 frames"));
    let out = run(&file, &[]);
    assert_eq!(out.status.code(), Some(1));
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.starts_with("warning: bundle adjustment was skipped"),
        "{text}"
    );
    assert!(text.contains("mirror (Necker) solution"), "{text}");
    // without the adjustment nothing is skipped: no warning, exit 0
    assert_eq!(run(&file, &["--no-bundle"]).status.code(), Some(0));
    let help = String::from_utf8(orthocheck(&["reconstruct", "--help"]).stdout).unwrap();
    assert!(
        help.contains("1 the whole result was printed, but with warnings"),
        "{help}"
    );
}

#[test]
fn robust_mode_names_frames_by_their_input_numbers_when_one_is_dropped() {
    use nalgebra::Vector2;
    use orthocheck::sfm::robust::RansacOptions;
    let mut t = Scene::random(20, 6, 23).tracks();
    // frame 4's image of point 8 moved far; frame 1 sees three points only
    t.frames[3][7] += Vector2::new(0.5, -0.4);
    let obs = Observations::seen_where(&t, |f, j| f != 0 || j < 3);
    let options = Options {
        robust: Some(RansacOptions::new(0.01)),
        ..Options::default()
    };
    let out = reconstruct(&obs, &options).unwrap();
    let dropped: Vec<usize> = out.dropped_frames.iter().map(|d| d.frame).collect();
    assert_eq!(dropped, [1]);
    assert_eq!(
        out.dropped_frames[0].why,
        "sees 3 points: at least 4 are needed"
    );
    let c = out.into_single().unwrap();
    assert_eq!(c.frames, [2, 3, 4, 5, 6]);
    let r = c.robust.unwrap();
    let moved: Vec<(String, usize)> = r
        .dropped
        .iter()
        .map(|d| (d.point.clone(), d.frame))
        .collect();
    assert_eq!(moved, [(t.names[7].clone(), 4)]);
    assert_eq!(r.inlier_frames[7], [2, 3, 5, 6]);
    assert_eq!(r.inlier_frames[0], [2, 3, 4, 5, 6]);
}

#[test]
fn a_degenerate_group_is_named_by_the_input_s_frame_numbers() {
    use nalgebra::{Rotation3, Vector2};
    use orthocheck::model::Motion;
    use orthocheck::sfm::{Degenerate, Error};
    // frame 1 sees three points and is dropped; frames 2–4 differ by in-plane turns only
    let body = Scene::random(8, 1, 3).body;
    let motions = [0.9, 0.0, 0.4, 1.1]
        .iter()
        .enumerate()
        .map(|(i, &a)| Motion {
            rotation: match i {
                0 => Rotation3::from_euler_angles(0.5, 0.3, 0.0),
                _ => Rotation3::from_euler_angles(0.0, 0.0, a),
            },
            translation: Vector2::new(0.25, -0.5),
        })
        .collect();
    let t = Scene { body, motions }.tracks();
    let obs = Observations::seen_where(&t, |f, j| f != 0 || j < 3);
    let e = reconstruct(&obs, &Options::default()).unwrap_err();
    assert_eq!(
        e,
        Error::Degenerate(Degenerate::InPlaneMotion {
            first: 2,
            second: 3
        })
    );
}
