//! Orthographic structure from motion: seeded scenes recovered up to the mirror, bundle
//! adjustment's descent, gaps, outliers, degenerate inputs named, the command line.

use std::path::Path;
use std::process::Command;

use nalgebra::{Rotation3, Vector2, Vector3};
use orthocheck::algebra::kabsch;
use orthocheck::model::{rng, Body, Motion, NoiseModel, Scene, Tracks};
use orthocheck::sfm::{
    bundle_adjust, reconstruct, robust::RansacOptions, tomasi_kanade, BundleOptions, Degenerate,
    Error, Observations, Options, Reconstruction,
};
use rand::Rng;

/// The shape error of `r` against the truth, relative to the body's size: the points centred,
/// turned onto the truth by the best rotation (Kabsch), the better of the reconstruction and
/// its mirror (both give the same images). No scale is fitted: orthography fixes it.
fn shape_error(r: &Reconstruction, truth: &[Vector3<f64>]) -> f64 {
    let centred = |v: &[Vector3<f64>]| {
        let c = v.iter().sum::<Vector3<f64>>() / v.len() as f64;
        v.iter().map(|x| x - c).collect::<Vec<_>>()
    };
    let t = centred(truth);
    let size = t.iter().map(|x| x.norm_squared()).sum::<f64>().sqrt();
    [r.clone(), r.mirror()]
        .iter()
        .map(|c| {
            let x = centred(&c.points);
            let k = kabsch(&x, &t);
            x.iter()
                .zip(&t)
                .map(|(a, b)| (k * a - b).norm_squared())
                .sum::<f64>()
                .sqrt()
                / size
        })
        .fold(f64::INFINITY, f64::min)
}

#[test]
fn noiseless_scenes_are_recovered_to_rounding_times_the_conditioning() {
    for seed in 0..20 {
        let (p, k) = (6 + seed as usize, 3 + (seed as usize % 5));
        let scene = Scene::random(p, k, seed);
        let r = tomasi_kanade(&scene.tracks()).unwrap();
        let c = r.conditioning.unwrap();
        // The Gram route perturbs the rank-3 subspace by about nε·κ² (n = 2k + p terms, κ the
        // factor's condition: the eigenvalue gap is σ₃²), the metric null vector by that times
        // the constraints' condition; the refit and rotations are backward stable.
        let bound = f64::EPSILON * (2 * k + p) as f64 * c.factor.powi(2) * c.metric;
        let e = shape_error(&r, &scene.body.points);
        assert!(e <= bound, "seed {seed}: error {e:e} above bound {bound:e}");
        let rot = r.frames[0].rotation;
        assert!((rot - nalgebra::Matrix3::identity()).norm() <= 8.0 * f64::EPSILON * 3.0);
    }
}

#[test]
fn the_mirror_gives_the_same_images() {
    let scene = Scene::random(10, 4, 3);
    let t = scene.tracks();
    let r = tomasi_kanade(&t).unwrap();
    let m = r.mirror();
    let obs = Observations::from_tracks(&t);
    assert!((r.rms(&obs) - m.rms(&obs)).abs() <= 1e3 * f64::EPSILON);
    assert!(m
        .frames
        .iter()
        .all(|f| (f.rotation.determinant() - 1.0).abs() < 1e-12));
}

/// A 1 % relative coordinate noise on a scene.
fn noisy(p: usize, k: usize, seed: u64, eps: f64) -> (Scene, Tracks) {
    let scene = Scene::random(p, k, seed);
    let t =
        NoiseModel::RelativeCoordinate { eps }.perturb_tracks(&scene.tracks(), &mut rng(seed + 7));
    (scene, t)
}

#[test]
fn noisy_scenes_are_recovered_within_the_noise_and_bundle_adjustment_descends() {
    let eps = 0.01;
    for seed in 0..5 {
        let (scene, t) = noisy(40, 8, seed, eps);
        let obs = Observations::from_tracks(&t);
        let tk = tomasi_kanade(&t).unwrap();
        let ba = bundle_adjust(&obs, &tk, &BundleOptions::default()).unwrap();
        let costs = &ba.report.costs;
        assert!(costs.windows(2).all(|w| w[1] <= w[0]), "{costs:?}");
        // the coordinates lie within about 2 of the origin: image errors up to 2ε, so shape
        // errors of that order are the noise itself
        let (e_tk, e_ba) = (
            shape_error(&tk, &scene.body.points),
            shape_error(&ba.reconstruction, &scene.body.points),
        );
        assert!(
            e_tk <= 2.0 * eps && e_ba <= 2.0 * eps,
            "seed {seed}: {e_tk} {e_ba}"
        );
        assert!(ba.reconstruction.rms(&obs) <= tk.rms(&obs));
    }
}

#[test]
fn bundle_adjustment_converges_to_the_truth_from_a_perturbed_start() {
    let scene = Scene::random(30, 6, 11);
    let t = scene.tracks();
    let obs = Observations::from_tracks(&t);
    let mut start = tomasi_kanade(&t).unwrap();
    let mut g = rng(5);
    for x in &mut start.points {
        *x += Vector3::new(
            g.random_range(-0.05..0.05),
            g.random_range(-0.05..0.05),
            g.random_range(-0.05..0.05),
        );
    }
    for f in start.frames.iter_mut().skip(1) {
        let w = Vector3::new(
            g.random_range(-0.05..0.05),
            g.random_range(-0.05..0.05),
            g.random_range(-0.05..0.05),
        );
        f.rotation *= Rotation3::new(w).into_inner();
        f.translation += Vector2::new(0.03, -0.02);
    }
    let before = shape_error(&start, &scene.body.points);
    let ba = bundle_adjust(&obs, &start, &BundleOptions::default()).unwrap();
    let after = shape_error(&ba.reconstruction, &scene.body.points);
    assert!(ba.report.converged);
    let costs = &ba.report.costs;
    assert!(costs.windows(2).all(|w| w[1] <= w[0]));
    // noiseless data: the minimum is the truth, reached to rounding of the coordinates
    // (sizes about 1, 2kp residuals: about √(2kp)·ε in the cost's square root)
    let floor = 64.0 * f64::EPSILON * ((2 * 6 * 30) as f64).sqrt();
    assert!(
        ba.reconstruction.rms(&obs) <= floor,
        "{}",
        ba.reconstruction.rms(&obs)
    );
    assert!(
        after <= 1e3 * floor && after < before / 1e6,
        "{before} → {after}"
    );
}

/// Remove a share of the observations, keeping frames 1–3 and the first 6 points complete.
fn with_gaps(t: &Tracks, share: f64, seed: u64) -> Observations {
    let mut o = Observations::from_tracks(t);
    let mut g = rng(seed);
    for (f, row) in o.frames.iter_mut().enumerate() {
        for (j, y) in row.iter_mut().enumerate() {
            if (f >= 3 || j >= 6) && g.random_range(0.0..1.0) < share {
                *y = None;
            }
        }
    }
    o
}

#[test]
fn tracks_with_gaps_are_reconstructed() {
    let scene = Scene::random(30, 8, 21);
    let obs = with_gaps(&scene.tracks(), 0.3, 2);
    assert!(obs.complete().is_none());
    let out = reconstruct(&obs, &Options::default()).unwrap();
    let r = &out.reconstruction;
    assert!(
        r.method
            .iter()
            .any(|m| m.contains("largest complete block")),
        "{:?}",
        r.method
    );
    assert!(r.method.iter().any(|m| m.contains("intersection")));
    assert!(
        shape_error(r, &scene.body.points) <= 1e-8,
        "{}",
        shape_error(r, &scene.body.points)
    );
    assert!(out.rms <= 1e-10);
}

#[test]
fn robust_mode_survives_twenty_percent_outliers() {
    let (scene, mut t) = noisy(50, 6, 4, 0.001);
    // 10 of 50 point tracks replaced by random image points
    let mut g = rng(99);
    let outliers: Vec<usize> = (0..10).map(|i| 5 * i + 2).collect();
    for f in &mut t.frames {
        for &j in &outliers {
            f[j] = Vector2::new(g.random_range(-2.0..2.0), g.random_range(-2.0..2.0));
        }
    }
    let obs = Observations::from_tracks(&t);
    let options = Options {
        robust: Some(RansacOptions::new(0.02)),
        ..Options::default()
    };
    let out = reconstruct(&obs, &options).unwrap();
    let kept = out.inliers.clone().unwrap();
    let truth: Vec<String> = (0..50)
        .filter(|j| !outliers.contains(j))
        .map(|j| t.names[j].clone())
        .collect();
    assert_eq!(kept, truth);
    let inlier_truth: Vec<Vector3<f64>> = (0..50)
        .filter(|j| !outliers.contains(j))
        .map(|j| scene.body.points[j])
        .collect();
    assert!(shape_error(&out.reconstruction, &inlier_truth) <= 0.01);
    // without RANSAC the outliers spoil the shape
    let plain = reconstruct(&obs, &Options::default()).unwrap();
    assert!(plain.rms > 10.0 * out.rms);
}

/// A scene of `points` under `rotations` (frame 1 the identity).
fn scene_of(points: Vec<Vector3<f64>>, rotations: &[Rotation3<f64>]) -> Tracks {
    let mut motions = vec![Motion::identity()];
    motions.extend(rotations.iter().map(|r| Motion {
        rotation: *r,
        translation: Vector2::new(0.25, -0.5),
    }));
    Scene {
        body: Body::new(points),
        motions,
    }
    .tracks()
}

#[test]
fn degenerate_inputs_are_named() {
    let turns = [
        Rotation3::from_euler_angles(0.3, 0.5, 0.1),
        Rotation3::from_euler_angles(-0.4, 0.2, 0.7),
    ];
    let planar: Vec<Vector3<f64>> = (0..6)
        .map(|i| Vector3::new(i as f64 * 0.3, (i * i) as f64 * 0.1, 0.0))
        .collect();
    let e = tomasi_kanade(&scene_of(planar, &turns)).unwrap_err();
    assert_eq!(e, Error::Degenerate(Degenerate::Coplanar));
    let body = Scene::random(6, 1, 3).body.points;
    let spins = [
        Rotation3::from_euler_angles(0.0, 0.0, 0.4),
        Rotation3::from_euler_angles(0.0, 0.0, 1.1),
    ];
    let e = tomasi_kanade(&scene_of(body.clone(), &spins)).unwrap_err();
    assert_eq!(
        e,
        Error::Degenerate(Degenerate::InPlaneMotion {
            first: 1,
            second: 2
        })
    );
    // frames 1 and 2 the same view turned in the image: the metric is not fixed by the others
    let mixed = [spins[0], turns[0]];
    let e = tomasi_kanade(&scene_of(body.clone(), &mixed)).unwrap_err();
    assert_eq!(
        e,
        Error::Degenerate(Degenerate::InPlaneMotion {
            first: 1,
            second: 2
        })
    );
    let line: Vec<Vector3<f64>> = (0..5)
        .map(|i| Vector3::new(1.0, 2.0, 3.0) * i as f64)
        .collect();
    assert_eq!(
        tomasi_kanade(&scene_of(line, &turns)).unwrap_err(),
        Error::Degenerate(Degenerate::Collinear)
    );
    let few = tomasi_kanade(&Scene::random(3, 5, 1).tracks()).unwrap_err();
    assert_eq!(few, Error::TooFewPoints { points: 3 });
    let two = tomasi_kanade(&Scene::random(8, 2, 1).tracks()).unwrap_err();
    assert_eq!(two, Error::TooFewFrames { frames: 2 });
}

fn orthocheck(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_orthocheck"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs")
}

#[test]
fn reconstruct_prints_json_without_nan_and_refuses_bad_input() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("t.yaml");
    let synth = orthocheck(&[
        "synth", "--points", "6", "--frames", "4", "--seed", "3", "--noise", "0.001",
    ]);
    std::fs::write(&file, &synth.stdout).unwrap();
    let f = file.to_str().unwrap();
    let out = orthocheck(&["reconstruct", "--input", f, "--json"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(!text.contains("NaN") && !text.contains("inf"));
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    // the points in the tracks' order (serde_json's map sorts its keys: read the text)
    let at: Vec<usize> = ["P", "Q", "R", "T", "S", "P6"]
        .iter()
        .map(|n| text.find(&format!("\"{n}\": [")).unwrap())
        .collect();
    assert!(at.windows(2).all(|w| w[0] < w[1]), "{at:?}");
    assert_eq!(v["points"].as_object().unwrap().len(), 6);
    assert_eq!(v["frames"].as_array().unwrap().len(), 4);
    assert!(
        v["mirror"]["points"]["P"].is_array() && v["rms"].is_number() && v["method"].is_string()
    );
    let robust = orthocheck(&[
        "reconstruct",
        "--input",
        f,
        "--robust",
        "--threshold",
        "0.05",
        "--json",
    ]);
    let rv: serde_json::Value = serde_json::from_slice(&robust.stdout).unwrap();
    assert_eq!(rv["inliers"].as_array().unwrap().len(), 6);
    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, "frame,point,x,y\n1,P,0,0\n1,Q,oops,1\n").unwrap();
    let out = orthocheck(&["reconstruct", "--input", bad.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("bad.csv:3: field `x`"), "{err}");
    let planar = dir.path().join("flat.csv");
    let mut csv = String::from("frame,point,x,y\n");
    for f in 1..=3 {
        for (n, x, y) in [
            ("P", 0.0, 0.0),
            ("Q", 1.0, 0.0),
            ("R", 0.0, 1.0),
            ("T", 1.0, 1.0),
        ] {
            csv.push_str(&format!("{f},{n},{},{}\n", x * f as f64, y));
        }
    }
    std::fs::write(&planar, csv).unwrap();
    let out = orthocheck(&["reconstruct", "--input", planar.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("planar"));
}

#[test]
fn reconstruct_snapshot_of_a_small_input() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/sfm/small.yaml");
    let out = orthocheck(&["reconstruct", "--input", path.to_str().unwrap()]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let mut s = insta::Settings::clone_current();
    s.set_snapshot_path(concat!(env!("CARGO_MANIFEST_DIR"), "/snapshots"));
    s.bind(|| {
        insta::assert_snapshot!(
            "cli__reconstruct_small",
            String::from_utf8_lossy(&out.stdout)
        )
    });
}
