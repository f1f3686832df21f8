//! The price of linearity (§4): the paper's words and printed runs, and the comparison study
//! of the paper's solvers with the standard method (its bodies, levels, trials and seed).

use serde::Deserialize;

use crate::cases::{ClaimRef, Printed, Validator};
use crate::error::Result;

/// The comparison study behind §4's "the linearity has clearly its price".
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct LinearityPriceCase {
    /// The claim the study decides.
    pub claim: ClaimRef,
    /// The paper's printed runs of the §4 solver, with their noise levels.
    pub printed_runs: Vec<PrintedRun>,
    /// The bodies, in report order.
    pub bodies: Vec<LinearityBody>,
    /// The body whose ratios decide the claim (a `name` of `bodies`).
    pub deciding_body: String,
    /// Noise levels ε (fractions: "0.001" is 0.1 %).
    pub levels: Vec<Printed>,
    /// The levels at which the claim is decided (a subset of `levels`): the paper's own.
    pub deciding_levels: Vec<Printed>,
    /// One-sided error probability α of each confidence bound ("0.05").
    pub alpha: Printed,
    /// Trials per body and level.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
}

/// A printed noisy run: its level and the squared edges printed.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PrintedRun {
    /// ε as printed.
    pub level: Printed,
    /// The printed x1 … x6 (squared edges).
    pub squares: Vec<Printed>,
}

/// One body of the study: the paper's printed edges, or random points.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct LinearityBody {
    /// The name shown in the report.
    pub name: String,
    /// Printed lengths in edge order (PQ, QR, RP, then TP, TQ, TR).
    #[serde(default)]
    pub lengths: Vec<Printed>,
    /// Printed squares, when printed (the body realizes them).
    #[serde(default)]
    pub squares: Vec<Printed>,
    /// A new random body of this many points per trial, instead of printed edges.
    #[serde(default)]
    pub random_points: Option<usize>,
}

/// Random bodies of the study: the least-squares form takes at most this many points, and a
/// bundle adjustment of more would slow the report.
pub const MAX_RANDOM_POINTS: usize = 20;

/// Checks serde cannot express: sizes, names, levels and the deciding subset.
pub(super) fn validate(c: &LinearityPriceCase, v: &Validator) -> Result<()> {
    v.limit("trials", "trials", c.trials, crate::limits::NOISE_TRIALS)?;
    v.list("bodies", c.bodies.len())?;
    v.list("levels", c.levels.len())?;
    v.limit(
        "trials",
        "trials × bodies × levels",
        c.trials
            .saturating_mul(c.bodies.len())
            .saturating_mul(c.levels.len()),
        crate::limits::LINEARITY_RUNS,
    )?;
    for (i, l) in c.levels.iter().enumerate() {
        if let Err(m) = crate::limits::noise_level("level", l.to_f64()) {
            return v.err(&format!("levels[{i}]"), m);
        }
    }
    if c.deciding_levels.iter().any(|d| !c.levels.contains(d)) {
        return v.err(
            "deciding_levels",
            "every deciding level must be one of the levels".into(),
        );
    }
    let alpha = c.alpha.to_f64();
    if !(alpha > 0.0 && alpha < 1.0) {
        return v.err("alpha", "α must lie strictly between 0 and 1".into());
    }
    if !c.bodies.iter().any(|b| b.name == c.deciding_body) {
        return v.err(
            "deciding_body",
            format!("names no body of the study ({})", c.deciding_body),
        );
    }
    let names: Vec<String> = c.bodies.iter().map(|b| b.name.clone()).collect();
    v.names("bodies", &names)?;
    for (i, b) in c.bodies.iter().enumerate() {
        body(b, &format!("bodies[{i}]"), v)?;
    }
    for (i, r) in c.printed_runs.iter().enumerate() {
        if r.squares.len() != 6 {
            return v.err(
                &format!("printed_runs[{i}].squares"),
                "a run of the §4 solver prints six squared edges".into(),
            );
        }
    }
    Ok(())
}

/// A body is printed edges of three or more points, or random points, not both.
fn body(b: &LinearityBody, at: &str, v: &Validator) -> Result<()> {
    if let Some((i, words)) = crate::cases::contradicting_square(&b.lengths, &b.squares) {
        return v.err(&format!("{at}.squares[{i}]"), words);
    }
    match (b.lengths.len(), b.random_points) {
        (0, Some(p)) if (3..=MAX_RANDOM_POINTS).contains(&p) => Ok(()),
        (0, Some(p)) => v.err(
            &format!("{at}.random_points"),
            format!("{p} points: a random body takes 3 to {MAX_RANDOM_POINTS}"),
        ),
        (3 | 6, None) if b.squares.is_empty() || b.squares.len() == b.lengths.len() => {
            // the body must exist (a triangle, or four points in 3-D), refused here with its
            // field rather than when the study runs
            let lengths: Vec<f64> = b.lengths.iter().map(|p| p.to_f64()).collect();
            let squares: Vec<f64> = b.squares.iter().map(|p| p.to_f64()).collect();
            match crate::studies::noise::body_of(&lengths, &squares) {
                Ok(_) => Ok(()),
                Err(e) => v.err(
                    &format!("{at}.lengths"),
                    e.to_string().trim_start_matches("invalid input: ").into(),
                ),
            }
        }
        (_, None) => v.err(
            &format!("{at}.lengths"),
            "a printed body has 3 or 6 lengths (and as many squares, if any)".into(),
        ),
        (_, Some(_)) => v.err(
            &format!("{at}.random_points"),
            "a body is printed lengths or random points, not both".into(),
        ),
    }
}
