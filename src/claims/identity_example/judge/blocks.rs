//! The debug printouts of §5.2's example as blocks: each printed block with the assignment
//! it matches, its recomputation and the author's program through it, and the judge of one
//! printed number against its recomputation. The other judges of the example read these.

use nalgebra::Vector2;

use super::{block_assignments, printed_num};
use crate::claims::identity_example::author_program::program::{run_bounded, Bounded};
use crate::claims::identity_example::author_program::{recompute, Example, Recomputed};
use crate::claims::identity_example::{DebugAttempt, IdentityExampleCase};

/// One printed block with what the study made of it.
pub(super) struct Block<'a> {
    pub attempt: &'a DebugAttempt,
    /// The assignments whose re-centred frame 2 matches the printed T₂, Q₂, P₂.
    pub matches: Vec<[usize; 4]>,
    pub recomputed: Option<Recomputed>,
    /// The block through the author's program as its printouts pin it down.
    pub program: Option<Bounded>,
}

impl Block<'_> {
    /// The block's assignment, when exactly one matches.
    pub fn assignment(&self) -> Option<[usize; 4]> {
        (self.matches.len() == 1).then(|| self.matches[0])
    }
}

pub(super) fn blocks<'a>(
    case: &'a IdentityExampleCase,
    ex: &Example,
    frame1: &[usize; 4],
) -> Vec<Block<'a>> {
    let d = case.debug.significant_digits;
    case.debug
        .attempts
        .iter()
        .map(|a| {
            let matches = block_assignments(ex, a, d);
            let recomputed = (matches.len() == 1).then(|| {
                let pb = [a.pb[0].to_f64(), a.pb[1].to_f64()];
                recompute(
                    ex,
                    frame1,
                    &matches[0],
                    printed_num(&a.d, d),
                    f64::from(a.version),
                    pb,
                )
            });
            let program = (matches.len() == 1)
                .then(|| run_block(ex, frame1, &matches[0], a, d))
                .flatten();
            Block {
                attempt: a,
                matches,
                recomputed: recomputed.flatten(),
                program,
            }
        })
        .collect()
}

/// One printed number against its recomputation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct NumberCheck {
    pub agree: bool,
    /// The printed magnitude lies inside the propagated bound: its digits (even its sign) are
    /// not determined by the rounded inputs, so only "zero to rounding" is checked.
    pub rounding_level: bool,
    /// The printed number moved by the mutant's half units either way is rejected.
    pub mutant_rejected: bool,
    /// The acceptance half-width in the printed number's half units.
    pub width: f64,
}

/// Accept when |computed − printed| ≤ bound + float + half. The mutant moves the printed
/// value by `k` half units (for a printed exact zero, the half unit a number of size one has
/// at the printed significant digits, `zero_half`).
pub(super) fn judge_number(
    printed: f64,
    half: f64,
    computed: f64,
    bound: f64,
    float: f64,
    k: f64,
    zero_half: f64,
) -> NumberCheck {
    let tol = bound + float + half;
    let h = if half > 0.0 { half } else { zero_half };
    let accepts = |x: f64| (computed - x).abs() <= tol;
    NumberCheck {
        agree: accepts(printed),
        rounding_level: printed != 0.0 && printed.abs() <= bound + float,
        mutant_rejected: !accepts(printed + k * h) && !accepts(printed - k * h),
        width: tol / h,
    }
}

/// Frames in program order (listed indices `order` of the program's P, Q, R, T).
fn program_frame(f: &[Vector2<f64>; 4], order: &[usize; 4]) -> [Vector2<f64>; 4] {
    std::array::from_fn(|j| f[order[j]])
}

/// One block through the program at its printed d0 and version.
pub(super) fn run_block(
    ex: &Example,
    frame1: &[usize; 4],
    asg: &[usize; 4],
    a: &DebugAttempt,
    digits: u32,
) -> Option<Bounded> {
    let d0 = printed_num(&a.d, digits);
    run_bounded(
        &program_frame(&ex.frame1, frame1),
        &program_frame(&ex.frame2, asg),
        d0.value,
        d0.half,
        f64::from(a.version),
        ex.coord_half,
    )
}
