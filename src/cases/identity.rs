//! §5: the two-frame construction, the identity example with its debug printouts and panels, the identity census.

use serde::Deserialize;

use super::{ClaimRef, Printed};

/// §5.1's printed construction and the general two-frame claims.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct TwoFramesCase {
    /// The printed points P, Q, R, Q′, R′.
    pub counterexample: PrintedPoints,
    /// The construction as the text describes it.
    pub construction: ClaimRef,
    /// "no possibility of recovery … from two images" (the family, at random scenes).
    pub family: ClaimRef,
    /// "the forth point T2 does carry only one piece of information".
    pub fourth_point: ClaimRef,
    /// §5.4: curves.
    pub curves: ClaimRef,
    /// Points of the random scenes (≥ 4).
    pub points: usize,
    /// Random scenes.
    pub trials: usize,
    /// Samples of the curve.
    pub curve_samples: usize,
    /// The angles β of the family members compared (each in (0, π)).
    pub betas: Vec<f64>,
    /// The control: how far one point of frame 2 is moved off the body (fraction of the
    /// image size), which the family's reprojection must then reject.
    pub control_shift: f64,
    /// The counterexample's mutant: Q′'s second coordinate moved by this many half units.
    pub mutant_half_units: f64,
    /// The member of the family the figures draw, when judged.
    #[serde(default)]
    pub drawn_member: Option<DrawnMember>,
    /// Seed.
    pub seed: u64,
}

/// §5.1's figures as drawn, against the printed points.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DrawnMember {
    /// The claim.
    pub claim: ClaimRef,
    /// The figure label the text says shows the rotated body (the other shows the original).
    pub rotated_figure: String,
    /// The pictures.
    pub drawings: Vec<Drawing>,
}

/// One picture: drawing coordinates as printed in its `\put` commands.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Drawing {
    /// Line range.
    pub lines: String,
    /// The figure label it belongs to.
    pub figure: String,
    /// The hidden corner of the cube, where its three thin edges start.
    pub corner: [Printed; 2],
    /// The other ends of the three thin edges.
    pub edges: Vec<[Printed; 2]>,
    /// The names of the three body points labelled (P first).
    pub label_names: Vec<String>,
    /// Their label positions.
    pub labels: Vec<[Printed; 2]>,
    /// The line n (two ends).
    pub n: [[Printed; 2]; 2],
    /// One frame-1 ray (two ends).
    pub frame1_ray: [[Printed; 2]; 2],
    /// The frame-2 rays (two ends each).
    pub frame2_rays: Vec<[[Printed; 2]; 2]>,
}

/// Printed 3-D points.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PrintedPoints {
    /// The claim.
    pub claim: ClaimRef,
    /// Names, as printed.
    pub names: Vec<String>,
    /// Coordinates, as printed.
    pub points: Vec<[Printed; 3]>,
}

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

/// The identity tests over seeded random scenes.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct IdentityCensusCase {
    /// "Three traced points ensure that … we can identify the line".
    pub line: ClaimRef,
    /// The procedure (c, b, a, T_a, T_b) and its c.
    pub procedure: ClaimRef,
    /// §5.3: five points.
    pub five_points: ClaimRef,
    /// The abstract's and the conclusions' identification claim.
    pub tracing: ClaimRef,
    /// Random scenes.
    pub trials: usize,
    /// Values of c per scene, as multiples of the smallest allowed c.
    pub c_factors: Vec<f64>,
    /// The control: how far T₂ (and S₂) is moved off the body (fraction of the image size),
    /// which the same tests must then reject.
    pub control_shift: f64,
    /// Seed.
    pub seed: u64,
}
