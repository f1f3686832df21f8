//! The calling convention shared by every solver: projected squared lengths in, every
//! solution out, each with its squared edges, a feasibility verdict with the reason, and a
//! residual; degenerate input is a typed outcome, never NaN.

use std::fmt;

use serde::Serialize;

use crate::error::{Error, Result};
use crate::model::Tracks;

/// The edges of a p-point body in the paper's order: PQ (a), QR (b), RP (c), then for each
/// further point its edges to the earlier ones (TP, TQ, TR, SP, SQ, SR, ST, …).
///
/// # Example
/// ```
/// use orthocheck::derivations::solver::edges;
/// assert_eq!(edges(4), [(0, 1), (1, 2), (2, 0), (3, 0), (3, 1), (3, 2)]);
/// ```
pub fn edges(p: usize) -> Vec<(usize, usize)> {
    let mut e = Vec::new();
    if p >= 2 {
        e.push((0, 1));
    }
    if p >= 3 {
        e.push((1, 2));
        e.push((2, 0));
    }
    for j in 3..p {
        for i in 0..j {
            e.push((j, i));
        }
    }
    e
}

/// Projected squared lengths of every edge in every frame.
#[derive(Clone, Debug, PartialEq)]
pub struct SquaredLengths {
    /// Point names.
    pub names: Vec<String>,
    /// Edges (point index pairs), in [`edges`] order.
    pub edges: Vec<(usize, usize)>,
    /// `frames[i][e]`: squared projected length of edge `e` in frame `i`.
    pub frames: Vec<Vec<f64>>,
}

impl SquaredLengths {
    /// From image points.
    pub fn from_tracks(t: &Tracks) -> Self {
        let e = edges(t.points());
        SquaredLengths {
            names: t.names.clone(),
            frames: (0..t.frames.len())
                .map(|f| e.iter().map(|&(i, j)| t.squared_length(f, i, j)).collect())
                .collect(),
            edges: e,
        }
    }

    /// Validated lengths for `names.len()` points: one value per edge, finite, non-negative.
    pub fn new(names: Vec<String>, frames: Vec<Vec<f64>>) -> Result<Self> {
        let e = edges(names.len());
        for (i, f) in frames.iter().enumerate() {
            if f.len() != e.len() {
                return Err(Error::InvalidInput(format!(
                    "frame {} has {} squared lengths, expected {}",
                    i + 1,
                    f.len(),
                    e.len()
                )));
            }
            if let Some(v) = f.iter().find(|v| !v.is_finite() || **v < 0.0) {
                return Err(Error::InvalidInput(format!(
                    "frame {}: squared length {v} is not a finite non-negative number",
                    i + 1
                )));
            }
        }
        Ok(SquaredLengths {
            names,
            edges: e,
            frames,
        })
    }

    /// Edge names such as "PQ".
    pub fn edge_names(&self) -> Vec<String> {
        self.edges
            .iter()
            .map(|&(i, j)| format!("{}{}", self.names[i], self.names[j]))
            .collect()
    }

    /// The longest projection of edge `e` over all frames.
    pub fn max_projection(&self, e: usize) -> f64 {
        self.frames.iter().map(|f| f[e]).fold(0.0, f64::max)
    }
}

/// Whether a solution is physically possible (§2.2's two rules).
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Feasibility {
    /// Real, no negative square, no edge shorter than a projection.
    Feasible,
    /// A complex root.
    Complex,
    /// A squared edge is negative.
    NegativeSquare {
        /// The edge.
        edge: String,
    },
    /// An edge is shorter than its projection in some frame.
    ShorterThanProjection {
        /// The edge.
        edge: String,
        /// The frame (1-based).
        frame: usize,
    },
}

impl Feasibility {
    /// Whether feasible.
    pub fn is_feasible(&self) -> bool {
        matches!(self, Feasibility::Feasible)
    }

    /// A sentence.
    pub fn reason(&self) -> String {
        match self {
            Feasibility::Feasible => "feasible".into(),
            Feasibility::Complex => "complex root".into(),
            Feasibility::NegativeSquare { edge } => format!("{edge}² is negative"),
            Feasibility::ShorterThanProjection { edge, frame } => {
                format!("{edge} is shorter than its projection in frame {frame}")
            }
        }
    }
}

/// Judge squared edges by the paper's rules.
pub fn feasibility(squares: &[f64], imag: &[f64], input: &SquaredLengths) -> Feasibility {
    if imag.iter().any(|v| *v != 0.0) {
        return Feasibility::Complex;
    }
    let names = input.edge_names();
    if let Some(e) = squares.iter().position(|v| *v < 0.0) {
        return Feasibility::NegativeSquare {
            edge: names[e].clone(),
        };
    }
    for (f, frame) in input.frames.iter().enumerate() {
        if let Some(e) = squares.iter().zip(frame).position(|(s, p)| s < p) {
            return Feasibility::ShorterThanProjection {
                edge: names[e].clone(),
                frame: f + 1,
            };
        }
    }
    Feasibility::Feasible
}

/// One solution.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Solution {
    /// Squared edges in [`edges`] order (real parts).
    pub squared_edges: Vec<f64>,
    /// Imaginary parts (all zero for a real solution).
    pub imaginary: Vec<f64>,
    /// Feasibility.
    pub feasibility: Feasibility,
    /// Largest equation residual, relative to the squared scale of the solution.
    pub residual: f64,
}

/// Input the paper's route cannot solve uniquely (or at all).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Degenerate {
    /// The points are collinear in every frame: infinitely many solutions.
    Collinear,
    /// Two frames have the same projected lengths (identical up to an in-plane motion):
    /// their difference equation vanishes, infinitely many solutions.
    IdenticalFrames {
        /// First frame (1-based).
        first: usize,
        /// Second frame (1-based).
        second: usize,
    },
    /// The frame-difference equations are linearly dependent.
    DependentDifferences,
    /// The paper's denominator d_{a,1}d_{b,2} − d_{a,2}d_{b,1} vanishes; another pair of
    /// unknowns was eliminated instead.
    PaperDenominatorVanishes,
    /// The quadratic's leading coefficient vanishes: one root from the linear equation.
    VanishingLeadingCoefficient,
    /// The equation vanishes identically: infinitely many solutions.
    Indeterminate,
    /// No real root.
    NoRealRoot,
    /// The motion is too special for a unique linear solution (rank below the unknowns).
    SpecialMotion {
        /// The rank found.
        rank: usize,
    },
}

impl fmt::Display for Degenerate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Degenerate::Collinear => write!(f, "collinear points: infinitely many solutions"),
            Degenerate::IdenticalFrames { first, second } => write!(
                f,
                "frames {first} and {second} are identical up to an in-plane rotation: infinitely many solutions"
            ),
            Degenerate::DependentDifferences => {
                write!(f, "the frame-difference equations are dependent")
            }
            Degenerate::PaperDenominatorVanishes => write!(
                f,
                "the paper's denominator vanishes; another pair of unknowns was eliminated"
            ),
            Degenerate::VanishingLeadingCoefficient => {
                write!(f, "vanishing leading coefficient: one solution")
            }
            Degenerate::Indeterminate => write!(f, "the equation vanishes: infinitely many solutions"),
            Degenerate::NoRealRoot => write!(f, "no real root"),
            Degenerate::SpecialMotion { rank } => write!(
                f,
                "the motion is too special: rank {rank} of 3, no unique solution"
            ),
        }
    }
}

/// What every solver returns.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SolverOutput {
    /// The method (p3f3, p3f4, …).
    pub method: String,
    /// Edge names in [`edges`] order.
    pub edges: Vec<String>,
    /// Every solution found, real and complex.
    pub solutions: Vec<Solution>,
    /// The degenerate case that applies, if any.
    pub degenerate: Option<Degenerate>,
    /// Condition number of the linear system, where there is one.
    pub condition: Option<f64>,
}

impl SolverOutput {
    /// The feasible solutions.
    pub fn feasible(&self) -> impl Iterator<Item = &Solution> {
        self.solutions.iter().filter(|s| s.feasibility.is_feasible())
    }
}
