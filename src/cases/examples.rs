//! The worked examples and censuses: §2.1 counts, eq. p3f3sqr, §2 and §4 examples, figures, solutions.

use serde::Deserialize;

use super::{ClaimRef, NoiseLevel, Printed};

/// A claim decided over seeded random scenes.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct CensusCase {
    /// The claims decided.
    pub claims: Vec<ClaimRef>,
    /// Frames per scene.
    pub frames: usize,
    /// Scenes.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
    /// Result suffixes per claim id, for a claim whose result sits beside others of the same
    /// claim (`abstract-linear: four-frames` gives the id `abstract-linear/four-frames`).
    #[serde(default)]
    pub suffixes: std::collections::BTreeMap<String, String>,
    /// A degenerate configuration the census finds and the paper never names: which claim it
    /// qualifies, and the suffix of the result that states it.
    #[serde(default)]
    pub exception: Option<CensusException>,
}

/// A degenerate configuration qualifying one claim of a census.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct CensusException {
    /// The claim id it qualifies (one of the case's claims).
    pub qualifies: String,
    /// The suffix of the result that states it.
    pub suffix: String,
}

/// §2.1 worked examples.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DofCountCase {
    /// Seed of the generic scene for the rank evidence.
    pub seed: u64,
    /// The printed examples.
    pub examples: Vec<DofExample>,
}

/// One printed count.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DofExample {
    /// The claim.
    pub claim: ClaimRef,
    /// p.
    pub points: usize,
    /// k.
    pub frames: usize,
    /// The printed −1+3p+5(k−1).
    pub unknowns: Printed,
    /// The printed 2kp.
    pub measurements: Printed,
}

/// Identifiability claims over a grid.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DofIdentifiabilityCase {
    /// Seed of the generic scenes.
    pub seed: u64,
    /// Largest p of the grid.
    pub max_points: usize,
    /// Largest k of the grid.
    pub max_frames: usize,
    /// The printed count formula.
    pub formula: FormulaClaim,
    /// The printed minimum.
    pub minimum: MinimumClaim,
    /// "two frames never suffice".
    pub two_frames: ClaimRef,
}

/// The count formula as printed.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct FormulaClaim {
    /// The claim.
    pub claim: ClaimRef,
    /// Unknowns, in p and k, as printed.
    pub unknowns: String,
    /// Measurements, in p and k, as printed.
    pub measurements: String,
}

/// A claimed minimal configuration.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct MinimumClaim {
    /// The claim.
    pub claim: ClaimRef,
    /// Claimed minimal number of points.
    pub points: usize,
    /// Claimed minimal number of frames.
    pub frames: usize,
}

/// Eq. p3f3sqr.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct TwofoldCase {
    /// The three signed relations.
    pub relations: RelationsClaim,
    /// The printed polynomial.
    pub polynomial: PolynomialClaim,
    /// Random rational points for the independent evaluation check.
    pub evaluation_points: usize,
    /// Seed of those points.
    pub seed: u64,
}

/// The printed sign patterns.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct RelationsClaim {
    /// The claim.
    pub claim: ClaimRef,
    /// Patterns such as `"+ + -"` for √A + √B − √C = 0.
    pub patterns: Vec<String>,
    /// Random triangles to test.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
}

/// A printed polynomial.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PolynomialClaim {
    /// The claim.
    pub claim: ClaimRef,
    /// The transcription.
    pub printed: String,
}

/// §2's example.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct P3f3ExampleCase {
    /// The body table.
    pub body: BodyTable,
    /// The figure.
    pub figure: FigureFrames,
    /// The printed solutions.
    pub solutions: PrintedSolutions,
    /// The feasibility rules, applied to the printed solutions.
    pub feasibility: ClaimRef,
    /// The claim of the rounding analysis restricted to exact views of the body, when judged.
    #[serde(default)]
    pub restricted: Option<ClaimRef>,
    /// The claim of the quadratic's discriminant at the printed data, when judged.
    #[serde(default)]
    pub discriminant: Option<ClaimRef>,
    /// Monte Carlo samples of the rounding box.
    pub rounding_trials: usize,
    /// Seed.
    pub seed: u64,
}

/// A printed edge table: lengths and their squares.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BodyTable {
    /// The claim.
    pub claim: ClaimRef,
    /// Printed lengths, in the paper's edge order.
    pub lengths: Vec<Printed>,
    /// Printed squares.
    pub squares: Vec<Printed>,
    /// Significant digits the program printed with (trailing zeros dropped), when the
    /// numbers are not exact.
    #[serde(default)]
    pub significant_digits: Option<u32>,
}

/// §4's example: the edge table, the figure, the printed coefficient matrix and solution.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct P4f3ExampleCase {
    /// The edge table (PQ, QR, RP, TP, TQ, TR).
    pub body: BodyTable,
    /// The figure: three frames of P, Q, R, T.
    pub figure: FigureFrames,
    /// The printed coefficient matrix.
    pub matrix: PrintedMatrix,
    /// The printed solution x1 … x6.
    pub solution: PrintedSolutions,
    /// The claim the conditioning result answers.
    pub conditioning: ClaimRef,
    /// The claim of the system solved from the figure's printed digits, when judged.
    #[serde(default)]
    pub figure_system: Option<ClaimRef>,
    /// The printed noise runs: each level is judged against random motions of the body and
    /// against the figure's own scene.
    pub noise: Vec<NoiseLevel>,
    /// Shifts of the single-entry mutants of the printed matrix, in half units of the entry:
    /// the same witness search must fail for every mutant at the largest shift; the counts
    /// at each shift are reported.
    pub matrix_mutant_half_units: Vec<f64>,
    /// Monte Carlo trials per level, noise model and scene.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
}

/// A printed matrix: rows of printed numbers, the last column the constant.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PrintedMatrix {
    /// The claim.
    pub claim: ClaimRef,
    /// Significant digits the program printed with.
    pub significant_digits: u32,
    /// The rows as printed.
    pub rows: Vec<Vec<Printed>>,
}

/// Figure coordinates: frames of points, each `[x, y]` as printed.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct FigureFrames {
    /// The claim.
    pub claim: ClaimRef,
    /// `frames[i][j] = [x, y]`.
    pub frames: Vec<Vec<[Printed; 2]>>,
    /// Whether the first point of each frame is the shifted origin (exact, not rounded).
    #[serde(default)]
    pub origin_exact: bool,
}

impl FigureFrames {
    /// Flat coordinates and their rounding half-widths (`(center, half)`).
    pub fn rounding_box(&self) -> (Vec<f64>, Vec<f64>) {
        let mut center = Vec::new();
        let mut half = Vec::new();
        for frame in &self.frames {
            for (j, p) in frame.iter().enumerate() {
                for c in p {
                    center.push(c.to_f64());
                    half.push(if j == 0 && self.origin_exact {
                        0.0
                    } else {
                        c.half_unit()
                    });
                }
            }
        }
        (center, half)
    }
}

/// Printed solutions (squared edges).
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PrintedSolutions {
    /// The claim.
    pub claim: ClaimRef,
    /// Significant digits the program printed (trailing zeros dropped).
    pub significant_digits: u32,
    /// The solutions, each in the paper's edge order.
    pub values: Vec<Vec<Printed>>,
}
