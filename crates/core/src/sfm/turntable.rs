//! A seeded turntable sequence: the missing data of real sequences (the Oxford dinosaur
//! kind), where each point is seen in a few consecutive frames only.
//!
//! The body (points uniform in [−1, 1]³) turns by 360°/k per frame about an axis tilted by
//! the camera's elevation from the image's vertical, so frame 1's rotation is the identity.
//! Each point is seen in `window` consecutive frames (cyclically: the table turns all the way
//! round) from its first one, the first frames spread evenly over the points in a random
//! order, so a frame sees about p · window / k points and consecutive frames share most of
//! them.

use nalgebra::{Rotation3, Vector2, Vector3};
use rand::seq::SliceRandom as _;
use rand::Rng;

use super::Observations;
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
