//! Frames re-seated where a fit leaves them uneven. A fit of a long sequence with short
//! tracks can be right but for a stretch of consecutive frames in a wrong basin (their part
//! of the body bent, or in its mirror twin): the frames at its ends fit far worse than the
//! median frame ([`uneven_frames`]), and every start of the whole group can share the fault,
//! since the chains and the windows pass through the same few frames (docs/limits.md). So
//! each run of such frames, and the run widened ([`WIDEN`]), is started again with the rest
//! of the fit kept ([`Reseat::seats`]): from a window's random rotations turned onto the
//! [`MARGIN`] frames each side, and from the motion either side carried through the run.
//! Each start has its points and translations placed and is screened; the best is adjusted
//! in full and kept where the cost falls, for up to [`PASSES`] passes.

use nalgebra::{Matrix3, UnitQuaternion};
use rayon::prelude::*;

use super::rotations::{place, take, turn, window};
use super::{adjusted, cost, screened, Fitted, AGREE};
use crate::sfm::bundle::BundleOptions;
use crate::sfm::pipeline::{ranges, uneven_frames};
use crate::sfm::{Observations, Reconstruction};

/// Frames each side of a run of uneven frames, kept as they are, that turn the window's
/// search onto the rest of the fit.
pub const MARGIN: usize = 2;

/// Frames each side a run is widened by, each width searched: the frames the fit leaves
/// uneven can be the ends of a longer stretch in a wrong basin.
pub const WIDEN: [usize; 3] = [0, 2, 4];

/// Passes over the uneven frames at most: a re-seated fit can leave other frames uneven.
pub const PASSES: usize = 4;

/// The offset of the windows' seeds from the group's (apart from the chained windows').
const SEED: u64 = 2000;

/// What a re-seating works with: the group's observations and frame numbers, the seed, the
/// adjustments' options (the screening's and the full one) and the cost's rounding floor
/// ([`rounding`](super::rounding)).
pub(super) struct Reseat<'a> {
    pub(super) used: &'a Observations,
    pub(super) numbers: &'a [usize],
    pub(super) seed: u64,
    pub(super) screen: &'a BundleOptions,
    pub(super) full: &'a BundleOptions,
    pub(super) floor: f64,
}

impl Reseat<'_> {
    /// `fit` with each run of its uneven frames re-seated in turn, where that lowers its
    /// cost beyond the fits' agreement ([`AGREE`] and the floor), pass after pass while one
    /// does; with the frames re-seated (as the input numbers them), or `None` when none was.
    pub(super) fn run(&self, fit: &Fitted) -> Option<(Fitted, String)> {
        let k = self.used.frames.len();
        let mut current = fit.clone();
        let mut seated: Vec<usize> = Vec::new();
        for _ in 0..PASSES {
            let bad: Vec<usize> = uneven_frames(self.used, &current.0)
                .into_iter()
                .map(|(f, _)| f)
                .collect();
            let mut fell = false;
            for run in runs(&bad, k) {
                let Some(better) = self.reseat(&current.0, &run) else {
                    continue;
                };
                let (now, was) = (cost(&better), cost(&current));
                if now * (1.0 + AGREE) + self.floor < was {
                    current = better;
                    seated.extend(run.iter().map(|&f| self.numbers[f]));
                    fell = true;
                }
            }
            if !fell {
                break;
            }
        }
        seated.sort_unstable();
        seated.dedup();
        (!seated.is_empty()).then(|| (current, ranges(&seated)))
    }

    /// `rec` with the frames of `run` re-seated, adjusted in full: of the starts
    /// [`Reseat::seats`] gives for the run and for it widened by each of [`WIDEN`] (where
    /// that and the margins leave a frame out), the best by its screening; `None` when no
    /// start is placed.
    fn reseat(&self, rec: &Reconstruction, run: &[usize]) -> Option<Fitted> {
        let k = self.used.frames.len();
        let span = (run[run.len() - 1] + k - run[0]) % k + 1;
        let own: Vec<Matrix3<f64>> = rec.frames.iter().map(|f| f.rotation).collect();
        let seats: Vec<Vec<Matrix3<f64>>> = WIDEN
            .iter()
            .filter(|&&w| span + 2 * (w + MARGIN) < k)
            .flat_map(|&w| {
                let frames: Vec<usize> = (0..span + 2 * (w + MARGIN))
                    .map(|i| (run[0] + 2 * k - MARGIN - w + i) % k)
                    .collect();
                self.seats(&own, &frames)
            })
            .collect();
        seats
            .into_par_iter()
            .filter_map(|rotations| screened(self.used, place(self.used, &rotations)?, self.screen))
            .min_by(|a, b| cost(a).total_cmp(&cost(b)))
            .and_then(|(start, _)| adjusted(self.used, self.numbers, start, self.full))
            .filter(|f| cost(f).is_finite())
    }

    /// Rotations of every frame with those of the run inside `frames` (the run with
    /// [`MARGIN`] frames each side) replaced: by a window's random search
    /// ([`window`]) turned onto the margins (the window and its mirror twin); by the
    /// rotations along the geodesic between the frames either side of the run; and by the
    /// step between the two frames before the run carried on through it, and the step after
    /// it carried back (a sequence's frames move smoothly; a turntable's by equal steps).
    fn seats(&self, own: &[Matrix3<f64>], frames: &[usize]) -> Vec<Vec<Matrix3<f64>>> {
        let inner = &frames[MARGIN..frames.len() - MARGIN];
        let mut out = Vec::new();
        if let Some((w, _)) = window(self.used, frames, self.seed.wrapping_add(SEED), self.screen) {
            for twin in [w.clone(), w.mirror()] {
                let mut known: Vec<Option<Matrix3<f64>>> = own.iter().copied().map(Some).collect();
                for &f in inner {
                    known[f] = None;
                }
                let (_, qt) = turn(&known, frames, &twin);
                take(&mut known, frames, &twin, &qt);
                out.extend(known.into_iter().collect::<Option<Vec<_>>>());
            }
        }
        let q = |f: usize| UnitQuaternion::from_matrix(&own[f]);
        let (before, after) = (q(frames[MARGIN - 1]), q(frames[frames.len() - MARGIN]));
        let (back, ahead) = (q(frames[MARGIN - 2]), q(frames[frames.len() - MARGIN + 1]));
        let (forwards, backwards) = (before * back.inverse(), after * ahead.inverse());
        let m = inner.len();
        let path = |at: &dyn Fn(usize) -> Option<UnitQuaternion<f64>>| {
            let mut rotations = own.to_vec();
            for (i, &f) in inner.iter().enumerate() {
                rotations[f] = at(i)?.to_rotation_matrix().into_inner();
            }
            Some(rotations)
        };
        let t = |i: usize| (i + 1) as f64 / (m + 1) as f64;
        // no geodesic between opposite rotations (half a turn apart, within rounding)
        out.extend(path(&|i| before.try_slerp(&after, t(i), f64::EPSILON)));
        out.extend(path(&|i| Some(forwards.powf((i + 1) as f64) * before)));
        out.extend(path(&|i| Some(backwards.powf((m - i) as f64) * after)));
        out
    }
}

/// The uneven frames `bad` (indices of `k` frames in a turn's order) as runs of frames:
/// frames at most two apart join one run, the frames between them with them, and the last
/// run joins the first across the end (a whole turn comes round to its first frame).
fn runs(bad: &[usize], k: usize) -> Vec<Vec<usize>> {
    let mut sorted = bad.to_vec();
    sorted.sort_unstable();
    let mut out: Vec<Vec<usize>> = Vec::new();
    for f in sorted {
        match out.last_mut() {
            Some(run) if f - run[run.len() - 1] <= 2 => {
                let from = run[run.len() - 1] + 1;
                run.extend(from..=f);
            }
            _ => out.push(vec![f]),
        }
    }
    if out.len() > 1 {
        let (head, tail) = (out[0][0], out[out.len() - 1][out[out.len() - 1].len() - 1]);
        if head + k - tail <= 2 {
            let first = out.remove(0);
            let last = out.last_mut().expect("two runs");
            let from = tail + 1;
            last.extend(from..k);
            last.extend(0..head);
            last.extend(first);
        }
    }
    out
}
