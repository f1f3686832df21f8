//! The standard errors the bundle adjustment reports for every point and frame match the
//! spread of the estimates over seeded noise replicates of one scene: complete tracks (the
//! camera system's point terms summed chunk by chunk in one product) and short tracks in
//! many frames (summed point by point).

use nalgebra::{Matrix3, Rotation3, Vector3};
use orthocheck_core::model::{rng, Scene, Tracks};
use orthocheck_core::sfm::{bundle_adjust, reconstruct, BundleOptions, Observations, Options};
use rand::Rng;

/// One replicate's estimates as rows of numbers, each with the standard error reported for
/// it: every point's three coordinates, then every frame's rotation (the angles about frame
/// 1's axes that take the first replicate's rotation to this one's, R₀·exp([δ]×)) and its
/// two translations.
struct Replicate {
    values: Vec<f64>,
    reported: Vec<f64>,
}

/// The first replicate's points and rotations, which the others are compared with.
type Pose = (Vec<Vector3<f64>>, Vec<Matrix3<f64>>);

/// The largest ratio (or inverse ratio) of the estimates' spread to the mean reported
/// standard error over every point's coordinates and every frame's parameters, from
/// `replicates` noisy copies of `clean` (uniform noise in ±`a`) seen where `seen` says:
/// (ratio, which: a point's coordinate, or a frame's parameter after all of them). The
/// first copy is reconstructed by the pipeline; every copy is adjusted from that fit, so the
/// estimates are the adjustment's optimum of each, in one basin, whatever the starts.
fn worst_ratio(
    clean: &Tracks,
    seen: &dyn Fn(usize, usize) -> bool,
    a: f64,
    replicates: u64,
) -> (f64, String) {
    let mut all: Vec<Replicate> = Vec::new();
    let mut start = None;
    let mut first: Option<Pose> = None;
    for r in 0..replicates {
        let mut g = rng(1000 + r);
        let mut t = clean.clone();
        for y in t.frames.iter_mut().flatten() {
            y.x += g.random_range(-a..a);
            y.y += g.random_range(-a..a);
        }
        let obs = Observations::seen_where(&t, seen);
        let from = start.get_or_insert_with(|| {
            reconstruct(&obs, &Options::default())
                .unwrap()
                .into_single()
                .unwrap()
                .reconstruction
        });
        let o = bundle_adjust(&obs, from, &BundleOptions::default()).unwrap();
        let mut pts = o.reconstruction.points.clone();
        let mut rots: Vec<Matrix3<f64>> =
            o.reconstruction.frames.iter().map(|f| f.rotation).collect();
        let (p0, r0) = first.get_or_insert_with(|| (pts.clone(), rots.clone()));
        // the mirror (Necker) twin gives the same images: take the one nearer the first
        let d = Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
        let mirrored: Vec<Vector3<f64>> = pts.iter().map(|x| d * x).collect();
        let dist = |v: &[Vector3<f64>]| -> f64 {
            v.iter()
                .zip(&*p0)
                .map(|(x, y)| (x - y).norm_squared())
                .sum()
        };
        if dist(&mirrored) < dist(&pts) {
            pts = mirrored;
            rots.iter_mut().for_each(|r| *r = d * *r * d);
        }
        let sd_p = o.report.points_std.expect("standard errors of the points");
        let sd_f = o.report.frames_std.expect("standard errors of the frames");
        let mut values: Vec<f64> = pts.iter().flat_map(|x| [x.x, x.y, x.z]).collect();
        let mut reported: Vec<f64> = sd_p.iter().flat_map(|e| [e.x, e.y, e.z]).collect();
        for ((rot, fr), (e, r0)) in rots
            .iter()
            .zip(&o.reconstruction.frames)
            .zip(sd_f.iter().zip(&*r0))
        {
            let delta = Rotation3::from_matrix_unchecked(r0.transpose() * rot).scaled_axis();
            values.extend([
                delta.x,
                delta.y,
                delta.z,
                fr.translation.x,
                fr.translation.y,
            ]);
            reported.extend([e.rotation.x, e.rotation.y, e.rotation.z]);
            reported.extend([e.translation.x, e.translation.y]);
        }
        all.push(Replicate { values, reported });
    }
    let n = replicates as f64;
    let points = 3 * clean.names.len();
    let mut worst = (1.0_f64, String::new());
    for i in 0..all[0].values.len() {
        let xs: Vec<f64> = all.iter().map(|r| r.values[i]).collect();
        let mean = xs.iter().sum::<f64>() / n;
        let spread = (xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
        let said = all.iter().map(|r| r.reported[i]).sum::<f64>() / n;
        // frame 1's rotation is the frame of reference: no error reported, none to compare
        if (points..points + 3).contains(&i) {
            assert!(said == 0.0, "frame 1's rotation: {said}");
            continue;
        }
        let ratio = spread / said;
        // a ratio that is not a number is the worst of all
        if ratio.is_nan() || ratio.ln().abs() > worst.0.ln().abs() {
            let which = if i < points {
                format!("point {} coordinate {}", i / 3, i % 3)
            } else {
                format!("frame {} parameter {}", (i - points) / 5, (i - points) % 5)
            };
            worst = (ratio, which);
        }
    }
    worst
}

/// The worst ratio of [`worst_ratio`] is within a factor of 1.5 either way.
fn within_a_factor_of_one_and_a_half((ratio, which): (f64, String)) {
    assert!(
        (1.0 / 1.5..=1.5).contains(&ratio),
        "{which}: spread / reported = {ratio}"
    );
}

#[test]
fn standard_errors_match_the_spread_over_noise_replicates() {
    // 200 replicates know a standard deviation to about 5 %; uniform in ±0.003 where the
    // body spans about 2 image units
    let clean = Scene::random(20, 6, 7).tracks();
    let worst = worst_ratio(&clean, &|_, _| true, 0.003, 200);
    within_a_factor_of_one_and_a_half(worst);
}

#[test]
fn standard_errors_of_short_tracks_match_the_spread_too() {
    // each point in 4 consecutive frames of 12 (from its own first, round the end): every
    // point's camera rows a fraction of the system's, so its terms are summed one by one;
    // 150 replicates know a standard deviation to about 6 %
    let (p, k) = (40, 12);
    let clean = Scene::random(p, k, 11).tracks();
    let first: Vec<usize> = (0..p).map(|j| (j * 7) % k).collect();
    let seen = move |f: usize, j: usize| (f + k - first[j]) % k < 4;
    let worst = worst_ratio(&clean, &seen, 0.003, 150);
    within_a_factor_of_one_and_a_half(worst);
}

#[test]
fn no_standard_errors_where_a_point_is_not_fixed() {
    // the last point seen in one frame only, frame 1 (its rotation the identity) or frame 2
    // (turned: its V singular up to rounding only): its depth is free
    let clean = Scene::random(8, 4, 5).tracks();
    let start = reconstruct(&Observations::from_tracks(&clean), &Options::default())
        .unwrap()
        .into_single()
        .unwrap()
        .reconstruction;
    for only in [0, 1] {
        let obs = Observations::seen_where(&clean, |f, j| j < 7 || f == only);
        let o = bundle_adjust(&obs, &start, &BundleOptions::default()).unwrap();
        assert!(o.report.points_std.is_none() && o.report.frames_std.is_none());
        let why = o.report.no_standard_errors.expect("a reason");
        assert!(why.contains("singular"), "frame {only}: {why}");
    }
}

/// With complete tracks the centroid's image in a frame is the mean of that frame's images:
/// its standard error is σ̂/√p on each axis, exactly (σ̂² = 2·cost/freedom).
#[test]
fn a_frame_translation_s_standard_error_with_complete_tracks_is_sigma_over_root_p() {
    let (p, k) = (12, 5);
    let clean = Scene::random(p, k, 21).tracks();
    let mut g = rng(22);
    let mut t = clean.clone();
    for y in t.frames.iter_mut().flatten() {
        y.x += g.random_range(-0.003..0.003);
        y.y += g.random_range(-0.003..0.003);
    }
    let obs = Observations::from_tracks(&t);
    let start = reconstruct(&obs, &Options::default())
        .unwrap()
        .into_single()
        .unwrap()
        .reconstruction;
    let o = bundle_adjust(&obs, &start, &BundleOptions::default()).unwrap();
    let cost = *o.report.costs.last().unwrap();
    let freedom = (2 * p * k - (5 * k - 3) - 3 * (p - 1)) as f64;
    let expected = (2.0 * cost / freedom / p as f64).sqrt();
    for f in o.report.frames_std.unwrap() {
        // to rounding: 10⁻⁶ is far above the solves' error at this size and far below what a
        // wrong or missing term changes (the cross terms alone move it several times over)
        for e in [f.translation.x, f.translation.y] {
            assert!(
                (e - expected).abs() <= 1e-6 * expected,
                "{e} against {expected}"
            );
        }
    }
}
