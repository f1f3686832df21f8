//! Frames re-seated where a fit leaves them uneven. A fit of a long sequence with short
//! tracks can be right but for a stretch of consecutive frames in a wrong basin (their part
//! of the body bent, or in its mirror twin): the frames at its ends fit far worse than the
//! median frame ([`uneven_frames`]), and every start of the whole group can share the fault,
//! since the chains and the windows pass through the same few frames (docs/limits.md). So
//! each run of such frames, and the run widened ([`WIDEN`]), is started again with the
//! other frames' rotations kept ([`Reseat::seats`]): from a window's random rotations turned
//! onto up to [`MARGIN`] kept frames each side, and from the motion either side carried
//! through the run. Each start has its points and translations placed and is screened; the best is
//! adjusted in full and kept where the cost falls, for up to [`PASSES`] re-seatings.
//!
//! Neighbours are frames next to each other in the group's order that are linked, sharing at
//! least [`LINK`] points (the last and the first too, where they are): a run, its widening
//! and its margins never cross two frames that are not, where the motion between them is
//! not fixed (`sfm::groups`).

use nalgebra::{Matrix3, Rotation3, UnitQuaternion};
use rayon::prelude::*;

use super::rotations::{place, take, turn, window};
use super::{adjusted, cost, same_optimum, screened, Fitted};
use crate::sfm::bundle::BundleOptions;
use crate::sfm::groups::LINK;
use crate::sfm::pipeline::{ranges, uneven_frames};
use crate::sfm::{Observations, Reconstruction};

/// Frames each side of a run, kept, that turn a window's random search onto the rest of the
/// fit, and whose step is carried through the run. Two: the fewest that give a step.
const MARGIN: usize = 2;
const _: () = assert!(MARGIN >= 2, "a step needs two frames");

/// Frames each side a run is widened by, each width searched: the frames the fit leaves
/// uneven can be the ends of a longer stretch in a wrong basin. On the 23 scenes the
/// turntable family's first seed missed before re-seating, the run alone reached 7, the run
/// widened by 0, 2 and 4 reached 13 (docs/limits.md).
const WIDEN: [usize; 3] = [0, 2, 4];
// stretches of equal frames then have equal inner frames too (the dedup in `reseat`)
const _: () = assert!(WIDEN[1] - WIDEN[0] >= MARGIN && WIDEN[2] - WIDEN[1] >= MARGIN);

/// Re-seatings kept at most: a re-seated fit can leave other frames uneven, and its uneven
/// frames are found again after each. Of the 23 scenes above, one re-seating reached 11,
/// up to four 13. Each try of a run costs up to three windows' random searches, fifteen
/// screened starts and a full adjustment; a run that lowers nothing is tried again after
/// each re-seating kept.
const PASSES: usize = 4;

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

/// A run, its widening and its margins, in order: `frames[inner]` (the run and its widening)
/// are started again, the frames before and after them (the margins) kept.
struct Stretch {
    frames: Vec<usize>,
    inner: std::ops::Range<usize>,
}

impl Reseat<'_> {
    /// `fit` with runs of its uneven frames re-seated, one at a time, each where it lowers
    /// the cost to another optimum ([`same_optimum`]), the uneven frames found
    /// again after each; with the frames whose rotations were started again (as the input
    /// numbers them), or `None` when none was.
    pub(super) fn run(&self, fit: &Fitted) -> Option<(Fitted, String)> {
        let links = self.links();
        let mut current = fit.clone();
        let mut seated: Vec<usize> = Vec::new();
        for _ in 0..PASSES {
            let bad: Vec<usize> = uneven_frames(self.used, &current.0)
                .into_iter()
                .map(|(f, _)| f)
                .collect();
            let better = runs(&bad, &links).into_iter().find_map(|run| {
                let (fit, frames) = self.reseat(&current.0, &run, &links)?;
                let lower = !same_optimum(cost(&current), cost(&fit), self.floor);
                lower.then_some((fit, frames))
            });
            let Some((fit, frames)) = better else {
                break;
            };
            current = fit;
            seated.extend(frames.iter().map(|&f| self.numbers[f]));
        }
        seated.sort_unstable();
        seated.dedup();
        (!seated.is_empty()).then(|| (current, ranges(&seated)))
    }

    /// Whether each frame and the next (the last and the first) share at least [`LINK`]
    /// points.
    fn links(&self) -> Vec<bool> {
        let frames = &self.used.frames;
        let k = frames.len();
        (0..k)
            .map(|f| {
                let next = &frames[(f + 1) % k];
                let shared = frames[f].iter().zip(next);
                shared.filter(|(a, b)| a.is_some() && b.is_some()).count() >= LINK
            })
            .collect()
    }

    /// `rec` with the frames of `run` re-seated, adjusted in full: of the starts
    /// [`Reseat::seats`] gives for the run and for it widened by each of [`WIDEN`], the best
    /// by its screening; with the frames it started again. `None` when no stretch has a
    /// margin, no start is placed and screened, or the full adjustment fails or ends without
    /// a finite cost.
    fn reseat(
        &self,
        rec: &Reconstruction,
        run: &[usize],
        links: &[bool],
    ) -> Option<(Fitted, Vec<usize>)> {
        let own: Vec<Matrix3<f64>> = rec.frames.iter().map(|f| f.rotation).collect();
        let mut stretches: Vec<Stretch> = Vec::new();
        for w in WIDEN {
            let s = stretch(run, w, links);
            let new = stretches.iter().all(|t| t.frames != s.frames);
            if new && s.inner.len() < s.frames.len() {
                stretches.push(s);
            }
        }
        let seats: Vec<(Vec<Matrix3<f64>>, Vec<usize>)> = stretches
            .iter()
            .flat_map(|s| {
                let inner = s.frames[s.inner.clone()].to_vec();
                self.seats(&own, s)
                    .into_iter()
                    .map(move |r| (r, inner.clone()))
            })
            .collect();
        let (start, inner) = seats
            .into_par_iter()
            .filter_map(|(rotations, inner)| {
                screened(self.used, place(self.used, &rotations)?, self.screen).map(|f| (f, inner))
            })
            .min_by(|a, b| cost(&a.0).total_cmp(&cost(&b.0)))?;
        let fit = adjusted(self.used, self.numbers, start.0, self.full)?;
        cost(&fit).is_finite().then_some((fit, inner))
    }

    /// Rotations of every frame with those of `s`'s inner frames replaced: by a window's
    /// random search ([`window`]) over the stretch, turned onto its margins (the window and
    /// its mirror twin); where both sides have a margin, by the rotations along the geodesic
    /// between the frames either side; and where a side has two, by the step between them
    /// carried on through the inner frames (a sequence's frames move smoothly; a
    /// turntable's by equal steps).
    fn seats(&self, own: &[Matrix3<f64>], s: &Stretch) -> Vec<Vec<Matrix3<f64>>> {
        let (frames, inner) = (&s.frames, &s.frames[s.inner.clone()]);
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
        let q = |at: Option<usize>| {
            at.map(|i| {
                UnitQuaternion::from_rotation_matrix(&Rotation3::from_matrix_unchecked(
                    own[frames[i]],
                ))
            })
        };
        let (a, b) = (s.inner.start, s.inner.end);
        let before = q(a.checked_sub(1));
        let back = q(a.checked_sub(2));
        let after = q((b < frames.len()).then_some(b));
        let ahead = q((b + 1 < frames.len()).then_some(b + 1));
        let m = inner.len();
        let path = |at: &dyn Fn(usize) -> UnitQuaternion<f64>| {
            let mut rotations = own.to_vec();
            for (i, &f) in inner.iter().enumerate() {
                rotations[f] = at(i).to_rotation_matrix().into_inner();
            }
            rotations
        };
        // steps compose on the left (Rₖ Rₖ₋₁ᵀ), as the frames' rotations do
        let share = |i: usize| (i + 1) as f64 / (m + 1) as f64;
        if let (Some(p), Some(n)) = (before, after) {
            out.push(path(&|i| (n * p.inverse()).powf(share(i)) * p));
        }
        if let (Some(p), Some(pp)) = (before, back) {
            out.push(path(&|i| (p * pp.inverse()).powf((i + 1) as f64) * p));
        }
        if let (Some(n), Some(nn)) = (after, ahead) {
            out.push(path(&|i| (n * nn.inverse()).powf((m - i) as f64) * n));
        }
        out
    }
}

/// `run` widened by up to `w` frames each side and given up to [`MARGIN`] more each side,
/// along links only (a side that reaches an unlinked pair ends there): the widening joins the
/// inner frames, the margins are kept. Never every frame: where the two sides would take
/// more than the frames outside the run less one, the longer side gives up its farthest.
fn stretch(run: &[usize], w: usize, links: &[bool]) -> Stretch {
    let k = links.len();
    let room = k.saturating_sub(run.len() + 1);
    let side = |from: usize, forwards: bool| {
        let mut out = Vec::new();
        let mut at = from;
        while out.len() < (w + MARGIN).min(room) {
            let (next, link) = match forwards {
                true => ((at + 1) % k, at),
                false => ((at + k - 1) % k, (at + k - 1) % k),
            };
            if !links[link] {
                break;
            }
            out.push(next);
            at = next;
        }
        out
    };
    let (mut left, mut right) = (side(run[0], false), side(run[run.len() - 1], true));
    while left.len() + right.len() > room {
        match left.len() >= right.len() {
            true => left.pop(),
            false => right.pop(),
        };
    }
    let (lw, rw) = (left.len().min(w), right.len().min(w));
    let mut frames: Vec<usize> = left.into_iter().rev().collect();
    let start = frames.len() - lw;
    frames.extend_from_slice(run);
    let end = frames.len() + rw;
    frames.extend(right);
    Stretch {
        frames,
        inner: start..end,
    }
}

/// The uneven frames `bad` (indices in the group's order) as runs of linked frames
/// ([`Reseat::links`]): frames at most two apart along links join one run, the frames
/// between them with them; the last run joins the first across the end where links join
/// them.
fn runs(bad: &[usize], links: &[bool]) -> Vec<Vec<usize>> {
    let k = links.len();
    let joined = |from: usize, to: usize| (from..to).all(|f| links[f % k]);
    let mut sorted = bad.to_vec();
    sorted.sort_unstable();
    let mut out: Vec<Vec<usize>> = Vec::new();
    for f in sorted {
        match out.last_mut() {
            Some(run) if f - run[run.len() - 1] <= 2 && joined(run[run.len() - 1], f) => {
                let from = run[run.len() - 1] + 1;
                run.extend(from..=f);
            }
            _ => out.push(vec![f]),
        }
    }
    if out.len() > 1 {
        let (head, tail) = (out[0][0], out[out.len() - 1][out[out.len() - 1].len() - 1]);
        if head + k - tail <= 2 && joined(tail, head + k) {
            let first = out.remove(0);
            let last = out.last_mut().expect("two runs");
            last.extend(tail + 1..k);
            last.extend(0..head);
            last.extend(first);
        }
    }
    out
}
