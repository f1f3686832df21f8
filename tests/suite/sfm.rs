//! Orthographic structure from motion: seeded scenes recovered up to the mirror, bundle
//! adjustment's descent, gaps, outliers, degenerate inputs named, the command line.

use std::collections::BTreeSet;
use std::f64::consts::TAU;
use std::path::Path;
use std::process::Command;

use nalgebra::{Rotation3, Vector2, Vector3};
use orthocheck::algebra::kabsch;
use orthocheck::model::{default_names, rng, Body, Motion, NoiseModel, Scene, Tracks};
use orthocheck::sfm::threshold::{RAYLEIGH_INLIER, RAYLEIGH_MEDIAN};
use orthocheck::sfm::{
    bundle_adjust, reconstruct, robust::RansacOptions, tomasi_kanade, BundleOptions, Degenerate,
    Error, Observations, Options, Reconstruction, Units,
};
use rand::Rng;

/// The shape error of `r` against the truth, relative to the body's size: the points centred,
/// turned onto the truth by the best rotation (Kabsch), the better of the reconstruction and
/// its mirror (both give the same images). No scale is fitted: orthography fixes it.
pub(crate) fn shape_error(r: &Reconstruction, truth: &[Vector3<f64>]) -> f64 {
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
    let out = reconstruct(&obs, &Options::default())
        .unwrap()
        .into_single()
        .unwrap();
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
    let out = reconstruct(&obs, &options).unwrap().into_single().unwrap();
    let kept = out.inliers.clone().unwrap();
    let truth: Vec<String> = (0..50)
        .filter(|j| !outliers.contains(j))
        .map(|j| t.names[j].clone())
        .collect();
    assert_eq!(kept, truth);
    // every image of a wrong track dropped, no good image (noise ≤ 0.3 % of 2.7 ≪ 0.02)
    let report = out.robust.clone().unwrap();
    let wrong: Vec<String> = outliers.iter().map(|&j| t.names[j].clone()).collect();
    assert_eq!(report.rejected, wrong);
    assert_eq!(report.dropped.len(), outliers.len() * 6);
    assert!(report.dropped.iter().all(|d| wrong.contains(&d.point)));
    assert_eq!(report.threshold.value, 0.02);
    let inlier_truth: Vec<Vector3<f64>> = (0..50)
        .filter(|j| !outliers.contains(j))
        .map(|j| scene.body.points[j])
        .collect();
    assert!(shape_error(&out.reconstruction, &inlier_truth) <= 0.01);
    // without RANSAC the outliers spoil the shape
    let plain = reconstruct(&obs, &Options::default())
        .unwrap()
        .into_single()
        .unwrap();
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

/// Identical frames, or frames that differ by an in-plane motion only, are refused with gaps
/// as without them: the test runs on what is observed (a quarter of the entries missing, and
/// most of them), not on a "reconstruction" that fits the flat data. 30 points, so that
/// frames next to each other share at least 4 even with most entries missing (with 12, each
/// frame shares 2 or 3 with the next and none can take part: see
/// `frames_that_share_too_few_points_are_never_one_body`).
#[test]
fn degenerate_motion_is_refused_with_gaps_too() {
    let body = Scene::random(30, 1, 7).body.points;
    let spins = [
        Rotation3::from_euler_angles(0.0, 0.0, 0.4),
        Rotation3::from_euler_angles(0.0, 0.0, 1.1),
        Rotation3::from_euler_angles(0.0, 0.0, -0.7),
        Rotation3::identity(),
    ];
    let tracks = scene_of(body.clone(), &spins);
    for (every, keep) in [(4, 3), (5, 2)] {
        // entry (frame f, point p) missing where (f + p) mod `every` ≥ `keep`
        let obs = orthocheck::sfm::Observations::seen_where(&tracks, |f, p| (f + p) % every < keep);
        assert!(obs.complete().is_none());
        let e =
            orthocheck::sfm::reconstruct(&obs, &orthocheck::sfm::Options::default()).unwrap_err();
        assert!(
            matches!(e, Error::Degenerate(Degenerate::InPlaneMotion { .. })),
            "{every}/{keep}: {e}"
        );
    }
    // the control: the same gaps in views that see depth reconstruct
    let turns = [
        Rotation3::from_euler_angles(0.3, 0.5, 0.1),
        Rotation3::from_euler_angles(-0.4, 0.2, 0.7),
        Rotation3::from_euler_angles(0.6, -0.3, 0.2),
        Rotation3::from_euler_angles(-0.2, -0.6, -0.4),
    ];
    let seen = scene_of(body, &turns);
    let obs = orthocheck::sfm::Observations::seen_where(&seen, |f, p| (f + p) % 4 < 3);
    assert!(orthocheck::sfm::reconstruct(&obs, &orthocheck::sfm::Options::default()).is_ok());
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
    // standard errors of every point and frame; frame 1 fixes the frame of reference
    assert_eq!(v["points_std"].as_object().unwrap().len(), 6);
    assert_eq!(v["depth_barely_determined"], serde_json::json!([]));
    let fsd = v["frames_std"].as_array().unwrap();
    assert_eq!(fsd.len(), 4);
    assert_eq!(fsd[0]["rotation_deg"], serde_json::json!([0.0, 0.0, 0.0]));
    assert!(fsd[1..].iter().all(|f| {
        let r = f["rotation_deg"].as_array().unwrap();
        let t = f["translation"].as_array().unwrap();
        r.iter().chain(t).all(|x| x.as_f64().unwrap() > 0.0)
    }));
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
fn reconstruct_names_the_points_whose_depth_is_barely_determined() {
    // frames turned by 1°–2° from the first, and noise: the images fix the points' depth
    // barely (a depth's standard error ≈ the noise over the angle turned)
    let clean = scene_of(
        Scene::random(12, 1, 3).body.points,
        &[
            Rotation3::from_euler_angles(0.02, 0.01, 0.3),
            Rotation3::from_euler_angles(-0.01, 0.03, 0.7),
            Rotation3::from_euler_angles(0.03, -0.02, 1.2),
        ],
    );
    let noisy = NoiseModel::RelativeCoordinate { eps: 0.003 }.perturb_tracks(&clean, &mut rng(8));
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("t.yaml");
    std::fs::write(&file, tracks_yaml(&noisy.frames)).unwrap();
    let f = file.to_str().unwrap();
    let out = orthocheck(&["reconstruct", "--input", f, "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let poor = strings(&v["depth_barely_determined"]);
    // exactly the points whose depth's standard error exceeds a tenth of the body's size
    let points = v["points"].as_object().unwrap();
    let size = (points
        .values()
        .map(|x| {
            x.as_array()
                .unwrap()
                .iter()
                .map(|c| c.as_f64().unwrap().powi(2))
                .sum::<f64>()
        })
        .sum::<f64>()
        / points.len() as f64)
        .sqrt();
    let expected: Vec<&str> = v["points_std"]
        .as_object()
        .unwrap()
        .iter()
        .filter(|(_, e)| e[2].as_f64().unwrap() > 0.1 * size)
        .map(|(n, _)| n.as_str())
        .collect();
    assert!(!poor.is_empty());
    assert_eq!(
        poor.iter().copied().collect::<BTreeSet<_>>(),
        expected.into_iter().collect::<BTreeSet<_>>()
    );
    let text = orthocheck(&["reconstruct", "--input", f]);
    let text = String::from_utf8(text.stdout).unwrap();
    let line = text
        .lines()
        .find(|l| l.starts_with("depth barely determined"))
        .unwrap();
    assert!(poor.iter().all(|n| line.contains(n)), "{line}");
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

/// A JSON array of strings (a test failure if it is anything else).
fn strings(v: &serde_json::Value) -> Vec<&str> {
    v.as_array()
        .unwrap()
        .iter()
        .map(|n| n.as_str().unwrap())
        .collect()
}

/// The most of `n` items a rule that sets each apart with probability `level` may set
/// apart in a test: n·level and three binomial standard deviations.
fn level_bound(n: usize, level: f64) -> f64 {
    let n = n as f64;
    n * level + 3.0 * (n * level * (1.0 - level)).sqrt()
}

/// A standard normal pair from the seeded generator (Box–Muller).
pub(crate) fn normal_pair(g: &mut impl Rng) -> Vector2<f64> {
    let u: f64 = g.random_range(f64::MIN_POSITIVE..1.0);
    let a: f64 = g.random_range(0.0..TAU);
    let r = (-2.0 * u.ln()).sqrt();
    Vector2::new(r * a.cos(), r * a.sin())
}

/// A YAML tracks file of complete frames.
fn tracks_yaml(frames: &[Vec<Vector2<f64>>]) -> String {
    let mut s = String::from("frames:\n");
    for f in frames {
        let row: Vec<String> = f.iter().map(|y| format!("[{}, {}]", y.x, y.y)).collect();
        s.push_str(&format!("  - [{}]\n", row.join(", ")));
    }
    s
}

/// 40 points in 8 frames with normal image noise of `noise` × the image size per coordinate
/// (the size: `Units`' power of two), and outliers: by point j mod 5, 0, 1, 0, 2, 0 images
/// moved by 20 % of the image size in a random direction; the last point's every image
/// replaced by a random point of the image. The frames, the replaced (point, frame) pairs
/// (indices) and σ in image units.
/// Frames of image points, the (point, frame) observations replaced, and the image size.
type Corrupted = (Vec<Vec<Vector2<f64>>>, Vec<(usize, usize)>, f64);

fn corrupted_scene(seed: u64, noise: f64) -> Corrupted {
    let (p, k) = (40, 8);
    let t = Scene::random(p, k, seed).tracks();
    let units = Units::of(&Observations::from_tracks(&t)).unwrap();
    let mut g = rng(seed + 100);
    let mut frames = t.frames.clone();
    for y in frames.iter_mut().flatten() {
        *y += normal_pair(&mut g) * (noise * units.scale);
    }
    let mut replaced = Vec::new();
    for j in 0..p - 1 {
        let mut moved: Vec<usize> = Vec::new();
        while moved.len() < [0, 1, 0, 2, 0][j % 5] {
            let f = g.random_range(0..k);
            if !moved.contains(&f) {
                moved.push(f);
            }
        }
        for &f in &moved {
            let a: f64 = g.random_range(0.0..TAU);
            frames[f][j] += Vector2::new(a.cos(), a.sin()) * (0.2 * units.scale);
            replaced.push((j, f));
        }
    }
    for (f, row) in frames.iter_mut().enumerate() {
        let r = Vector2::new(g.random_range(-1.0..1.0), g.random_range(-1.0..1.0));
        row[p - 1] = units.centre + r * units.scale;
        replaced.push((p - 1, f));
    }
    (frames, replaced, noise * units.scale)
}

/// `reconstruct --robust --json` on a tracks file, with more arguments: the JSON.
fn robust_json(file: &Path, more: &[&str]) -> serde_json::Value {
    let mut args = vec![
        "reconstruct",
        "--input",
        file.to_str().unwrap(),
        "--robust",
        "--json",
    ];
    args.extend_from_slice(more);
    let out = orthocheck(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(!text.contains("NaN") && !text.contains("inf"));
    serde_json::from_str(&text).unwrap()
}

/// The dropped observations of a robust JSON document: (point, frame from 1).
fn dropped_of(v: &serde_json::Value) -> BTreeSet<(String, u64)> {
    v["dropped"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| {
            assert!(d["residual"].is_number() || d["residual"].is_null());
            (
                d["point"].as_str().unwrap().to_string(),
                d["frame"].as_u64().unwrap(),
            )
        })
        .collect()
}

/// The replaced observations by name and frame counted from 1.
fn named(replaced: &[(usize, usize)]) -> BTreeSet<(String, u64)> {
    let names = default_names(40);
    replaced
        .iter()
        .map(|&(j, f)| (names[j].clone(), f as u64 + 1))
        .collect()
}

#[test]
fn robust_mode_takes_its_threshold_from_the_data_and_drops_single_observations() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("outliers.yaml");
    let (frames, replaced, sigma) = corrupted_scene(31, 0.001);
    std::fs::write(&file, tracks_yaml(&frames)).unwrap();
    let v = robust_json(&file, &[]);
    let t = &v["threshold"];
    assert_eq!(t["from"], "data", "{t}");
    let value = t["value"].as_f64().unwrap();
    // about 3.035 σ (a little more: outliers lift the median)
    assert!(
        value > 2.0 * sigma && value < 6.0 * sigma,
        "{value} against σ = {sigma}"
    );
    let dropped = dropped_of(&v);
    let moved = named(&replaced);
    assert!(
        moved.is_subset(&dropped),
        "{:?}",
        moved.difference(&dropped)
    );
    // a 99 % point drops 1 % of the good observations with normal errors, as here: at most
    // that share's count and three of its binomial standard deviations
    let good = 320 - moved.len();
    assert!(
        (dropped.len() - moved.len()) as f64 <= level_bound(good, 0.01),
        "{dropped:?}"
    );
    // every point with at least three good images is kept; the wrong track is rejected
    let names = default_names(40);
    assert_eq!(v["rejected"], serde_json::json!(["P40"]));
    // complete tracks: the first judgement is a sample's
    assert_eq!(v["robust_start"], "sample");
    let kept = strings(&v["inliers"]);
    assert_eq!(kept, names[..39]);
    assert_eq!(v["points"].as_object().unwrap().len(), 39);
    // each kept point's inlier frames: its 8 frames less the dropped
    let inlier_frames = v["inlier_frames"].as_object().unwrap();
    let listed: BTreeSet<&str> = inlier_frames.keys().map(String::as_str).collect();
    assert_eq!(listed, names[..39].iter().map(String::as_str).collect());
    for (name, frames) in inlier_frames {
        let frames: BTreeSet<u64> = frames
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f.as_u64().unwrap())
            .collect();
        let expected: BTreeSet<u64> = (1..=8)
            .filter(|f| !dropped.contains(&(name.clone(), *f)))
            .collect();
        assert_eq!(frames, expected, "{name}");
    }
    // the text says the threshold and counts the dropped
    let out = orthocheck(&["reconstruct", "--input", file.to_str().unwrap(), "--robust"]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("threshold ") && text.contains("from the data"),
        "{text}"
    );
    assert!(text.contains("--threshold sets it"), "{text}");
    assert!(
        text.contains(&format!("dropped observations ({} of 320", dropped.len())),
        "{text}"
    );
    assert!(text.contains("rejected points (1;"), "{text}");
}

/// A long turntable of short tracks (40 frames, each point in 8): no sample explains half
/// the observations, and the JSON says the first judgement came from the whole fit.
#[test]
fn robust_json_names_the_start_of_a_long_sequence() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("long.csv");
    let args = [
        "synth",
        "--points",
        "150",
        "--frames",
        "40",
        "--seed",
        "3",
        "--turntable",
        "--window",
        "8",
        "--noise",
        "0.001",
        "--format",
        "csv",
        "--out",
    ];
    let out = orthocheck(&[&args[..], &[file.to_str().unwrap()]].concat());
    assert!(out.status.success());
    let out = orthocheck(&[
        "reconstruct",
        "--input",
        file.to_str().unwrap(),
        "--robust",
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["robust_start"], "fit of every observation");
    let method = v["method"].as_str().unwrap();
    assert!(method.contains("none of 10000 samples"), "{method}");
}

#[test]
fn robust_mode_on_exact_data_has_a_positive_threshold_and_the_option_overrides_it() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("exact.yaml");
    let (frames, replaced, _) = corrupted_scene(32, 0.0);
    std::fs::write(&file, tracks_yaml(&frames)).unwrap();
    let v = robust_json(&file, &[]);
    let t = &v["threshold"];
    assert_eq!(t["from"], "data", "{t}");
    // the median residual is rounding: the floor, 2^10 ε × the image size at least, decides
    let value = t["value"].as_f64().unwrap();
    assert!(value >= 1024.0 * f64::EPSILON, "{t}");
    assert_eq!(t["floored"], true, "{t}");
    assert_eq!(dropped_of(&v), named(&replaced));
    let given = robust_json(&file, &["--threshold", "0.05"]);
    assert_eq!(
        given["threshold"],
        serde_json::json!({"value": 0.05, "from": "--threshold"})
    );
    assert_eq!(dropped_of(&given), named(&replaced));
    assert_eq!(given["rejected"], serde_json::json!(["P40"]));
}

#[test]
fn the_help_states_the_threshold_rule_of_the_constants() {
    assert!((RAYLEIGH_INLIER - 3.035).abs() < 5e-4);
    assert!((RAYLEIGH_MEDIAN - 1.1774).abs() < 5e-5);
    let out = orthocheck(&["reconstruct", "--help"]);
    let help = String::from_utf8(out.stdout).unwrap();
    assert!(
        help.contains("3.035 σ") && help.contains("1.1774"),
        "{help}"
    );
    assert!(!help.contains("needs --threshold"), "{help}");
}

#[test]
fn robust_mode_weighs_each_residual_by_its_coordinates_under_relative_noise() {
    // noise relative to the coordinates (x ↦ x(1 + u), u uniform in ±1 %): one scale for all
    // residuals drops the images far from the origin; the fit's mix weighs them
    let (mut good, mut lost) = (0, 0);
    for seed in 1..=8 {
        let clean = Scene::random(30, 6, seed).tracks();
        let mut g = rng(seed + 50);
        let mut noisy = NoiseModel::RelativeCoordinate { eps: 0.01 }.perturb_tracks(&clean, &mut g);
        let moved = [(seed as usize % 6, 3usize), ((seed as usize + 2) % 6, 17)];
        for &(f, j) in &moved {
            noisy.frames[f][j] += Vector2::new(0.3, -0.2);
        }
        let options = Options {
            robust: Some(RansacOptions::from_data()),
            ..Options::default()
        };
        let out = reconstruct(&Observations::from_tracks(&noisy), &options)
            .unwrap()
            .into_single()
            .unwrap();
        let r = out.robust.unwrap();
        let t = r.threshold;
        assert!(t.mix().relative >= 0.5, "seed {seed}: {t:?}");
        let dropped: BTreeSet<(usize, usize)> = r
            .dropped
            .iter()
            .map(|d| {
                let j = noisy.names.iter().position(|n| *n == d.point).unwrap();
                (d.frame - 1, j)
            })
            .collect();
        assert!(moved.iter().all(|m| dropped.contains(m)), "seed {seed}");
        good += 180 - moved.len();
        lost += dropped.len() - moved.len();
    }
    // the threshold's rule drops 1 % of good observations (these scenes: 11 of 1424); one
    // scale for all dropped 3.4 % of them (49)
    assert!(
        lost as f64 <= level_bound(good, 0.01),
        "{lost} of {good} good observations dropped"
    );
    // the command says how it weighed them, in JSON and in the text
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("relative.yaml");
    let clean = Scene::random(30, 6, 1).tracks();
    let noisy = NoiseModel::RelativeCoordinate { eps: 0.01 }.perturb_tracks(&clean, &mut rng(51));
    std::fs::write(&file, tracks_yaml(&noisy.frames)).unwrap();
    let t = &robust_json(&file, &[])["threshold"];
    assert!(t["relative"].as_f64().unwrap() >= 0.5, "{t}");
    assert!(t["freedom"].as_u64().unwrap() > 0, "{t}");
    assert!(t["multiple"].as_f64().unwrap() > RAYLEIGH_INLIER, "{t}");
    let out = orthocheck(&["reconstruct", "--input", file.to_str().unwrap(), "--robust"]);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.contains("each residual coordinate x divided by"),
        "{text}"
    );
    assert!(text.contains("degrees of freedom"), "{text}");
}
