//! A seeded turntable sequence: the missing data of real sequences (the Oxford dinosaur
//! kind), where each point is seen in a few consecutive frames only.
//!
//! The body (points uniform in [−1, 1]³) turns by 360°/k per frame about an axis tilted by
//! the camera's elevation from the image's vertical, so frame 1's rotation is the identity.
//! Each point is seen in `window` consecutive frames (cyclically: the table turns all the way
//! round) from its first one, the first frames spread evenly over the points in a random
//! order, so a frame sees about p · window / k points and consecutive frames share most of
//! them.
//!
//! The turntable family ([`family_scene`]) varies everything instead: points, elevation,
//! each track's length, the frames and the noise, seeded scene by scene; the pipeline is
//! judged on it against the truth (docs/limits.md).

use nalgebra::{Rotation3, Vector2, Vector3};
use rand::seq::SliceRandom as _;
use rand::Rng;

use super::{Frame, Observations, Reconstruction};
use crate::model::{rng, Body, Motion, NoiseModel, Scene};

/// A turntable sequence's settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Turntable {
    /// Points.
    pub points: usize,
    /// Frames, evenly spaced over one turn.
    pub frames: usize,
    /// Consecutive frames each point is seen in.
    pub window: usize,
    /// The camera's elevation above the table's plane, radians.
    pub elevation: f64,
    /// Relative error up to ε on every image coordinate (as `synth --noise`).
    pub noise: Option<f64>,
    /// The seed of the body and the windows (the noise draws from `seed + 1`).
    pub seed: u64,
}

impl Turntable {
    /// The scene (every point in every frame: the truth) and the observations with the
    /// gaps of the visible windows.
    pub fn generate(&self) -> (Scene, Observations) {
        let mut g = rng(self.seed);
        let (p, k) = (self.points, self.frames);
        let points: Vec<Vector3<f64>> = (0..p)
            .map(|_| Vector3::from_fn(|_, _| g.random_range(-1.0..1.0)))
            .collect();
        // first frames spread evenly (each frame is the first of ⌊p/k⌋ or ⌈p/k⌉ points, in a
        // random order): random ones leave, now and then, fewer than four points joining the
        // frames before a frame to those after it, and the affine factorisation is then not
        // fixed (the metric one still is)
        let mut first: Vec<usize> = (0..p).map(|j| j * k.max(1) / p.max(1)).collect();
        first.shuffle(&mut g);
        let tilt = Rotation3::from_axis_angle(&Vector3::x_axis(), self.elevation);
        let motions = (0..k)
            .map(|f| {
                let turn = std::f64::consts::TAU * f as f64 / k as f64;
                let spin = Rotation3::from_axis_angle(&Vector3::y_axis(), turn);
                Motion {
                    rotation: tilt * spin * tilt.inverse(),
                    translation: Vector2::zeros(),
                }
            })
            .collect();
        let names = (1..=p).map(|j| format!("P{j}")).collect();
        let scene = Scene {
            body: Body { names, points },
            motions,
        };
        let mut tracks = scene.tracks();
        if let Some(eps) = self.noise {
            tracks = NoiseModel::RelativeCoordinate { eps }
                .perturb_tracks(&tracks, &mut rng(self.seed.wrapping_add(1)));
        }
        let seen = |f: usize, j: usize| (f + k - first[j]) % k.max(1) < self.window;
        let obs = Observations::seen_where(&tracks, seen);
        (scene, obs)
    }
}

/// A scene of the turntable family (docs/limits.md, and the benchmarks' example `turntable_family`): its observations, the truth (the
/// body centred, in frame 1's camera coordinates, and the motions), the camera's elevation
/// (degrees) and the longest track.
pub struct FamilyScene {
    /// The observations, with gaps.
    pub obs: Observations,
    /// The true body and motions.
    pub truth: Reconstruction,
    /// The camera's elevation above the table, in degrees.
    pub elevation: f64,
    /// The longest track, L: each point is seen in 1..=L consecutive frames.
    pub longest: usize,
}

/// The seed of scene `s` of the family's run of seed `seed`.
pub fn family_seed(seed: u64, s: u64) -> u64 {
    seed.wrapping_mul(7_919).wrapping_add(s)
}

/// The family's scene of seed `seed`: 50–500 points uniform in [−1, 1]³ on a table turning
/// once over the frames, the camera's elevation 10°–70°, each point seen in consecutive
/// frames from a random first one (round the end), its track's length uniform in 1..=L (L
/// 2–8), the frame count k = round((L + 1) / (2 (1 − m))) for a missing share m drawn in
/// 80–92 %, clamped to 20–100 (so 20–56: tracks of at most 8 frames cannot leave 92 % or
/// less missing in more; L = 2 gives 20 frames, 92.5 % missing), relative noise 0.1 %–1 %.
pub fn family_scene(seed: u64) -> FamilyScene {
    let mut g = rng(seed);
    let p = g.random_range(50..=500usize);
    let longest = g.random_range(2..=8usize);
    let missing = g.random_range(0.80..0.92);
    let k = (((longest + 1) as f64 / (2.0 * (1.0 - missing))).round() as usize).clamp(20, 100);
    let elevation: f64 = g.random_range(10.0f64..70.0);
    let eps = g.random_range(0.001..0.01);
    let points: Vec<Vector3<f64>> = (0..p)
        .map(|_| Vector3::from_fn(|_, _| g.random_range(-1.0..1.0)))
        .collect();
    let tilt = Rotation3::from_axis_angle(&Vector3::x_axis(), elevation.to_radians());
    let motions: Vec<Motion> = (0..k)
        .map(|f| {
            let spin = Rotation3::from_axis_angle(
                &Vector3::y_axis(),
                std::f64::consts::TAU * f as f64 / k as f64,
            );
            Motion {
                rotation: tilt * spin * tilt.inverse(),
                translation: Vector2::zeros(),
            }
        })
        .collect();
    let names: Vec<String> = (1..=p).map(|j| format!("P{j}")).collect();
    let s = Scene {
        body: Body {
            names,
            points: points.clone(),
        },
        motions: motions.clone(),
    };
    let tracks = NoiseModel::RelativeCoordinate { eps }.perturb_tracks(&s.tracks(), &mut g);
    let spans: Vec<(usize, usize)> = (0..p)
        .map(|_| (g.random_range(0..k), g.random_range(1..=longest)))
        .collect();
    let obs = Observations::seen_where(&tracks, |f, j| (f + k - spans[j].0) % k < spans[j].1);
    let c = points.iter().sum::<Vector3<f64>>() / p as f64;
    let truth = Reconstruction {
        names: s.body.names.clone(),
        points: points.iter().map(|x| x - c).collect(),
        frames: motions
            .iter()
            .map(|m| {
                let r = *m.rotation.matrix();
                Frame {
                    rotation: r,
                    translation: (r * c).xy(),
                }
            })
            .collect(),
        method: Vec::new(),
        conditioning: None,
        warnings: Vec::new(),
    };
    FamilyScene {
        obs,
        truth,
        elevation,
        longest,
    }
}
