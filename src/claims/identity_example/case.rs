//! The case schema of §5.2's example: the frames, the hidden table, the debug printouts, the panels.

use serde::Deserialize;

use crate::cases::{ClaimRef, Printed, Validator};
use crate::error::Result;
use crate::limits;

/// §5.2's example.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct IdentityExampleCase {
    /// The two printed frames.
    pub frames: ExampleFrames,
    /// The hidden distance table.
    pub table: DistanceTable,
    /// "The first two attempts are the correct ones".
    pub correct: ClaimRef,
    /// "b can in fact take one of two distinct values … the lower value of the distance …
    /// shall be taken" (§5.2's procedure): what the census of seeded scenes judges.
    pub two_values_of_b: ClaimRef,
    /// The debug printouts.
    pub debug: DebugBlocks,
    /// The figure panels (boxed: they make the case large).
    pub panels: Box<Panels>,
    /// Random generic scenes for the comparison with the example.
    pub census_trials: usize,
    /// c in those scenes, as a multiple of the smallest admissible c.
    pub census_c_factor: f64,
    /// Seed.
    pub seed: u64,
}

/// Two frames of four points, as printed.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ExampleFrames {
    /// The claim.
    pub claim: ClaimRef,
    /// Frame 1.
    pub frame1: Vec<[Printed; 2]>,
    /// Frame 2.
    pub frame2: Vec<[Printed; 2]>,
    /// The figure macro's labels of its arguments, in order.
    pub figure_labels: Vec<String>,
}

/// A printed table of real and projected distances.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DistanceTable {
    /// The claim.
    pub claim: ClaimRef,
    /// Column headers as printed (two point letters each).
    pub columns: Vec<String>,
    /// Row "real".
    pub real: Vec<Printed>,
    /// Row "real2".
    pub real2: Vec<Printed>,
    /// Row "squared".
    pub squared: Vec<Printed>,
    /// Row "projected 1".
    pub projected1: Vec<Printed>,
    /// Row "projected 2".
    pub projected2: Vec<Printed>,
    /// Significant digits printed.
    pub significant_digits: u32,
    /// The names the table's letters give the four points (the program's naming).
    pub point_names: Vec<String>,
}

/// The debug printouts.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DebugBlocks {
    /// The claim.
    pub claim: ClaimRef,
    /// Significant digits printed.
    pub significant_digits: u32,
    /// The paper's names (§5.2's procedure tests T against PQR) of the program's P, Q, R, T.
    pub program_order: Vec<String>,
    /// The program's labels of the twelve numbers of a block that are recomputed, in order:
    /// b², PaK (x, y, z), PbK (x, y, z), Pa (x, y), Pb (x, y), the (Linie) difference.
    pub quantities: Vec<String>,
    /// The program's labels of every number a block prints besides its flags and version,
    /// in print order: b, b0, d, d0, T1 (x, y), Q1, T2, Q2, PaK (x, y, z), PbK, Pa, Pb, P2
    /// (x, y), P1, and the (Linie) left side, right side and difference (31).
    pub printed_labels: Vec<String>,
    /// The factors d0 is multiplied by to see whether a block's distance depends on d.
    pub d_factors: Vec<f64>,
    /// Seeded draws of the frames inside their rounding box for the floating-point sign of
    /// Δ_b at its exact double root.
    pub rounding_draws: usize,
    /// The mutant of every printed number: moved by this many half units.
    pub mutant_half_units: f64,
    /// One block per attempt.
    pub attempts: Vec<DebugAttempt>,
    /// The blocks of error lines.
    pub errors: Vec<DebugError>,
}

/// One attempt as the program printed it (its names: P is the tested point).
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DebugAttempt {
    /// Lines of the block.
    pub lines: String,
    /// "b=": b².
    pub b2: Printed,
    /// "b0=": b.
    pub b: Printed,
    /// "d=": the chosen d².
    pub d2: Printed,
    /// "d0=": d.
    pub d: Printed,
    /// T₁ as printed.
    pub t1: [Printed; 2],
    /// Q₁.
    pub q1: [Printed; 2],
    /// T₂ (frame 2 shifted so that the assigned R is at the origin).
    pub t2: [Printed; 2],
    /// Q₂.
    pub q2: [Printed; 2],
    /// The signs printed after T₁, Q₁, T₂, Q₂.
    pub signs: [i8; 4],
    /// "PaK".
    pub pak: [Printed; 3],
    /// "PbK".
    pub pbk: [Printed; 3],
    /// "Pa".
    pub pa: [Printed; 3],
    /// "Pb".
    pub pb: [Printed; 3],
    /// "P2".
    pub p2: [Printed; 2],
    /// "P1".
    pub p1: [Printed; 2],
    /// "(Linie) x = y (diff z)".
    pub line: [Printed; 3],
    /// "(version v)".
    pub version: i8,
}

/// A block of error lines.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DebugError {
    /// Lines.
    pub lines: String,
    /// "ERROR: Fdg_dg / Fdg_g2 = r", in order.
    pub ratios: Vec<Printed>,
    /// "ERROR: Root of deltab negative", how often.
    pub delta_b_negative: usize,
}

/// The figure panels.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Panels {
    /// The claim.
    pub claim: ClaimRef,
    /// Half the side of the square box the segments are clipped to, as the panels print it.
    #[serde(rename = "box")]
    pub box_half: Printed,
    /// One per `\DreieckMitGerade`.
    pub items: Vec<Panel>,
}

/// One panel.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Panel {
    /// Its line in the source.
    pub line: u32,
    /// The four frame-2 points (#1 … #4).
    pub points: Vec<[Printed; 2]>,
    /// The segment drawn (#5, #6).
    pub segment: Vec<[Printed; 2]>,
}

pub(super) fn sizes(c: &IdentityExampleCase, v: &Validator) -> Result<()> {
    v.limit(
        "census_trials",
        "census_trials",
        c.census_trials,
        limits::CASE_TRIALS,
    )?;
    if !c.census_c_factor.is_finite() || !c.debug.mutant_half_units.is_finite() {
        return v.err("census_c_factor", "must be a finite number".into());
    }
    v.digits("table.significant_digits", c.table.significant_digits)?;
    v.digits("debug.significant_digits", c.debug.significant_digits)?;
    v.names("frames.figure_labels", &c.frames.figure_labels)?;
    v.names("table.point_names", &c.table.point_names)?;
    v.names("table.columns", &c.table.columns)?;
    v.names("debug.program_order", &c.debug.program_order)
}

pub(super) fn checks(c: &IdentityExampleCase, v: &Validator) -> Result<()> {
    let f = &c.frames;
    if f.frame1.len() != 4 || f.frame2.len() != 4 || f.figure_labels.len() != 4 {
        return v.err(
            "frames.frame1",
            "needs two frames of 4 points and 4 figure labels".into(),
        );
    }
    let t = &c.table;
    let n = t.columns.len();
    if n != 6
        || [&t.real, &t.real2, &t.squared, &t.projected1, &t.projected2]
            .iter()
            .any(|r| r.len() != n)
        || t.columns.iter().any(|h| h.chars().count() != 2)
    {
        return v.err(
            "table.columns",
            "needs 6 two-letter columns and 6 values per row".into(),
        );
    }
    if let Some(i) = c
        .panels
        .items
        .iter()
        .position(|p| p.points.len() != 4 || p.segment.len() != 2)
    {
        return v.err(
            &format!("panels.items[{i}].points"),
            "needs 4 points and a segment of 2".into(),
        );
    }
    let names = &t.point_names;
    let mut order = c.debug.program_order.clone();
    order.sort();
    let mut sorted = names.clone();
    sorted.sort();
    if names.len() != 4 || order != sorted {
        return v.err(
            "debug.program_order",
            "needs four point names, and the program order a permutation of them".into(),
        );
    }
    if c.debug.quantities.len() != 12 || c.debug.mutant_half_units <= 1.0 {
        return v.err(
            "debug.quantities",
            "needs the 12 labels of a block's recomputed numbers and a mutant of more than one half unit".into(),
        );
    }
    if c.debug.printed_labels.len() != 31
        || c.debug
            .d_factors
            .iter()
            .any(|k| !(k.is_finite() && *k > 0.0))
    {
        return v.err(
            "debug.printed_labels",
            "needs the 31 labels of a block's printed numbers, and positive finite d factors"
                .into(),
        );
    }
    if c.census_c_factor.is_nan() || c.census_c_factor < 1.0 {
        return v.err("census_c_factor", "must be at least 1".into());
    }
    Ok(())
}
