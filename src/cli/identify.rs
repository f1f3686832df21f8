//! `orthocheck identify`: which frame-2 point is which frame-1 point.

use std::path::PathBuf;

use clap::ValueEnum;
use orthocheck::derivations::identity;
use orthocheck::input::PointOrder;
use orthocheck::{report, Error};

use super::{emit, in_file, two_frames};

/// Arguments of `identify`.
#[derive(clap::Args)]
pub struct Args {
    /// Tracks file with two frames (frame 2's points in any order).
    #[arg(long)]
    input: PathBuf,
    /// Test: the equal-scale epipolar residual of four points, the paper's four-point
    /// test, or the five-point line.
    #[arg(long, value_enum, default_value = "epipolar")]
    method: IdentifyMethod,
    /// Assignments listed.
    #[arg(long, default_value_t = 10)]
    top: usize,
    /// JSON output.
    #[arg(long)]
    json: bool,
}

/// The tests, as the command line names them.
#[derive(Clone, Copy, ValueEnum)]
enum IdentifyMethod {
    Epipolar,
    Four,
    Five,
}

impl From<IdentifyMethod> for identity::IdentifyMethod {
    fn from(m: IdentifyMethod) -> identity::IdentifyMethod {
        match m {
            IdentifyMethod::Epipolar => identity::IdentifyMethod::Epipolar,
            IdentifyMethod::Four => identity::IdentifyMethod::Four,
            IdentifyMethod::Five => identity::IdentifyMethod::Five,
        }
    }
}

/// Rank the assignments of frame 2's points to frame 1's, print the best `top`.
pub fn run(a: Args) -> Result<(), Error> {
    let t = two_frames(&a.input, PointOrder::AsListed)?;
    let r = identity::identify(&t.frames[0], &t.frames[1], a.method.into(), a.top)
        .map_err(|e| in_file(&a.input, e))?;
    emit(a.json, &r, report::identify_text)?;
    Ok(())
}
