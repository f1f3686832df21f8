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
    /// Largest number of points per frame accepted; by default the method's limit
    /// (docs/limits.md: 40 epipolar, 20 four, 30 five). Time grows as n⁴ (n⁵ for five).
    #[arg(long)]
    max_points: Option<usize>,
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
    check_size(&a, t.frames[0].len()).map_err(|m| in_file(&a.input, Error::InvalidInput(m)))?;
    let r = identity::identify(&t.frames[0], &t.frames[1], a.method.into(), a.top)
        .map_err(|e| in_file(&a.input, e))?;
    emit(a.json, &r, report::identify_text)?;
    Ok(())
}

/// The points per frame within the method's limit (or `--max-points`), before any work.
fn check_size(a: &Args, n: usize) -> Result<(), String> {
    use orthocheck::limits::{
        at_most, IDENTIFY_POINTS_EPIPOLAR, IDENTIFY_POINTS_FIVE, IDENTIFY_POINTS_FOUR,
    };
    let (name, limit, growth) = match a.method {
        IdentifyMethod::Epipolar => ("epipolar", IDENTIFY_POINTS_EPIPOLAR, "n⁴"),
        IdentifyMethod::Four => ("four", IDENTIFY_POINTS_FOUR, "n⁴"),
        IdentifyMethod::Five => ("five", IDENTIFY_POINTS_FIVE, "n⁵"),
    };
    at_most(
        &format!("the number of points per frame for --method {name}"),
        n,
        a.max_points.unwrap_or(limit),
    )
    .map_err(|m| format!("{m}; its time grows as {growth}: --max-points raises the limit"))
}
