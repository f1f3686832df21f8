//! Structure from motion on tracks as real sequences give them: turntable-like missing
//! data, outlying single observations, Huber's loss, and three frames that share only three
//! points.

use std::collections::BTreeSet;

use nalgebra::Vector2;
use orthocheck::model::{rng, Scene, Tracks};
use orthocheck::sfm::{
    bundle_adjust, reconstruct, robust::RansacOptions, tomasi_kanade, BundleOptions, Error,
    Observations, Options, Units,
};
use rand::Rng;

use crate::sfm::{normal_pair, shape_error};

/// The images robust mode dropped, as (point, frame counted from 1).
fn dropped_images(report: &orthocheck::sfm::robust::RobustReport) -> BTreeSet<(String, usize)> {
    report
        .dropped
        .iter()
        .map(|d| (d.point.clone(), d.frame))
        .collect()
}

#[test]
fn a_turntable_sequence_ninety_percent_missing_is_reconstructed() {
    use orthocheck::sfm::turntable::Turntable;
    // 36 frames, every point in 4 consecutive ones: 89 % missing, 13 points a frame
    let t = Turntable {
        points: 117,
        frames: 36,
        window: 4,
        elevation: 30f64.to_radians(),
        noise: Some(0.001),
        seed: 1,
    };
    let (scene, obs) = t.generate();
    let cells = 117 * 36;
    assert_eq!(obs.count(), 117 * 4);
    assert!(1.0 - obs.count() as f64 / cells as f64 > 0.88);
    let per_frame: Vec<usize> = obs
        .frames
        .iter()
        .map(|f| f.iter().flatten().count())
        .collect();
    assert!(
        per_frame.iter().all(|&n| (12..=14).contains(&n)),
        "{per_frame:?}"
    );
    let out = reconstruct(&obs, &Options::default())
        .unwrap()
        .into_single()
        .unwrap();
    let method = out.reconstruction.method.join("; ");
    assert!(method.starts_with("variable projection"), "{method}");
    assert!(method.contains("metric upgrade") && method.contains("bundle adjustment"));
    // a clean first fit is checked against the other starts too, and kept when none is lower
    assert!(
        method.ends_with("tracks with gaps: of 10 starts, the one of least final cost (2.55534e-5) kept: the first"),
        "{method}"
    );
    assert!(
        out.reconstruction.warnings.is_empty(),
        "{:?}",
        out.reconstruction.warnings
    );
    // every point (each in 4 ≥ 2 frames) returned, within 3 % of the body's size
    assert_eq!(out.reconstruction.points.len(), 117);
    let e = shape_error(&out.reconstruction, &scene.body.points);
    assert!(e <= 0.03, "relative shape error {e}");
    // each coordinate moved by at most 0.1 % of itself: the truth reprojects within
    // √2 · 0.001 · the largest coordinate, and the fit (the least squares) no worse
    let big = obs.seen().map(|(_, _, y)| y.amax()).fold(0.0, f64::max);
    assert!(out.rms <= 2f64.sqrt() * 0.001 * big, "rms {}", out.rms);
}

#[test]
fn robust_mode_returns_every_point_from_its_inliers_at_fifteen_percent_outlying_observations() {
    let (p, k) = (40, 8);
    let scene = Scene::random(p, k, 21);
    let clean = scene.tracks();
    let units = Units::of(&Observations::from_tracks(&clean)).unwrap();
    let mut g = rng(22);
    let mut noisy = clean.frames.clone();
    for y in noisy.iter_mut().flatten() {
        *y += normal_pair(&mut g) * (0.001 * units.scale);
    }
    let good = Tracks::new(clean.names.clone(), noisy.clone()).unwrap();
    // 15 % of the observations replaced by random points of the image
    let mut spoiled = noisy;
    let mut replaced = BTreeSet::new();
    while replaced.len() < (p * k * 15) / 100 {
        replaced.insert((g.random_range(0..p), g.random_range(0..k)));
    }
    for &(j, f) in &replaced {
        let r = Vector2::new(g.random_range(-1.0..1.0), g.random_range(-1.0..1.0));
        spoiled[f][j] = units.centre + r * units.scale;
    }
    let bad = Tracks::new(clean.names.clone(), spoiled).unwrap();
    let robust = Options {
        robust: Some(RansacOptions::from_data()),
        ..Options::default()
    };
    let free = reconstruct(&Observations::from_tracks(&good), &Options::default())
        .unwrap()
        .into_single()
        .unwrap();
    let out = reconstruct(&Observations::from_tracks(&bad), &robust)
        .unwrap()
        .into_single()
        .unwrap();
    let report = out.robust.as_ref().unwrap();
    assert_eq!(report.kept.len(), p, "rejected: {:?}", report.rejected);
    // no replaced observation kept (a random point lies far beyond the threshold)
    let dropped = dropped_images(report);
    for &(j, f) in &replaced {
        assert!(
            dropped.contains(&(clean.names[j].clone(), f + 1)),
            "{j} {f}"
        );
    }
    let (e_free, e) = (
        shape_error(&free.reconstruction, &scene.body.points),
        shape_error(&out.reconstruction, &scene.body.points),
    );
    assert!(
        e <= 2.0 * e_free,
        "error {e} against {e_free} without outliers"
    );
}

#[test]
fn huber_loss_bounds_the_pull_of_an_outlier_in_bundle_adjustment() {
    let scene = Scene::random(20, 5, 41);
    let clean = scene.tracks();
    let mut g = rng(42);
    let mut frames = clean.frames.clone();
    for y in frames.iter_mut().flatten() {
        *y += normal_pair(&mut g) * 0.001;
    }
    // one observation moved far: the judgement would drop it; here it stays in
    frames[2][7] += Vector2::new(0.5, -0.4);
    let t = Tracks::new(clean.names.clone(), frames).unwrap();
    let obs = Observations::from_tracks(&t);
    let start = tomasi_kanade(&t).unwrap();
    let adjust = |huber| {
        let o = BundleOptions {
            huber,
            ..BundleOptions::default()
        };
        bundle_adjust(&obs, &start, &o).unwrap()
    };
    let (ls, hub) = (adjust(None), adjust(Some(0.00135)));
    // reweighting lowers Huber's cost at every accepted step
    assert!(hub.report.costs.windows(2).all(|w| w[1] < w[0]));
    assert!(hub
        .reconstruction
        .method
        .last()
        .unwrap()
        .contains("huber loss"));
    let (e_ls, e_hub) = (
        shape_error(&ls.reconstruction, &scene.body.points),
        shape_error(&hub.reconstruction, &scene.body.points),
    );
    assert!(
        e_hub < e_ls / 2.0,
        "huber {e_hub} against least squares {e_ls}"
    );
    let bad = BundleOptions {
        huber: Some(0.0),
        ..BundleOptions::default()
    };
    assert!(matches!(
        bundle_adjust(&obs, &start, &bad),
        Err(Error::InvalidOption(_))
    ));
}

#[test]
fn where_three_frames_share_only_three_points_ransac_uses_the_three_point_solver() {
    // P1–P3 in all 4 frames; every other point in exactly 2 frames (each pair of frames
    // twice, three times over): any 3 frames share P1–P3 only, so no four-point sample
    // exists and every hypothesis comes from §3's solver
    let pairs = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];
    let p = 3 + 3 * pairs.len();
    let scene = Scene::random(p, 4, 51);
    let clean = scene.tracks();
    let mut g = rng(52);
    let mut frames = clean.frames.clone();
    for y in frames.iter_mut().flatten() {
        *y += normal_pair(&mut g) * 1e-4;
    }
    let t = Tracks::new(clean.names.clone(), frames).unwrap();
    let obs = Observations::seen_where(&t, |f, j| {
        j < 3 || {
            let (a, b) = pairs[(j - 3) % pairs.len()];
            f == a || f == b
        }
    });
    let options = Options {
        robust: Some(RansacOptions::new(1e-3)),
        ..Options::default()
    };
    let out = reconstruct(&obs, &options).unwrap().into_single().unwrap();
    let report = out.robust.as_ref().unwrap();
    assert!(report.triangles > 0 && report.triangles <= report.samples);
    assert!(out.reconstruction.method[0].contains("by the three-point solver"));
    assert_eq!(report.kept.len(), p, "rejected {:?}", report.rejected);
    let e = shape_error(&out.reconstruction, &scene.body.points);
    assert!(e < 1e-2, "shape error {e}");
}

#[test]
fn where_no_sample_explains_half_a_long_sequence_robust_mode_judges_from_the_whole_fit() {
    use orthocheck::sfm::turntable::Turntable;
    // 40 frames, every point in 8 consecutive ones: three random frames rarely share four
    // points, and no sample's cameras reproject half the observations
    let t = Turntable {
        points: 150,
        frames: 40,
        window: 8,
        elevation: 30f64.to_radians(),
        noise: Some(0.001),
        seed: 3,
    };
    let (_, mut obs) = t.generate();
    let units = Units::of(&obs).unwrap();
    // six images moved by a third of the image's scale
    let mut g = rng(4);
    let seen: Vec<(usize, usize)> = obs.seen().map(|(f, j, _)| (f, j)).collect();
    let mut moved = BTreeSet::new();
    while moved.len() < 6 {
        moved.insert(seen[g.random_range(0..seen.len())]);
    }
    for &(f, j) in &moved {
        if let Some(y) = obs.frames[f][j].as_mut() {
            y.x += units.scale / 3.0;
        }
    }
    let robust = Options {
        robust: Some(RansacOptions::from_data()),
        ..Options::default()
    };
    let out = reconstruct(&obs, &robust).unwrap().into_single().unwrap();
    let report = out.robust.as_ref().unwrap();
    assert!(report.whole_fit, "{}", out.reconstruction.method[0]);
    assert!(out.reconstruction.method[0].contains("the fit of every observation"));
    let dropped = dropped_images(report);
    for &(f, j) in &moved {
        assert!(dropped.contains(&(obs.names[j].clone(), f + 1)), "{f} {j}");
    }
    // of the 1,194 good images, at most 1 % dropped
    let good_dropped = dropped.len() - moved.len();
    assert!(
        good_dropped * 100 <= seen.len() - moved.len(),
        "{dropped:?}"
    );
    assert!(
        out.reconstruction.warnings.is_empty(),
        "{:?}",
        out.reconstruction.warnings
    );
}
