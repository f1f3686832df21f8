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
    let m = membership(&t.frames[0], &f2, &Tolerance::uniform(1e-9));
    assert!(!m[5].member);
    assert!(m.iter().enumerate().all(|(i, j)| j.member == (i != 5)));
}

/// The default tolerance of `membership` rejects at most its level's share of true members
/// (1 %) and finds 99 % of the foreign points farther than 10 σ from the body's true
/// epipolar geometry (σ the members' rms distance from it), over seeded scenes of 20–50
/// members with noise of one scale across the image and 1–3 foreign points (the whole
/// family, 6–50 members and relative noise too, is measured by the benchmarks' example
/// `membership_calibration`, docs/limits.md: there 99.92 % of this band's far points).
#[test]
fn the_default_membership_tolerance_keeps_its_level() {
    use nalgebra::Vector2;
    use orthocheck_core::derivations::identity::{membership, robust_tolerance};
    use orthocheck_core::derivations::two_frames::epipolar;
    use orthocheck_core::model::{rng, Scene};
    use rand::Rng;
    let (mut members, mut rejected, mut far, mut found) = (0, 0, 0, 0);
    for s in 0..200u64 {
        let mut g = rng(500 + s);
        let m = g.random_range(20..=50usize);
        let eps = g.random_range(0.001..0.01);
        let t = Scene::random(m, 2, g.random()).tracks();
        let mut f: [Vec<Vector2<f64>>; 2] = [t.frames[0].clone(), t.frames[1].clone()];
        for y in f.iter_mut().flatten() {
            *y += Vector2::new(g.random_range(-eps..eps), g.random_range(-eps..eps));
        }
        // foreign points: each frame's image drawn anew in the image box
        let extra = g.random_range(1..=3usize);
        for _ in 0..extra {
            for frame in f.iter_mut() {
                frame.push(Vector2::new(
                    g.random_range(-1.0..1.0),
                    g.random_range(-1.0..1.0),
                ));
            }
        }
        // distances from the true epipolar line, in one unit for every point
        let [a, b, c, d] = epipolar(&t.frames[0], &t.frames[1]).coefficients;
        let m1 = t.frames[0].iter().sum::<Vector2<f64>>() / m as f64;
        let m2 = t.frames[1].iter().sum::<Vector2<f64>>() / m as f64;
        let dist: Vec<f64> = (0..m + extra)
            .map(|j| {
                let (p, q) = (f[0][j] - m1, f[1][j] - m2);
                (a * p.x + b * p.y + c * q.x + d * q.y).abs()
            })
            .collect();
        let sigma = (dist[..m].iter().map(|x| x * x).sum::<f64>() / m as f64).sqrt();
        let tol = robust_tolerance(&f[0], &f[1]);
        let judged = membership(&f[0], &f[1], &tol);
        members += m;
        rejected += judged[..m].iter().filter(|j| !j.member).count();
        for j in m..m + extra {
            if dist[j] > 10.0 * sigma {
                far += 1;
                found += usize::from(!judged[j].member);
            }
        }
    }
    assert!(
        rejected as f64 <= 0.01 * members as f64,
        "{rejected} of {members} true members rejected"
    );
    // a foreign point drawn at random may fall near the line by chance: only the far count
    assert!(far >= 300, "{far} far foreign points");
    assert!(
        found as f64 >= 0.99 * far as f64,
        "{found} of {far} far foreign points found"
    );
}

/// Noise relative to the coordinates (`synth --noise`: x ↦ x(1 + u)) makes far points
/// noisier than near ones; the default tolerance finds that mix and keeps its level of 1 %
/// over seeded scenes of 20–50 members and 1–3 foreign points (one scale for all points
/// rejected 2.5 % of true members in such scenes).
#[test]
fn the_default_tolerance_follows_noise_relative_to_the_coordinates() {
    use nalgebra::Vector2;
    use orthocheck_core::derivations::identity::{membership, robust_tolerance};
    use orthocheck_core::model::{rng, NoiseModel, Scene};
    use rand::Rng;
    let (mut members, mut rejected, mut mixed) = (0, 0, 0);
    for s in 0..200u64 {
        let mut g = rng(900 + s);
        let m = g.random_range(20..=50usize);
        let eps = g.random_range(0.001..0.01);
        let clean = Scene::random(m, 2, g.random()).tracks();
        let t = NoiseModel::RelativeCoordinate { eps }.perturb_tracks(&clean, &mut g);
        let mut f: [Vec<Vector2<f64>>; 2] = [t.frames[0].clone(), t.frames[1].clone()];
        for _ in 0..g.random_range(1..=3usize) {
            for frame in f.iter_mut() {
                frame.push(Vector2::new(
                    g.random_range(-1.0..1.0),
                    g.random_range(-1.0..1.0),
                ));
            }
        }
        let tol = robust_tolerance(&f[0], &f[1]);
        mixed += usize::from(tol.relative > 0.5);
        let judged = membership(&f[0], &f[1], &tol);
        members += m;
        rejected += judged[..m].iter().filter(|j| !j.member).count();
    }
    assert!(
        rejected as f64 <= 0.01 * members as f64,
        "{rejected} of {members} true members rejected"
    );
    // the noise is relative: most scenes find it so
    assert!(
        mixed >= 150,
        "{mixed} of 200 scenes found the noise mostly relative"
    );
}

/// Two scenes of six members and one foreign point (the last), noise of one scale
/// (`membership_calibration 2000 2 absolute`, scenes 646 and 818): rows x₁, y₁, x₂, y₂.
#[rustfmt::skip]
const BODY_AND_FOREIGN: [[[f64; 4]; 7]; 2] = [
    [
        [-0.3566096035211434, -0.947798945913236, 0.438999735062447, 1.1884745362652196],
        [0.6578621094763839, -0.26301136705849737, 0.5020797381299086, -0.0830537781432127],
        [-0.33969929531176757, 0.7905383718487405, 1.45261012402057, 0.56303623155267],
        [-0.9647338500031574, -0.8953227576472234, 0.3911565577814718, 2.007493047874132],
        [-0.07281068370918027, 0.18734716749223773, 1.0086455958906129, 0.5001991117505741],
        [0.1466434290647501, -0.8882912603526155, 0.24377714027384706, 0.7036038784614838],
        [0.6442052783060036, -0.9326498491548574, 1.077354128303114, 1.9783546889112962],
    ],
    [
        [0.7939038974314795, -0.6190666580668233, -1.1826576575041168, 0.6145112153655605],
        [-0.7171103665685032, -0.08715975137293909, -0.9630930725874617, 1.534951766168753],
        [-0.44048816781265154, -0.4632962431609748, -0.8395049307321792, 1.5055403588478733],
        [-0.28093576828407085, -0.7249466434623714, -0.7488409204886196, 1.5008910912514524],
        [-0.26047289928086415, 0.09681888400595105, -0.9514951955869787, 1.0541370550164042],
        [-0.7167667336056713, 0.3129769207082514, 0.1019409347032326, 1.1507420675776237],
        [-0.5100274284466126, -0.5752485717297129, -0.356150404168294, 1.018757288853509],
    ],
];

/// A rigid body plus a foreign point is never refused as "no rigid body": in both scenes of
/// [`BODY_AND_FOREIGN`] a least-median start without equal scale passed through the foreign
/// point and three members, set two members apart, and the rigidity check then refused the
/// members chosen.
#[test]
fn a_body_and_a_foreign_point_are_not_refused() {
    use nalgebra::Vector2;
    use orthocheck_core::derivations::identity::{members_rigid, membership, robust_tolerance};
    for (s, rows) in BODY_AND_FOREIGN.iter().enumerate() {
        let f1: Vec<Vector2<f64>> = rows.iter().map(|r| Vector2::new(r[0], r[1])).collect();
        let f2: Vec<Vector2<f64>> = rows.iter().map(|r| Vector2::new(r[2], r[3])).collect();
        let tol = robust_tolerance(&f1, &f2);
        let judged = membership(&f1, &f2, &tol);
        let inside: Vec<bool> = judged.iter().map(|j| j.member).collect();
        assert_eq!(
            inside,
            [true, true, true, true, true, true, false],
            "scene {s}: {judged:?}"
        );
        let refused = members_rigid(&f1, &f2, &inside, tol.largest(&judged));
        assert_eq!(refused, None, "scene {s}");
    }
}

/// Points of no rigid body are refused, however few: five points drawn at random in each
/// frame leave only the start's three within the default tolerance (the floor), and the
/// nearest fourth joins them, so the rigidity check has four points to judge.
#[test]
fn five_points_of_no_body_are_refused() {
    use nalgebra::Vector2;
    use orthocheck_core::derivations::identity::{members_rigid, membership, robust_tolerance};
    use rand::Rng;
    for seed in 0..20u64 {
        let mut g = orthocheck_core::model::rng(seed);
        let mut draw = || -> Vec<Vector2<f64>> {
            (0..5)
                .map(|_| Vector2::new(g.random_range(-1.0..1.0), g.random_range(-1.0..1.0)))
                .collect()
        };
        let (f1, f2) = (draw(), draw());
        let tol = robust_tolerance(&f1, &f2);
        let judged = membership(&f1, &f2, &tol);
        let inside: Vec<bool> = judged.iter().map(|j| j.member).collect();
        let members = inside.iter().filter(|m| **m).count();
        assert!(members >= 4, "seed {seed}: {judged:?}");
        let refused = members_rigid(&f1, &f2, &inside, tol.largest(&judged));
        assert!(refused.is_some(), "seed {seed}: {judged:?}");
    }
}

/// Views of no rigid body are refused at the members' own noise: 30 points with noise of
/// 0.5 % of one scale, frame 2 stretched to twice its width, are refused in 18 of 20 seeds
/// (a stretch along the epipolar direction cannot be seen), and never unstretched. The
/// worst-case bound on the noise that the tolerance admits, the rule before the F test,
/// refused 4 of these 20 stretched scenes.
#[test]
fn stretched_views_are_refused_and_rigid_ones_kept() {
    use nalgebra::Vector2;
    use orthocheck_core::derivations::identity::{members_rigid, membership, robust_tolerance};
    use orthocheck_core::model::{rng, Scene};
    use rand::Rng;
    let mut refused = [0, 0];
    for seed in 0..20u64 {
        let mut g = rng(seed);
        let t = Scene::random(30, 2, g.random()).tracks();
        for (s, stretch) in [1.0, 2.0].into_iter().enumerate() {
            let mut f: [Vec<Vector2<f64>>; 2] = [t.frames[0].clone(), t.frames[1].clone()];
            f[1].iter_mut().for_each(|y| y.x *= stretch);
            for y in f.iter_mut().flatten() {
                *y += Vector2::new(g.random_range(-0.005..0.005), g.random_range(-0.005..0.005));
            }
            let tol = robust_tolerance(&f[0], &f[1]);
            let judged = membership(&f[0], &f[1], &tol);
            let inside: Vec<bool> = judged.iter().map(|j| j.member).collect();
            let r = members_rigid(&f[0], &f[1], &inside, tol.largest(&judged));
            refused[s] += usize::from(r.is_some());
        }
    }
    assert_eq!(refused[0], 0, "rigid scenes refused");
    assert!(
        refused[1] >= 16,
        "{} of 20 stretched scenes refused",
        refused[1]
    );
}

/// The rigidity test at rounding level: exact views and views with noise of 10⁻¹⁰ (the
/// least squares then near rounding, so their F ratio is rounding over rounding) are kept,
/// exact stretched views refused.
#[test]
fn rigidity_at_rounding_level() {
    use nalgebra::Vector2;
    use orthocheck_core::derivations::identity::{members_rigid, membership, robust_tolerance};
    use orthocheck_core::model::{rng, Scene};
    use rand::Rng;
    for seed in 0..20u64 {
        let mut g = rng(seed);
        let t = Scene::random(12, 2, g.random()).tracks();
        for (noise, stretch, rigid) in [(0.0, 1.0, true), (1e-10, 1.0, true), (0.0, 2.0, false)] {
            let mut f: [Vec<Vector2<f64>>; 2] = [t.frames[0].clone(), t.frames[1].clone()];
            f[1].iter_mut().for_each(|y| y.x *= stretch);
            if noise > 0.0 {
                for y in f.iter_mut().flatten() {
                    *y +=
                        Vector2::new(g.random_range(-noise..noise), g.random_range(-noise..noise));
                }
            }
            let tol = robust_tolerance(&f[0], &f[1]);
            let judged = membership(&f[0], &f[1], &tol);
            let inside: Vec<bool> = judged.iter().map(|j| j.member).collect();
            let r = members_rigid(&f[0], &f[1], &inside, tol.largest(&judged));
            let case = format!("seed {seed}, noise {noise}, stretch {stretch}: {judged:?}");
            assert_eq!(r.is_none(), rigid, "{case}");
        }
    }
}
