//! The seed policy of generated scenes: which random stream serves what, so that the same
//! command gives the same scene and the same noise.

use crate::model::{rng, NoiseModel, Scene, Tracks};

/// The stream of the noise added to a scene made from `scene_seed`: apart from the scene's
/// own stream, so that noise ε = 0 gives exactly the scene's tracks and a different ε moves
/// the same scene.
pub fn noise_seed(scene_seed: u64) -> u64 {
    scene_seed.wrapping_add(1)
}

/// A seeded random scene and its tracks.
#[derive(Clone, Debug)]
pub struct Synthetic {
    /// The scene (the truth).
    pub scene: Scene,
    /// Its tracks, with noise when asked for.
    pub tracks: Tracks,
}

/// A random scene of `points` points in `frames` frames from `seed`, its tracks perturbed by
/// a relative error up to `noise` on every image coordinate (stream [`noise_seed`]).
pub fn synthetic(points: usize, frames: usize, seed: u64, noise: Option<f64>) -> Synthetic {
    let scene = Scene::random(points, frames, seed);
    let mut tracks = scene.tracks();
    if let Some(eps) = noise {
        tracks = NoiseModel::RelativeCoordinate { eps }
            .perturb_tracks(&tracks, &mut rng(noise_seed(seed)));
    }
    Synthetic { scene, tracks }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_noise_gives_the_scene_itself() {
        let clean = synthetic(3, 3, 5, None);
        let zero = synthetic(3, 3, 5, Some(0.0));
        assert_eq!(clean.tracks.frames, zero.tracks.frames);
        assert_ne!(noise_seed(5), 5);
    }
}
