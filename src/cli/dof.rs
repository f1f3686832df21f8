//! `orthocheck dof`: degrees of freedom (§2.1) and identifiability by Jacobian rank.

use crate::derivations::dof;
use std::fmt::Write as _;

use crate::Error;

use super::emit;

/// Arguments of `dof`.
#[derive(clap::Args)]
pub struct Args {
    /// Number of points p.
    #[arg(long, allow_negative_numbers = true, required_unless_present = "table")]
    points: Option<usize>,
    /// Number of frames k.
    #[arg(long, allow_negative_numbers = true, required_unless_present = "table")]
    frames: Option<usize>,
    /// The whole grid p = 1..max-points, k = 1..max-frames.
    #[arg(long, conflicts_with_all = ["points", "frames"])]
    table: bool,
    /// Largest p of the grid.
    #[arg(
        long,
        allow_negative_numbers = true,
        default_value_t = 8,
        requires = "table"
    )]
    max_points: usize,
    /// Largest k of the grid.
    #[arg(
        long,
        allow_negative_numbers = true,
        default_value_t = 6,
        requires = "table"
    )]
    max_frames: usize,
    /// Seed of the generic scene.
    #[arg(long, allow_negative_numbers = true, value_parser = super::SeedParser, default_value_t = 1)]
    seed: u64,
    /// JSON output.
    #[arg(long)]
    json: bool,
}

/// One (p, k), or the whole grid.
pub fn run(a: Args) -> Result<(), Error> {
    check_limits(&a).map_err(Error::InvalidInput)?;
    if a.table {
        let rows = dof::table(a.max_points, a.max_frames, a.seed)?;
        emit(a.json, &rows, |r| dof_table_text(r))?;
    } else {
        let (p, k) = (a.points.unwrap_or(0), a.frames.unwrap_or(0));
        let r = dof::identifiability(p, k, a.seed)?;
        emit(a.json, &r, dof_text)?;
    }
    Ok(())
}

/// The sizes within `docs/limits.md` before any work starts.
fn check_limits(a: &Args) -> Result<(), String> {
    use crate::limits::{at_most, DOF_FRAMES, DOF_GRID, DOF_POINTS, DOF_POINTS_TIMES_FRAMES};
    if a.table {
        if a.max_points == 0 || a.max_frames == 0 {
            return Err(
                "--max-points and --max-frames must be at least 1: the table would be empty".into(),
            );
        }
        at_most("--max-points", a.max_points, DOF_GRID)?;
        return at_most("--max-frames", a.max_frames, DOF_GRID);
    }
    let (p, k) = (a.points.unwrap_or(0), a.frames.unwrap_or(0));
    at_most("--points", p, DOF_POINTS)?;
    at_most("--frames", k, DOF_FRAMES)?;
    at_most(
        "--points × --frames",
        p.saturating_mul(k),
        DOF_POINTS_TIMES_FRAMES,
    )
}

/// The `dof --table` grid as text: counted against the real (Jacobian) rank.
fn dof_table_text(rows: &[dof::Identifiability]) -> String {
    let mut s = String::from(
        "  p  k  unknowns  measurements  balance  rank  deficiency  count says  rank says\n",
    );
    for r in rows {
        let c = &r.count;
        let _ = writeln!(
            s,
            "{:>3}{:>3}{:>10}{:>14}{:>9}{:>6}{:>12}  {:<10}  {}",
            c.points,
            c.frames,
            c.unknowns,
            c.measurements,
            c.balance,
            r.exact_rank,
            r.deficiency,
            if c.balance >= 0 { "enough" } else { "too few" },
            if r.deficiency == 0 {
                "identifiable"
            } else {
                "ambiguous"
            }
        );
    }
    s
}

/// One `dof` cell as text.
fn dof_text(r: &dof::Identifiability) -> String {
    let c = &r.count;
    format!(
        "points {p}, frames {k}\n\
         unknowns      -1+3p+5(k-1) = {u}\n\
         measurements  2kp          = {m}\n\
         balance                    = {b}\n\
         jacobian rank (svd)        = {jr} of {n} parameters (condition {cond})\n\
         exact rank                 = {er} ({method})\n\
         deficiency                 = {d}  ({verdict})\n",
        p = c.points,
        k = c.frames,
        u = c.unknowns,
        m = c.measurements,
        b = c.balance,
        jr = r.jacobian_rank,
        n = r.parameters,
        cond = r
            .condition
            .map_or("- (rank-deficient)".into(), crate::numfmt::sig),
        er = r.exact_rank,
        method = r.exact_method.describe(),
        d = r.deficiency,
        verdict = if r.deficiency == 0 {
            "finitely many solutions near this scene".to_string()
        } else {
            format!(
                "a {}-dimensional family of scenes gives the same images",
                r.deficiency
            )
        }
    )
}
