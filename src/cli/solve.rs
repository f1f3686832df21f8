//! `orthocheck solve`: the squared edges (and the body) from a tracks file.

use std::path::PathBuf;

use clap::ValueEnum;
use orthocheck::derivations::solver::{solve_tracks, Method};
use orthocheck::input::{load_tracks, PointOrder};
use orthocheck::{report, Error};

use super::{in_file, json_out, non_finite, out};

/// Arguments of `solve`.
#[derive(clap::Args)]
pub struct Args {
    /// Tracks: YAML (`frames:` lists of [x, y], optional `points:`) or CSV
    /// (`frame,point,x,y`).
    #[arg(long)]
    input: PathBuf,
    /// Solver; `auto` picks from the number of points and frames (p3f3, p3f4, p4f3, or
    /// lsq for p ≥ 4 points in k ≥ 3 frames).
    #[arg(long, value_enum, default_value = "auto")]
    method: MethodArg,
    /// JSON output.
    #[arg(long)]
    json: bool,
}

/// The solvers, as the command line names them.
#[derive(Clone, Copy, ValueEnum)]
enum MethodArg {
    Auto,
    P3f3,
    P3f4,
    P4f3,
    Lsq,
}

impl From<MethodArg> for Method {
    fn from(m: MethodArg) -> Method {
        match m {
            MethodArg::Auto => Method::Auto,
            MethodArg::P3f3 => Method::P3f3,
            MethodArg::P3f4 => Method::P3f4,
            MethodArg::P4f3 => Method::P4f3,
            MethodArg::Lsq => Method::Lsq,
        }
    }
}

/// Load the tracks, solve, print the solutions.
pub fn run(a: Args) -> Result<(), Error> {
    let tracks = load_tracks(&a.input, PointOrder::ByName)?;
    let solved = solve_tracks(&tracks, a.method.into()).map_err(|e| in_file(&a.input, e))?;
    if a.json {
        // the guard walks what was solved: the JSON built from it would hold `null`s
        if let Some(bad) = orthocheck::report::finite::first_non_finite(&solved) {
            return Err(non_finite(&bad.to_string()));
        }
        json_out(&report::solve_json(&solved))?;
    } else {
        out(&report::solve_text(&solved))?;
    }
    Ok(())
}
