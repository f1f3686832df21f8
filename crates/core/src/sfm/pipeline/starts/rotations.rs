//! Starts from seeded random rotations. Where the frames' tracks are short, the chain of frame
//! pairs and the largest complete block can both start in a wrong basin (docs/limits.md);
//! a group of few frames is small enough to search globally instead: [`ROTATION_STARTS`]
//! random rotations of every frame, the points and translations placed for them
//! ([`place`]). A larger group is searched window by window ([`windowed`]), the windows chained
//! through the frames they share.

use nalgebra::{Matrix3, Vector2, Vector3};
use rayon::prelude::*;

use super::{cost, screened, Fitted};
use crate::algebra::nearest_rotation;
use crate::sfm::bundle::BundleOptions;
use crate::sfm::gaps::intersect;
use crate::sfm::{Frame, Observations, Reconstruction};

/// Groups of at most this many frames are started from random rotations of every frame;
/// larger ones window by window. Measured on the turntable family (docs/limits.md): random
/// starts reached the optimum in 6 of 11 missed scenes whose groups have 7–13 frames, and
/// in few of those with larger groups.
pub const ROTATION_FRAMES: usize = 13;

/// Random starts of a group, and of each window ([`windowed`]), each screened by the short
/// adjustment (a group's best go on to the full adjustment with the other starts; a window
/// keeps its best). Of 11 scenes of the turntable family missed in groups of 7–13 frames,
/// 24 starts reached the optimum in 2, 64 in 6 (docs/limits.md).
pub const ROTATION_STARTS: usize = 64;

/// Frames in a window of [`windowed`]; consecutive windows share half of them. Windows of 4,
/// 6, 8 and 10 frames each reached the optimum in 6 of the 34 scenes the family's first seed
/// missed in groups of 7 frames or more (docs/limits.md).
pub const WINDOW_FRAMES: usize = 6;

/// Points a window's random starts use at most: only its rotations are chained, and a few
/// dozen points seen in several of its frames fix them; the search's work then does not grow
/// with the points (a sequence of the Oxford dinosaur's size took 5.0 s with every point,
/// 0.76–0.89 s before the random starts, 0.96–1.19 s with the cap; docs/limits.md).
pub const WINDOW_POINTS: usize = 60;

/// The offset of the windows' seeds from the group's (every window draws the same 64
/// sets of rotations; the random starts of a whole group and the windows never run on the
/// same group).
const WINDOW_SEED: u64 = 1000;

/// [`ROTATION_STARTS`] starts from random rotations (seeds `seed`, `seed` + 1, …), each placed
/// ([`place`]) and screened by `bo`, in the seeds' order, each with its offset from `seed`;
/// those that fail are left out.
pub(super) fn random_fits(
    used: &Observations,
    seed: u64,
    bo: &BundleOptions,
) -> Vec<(u64, Fitted)> {
    (0..ROTATION_STARTS as u64)
        .into_par_iter()
        .filter_map(|i| {
            let g = &mut crate::model::rng(seed.wrapping_add(i));
            let rotations: Vec<Matrix3<f64>> = used
                .frames
                .iter()
                .map(|_| *crate::model::random_rotation(g).matrix())
                .collect();
            screened(used, place(used, &rotations)?, bo).map(|f| (i, f))
        })
        .collect()
}

/// Windows of [`WINDOW_FRAMES`] consecutive frames (in the group's order), each the best of
/// its random starts ([`random_fits`] of the points it sees twice), chained: each window turned
/// onto the rotations of the frames it shares with those before it (it or its mirror twin,
/// whichever agrees better), then the points and translations placed for every frame's
/// rotation. `None` when a frame is left without a window's rotation, or a window shares no
/// frame with those chained before it ([`chain`]).
pub(super) fn windowed(
    used: &Observations,
    seed: u64,
    bo: &BundleOptions,
) -> Option<Reconstruction> {
    let k = used.frames.len();
    let mut known: Vec<Option<Matrix3<f64>>> = vec![None; k];
    let mut first = 0;
    loop {
        let last = (first + WINDOW_FRAMES).min(k);
        let frames: Vec<usize> = (first..last).collect();
        if let Some((window, _)) = window(used, &frames, seed.wrapping_add(WINDOW_SEED), bo)
            && !chain(&mut known, &frames, &window)
        {
            return None;
        }
        if last == k {
            break;
        }
        first += WINDOW_FRAMES / 2;
    }
    let rotations: Option<Vec<Matrix3<f64>>> = known.into_iter().collect();
    place(used, &rotations?)
}

/// The best random start of the frames `frames` and the points they see at least twice (at
/// most [`WINDOW_POINTS`]: those seen in the most of its frames, the earlier on a tie).
pub(super) fn window(
    used: &Observations,
    frames: &[usize],
    seed: u64,
    bo: &BundleOptions,
) -> Option<Fitted> {
    let views = |j: usize| {
        frames
            .iter()
            .filter(|&&f| used.frames[f][j].is_some())
            .count()
    };
    let mut keep: Vec<usize> = (0..used.names.len()).filter(|&j| views(j) >= 2).collect();
    // a stable sort: the earlier point first on a tie
    keep.sort_by_key(|&j| std::cmp::Reverse(views(j)));
    keep.truncate(WINDOW_POINTS);
    keep.sort_unstable();
    if keep.len() < crate::sfm::MIN_POINTS {
        return None;
    }
    let part = used.select_frames(frames).select_points(&keep);
    random_fits(&part, seed, bo)
        .into_iter()
        .map(|(_, f)| f)
        .min_by(|a, b| cost(a).total_cmp(&cost(b)))
}

/// `window` (the fit of `frames`) turned into the rotations already `known` ([`turn`]), the
/// window or its mirror twin, whichever leaves the smaller misfit; the frames not yet known
/// take it. False when frames are known and the window shares none of them (a window before
/// it failed): nothing then relates its frame of reference to theirs.
fn chain(known: &mut [Option<Matrix3<f64>>], frames: &[usize], window: &Reconstruction) -> bool {
    let linked = frames.iter().any(|&f| known[f].is_some());
    if !linked && known.iter().any(Option::is_some) {
        return false;
    }
    let mirror = window.mirror();
    let (plain, twin) = (turn(known, frames, window), turn(known, frames, &mirror));
    let (qt, chosen) = match twin.0 < plain.0 {
        true => (twin.1, &mirror),
        false => (plain.1, window),
    };
    take(known, frames, chosen, &qt);
    true
}

/// The turn Qᵀ that brings `window` (the fit of `frames`) onto the rotations already `known`,
/// Rₖ = R_w Q: the rotation nearest the sum of Rₖᵀ R_w over the frames both have (the
/// identity where they share none), with its misfit Σ ‖Rₖ Qᵀ − R_w‖².
pub(super) fn turn(
    known: &[Option<Matrix3<f64>>],
    frames: &[usize],
    window: &Reconstruction,
) -> (f64, Matrix3<f64>) {
    let shared: Vec<(Matrix3<f64>, Matrix3<f64>)> = frames
        .iter()
        .zip(&window.frames)
        .filter_map(|(&f, w)| known[f].map(|r| (r, w.rotation)))
        .collect();
    let qt = match shared.is_empty() {
        true => Matrix3::identity(),
        false => nearest_rotation(&shared.iter().map(|(r, w)| r.transpose() * w).sum()),
    };
    let misfit = shared
        .iter()
        .map(|(r, w)| (r * qt - w).norm_squared())
        .sum();
    (misfit, qt)
}

/// The frames of `frames` not yet `known` take `window`'s rotations, turned by `qt` ([`turn`]).
pub(super) fn take(
    known: &mut [Option<Matrix3<f64>>],
    frames: &[usize],
    window: &Reconstruction,
    qt: &Matrix3<f64>,
) {
    for (&f, w) in frames.iter().zip(&window.frames) {
        if known[f].is_none() {
            known[f] = Some(w.rotation * qt.transpose());
        }
    }
}

/// Points and translations for fixed rotations, by alternating least squares: each frame's
/// translation first its images' centroid; then, three times, the points intersected and
/// each translation the mean of its images' residuals; the points intersected once more.
/// Centred, frame 1 turned to the identity. `None` when a point's views do not fix it.
pub(super) fn place(used: &Observations, rotations: &[Matrix3<f64>]) -> Option<Reconstruction> {
    let mut frames: Vec<Frame> = rotations
        .iter()
        .zip(&used.frames)
        .map(|(r, row)| Frame {
            rotation: *r,
            translation: mean(row.iter().flatten().copied()),
        })
        .collect();
    let by_point = used.by_point();
    let intersected = |frames: &[Frame]| -> Option<Vec<Vector3<f64>>> {
        let known: Vec<Option<Frame>> = frames.iter().copied().map(Some).collect();
        by_point
            .iter()
            .map(|seen| intersect(&known, seen))
            .collect()
    };
    for _ in 0..3 {
        let points = intersected(&frames)?;
        for (frame, row) in frames.iter_mut().zip(&used.frames) {
            let c = frame.rows();
            let residuals = row
                .iter()
                .zip(&points)
                .filter_map(|(y, x)| y.map(|y| y - c * x));
            frame.translation = mean(residuals);
        }
    }
    let mut rec = Reconstruction {
        names: used.names.clone(),
        points: intersected(&frames)?,
        frames,
        method: Vec::new(),
        conditioning: None,
        warnings: Vec::new(),
    };
    rec.align_to_first();
    rec.centre();
    Some(rec)
}

/// The mean of image points; zero for none.
fn mean(v: impl Iterator<Item = Vector2<f64>>) -> Vector2<f64> {
    let (sum, n) = v.fold((Vector2::zeros(), 0usize), |(s, n), y| (s + y, n + 1));
    if n == 0 {
        sum
    } else {
        sum / n as f64
    }
}
