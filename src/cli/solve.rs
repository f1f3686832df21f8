//! `orthocheck solve`: the squared edges (and the body) from a tracks file.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use crate::derivations::solver::{solve_tracks, Method, Solution, Solved, Structure};
use crate::input::{load_observations, load_tracks, PointOrder};
use crate::numfmt::{below, sig, sig_list};
use crate::Error;
use clap::ValueEnum;

use super::{in_file, json_out, non_finite, out};

/// Arguments of `solve`.
#[derive(clap::Args)]
pub struct Args {
    /// Tracks: YAML (`frames:` lists of [x, y], optional `points:`) or CSV
    /// (`frame,point,x,y`), every point in every frame (tracks with gaps are for
    /// `reconstruct`).
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

/// Load the tracks, solve, print the solutions; a degenerate input that leaves nothing to
/// report is an error (exit 2) that names the degeneracy.
pub fn run(a: Args) -> Result<(), Error> {
    let tracks =
        load_tracks(&a.input, PointOrder::ByName).map_err(|e| with_gaps_pointer(&a.input, e))?;
    let solved = solve_tracks(&tracks, a.method.into()).map_err(|e| in_file(&a.input, e))?;
    if solved.output.solutions.is_empty()
        && let Some(d) = solved.output.degenerate
    {
        return Err(in_file(
            &a.input,
            Error::InvalidInput(format!("degenerate input, not solved: {d}")),
        ));
    }
    if a.json {
        // the guard walks what was solved: the JSON built from it would hold `null`s
        if let Some(bad) = crate::report::finite::first_non_finite(&solved) {
            return Err(non_finite(&bad.to_string()));
        }
        json_out(&solve_json(&solved))?;
    } else {
        out(&solve_text(&solved))?;
    }
    Ok(())
}

/// What `solve` says after a tracks file's own error when the file reads as tracks with gaps
/// (a `null` entry, a frame without a point's row): `reconstruct` takes those.
const GAPS_POINTER: &str =
    "solve needs every point in every frame; `orthocheck reconstruct` reads tracks with gaps";

/// A tracks file `solve` cannot read, which would read as tracks with gaps: the error says so
/// and points to `reconstruct`. The location stays the reader's (file, line, field); a CSV
/// reader's message is kept, a YAML `null` is named as a missing point.
fn with_gaps_pointer(path: &Path, e: Error) -> Error {
    let (location, message) = match e {
        Error::Input { location, message } => (location, message),
        e => return e,
    };
    let gap = load_observations(path).ok().and_then(|o| {
        o.frames.iter().enumerate().find_map(|(f, frame)| {
            let j = frame.iter().position(Option::is_none)?;
            Some((f + 1, o.names.get(j).cloned().unwrap_or_default()))
        })
    });
    let Some((frame, point)) = gap else {
        return Error::Input { location, message };
    };
    let is_csv = path
        .extension()
        .is_some_and(|x| x.eq_ignore_ascii_case("csv"));
    let what = if is_csv {
        message
    } else {
        format!("point `{point}` is missing from frame {frame} (`null`)")
    };
    Error::Input {
        location,
        message: format!("{what}; {GAPS_POINTER}"),
    }
}

/// `solve` as text: the method and why, a degenerate case, the p3f3 cross-check, then one
/// line per solution (complex roots as `re+imi` / `re-imi`) and the body behind it.
fn solve_text(s: &Solved) -> String {
    let o = &s.output;
    let mut t = format!("method: {} ({})\n", o.method, s.why);
    if let Some(d) = &o.degenerate {
        let _ = writeln!(t, "degenerate: {d}");
    }
    if let Some(c) = o.condition {
        let _ = writeln!(t, "condition number: {}", sig(c));
    }
    if o.solutions.is_empty() {
        t.push_str("no solution\n");
    }
    if let Some(v) = &s.validation {
        let _ = writeln!(
            t,
            "c² by independent routes (exact elimination over ℚ + Sturm, closed form, companion matrix): largest relative disagreement {}; same number of real roots: {}",
            below(v.max_relative_disagreement),
            v.same_count
        );
    }
    for (i, (sol, st)) in o.solutions.iter().zip(&s.structures).enumerate() {
        let _ = writeln!(
            t,
            "solution {}: {}  [{}; residual {}]",
            i + 1,
            edges_text(&o.edges, sol),
            sol.feasibility.reason(),
            below(sol.residual)
        );
        if let Some(st) = st {
            t.push_str(&body_text(st));
        }
    }
    t
}

/// One solution's squared edges, `PQ²=4 QR²=9 …`; a complex value with the sign of its
/// imaginary part always written.
fn edges_text(names: &[String], sol: &Solution) -> String {
    names
        .iter()
        .zip(sol.squared_edges.iter().zip(&sol.imaginary))
        .map(|(n, (re, im))| format!("{n}²={}", complex_text(*re, *im)))
        .collect::<Vec<_>>()
        .join(" ")
}

/// A real or complex number as text: `3.07053`, `3.07053+0.169191i`, `3.07053-0.169191i`
/// (the minus the numbers themselves print, [`sig`]'s).
fn complex_text(re: f64, im: f64) -> String {
    if im == 0.0 {
        sig(re)
    } else if im < 0.0 {
        format!("{}-{}i", sig(re), sig(-im))
    } else {
        format!("{}+{}i", sig(re), sig(im))
    }
}

/// The line of the body behind a feasible solution.
fn body_text(st: &Structure) -> String {
    let pts: Vec<String> = st.points.iter().map(|p| sig_list(p)).collect();
    format!(
        "  body in frame 1: {}; {} structure-and-motion solutions reproject ({} with the mirror reversal)\n",
        pts.join(" "),
        st.motions,
        2 * u128::from(st.motions)
    )
}

/// `orthocheck solve --json`: `{"method", "why", "solutions": [{"squared_edges": {"PQ": …},
/// "feasible", "reason", "residual", …}], "degenerate": null | "…", "condition"}`.
fn solve_json(s: &Solved) -> serde_json::Value {
    use serde_json::{json, Map, Value};
    let o = &s.output;
    let solutions: Vec<Value> = o
        .solutions
        .iter()
        .zip(&s.structures)
        .map(|(sol, st)| {
            let edges: Map<String, Value> = o
                .edges
                .iter()
                .zip(&sol.squared_edges)
                .map(|(n, v)| (n.clone(), json!(v)))
                .collect();
            let mut v = json!({
                "squared_edges": edges,
                "feasible": sol.feasibility.is_feasible(),
                "reason": sol.feasibility.reason(),
                "residual": sol.residual,
                "error_bound": sol.error_bound,
            });
            if sol.imaginary.iter().any(|x| *x != 0.0) {
                let im: Map<String, Value> = o
                    .edges
                    .iter()
                    .zip(&sol.imaginary)
                    .map(|(n, v)| (n.clone(), json!(v)))
                    .collect();
                v["imaginary"] = Value::Object(im);
            }
            if let Some(st) = st {
                v["structure"] = json!(st);
            }
            v
        })
        .collect();
    json!({
        "method": o.method,
        "why": s.why,
        "solutions": solutions,
        "degenerate": o.degenerate.map(|d| d.to_string()),
        "condition": o.condition,
        "validation": s.validation,
    })
}
