//! `orthocheck identify`: which frame-2 point is which frame-1 point.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use crate::derivations::identity;
use crate::input::PointOrder;
use crate::Error;
use clap::ValueEnum;
use serde::Serialize;

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
    #[arg(long, allow_negative_numbers = true, default_value_t = 10)]
    top: usize,
    /// JSON output.
    #[arg(long)]
    json: bool,
    /// Largest number of points per frame accepted; by default the method's limit
    /// (docs/limits.md: 40 epipolar, 20 four, 30 five). Time grows as n⁴ (n⁵ for five).
    #[arg(long, allow_negative_numbers = true)]
    max_points: Option<usize>,
}

/// The tests, as the command line names them.
#[derive(Clone, Copy, ValueEnum)]
enum IdentifyMethod {
    Epipolar,
    Four,
    Five,
}

impl IdentifyMethod {
    /// The name as typed.
    fn name(self) -> &'static str {
        match self {
            IdentifyMethod::Epipolar => "epipolar",
            IdentifyMethod::Four => "four",
            IdentifyMethod::Five => "five",
        }
    }
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

/// Rank the assignments of frame 2's points to frame 1's, print the best `top` by name.
pub fn run(a: Args) -> Result<(), Error> {
    crate::limits::count("--top", a.top, crate::limits::IDENTIFY_TOP)
        .map_err(Error::InvalidInput)?;
    let t = two_frames(&a.input, PointOrder::AsListed)?;
    check_size(&a, t.frames[0].len()).map_err(|m| in_file(&a.input, Error::InvalidInput(m)))?;
    // a bar on a terminal: at the point limits the ranking takes seconds
    let bar = super::progress::bar(t.frames[1].len() as u64, "first points tried");
    let tick = || bar.inc(1);
    let r = identity::identify_reporting(&t.frames[0], &t.frames[1], a.method.into(), a.top, &tick)
        .map_err(|e| in_file(&a.input, e))?;
    bar.finish_and_clear();
    let (frame2, named) = frame2_labels(&a.input, t.frames[1].len())?;
    let matches = r.full.as_ref().map_or_else(Vec::new, |f| {
        pairs(&t.names, &frame2, &f.frame2_indices)
            .into_iter()
            .map(|(frame1, frame2)| Match { frame1, frame2 })
            .collect()
    });
    let shown = Named {
        identified: &r,
        frame1_points: &t.names,
        frame2_points: &frame2,
        matches,
    };
    emit(a.json, &shown, |n| identify_text(n, a.method.name(), named))?;
    Ok(())
}

/// What `identify` prints: the ranking, with the points named.
#[derive(Serialize)]
struct Named<'a> {
    /// The ranking (frame-2 indices, 0-based).
    #[serde(flatten)]
    identified: &'a identity::Identified,
    /// Frame 1's point names.
    frame1_points: &'a [String],
    /// Frame 2's points: their names in a CSV file, else `#k` for the k-th listed.
    frame2_points: &'a [String],
    /// The best full correspondence by name.
    matches: Vec<Match>,
}

/// One frame-1 point and the frame-2 point it is.
#[derive(Serialize)]
struct Match {
    /// The frame-1 point's name.
    frame1: String,
    /// The frame-2 point's label.
    frame2: String,
}

/// Frame 2's point labels: the names a CSV file gives them (and `true`), else `#1`, `#2`, …
/// by position (and `false`).
fn frame2_labels(path: &Path, n: usize) -> Result<(Vec<String>, bool), Error> {
    let listed = crate::input::listed_names(path)?;
    match listed.and_then(|frames| frames.into_iter().nth(1)) {
        Some(names) if names.len() == n => Ok((names, true)),
        _ => Ok(((1..=n).map(|k| format!("#{k}")).collect(), false)),
    }
}

/// Frame-1 point `i` with the frame-2 point `indices[i]`, by name.
fn pairs(frame1: &[String], frame2: &[String], indices: &[usize]) -> Vec<(String, String)> {
    frame1
        .iter()
        .zip(indices)
        .map(|(p, &j)| {
            (
                p.clone(),
                frame2.get(j).cloned().unwrap_or_else(|| "?".into()),
            )
        })
        .collect()
}

/// `identify` as text: the method, the assignments as `P→X3 Q→X1 …` (frame-1 point →
/// frame-2 point), then the best full correspondence.
fn identify_text(n: &Named, method: &str, named: bool) -> String {
    use crate::numfmt::sig;
    let r = n.identified;
    let arrows = |indices: &[usize]| -> String {
        pairs(n.frame1_points, n.frame2_points, indices)
            .iter()
            .map(|(p, q)| format!("{p}→{q}"))
            .collect::<Vec<_>>()
            .join(" ")
    };
    let mut s = format!("method: {method} ({} assignments tried)\n", r.tried);
    if let Some(d) = &r.degenerate {
        let _ = writeln!(s, "degenerate: {d}");
    }
    s.push_str(if named {
        "frame-2 points by their names in the file; frame-1 point → frame-2 point\n"
    } else {
        "frame-2 points by position: #k is the k-th listed; frame-1 point → frame-2 point\n"
    });
    for (i, a) in r.assignments.iter().enumerate() {
        let _ = writeln!(
            s,
            "{:>3}. {}  residual {}",
            i + 1,
            arrows(&a.frame2_indices[..]),
            sig(a.residual)
        );
    }
    if let Some(f) = &r.full {
        let _ = writeln!(
            s,
            "best full correspondence (RMS epipolar distance {} of the image size):\n  {}",
            sig(f.residual),
            arrows(&f.frame2_indices[..])
        );
    }
    s
}

/// The points per frame within the method's limit (or `--max-points`), before any work.
fn check_size(a: &Args, n: usize) -> Result<(), String> {
    use crate::limits::{
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
