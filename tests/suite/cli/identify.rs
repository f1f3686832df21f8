//! `identify`, `membership` and `family` on two frames.

use super::{json, orthocheck};

#[test]
fn identify_membership_and_family_on_two_frames() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("two.csv");
    // five points in two frames; frame 2 listed in another order
    let t = orthocheck::model::Scene::random(5, 2, 21).tracks();
    let order = [3, 0, 4, 2, 1];
    let mut csv = String::from("frame,point,x,y\n");
    for (i, p) in t.frames[0].iter().enumerate() {
        csv.push_str(&format!("1,{},{:?},{:?}\n", t.names[i], p.x, p.y));
    }
    for (k, &j) in order.iter().enumerate() {
        let p = t.frames[1][j];
        csv.push_str(&format!("2,X{k},{:?},{:?}\n", p.x, p.y));
    }
    std::fs::write(&file, csv).unwrap();
    let out = orthocheck(&["identify", "--input", file.to_str().unwrap(), "--json"]);
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v = json(&out);
    let best: Vec<usize> = v["assignments"][0]["frame2_indices"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_u64().unwrap() as usize)
        .collect();
    // frame-1 point i is frame-2 index k with order[k] == i
    let truth: Vec<usize> = (0..4)
        .map(|i| order.iter().position(|j| *j == i).unwrap())
        .collect();
    assert_eq!(best, truth);
    assert!(v["full"]["frame2_indices"].as_array().unwrap().len() == 5);

    let same = dir.path().join("same.yaml");
    std::fs::write(&same, orthocheck::input::tracks_to_yaml(&t)).unwrap();
    let out = orthocheck(&["membership", "--input", same.to_str().unwrap(), "--json"]);
    assert_eq!(out.status.code(), Some(0));
    assert!(json(&out)
        .as_array()
        .unwrap()
        .iter()
        .all(|r| r["member"] == true));
    let out = orthocheck(&[
        "family",
        "--input",
        same.to_str().unwrap(),
        "--samples",
        "3",
        "--json",
    ]);
    assert_eq!(json(&out).as_array().unwrap().len(), 3);
    // three points are too few; three frames are not two
    let three = dir.path().join("three.yaml");
    let t3 = orthocheck::model::Scene::random(3, 2, 1).tracks();
    std::fs::write(&three, orthocheck::input::tracks_to_yaml(&t3)).unwrap();
    assert_eq!(
        orthocheck(&["identify", "--input", three.to_str().unwrap()])
            .status
            .code(),
        Some(2)
    );
    let out = orthocheck(&["family", "--input", "tests/bad_tracks/two_frames.yaml"]);
    assert_eq!(out.status.code(), Some(2));
}

/// identify's time grows as n⁴ (n⁵ for five): beyond the method's limit it refuses before any
/// work (exit 2), naming the limit and the override; `--max-points` moves the limit.
#[test]
fn identify_refuses_more_points_than_its_limit() {
    let dir = tempfile::tempdir().unwrap();
    let big = dir.path().join("big.yaml");
    let n = orthocheck::limits::IDENTIFY_POINTS_EPIPOLAR + 1;
    let t = orthocheck::model::Scene::random(n, 2, 5).tracks();
    std::fs::write(&big, orthocheck::input::tracks_to_yaml(&t)).unwrap();
    let start = std::time::Instant::now();
    let out = orthocheck(&["identify", "--input", big.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    let e = String::from_utf8_lossy(&out.stderr);
    assert!(
        e.contains(&format!("is {n}, more than the limit of {}", n - 1))
            && e.contains("--max-points"),
        "{e}"
    );
    assert!(e.contains("big.yaml"), "the message names the file: {e}");
    assert!(start.elapsed() < std::time::Duration::from_secs(5));
    for (method, limit) in [
        ("four", orthocheck::limits::IDENTIFY_POINTS_FOUR),
        ("five", orthocheck::limits::IDENTIFY_POINTS_FIVE),
    ] {
        let e = orthocheck(&[
            "identify",
            "--input",
            big.to_str().unwrap(),
            "--method",
            method,
        ]);
        assert_eq!(e.status.code(), Some(2));
        assert!(String::from_utf8_lossy(&e.stderr).contains(&format!("limit of {limit}")));
    }
    // the override lowers it as well as raising it
    let small = dir.path().join("small.yaml");
    let t = orthocheck::model::Scene::random(5, 2, 5).tracks();
    std::fs::write(&small, orthocheck::input::tracks_to_yaml(&t)).unwrap();
    let s = small.to_str().unwrap();
    assert_eq!(
        orthocheck(&["identify", "--input", s, "--max-points", "4"])
            .status
            .code(),
        Some(2)
    );
    assert_eq!(
        orthocheck(&["identify", "--input", s, "--max-points", "5"])
            .status
            .code(),
        Some(0)
    );
}

/// `membership` without `--tolerance` takes it from the data's noise: a foreign point among
/// six points of one body at 0.1 % noise is set apart, the five others kept, in every scene.
#[test]
fn membership_finds_a_foreign_point_at_its_default_tolerance() {
    use rand::{Rng, SeedableRng};
    let dir = tempfile::tempdir().unwrap();
    for seed in 1..=10u64 {
        let mut t = orthocheck::model::Scene::random(6, 2, seed).tracks();
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
        for f in &mut t.frames {
            for p in f.iter_mut() {
                p.x *= 1.0 + 1e-3 * rng.random_range(-1.0..1.0);
                p.y *= 1.0 + 1e-3 * rng.random_range(-1.0..1.0);
            }
        }
        // the last point of frame 2 belongs to another body: moved by a third of the image
        let size = t.frames[1].iter().map(|p| p.norm()).fold(0.0f64, f64::max);
        t.frames[1][5].x += size / 3.0;
        t.frames[1][5].y -= size / 4.0;
        let file = dir.path().join(format!("six-{seed}.yaml"));
        std::fs::write(&file, orthocheck::input::tracks_to_yaml(&t)).unwrap();
        let out = orthocheck(&["membership", "--input", file.to_str().unwrap(), "--json"]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "seed {seed}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let members: Vec<bool> = json(&out)
            .as_array()
            .unwrap()
            .iter()
            .map(|r| r["member"] == true)
            .collect();
        assert_eq!(
            members,
            [true, true, true, true, true, false],
            "seed {seed}"
        );
    }
    let out = orthocheck(&["membership", "--input", "tests/bad_tracks/two_frames.yaml"]);
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.code() != Some(0) || text.contains("from the data"),
        "{text}"
    );
}

/// Views of no rigid body are refused, exit 2: 30 points with relative noise of 0.5 %
/// (`synth --noise`'s model) and frame 2 stretched to twice its width (the unit tests and
/// `membership_calibration STRETCH=2` measure how often). The worst-case bound alone let
/// this scene through, exit 0, as it let 10 of seeds 1–12 of such scenes; with the F test
/// all 12 are refused.
#[test]
fn membership_refuses_stretched_views() {
    use orthocheck::model::{rng, NoiseModel, Scene};
    const SEED: u64 = 1;
    let dir = tempfile::tempdir().unwrap();
    let mut clean = Scene::random(30, 2, SEED).tracks();
    clean.frames[1].iter_mut().for_each(|p| p.x *= 2.0);
    let t = NoiseModel::RelativeCoordinate { eps: 5e-3 }.perturb_tracks(&clean, &mut rng(SEED));
    let file = dir.path().join("stretched.yaml");
    std::fs::write(&file, orthocheck::input::tracks_to_yaml(&t)).unwrap();
    let out = orthocheck(&["membership", "--input", file.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{err}");
    assert!(
        err.contains("no rigid body") && err.contains("own residuals"),
        "{err}"
    );
}

/// Under noise relative to the coordinates (30 points of one body, 0.5 %), `membership`
/// finds the noise growing with them and gives each point its own tolerance, in the text
/// and in JSON; the foreign point is set apart. (The level itself, over 200 scenes: the
/// unit test `the_default_tolerance_follows_noise_relative_to_the_coordinates`.)
#[test]
fn membership_gives_each_point_its_own_tolerance_under_relative_noise() {
    use rand::{Rng, SeedableRng};
    let dir = tempfile::tempdir().unwrap();
    let mut t = orthocheck::model::Scene::random(31, 2, 3).tracks();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(3);
    for p in t.frames.iter_mut().flatten() {
        p.x *= 1.0 + 5e-3 * rng.random_range(-1.0..1.0);
        p.y *= 1.0 + 5e-3 * rng.random_range(-1.0..1.0);
    }
    let size = t.frames[1].iter().map(|p| p.norm()).fold(0.0f64, f64::max);
    t.frames[1][30].x += size / 3.0;
    let file = dir.path().join("thirty.yaml");
    std::fs::write(&file, orthocheck::input::tracks_to_yaml(&t)).unwrap();
    let out = orthocheck(&["membership", "--input", file.to_str().unwrap(), "--json"]);
    assert_eq!(out.status.code(), Some(0));
    let rows = json(&out);
    let rows = rows.as_array().unwrap();
    let member: Vec<bool> = rows.iter().map(|r| r["member"] == true).collect();
    // each true member is rejected with probability 1 % at most: three or more of 30 with
    // probability 0.3 % (this scene: 28 kept)
    assert!(
        member[..30].iter().filter(|m| **m).count() >= 28,
        "{member:?}"
    );
    assert!(!member[30]);
    let tol: Vec<f64> = rows
        .iter()
        .map(|r| r["tolerance"].as_f64().unwrap())
        .collect();
    let (lo, hi) = tol
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(a, b), t| (a.min(*t), b.max(*t)));
    assert!(
        hi > 2.0 * lo,
        "tolerances from {lo} to {hi}: one scale, not one per point"
    );
    let text = orthocheck(&["membership", "--input", file.to_str().unwrap()]);
    let text = String::from_utf8_lossy(&text.stdout);
    assert!(
        text.contains("noise weight") && text.contains("(at most "),
        "{text}"
    );
}
