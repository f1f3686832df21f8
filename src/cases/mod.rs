//! The paper's data: the YAML files of `paper_cases/` (format in `docs/case-format.md`).
//!
//! The paper's numbers live only here. A printed number keeps its printed digits, which give
//! both its exact value and its precision.

use std::collections::BTreeMap;
use std::fmt;
use std::path::{Path, PathBuf};

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::ToPrimitive;
use serde::de::{self, Deserializer, Visitor};
use serde::Deserialize;

use crate::algebra::{parse_decimal, Poly};
use crate::error::{Error, InputLocation, Result};

/// A number as the paper printed it: exact value plus precision.
///
/// # Example
/// ```
/// use orthocheck::cases::Printed;
/// let x = Printed::parse("1.2345").unwrap();
/// assert_eq!(x.decimals, 4);
/// assert_eq!(x.half_unit(), 0.00005);
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Printed {
    /// The digits as printed.
    pub text: String,
    /// The exact value of those digits.
    pub value: BigRational,
    /// Digits after the decimal point, less the printed exponent (`"2.5e-3"` has 4).
    pub decimals: i32,
}

impl Printed {
    /// Parse printed digits (`"12.345"`, `"-0.5"`, `"18"`, `".25"`, `"1.5e-14"`).
    pub fn parse(text: &str) -> Option<Printed> {
        let t = text.trim();
        let (mantissa, exponent) = match t.split_once(['e', 'E']) {
            Some((m, e)) => (m, e.parse::<i32>().ok()?),
            None => (t, 0),
        };
        let mut value = parse_decimal(mantissa)?;
        let ten = BigRational::from_integer(BigInt::from(10));
        for _ in 0..exponent.unsigned_abs() {
            value = if exponent > 0 {
                &value * &ten
            } else {
                &value / &ten
            };
        }
        let decimals = mantissa.split_once('.').map_or(0, |(_, f)| f.len() as i32) - exponent;
        Some(Printed {
            text: t.to_string(),
            value,
            decimals,
        })
    }

    /// Half a unit in the last printed digit: the rounding bound of the printed value.
    pub fn half_unit(&self) -> f64 {
        0.5 * 10f64.powi(-self.decimals)
    }

    /// Half a unit in the `digits`-th significant digit: the precision of a number printed
    /// with a fixed count of significant digits and trailing zeros dropped (C's `%g`, C++
    /// stream defaults), where "4" printed with six digits means 4.00000.
    pub fn half_unit_significant(&self, digits: u32) -> f64 {
        let v = self.to_f64().abs();
        if v == 0.0 {
            return self.half_unit();
        }
        let magnitude = v.log10().floor() as i32;
        0.5 * 10f64.powi(magnitude - digits as i32 + 1)
    }

    /// The value as `f64`.
    pub fn to_f64(&self) -> f64 {
        self.value.to_f64().unwrap_or(f64::NAN)
    }

    /// The value as an integer, when it is one.
    pub fn to_integer(&self) -> Option<BigInt> {
        self.value.is_integer().then(|| self.value.to_integer())
    }
}

impl Printed {
    /// Printed numbers as printed, comma-separated.
    pub fn join(v: &[Printed]) -> String {
        v.iter()
            .map(|p| p.text.as_str())
            .collect::<Vec<_>>()
            .join(", ")
    }
}

impl fmt::Display for Printed {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

impl<'de> Deserialize<'de> for Printed {
    fn deserialize<D: Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = Printed;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a printed number as a quoted string, e.g. \"1.2345\"")
            }
            fn visit_str<E: de::Error>(self, s: &str) -> std::result::Result<Printed, E> {
                Printed::parse(s)
                    .ok_or_else(|| E::custom(format!("'{s}' is not a printed decimal number")))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> std::result::Result<Printed, E> {
                self.visit_str(&v.to_string())
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> std::result::Result<Printed, E> {
                self.visit_str(&v.to_string())
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> std::result::Result<Printed, E> {
                Err(E::custom(format!(
                    "{v} is an unquoted float: quote it so its printed digits are kept"
                )))
            }
        }
        d.deserialize_str(V)
    }
}

/// Where in the paper a case or claim comes from.
#[derive(Clone, Debug, Deserialize, serde::Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Source {
    /// Section number as in the paper ("2.1", "A" for the appendix).
    pub section: String,
    /// Equation, table or figure label, if any.
    #[serde(default)]
    pub label: Option<String>,
    /// Line range in the LaTeX source.
    pub lines: String,
    /// A short quote.
    pub quote: String,
}

/// One claim of CLAIMS.md as a case refers to it.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ClaimRef {
    /// The CLAIMS.md id.
    pub claim: String,
    /// Line range.
    pub lines: String,
    /// A short quote.
    pub quote: String,
}

/// A case file.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Case {
    /// Unique case id (also the snapshot name).
    pub id: String,
    /// Human title.
    pub title: String,
    /// Where the case sits in the paper.
    pub source: Source,
    /// What to check, by kind.
    pub check: CaseCheck,
    /// The file it was read from (set by [`load_case`]).
    #[serde(skip)]
    pub file: Option<PathBuf>,
}

/// The kinds of case; each kind has its runner in `check`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum CaseCheck {
    /// §2.1's worked counts.
    DofCount(DofCountCase),
    /// §2.1 and the abstract: identifiability decided by Jacobian rank.
    DofIdentifiability(DofIdentifiabilityCase),
    /// Eq. p3f3sqr and the signed relations.
    TwofoldSquared(TwofoldCase),
    /// §2's worked example.
    P3f3Example(P3f3ExampleCase),
    /// §4's worked example.
    P4f3Example(P4f3ExampleCase),
    /// §4's uniqueness over generic and degenerate scenes.
    P4f3Census(CensusCase),
    /// §2.2's solution count over generic and degenerate scenes.
    P3f3Census(CensusCase),
    /// §3's uniqueness over generic and special motions.
    P3f4Census(CensusCase),
    /// Claims the paper gives no data for: what is printed and what a reproduction lacks.
    NotReproducible(NotReproducibleCase),
    /// Every displayed formula and derivation step, machine-checked.
    FormulaAudit(FormulaAuditCase),
    /// §5.1 and §5.4: two frames are not enough; the counterexample; curves.
    TwoFrames(TwoFramesCase),
    /// §5.2 and §5.3 over seeded random scenes: the identity tests.
    IdentityCensus(IdentityCensusCase),
    /// §5.2's example: the frames, the hidden table, the debug printouts, the panels.
    IdentityExample(IdentityExampleCase),
    /// Restatements (discussion, conclusions): each decided by the claims it restates.
    Restatements(RestatementsCase),
    /// A noise study (§2, §3).
    NoiseStudy(NoiseStudyCase),
}

/// The formula audit.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct FormulaAuditCase {
    /// Random rational points for the second, independent check of every identity.
    pub evaluation_points: usize,
    /// Seed of those points.
    pub seed: u64,
    /// The paper's macros (`\faca{1}` …), transcribed: names usable in every formula.
    #[serde(default)]
    pub definitions: Vec<Definition>,
    /// Displayed formulas, each compared with a derivation.
    #[serde(default)]
    pub formulas: Vec<FormulaItem>,
    /// Printed arithmetic.
    #[serde(default)]
    pub arithmetic: Vec<ArithmeticItem>,
    /// Statements decided by a dedicated computation.
    #[serde(default)]
    pub computed: Vec<ComputedItem>,
    /// Textual and typographic errata.
    #[serde(default)]
    pub text: Vec<TextItem>,
}

/// Where an audit item sits in the paper.
#[derive(Clone, Debug, Deserialize, PartialEq, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Place {
    /// Section as numbered ("2.2", "A").
    pub section: String,
    /// Equation label, if any.
    #[serde(default)]
    pub label: Option<String>,
    /// The LaTeX macros involved.
    #[serde(default)]
    pub macros: Vec<String>,
}

impl fmt::Display for Place {
    /// `§5.2, label p4f2, macros \faca \facb`
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "§{}", self.section)?;
        if let Some(l) = &self.label {
            write!(f, ", label {l}")?;
        }
        if !self.macros.is_empty() {
            write!(f, ", macros {}", self.macros.join(" "))?;
        }
        Ok(())
    }
}

/// A macro of the paper, transcribed.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Definition {
    /// The name formulas use.
    pub name: String,
    /// The LaTeX macro.
    #[serde(rename = "macro")]
    pub latex: String,
    /// Its expansion, transcribed.
    pub printed: String,
}

/// How a printed formula must relate to its derivation.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Relation {
    /// The same expression.
    #[default]
    Equal,
    /// A non-zero rational multiple (an equation `= 0` printed with another sign or scale).
    Proportional,
}

/// A displayed formula.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct FormulaItem {
    /// The claim.
    pub claim: ClaimRef,
    /// The result id's suffix.
    pub id: String,
    /// Where.
    #[serde(rename = "where")]
    pub place: Place,
    /// The printed formula, transcribed faithfully (defects kept where they change the
    /// meaning); absent when it is not a formula at all.
    #[serde(default)]
    pub printed: Option<String>,
    /// The LaTeX as printed, when the transcription alone would hide the defect.
    #[serde(default)]
    pub printed_text: Option<String>,
    /// The defect, in words.
    #[serde(default)]
    pub defect: Option<String>,
    /// The corrected formula, for an erratum.
    #[serde(default)]
    pub corrected: Option<String>,
    /// The derivation it must equal (see `derivations::formulas::NAMES`).
    pub derived: String,
    /// Equal (default) or proportional.
    #[serde(default)]
    pub relation: Relation,
    /// Defined names kept as free symbols here.
    #[serde(default)]
    pub symbols: Vec<String>,
    /// The name this formula defines for later ones.
    #[serde(default)]
    pub defines: Option<String>,
    /// Groups of variables in whose squares the formula must be at most quadratic.
    #[serde(default)]
    pub quadratic_in: Vec<Vec<String>>,
}

/// Printed arithmetic: an expression and the value printed for it.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ArithmeticItem {
    /// The claim.
    pub claim: ClaimRef,
    /// The result id's suffix.
    pub id: String,
    /// Where.
    #[serde(rename = "where")]
    pub place: Place,
    /// The printed steps, each an expression, in order (`-1+3*p+5*(k-1)`, `-1+12+5`).
    pub steps: Vec<String>,
    /// Values of the variables.
    #[serde(default)]
    pub values: BTreeMap<String, i64>,
    /// The printed result.
    pub equals: Printed,
}

/// A statement decided by a dedicated computation.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ComputedItem {
    /// The claim.
    pub claim: ClaimRef,
    /// The result id's suffix.
    pub id: String,
    /// Where.
    #[serde(rename = "where")]
    pub place: Place,
    /// What the paper says, in its words.
    pub printed: String,
    /// The computation.
    pub test: ComputedTest,
}

/// The dedicated computations.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum ComputedTest {
    /// §5: "linearly dependent on the three previous ones".
    FourthRelation {
        /// Seed of the rational scene for the ranks.
        seed: u64,
    },
    /// The formula for b solves the quadratic in b² (Appendix A, §5.2).
    BFormula,
    /// `√(e₀² − e₀ᵢ²) = ±√(e₁² − e₁ᵢ²) ± √(e₂² − e₂ᵢ²)`, every sign choice squared twice,
    /// against eq. p3f3sqr of the triangle with these edges.
    SignedRelation {
        /// The three edge letters, the left-hand side first.
        edges: Vec<String>,
    },
    /// A list of "constant symbols" against the symbols the expression uses.
    ConstantSymbols {
        /// The symbols the text lists.
        listed: Vec<String>,
        /// The symbols the expression uses.
        used: Vec<String>,
    },
    /// n(n−1)(n−2)(n−3) against the number of ordered choices of four of n points.
    OrderedQuadruples {
        /// The n to check.
        n: Vec<usize>,
        /// The printed value for the first n.
        printed: Printed,
    },
}

/// A textual or typographic erratum.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct TextItem {
    /// The claim.
    pub claim: ClaimRef,
    /// The result id's suffix.
    pub id: String,
    /// Where.
    #[serde(rename = "where")]
    pub place: Place,
    /// As printed.
    pub printed: String,
    /// As it should read.
    pub corrected: String,
    /// Why it matters to a reader reproducing the result.
    pub effect: String,
}

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
    /// Seed.
    pub seed: u64,
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
    /// The figure panels.
    pub panels: Panels,
    /// Random generic scenes for the comparison with the example.
    pub census_trials: usize,
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
}

/// The debug printouts.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct DebugBlocks {
    /// The claim.
    pub claim: ClaimRef,
    /// Significant digits printed.
    pub significant_digits: u32,
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
    /// Seed.
    pub seed: u64,
}

/// Restatements of earlier claims.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct RestatementsCase {
    /// One per restated sentence or bullet.
    pub items: Vec<Restatement>,
}

/// One restatement.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Restatement {
    /// The claim.
    pub claim: ClaimRef,
    /// The result id's suffix.
    pub id: String,
    /// The CLAIMS.md ids it restates (every result of each counts); empty for a statement
    /// outside the paper's scope.
    #[serde(default)]
    pub restates: Vec<String>,
    /// Why it is outside the scope, when `restates` is empty.
    #[serde(default)]
    pub out_of_scope: Option<String>,
}

/// Claims without data.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct NotReproducibleCase {
    /// One entry per claim.
    pub claims: Vec<MissingData>,
}

/// One claim the paper gives no data for.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct MissingData {
    /// The claim.
    pub claim: ClaimRef,
    /// What the paper does print about it.
    pub printed: String,
    /// What a reproduction would need and the paper does not give.
    pub missing: Vec<String>,
}

/// A noise study as the paper reports it.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct NoiseStudyCase {
    /// The solver the paper used.
    pub solver: crate::derivations::noise::StudySolver,
    /// The body.
    pub body: NoiseBody,
    /// Frames per trial.
    pub frames: usize,
    /// Trials per level and noise model.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
    /// The levels the paper reports.
    pub levels: Vec<NoiseLevel>,
}

/// The body of a noise study: printed lengths (and squares, when printed).
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct NoiseBody {
    /// The claim about the printed body, if any.
    #[serde(default)]
    pub claim: Option<ClaimRef>,
    /// Printed lengths in edge order (PQ, QR, RP, then TP, TQ, TR for four points).
    pub lengths: Vec<Printed>,
    /// Printed squares, if printed.
    #[serde(default)]
    pub squares: Vec<Printed>,
    /// Significant digits the program printed the squares with.
    #[serde(default)]
    pub significant_digits: Option<u32>,
}

/// What the paper's symbols say the printed values are.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Quantity {
    /// a², b², c².
    Squares,
    /// a, b, c.
    Lengths,
}

/// One noise level as reported.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct NoiseLevel {
    /// The claim.
    pub claim: ClaimRef,
    /// ε as printed ("up to 0.1 %" is "0.001").
    pub level: Printed,
    /// What the printed symbols say the values are.
    pub labelled_as: Quantity,
    /// The printed run's solutions; the first is the one compared with the truth.
    pub printed: Vec<Vec<Printed>>,
    /// A numeric statement about the errors, if the paper makes one.
    #[serde(default)]
    pub statement: Option<Statement>,
}

/// "error below 0.2 %", "deviates more than 15 %", "average performance within 20 %".
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Statement {
    /// Whether it is about the printed example or about the mean over trials.
    pub about: StatementSubject,
    /// The bound is an upper one ("below") or a lower one ("above").
    pub direction: Direction,
    /// The bound as a fraction ("0.002" for 0.2 %).
    pub bound: Printed,
    /// How the edges' errors combine: the worst edge (default) or their mean ("on average").
    #[serde(default)]
    pub over_edges: OverEdges,
}

/// How a statement combines the errors of the edges.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum OverEdges {
    /// The largest error over the edges.
    #[default]
    Max,
    /// The mean error over the edges.
    Mean,
}

/// The subject of a statement.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum StatementSubject {
    /// The printed run.
    Example,
    /// The mean error over all trials.
    TrialMean,
}

/// Below or above.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum Direction {
    /// The error is below the bound.
    Below,
    /// The error is above the bound.
    Above,
}

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
    /// The printed noise runs: each level is judged against random motions of the body and
    /// against the figure's own scene.
    pub noise: Vec<NoiseLevel>,
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
    /// Flat coordinates and rounding half-widths.
    pub fn rounding_box(&self) -> crate::derivations::rounding::RoundingBox {
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
        crate::derivations::rounding::RoundingBox { center, half }
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

impl Case {
    /// Every seed the case sets (the report lists them, so that a run can be repeated).
    pub fn seeds(&self) -> Vec<u64> {
        match &self.check {
            CaseCheck::DofCount(c) => vec![c.seed],
            CaseCheck::DofIdentifiability(c) => vec![c.seed],
            CaseCheck::TwofoldSquared(c) => vec![c.relations.seed, c.seed],
            CaseCheck::P3f3Example(c) => vec![c.seed],
            CaseCheck::P4f3Example(c) => vec![c.seed],
            CaseCheck::P4f3Census(c) | CaseCheck::P3f3Census(c) | CaseCheck::P3f4Census(c) => {
                vec![c.seed]
            }
            CaseCheck::FormulaAudit(c) => vec![c.seed],
            CaseCheck::TwoFrames(c) => vec![c.seed],
            CaseCheck::IdentityCensus(c) => vec![c.seed],
            CaseCheck::IdentityExample(c) => vec![c.seed],
            CaseCheck::NoiseStudy(c) => vec![c.seed],
            CaseCheck::NotReproducible(_) | CaseCheck::Restatements(_) => Vec::new(),
        }
    }
}

/// Read and validate one case file.
pub fn load_case(path: &Path) -> Result<Case> {
    let text = std::fs::read_to_string(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let mut case = parse_case(&text, path)?;
    case.file = Some(path.to_path_buf());
    Ok(case)
}

/// Parse and validate case text; `path` names the file in errors.
pub fn parse_case(text: &str, path: &Path) -> Result<Case> {
    let case: Case = parse_yaml(text, path)?;
    validate(&case, text, path)?;
    Ok(case)
}

/// Deserialize YAML with errors that name the file, line, column and field path.
pub fn parse_yaml<T: serde::de::DeserializeOwned>(text: &str, path: &Path) -> Result<T> {
    let options = serde_saphyr::options! { with_snippet: false };
    let mut field: Option<String> = None;
    let parsed = serde_saphyr::with_deserializer_from_str_with_options(text, options, |de| {
        serde_path_to_error::deserialize(de).map_err(|e| {
            let p = e.path().to_string();
            if p != "." && p != "?" {
                field = Some(p);
            }
            e.into_inner()
        })
    });
    parsed.map_err(|e| {
        let loc = e.location();
        let message = e.to_string();
        Error::Input {
            location: InputLocation {
                file: path.to_path_buf(),
                line: loc.map(|l| l.line()),
                column: loc.map(|l| l.column()),
                field: field.or_else(|| field_of(&message)),
            },
            message: strip_location(&message),
        }
    })
}

/// The field a message names (`missing field `x``, `duplicate mapping key: x`).
fn field_of(message: &str) -> Option<String> {
    if let Some(i) = message.find("field `") {
        let start = i + "field `".len();
        let end = message[start..].find('`')?;
        return Some(message[start..start + end].to_string());
    }
    let start = message.find("duplicate mapping key: ")? + "duplicate mapping key: ".len();
    let key = message[start..].split([',', ' ']).next()?;
    Some(key.to_string())
}

/// The 1-based line of a dotted field path (`check.dof_count.examples[1].points`) in
/// block-style YAML, for errors found after parsing.
pub(crate) fn line_of(text: &str, field: &str) -> Option<u64> {
    let lines: Vec<&str> = text.lines().collect();
    let indent = |l: &str| l.len() - l.trim_start().len();
    let (mut pos, mut min_indent) = (0usize, 0usize);
    for segment in field.split('.') {
        let (key, index) = match segment.split_once('[') {
            // the first index only: deeper ones sit in flow sequences on the item's line
            Some((k, i)) => (k, i.split(']').next().and_then(|n| n.parse::<usize>().ok())),
            None => (segment, None),
        };
        let found = (pos..lines.len()).find(|&i| {
            let t = lines[i].trim_start().trim_start_matches("- ");
            indent(lines[i]) >= min_indent && t.starts_with(&format!("{key}:"))
        })?;
        pos = found;
        min_indent = indent(lines[found]);
        if let Some(n) = index {
            let items: Vec<usize> = (found + 1..lines.len())
                .take_while(|&i| {
                    lines[i].trim().is_empty()
                        || indent(lines[i]) > min_indent
                        || lines[i].trim_start().starts_with('-')
                })
                .filter(|&i| lines[i].trim_start().starts_with('-'))
                .collect();
            // A flow sequence (`[..]`) has no item lines: the key's line is the best answer.
            let Some(item_indent) = items.first().map(|&i| indent(lines[i])) else {
                break;
            };
            let Some(at) = items
                .into_iter()
                .filter(|&i| indent(lines[i]) == item_indent)
                .nth(n)
            else {
                break;
            };
            pos = at;
            min_indent = item_indent;
        }
    }
    Some(pos as u64 + 1)
}

/// Drop a trailing " at line L, column C" that the location already says.
fn strip_location(message: &str) -> String {
    match message.find(" at line ") {
        Some(i) => message[..i].to_string(),
        None => message.to_string(),
    }
}

fn invalid(text: &str, path: &Path, field: &str, message: String) -> Error {
    Error::Input {
        location: InputLocation {
            file: path.to_path_buf(),
            line: line_of(text, field),
            column: None,
            field: Some(field.to_string()),
        },
        message,
    }
}

/// Checks serde cannot express: counts, sign patterns, and that every formula parses.
fn validate(case: &Case, text: &str, path: &Path) -> Result<()> {
    let err = |field: &str, message: String| Err(invalid(text, path, field, message));
    let formula = |field: &str, f: &str| match Poly::parse(f) {
        Ok(_) => Ok(()),
        Err(e) => err(field, format!("formula does not parse: {e}")),
    };
    if case.id.trim().is_empty() {
        return err("id", "must not be empty".into());
    }
    match &case.check {
        CaseCheck::DofCount(c) => {
            for (i, e) in c.examples.iter().enumerate() {
                if e.points == 0 || e.frames == 0 {
                    return err(
                        &format!("check.dof_count.examples[{i}].points"),
                        "points and frames must be at least 1".into(),
                    );
                }
            }
        }
        CaseCheck::DofIdentifiability(c) => {
            if c.max_points < 3 || c.max_frames < 3 {
                return err(
                    "check.dof_identifiability.max_points",
                    "the grid must reach at least 3 points and 3 frames".into(),
                );
            }
            formula(
                "check.dof_identifiability.formula.unknowns",
                &c.formula.unknowns,
            )?;
            formula(
                "check.dof_identifiability.formula.measurements",
                &c.formula.measurements,
            )?;
        }
        CaseCheck::TwofoldSquared(c) => {
            for (i, p) in c.relations.patterns.iter().enumerate() {
                if parse_signs(p).is_none() {
                    return err(
                        &format!("check.twofold_squared.relations.patterns[{i}]"),
                        format!("'{p}' is not three signs such as \"+ + -\""),
                    );
                }
            }
            formula(
                "check.twofold_squared.polynomial.printed",
                &c.polynomial.printed,
            )?;
        }
        CaseCheck::NoiseStudy(c) => {
            use crate::derivations::noise::StudySolver;
            let edges = match c.solver {
                StudySolver::P3f3 | StudySolver::P3f4 => 3,
                StudySolver::P4f3 => 6,
            };
            if c.body.lengths.len() != edges
                || !(c.body.squares.is_empty() || c.body.squares.len() == edges)
            {
                return err(
                    "check.noise_study.body.lengths",
                    format!("the solver needs {edges} lengths (and {edges} squares if any)"),
                );
            }
            let frames_ok = match c.solver {
                StudySolver::P3f3 | StudySolver::P4f3 => c.frames == 3,
                StudySolver::P3f4 => c.frames >= 4,
            };
            if !frames_ok {
                return err(
                    "check.noise_study.frames",
                    "p3f3 and p4f3 need 3 frames, p3f4 at least 4".into(),
                );
            }
            for (i, l) in c.levels.iter().enumerate() {
                if l.printed.is_empty() || l.printed.iter().any(|p| p.len() != edges) {
                    return err(
                        &format!("check.noise_study.levels[{i}].printed"),
                        format!("needs solutions of {edges} values"),
                    );
                }
            }
        }
        CaseCheck::TwoFrames(c) => {
            if c.counterexample.points.len() != 5 || c.counterexample.names.len() != 5 {
                return err(
                    "check.two_frames.counterexample.points",
                    "needs the five points P, Q, R, Q′, R′".into(),
                );
            }
            if c.points < 4 || c.trials == 0 || c.curve_samples < 4 {
                return err(
                    "check.two_frames.points",
                    "needs at least 4 points, 1 trial and 4 curve samples".into(),
                );
            }
        }
        CaseCheck::IdentityExample(c) => {
            let f = &c.frames;
            if f.frame1.len() != 4 || f.frame2.len() != 4 || f.figure_labels.len() != 4 {
                return err(
                    "check.identity_example.frames.frame1",
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
                return err(
                    "check.identity_example.table.columns",
                    "needs 6 two-letter columns and 6 values per row".into(),
                );
            }
            if let Some(i) = c
                .panels
                .items
                .iter()
                .position(|p| p.points.len() != 4 || p.segment.len() != 2)
            {
                return err(
                    &format!("check.identity_example.panels.items[{i}].points"),
                    "needs 4 points and a segment of 2".into(),
                );
            }
        }
        CaseCheck::Restatements(c) => {
            if let Some(i) = c
                .items
                .iter()
                .position(|r| r.restates.is_empty() == r.out_of_scope.is_none())
            {
                return err(
                    &format!("check.restatements.items[{i}].restates"),
                    "give either the claims it restates or why it is out of scope".into(),
                );
            }
        }
        CaseCheck::IdentityCensus(c) => {
            if c.trials == 0 || c.c_factors.iter().any(|f| f.is_nan() || *f < 1.0) {
                return err(
                    "check.identity_census.c_factors",
                    "needs trials and factors of at least 1".into(),
                );
            }
        }
        CaseCheck::P4f3Census(c) => {
            if c.trials == 0 || c.claims.is_empty() || c.frames != 3 {
                return err("check", "needs a claim, a trial and 3 frames".into());
            }
        }
        CaseCheck::P3f3Census(c) | CaseCheck::P3f4Census(c) => {
            if c.trials == 0 || c.claims.is_empty() {
                return err("check", "needs at least one claim and one trial".into());
            }
            let needed = if matches!(case.check, CaseCheck::P3f3Census(_)) {
                3
            } else {
                4
            };
            if c.frames < needed || (needed == 3 && c.frames != 3) {
                return err(
                    "check",
                    format!(
                        "frames must be {}",
                        if needed == 3 { "3" } else { "at least 4" }
                    ),
                );
            }
        }
        CaseCheck::P4f3Example(c) => {
            let f = &c.figure.frames;
            if f.len() != 3 || f.iter().any(|fr| fr.len() != 4) {
                return err(
                    "check.p4f3_example.figure.frames",
                    "needs 3 frames of 4 points".into(),
                );
            }
            if c.body.lengths.len() != 6 || c.body.squares.len() != 6 {
                return err(
                    "check.p4f3_example.body.lengths",
                    "needs 6 lengths and 6 squares".into(),
                );
            }
            if c.matrix.rows.len() != 6 || c.matrix.rows.iter().any(|r| r.len() != 7) {
                return err(
                    "check.p4f3_example.matrix.rows",
                    "needs 6 rows of 7 numbers (x1 … x6 and the constant)".into(),
                );
            }
            if let Some(i) = c
                .noise
                .iter()
                .position(|l| l.printed.is_empty() || l.printed.iter().any(|p| p.len() != 6))
            {
                return err(
                    &format!("check.p4f3_example.noise[{i}].printed"),
                    "needs solutions of 6 values".into(),
                );
            }
            if c.solution.values.len() != 1 || c.solution.values[0].len() != 6 {
                return err(
                    "check.p4f3_example.solution.values",
                    "needs one solution of 6 values".into(),
                );
            }
        }
        CaseCheck::FormulaAudit(c) => {
            let parses = |field: &str, f: &str| match crate::algebra::RatFn::parse(f) {
                Ok(_) => Ok(()),
                Err(e) => err(field, format!("formula does not parse: {e}")),
            };
            for (i, d) in c.definitions.iter().enumerate() {
                parses(
                    &format!("check.formula_audit.definitions[{i}].printed"),
                    &d.printed,
                )?;
            }
            let known: Vec<&str> = crate::derivations::formulas::NAMES
                .iter()
                .map(|n| n.0)
                .collect();
            for (i, f) in c.formulas.iter().enumerate() {
                let at = |k: &str| format!("check.formula_audit.formulas[{i}].{k}");
                if let Some(p) = &f.printed {
                    parses(&at("printed"), p)?;
                }
                if let Some(p) = &f.corrected {
                    parses(&at("corrected"), p)?;
                }
                if f.printed.is_none() && f.corrected.is_none() {
                    return err(
                        &at("printed"),
                        "needs a printed or a corrected formula".into(),
                    );
                }
                if !known.contains(&f.derived.as_str()) {
                    return err(
                        &at("derived"),
                        format!("unknown derivation `{}`", f.derived),
                    );
                }
            }
            for (i, a) in c.arithmetic.iter().enumerate() {
                for (j, st) in a.steps.iter().enumerate() {
                    if crate::algebra::Poly::parse(st).is_err() {
                        return err(
                            &format!("check.formula_audit.arithmetic[{i}].steps[{j}]"),
                            format!("'{st}' does not parse"),
                        );
                    }
                }
            }
        }
        CaseCheck::NotReproducible(c) => {
            if let Some(i) = c.claims.iter().position(|m| m.missing.is_empty()) {
                return err(
                    &format!("check.not_reproducible.claims[{i}].missing"),
                    "say what is missing".into(),
                );
            }
        }
        CaseCheck::P3f3Example(c) => {
            let f = &c.figure.frames;
            if f.len() != 3 || f.iter().any(|fr| fr.len() != 3) {
                return err(
                    "check.p3f3_example.figure.frames",
                    "needs 3 frames of 3 points".into(),
                );
            }
            if c.body.lengths.len() != 3 || c.body.squares.len() != 3 {
                return err(
                    "check.p3f3_example.body.lengths",
                    "needs 3 lengths and 3 squares".into(),
                );
            }
            if c.solutions.values.len() > 2 || c.solutions.values.iter().any(|v| v.len() != 3) {
                return err(
                    "check.p3f3_example.solutions.values",
                    "at most 2 solutions of 3 squared edges".into(),
                );
            }
        }
    }
    Ok(())
}

/// Parse a sign pattern `"+ + -"`.
pub fn parse_signs(text: &str) -> Option<[i64; 3]> {
    let signs: Vec<i64> = text
        .split_whitespace()
        .map(|t| match t {
            "+" => Some(1),
            "-" => Some(-1),
            _ => None,
        })
        .collect::<Option<_>>()?;
    signs.try_into().ok()
}

/// All `*.yaml` files of a folder, sorted by name.
pub fn case_files(dir: &Path) -> Result<Vec<PathBuf>> {
    let entries = std::fs::read_dir(dir).map_err(|source| Error::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    let mut files: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
        .collect();
    files.sort();
    Ok(files)
}

/// Load every case of a folder.
pub fn load_all(dir: &Path) -> Result<Vec<Case>> {
    case_files(dir)?.iter().map(|p| load_case(p)).collect()
}
