//! The calling convention shared by every solver: projected squared lengths in, every
//! solution out, each with its squared edges, a feasibility verdict with the reason, and a
//! residual; degenerate input is a typed outcome, never NaN.

use std::fmt;

use serde::Serialize;

use crate::error::{Error, Result};
use crate::model::Tracks;

pub use crate::model::edges;

/// The names of the first `count` edges of a body with the default point names ("PQ", "QR",
/// "RP", "TP", …).
///
/// # Example
/// ```
/// use orthocheck_core::derivations::solver::default_edge_names;
/// assert_eq!(default_edge_names(4), ["PQ", "QR", "RP", "TP"]);
/// ```
pub fn default_edge_names(count: usize) -> Vec<String> {
    let p = (2..).find(|p| p * (p - 1) / 2 >= count).unwrap_or(2);
    let names = crate::model::default_names(p);
    edges(p)
        .iter()
        .take(count)
        .map(|&(i, j)| edge_name(&names[i], &names[j]))
        .collect()
}

/// The name of the edge between points named `a` and `b`: "PQ" for one-letter names, "A1–B"
/// once either is longer, where joined names would run together ("AB" and "C" against "A"
/// and "BC", or "inf" and "NaN" reading as two numbers).
pub fn edge_name(a: &str, b: &str) -> String {
    if a.chars().count() == 1 && b.chars().count() == 1 {
        format!("{a}{b}")
    } else {
        format!("{a}–{b}")
    }
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
            .map(|&(i, j)| edge_name(&self.names[i], &self.names[j]))
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
    /// The squared edges are not the distances of any point set in 3-D: the Gram matrix
    /// of the edge vectors from the first point has a negative eigenvalue.
    NotRealizable {
        /// The most negative eigenvalue.
        eigenvalue: f64,
    },
    /// The squared edges satisfy the equations but no rigid motion reprojects their body onto
    /// the tracks (frames that no rigid body gives, e.g. one scaled, or noisy tracks).
    NoMotionReprojects {
        /// The best reprojection error found, relative to the largest edge.
        error: f64,
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
            Feasibility::NotRealizable { eigenvalue } => format!(
                "not realizable in 3-D (Gram eigenvalue {})",
                crate::numfmt::sig(*eigenvalue)
            ),
            Feasibility::NoMotionReprojects { error } => format!(
                "no rigid motion reprojects it (best reprojection error {})",
                crate::numfmt::sig(*error)
            ),
            Feasibility::ShorterThanProjection { edge, frame } => {
                format!("{edge} is shorter than its projection in frame {frame}")
            }
        }
    }
}

/// The first violation of §2.2's rules by squared edges against the projections of some
/// frames: `(edge, None)` for a negative square, `(edge, Some(frame))` (0-based) for an
/// edge shorter than its projection in that frame; `None` when feasible. The one place the
/// rules are written.
pub fn first_violation<'a>(
    squares: &[f64],
    frames: impl IntoIterator<Item = &'a [f64]>,
) -> Option<(usize, Option<usize>)> {
    if let Some(e) = squares.iter().position(|v| *v < 0.0) {
        return Some((e, None));
    }
    frames.into_iter().enumerate().find_map(|(f, frame)| {
        squares
            .iter()
            .zip(frame)
            .position(|(s, p)| s < p)
            .map(|e| (e, Some(f)))
    })
}

/// Judge squared edges by the paper's rules.
pub fn feasibility(squares: &[f64], imag: &[f64], input: &SquaredLengths) -> Feasibility {
    if imag.iter().any(|v| *v != 0.0) {
        return Feasibility::Complex;
    }
    // names only for a violation: this runs for every solve
    let name = |e: usize| {
        let (i, j) = input.edges[e];
        edge_name(&input.names[i], &input.names[j])
    };
    match first_violation(squares, input.frames.iter().map(|f| &f[..])) {
        None => Feasibility::Feasible,
        Some((e, None)) => Feasibility::NegativeSquare { edge: name(e) },
        Some((e, Some(f))) => Feasibility::ShorterThanProjection {
            edge: name(e),
            frame: f + 1,
        },
    }
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
    /// First-order bound on the rounding error of the squared edges (absolute), where the
    /// solver can give one; infinite at a double root.
    pub error_bound: Option<f64>,
}

/// Input the paper's route cannot solve uniquely (or at all).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Degenerate {
    /// Two points have exactly the same image in every frame (a point listed twice): their
    /// edge is zero and the body has fewer points than named.
    DuplicatedPoints {
        /// First point (1-based).
        first: usize,
        /// Second point (1-based).
        second: usize,
    },
    /// Two points coincide within rounding in every frame: as good as one point.
    CoincidentPoints {
        /// First point (1-based).
        first: usize,
        /// Second point (1-based).
        second: usize,
    },
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
    /// Two frames differ by an in-plane motion (or a mirror) only: the same view, turned or
    /// shifted in the image plane; their lengths agree and add no equation.
    InPlaneMotion {
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
        /// The number of unknowns.
        unknowns: usize,
    },
    /// Every frame is an affine image of one plane (the triangles' area ratios agree in all
    /// frames): a planar body. The linear systems of §4 are then singular.
    Coplanar,
}

impl fmt::Display for Degenerate {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Degenerate::DuplicatedPoints { first, second } => write!(
                f,
                "points {first} and {second} are the same point in every frame (a point listed twice)"
            ),
            Degenerate::CoincidentPoints { first, second } => write!(
                f,
                "points {first} and {second} coincide in every frame (within rounding): as good as one point"
            ),
            Degenerate::Collinear => write!(f, "collinear points: infinitely many solutions"),
            Degenerate::IdenticalFrames { first, second } => write!(
                f,
                "frames {first} and {second} are identical (the same lengths): infinitely many solutions"
            ),
            Degenerate::InPlaneMotion { first, second } => write!(
                f,
                "frames {first} and {second} differ by an in-plane motion (or a mirror) only: the same view, infinitely many solutions"
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
            Degenerate::SpecialMotion { rank, unknowns } => write!(
                f,
                "the motion is too special: rank {rank} of {unknowns}, no unique solution"
            ),
            Degenerate::Coplanar => write!(
                f,
                "the body is planar (every frame an affine image of one plane): the linear system is singular, infinitely many solutions"
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
    /// No solution: `input` is the degenerate case `d`.
    pub fn degenerate(method: &str, input: &SquaredLengths, d: Degenerate) -> Self {
        SolverOutput {
            method: method.into(),
            edges: input.edge_names(),
            solutions: Vec::new(),
            degenerate: Some(d),
            condition: None,
        }
    }

    /// The feasible solutions.
    pub fn feasible(&self) -> impl Iterator<Item = &Solution> {
        self.solutions
            .iter()
            .filter(|s| s.feasibility.is_feasible())
    }
}

/// Which solver `solve` runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Pick from the number of points and frames.
    Auto,
    /// §2.2: three points, three frames.
    P3f3,
    /// §3: three points, four or more frames.
    P3f4,
    /// §4: four points, three frames (the paper's six equations).
    P4f3,
    /// §4 generalised: p ≥ 4 points, k ≥ 3 frames, every triangle, least squares.
    Lsq,
}

impl Method {
    /// The method for `p` points in `k` frames, and why; an error when no solver applies.
    ///
    /// # Example
    /// ```
    /// use orthocheck_core::derivations::solver::Method;
    /// assert_eq!(Method::Auto.resolve(3, 5).unwrap().0, Method::P3f4);
    /// assert!(Method::Auto.resolve(3, 2).is_err());
    /// ```
    pub fn resolve(self, p: usize, k: usize) -> Result<(Method, String)> {
        let (m, why) = self.resolve_shape(p, k)?;
        let most = super::p4f3::MAX_LSQ_POINTS;
        if m == Method::Lsq && p > most {
            // refused before the p(p − 1)/2 squared lengths of every frame are computed
            return Err(Error::InvalidInput(format!(
                "{p} points: the least-squares form solves for every one of the p(p − 1)/2 squared edges and takes at most {most} points"
            )));
        }
        Ok((m, why))
    }

    /// [`Method::resolve`] by the numbers of points and frames alone.
    fn resolve_shape(self, p: usize, k: usize) -> Result<(Method, String)> {
        let auto = match (p, k) {
            (3, 3) => Ok((
                Method::P3f3,
                "3 points in 3 frames: the closed form of §2.2",
            )),
            (3, k) if k >= 4 => Ok((
                Method::P3f4,
                "3 points in 4 or more frames: the linear system of §3 (least squares beyond 4)",
            )),
            (_, k) if k < 3 => Err(format!(
                "{k} frame(s): at least 3 are needed (two frames never determine the body, §5)"
            )),
            (p, _) if p < 3 => Err(format!("{p} point(s): at least 3 are needed")),
            (4, 3) => Ok((Method::P4f3, "4 points in 3 frames: the linear system of §4")),
            _ => Ok((
                Method::Lsq,
                "4 or more points in 3 or more frames: the triangles through the first two points against frame 1, least squares",
            )),
        };
        match self {
            Method::Auto => auto
                .map(|(m, why)| (m, why.to_string()))
                .map_err(Error::InvalidInput),
            m => {
                let fits = match m {
                    Method::P3f3 => p == 3 && k == 3,
                    Method::P3f4 => p == 3 && k >= 4,
                    Method::P4f3 => p == 4 && k == 3,
                    Method::Lsq => p >= 4 && k >= 3,
                    Method::Auto => true,
                };
                if fits {
                    Ok((m, "chosen on the command line".into()))
                } else {
                    Err(Error::InvalidInput(format!(
                        "{} does not apply to {p} points in {k} frames",
                        m.name()
                    )))
                }
            }
        }
    }

    /// The method's name.
    pub fn name(self) -> &'static str {
        match self {
            Method::Auto => "auto",
            Method::P3f3 => "p3f3",
            Method::P3f4 => "p3f4",
            Method::P4f3 => "p4f3",
            Method::Lsq => "lsq",
        }
    }
}

/// The 3-D body behind one feasible solution, where the solver recovers it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Structure {
    /// The points in frame 1's camera coordinates, the first at the origin.
    pub points: Vec<[f64; 3]>,
    /// Structure-and-motion solutions behind this edge solution that reproject (depth-sign
    /// combinations of the later frames; the global mirror reversal doubles this count).
    pub motions: u64,
    /// Reprojection error of the best of them, relative to the largest edge (noisy tracks
    /// reproject only approximately, and then `motions` may be 0).
    pub reprojection_error: f64,
}

/// What [`solve_tracks`] returns.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Solved {
    /// The solver's output.
    #[serde(flatten)]
    pub output: SolverOutput,
    /// Why this method.
    pub why: String,
    /// Per solution: the recovered body, for feasible p3f3 solutions.
    pub structures: Vec<Option<Structure>>,
    /// For p3f3: the c² roots by independent routes (exact elimination over ℚ of the input's
    /// exact binary values with Sturm isolation, the `roots` closed form, the companion
    /// matrix) and their largest disagreement with the solver.
    pub validation: Option<super::p3f3::Validation>,
}

/// Reprojection errors at most this (relative to the largest edge) count as exact: the
/// reconstruction is computed from rounded square roots of differences of squares.
pub const REPROJECTION_EXACT: f64 = 1e-6;

/// Solve tracks with `method` (resolved by [`Method::resolve`]), and recover the body behind
/// every feasible solution. The solvers run on the tracks brought to unit size
/// ([`normalise`](super::scale::normalise)) and every length is mapped back; a solution no
/// rigid motion reprojects is not called feasible; no number of the answer is non-finite.
///
/// # Example
/// ```
/// use orthocheck_core::derivations::solver::{solve_tracks, Method};
/// let scene = orthocheck_core::model::Scene::random(3, 4, 2);
/// let s = solve_tracks(&scene.tracks(), Method::Auto).unwrap();
/// assert_eq!(s.output.method, "p3f4");
/// assert_eq!(s.output.feasible().count(), 1);
/// ```
pub fn solve_tracks(tracks: &Tracks, method: Method) -> Result<Solved> {
    let (m, why) = method.resolve(tracks.points(), tracks.frames.len())?;
    let unit = super::scale::normalise(tracks)?;
    let input = SquaredLengths::from_tracks(&unit.tracks);
    let mut output = match m {
        Method::P3f3 => super::p3f3::solve(&input)?,
        Method::P3f4 | Method::Auto => super::p3f4::solve(&input)?,
        Method::P4f3 => super::p4f3::solve(&input)?,
        Method::Lsq => super::p4f3::solve_least_squares(&input)?,
    };
    output.degenerate = output
        .degenerate
        .map(|d| super::degenerate::refine_frames(d, &unit.tracks));
    let structures = output
        .solutions
        .iter()
        .map(|s| structure(&unit.tracks, s))
        .collect::<Result<Vec<_>>>()?;
    let validation = (m == Method::P3f3).then(|| {
        use num_rational::BigRational;
        let l: [[BigRational; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|e| BigRational::from_float(input.frames[i][e]).unwrap_or_default())
        });
        super::p3f3::validate(&l)
    });
    let mut solved = Solved {
        output,
        why,
        structures,
        validation,
    };
    back_to_input_units(&mut solved, &unit)?;
    Ok(solved)
}

/// The body behind one feasible solution (unit tracks); `None` for an infeasible one.
fn structure(tracks: &Tracks, s: &Solution) -> Result<Option<Structure>> {
    if !s.feasibility.is_feasible() {
        return Ok(None);
    }
    if s.squared_edges.len() != 3 {
        // four or more points: one body up to the mirror, one camera per frame
        let fit = super::p4f3::fit(tracks, &s.squared_edges);
        return Ok(Some(Structure {
            points: fit.points.iter().map(|p| [p.x, p.y, p.z]).collect(),
            motions: u64::from(fit.residual <= REPROJECTION_EXACT),
            reprojection_error: fit.residual,
        }));
    }
    let sq = [s.squared_edges[0], s.squared_edges[1], s.squared_edges[2]];
    let summary = super::p3f3::motion_summary(tracks, &sq, REPROJECTION_EXACT)?;
    Ok(summary.map(|m| Structure {
        points: m.best.points.iter().map(|p| [p.x, p.y, p.z]).collect(),
        motions: m.reprojecting,
        reprojection_error: m.best.reprojection_error,
    }))
}

/// Lengths back in the input's units; a solution no motion reprojects is marked so; every
/// number checked finite (a typed error otherwise, never NaN in the answer).
fn back_to_input_units(s: &mut Solved, unit: &super::scale::Normalised) -> Result<()> {
    use super::scale::squares_back;
    for (sol, st) in s.output.solutions.iter_mut().zip(&mut s.structures) {
        squares_back(unit, &mut sol.squared_edges)?;
        squares_back(unit, &mut sol.imaginary)?;
        if let Some(b) = sol.error_bound.as_mut() {
            // an infinite bound (a double root) is a fact, not an overflow
            if b.is_finite() {
                *b = unit.square_back(*b);
            }
        }
        if let Some(st) = st {
            for p in &mut st.points {
                for c in p.iter_mut() {
                    *c *= unit.scale;
                }
            }
            if st.motions == 0 {
                sol.feasibility = Feasibility::NoMotionReprojects {
                    error: st.reprojection_error,
                };
            }
        }
    }
    if let Some(v) = s.validation.as_mut() {
        for list in [&mut v.solver, &mut v.closed_form, &mut v.companion]
            .into_iter()
            .chain(v.exact.as_mut())
        {
            squares_back(unit, list)?;
        }
    }
    finite(s)
}

/// Every number of an answer finite: the last guard before a renderer sees it.
fn finite(s: &Solved) -> Result<()> {
    let bad = |what: &str| {
        Err(Error::Numerical(format!(
            "the {} solver produced a non-finite {what}; nothing is reported",
            s.output.method
        )))
    };
    for sol in &s.output.solutions {
        if !sol
            .squared_edges
            .iter()
            .chain(&sol.imaginary)
            .all(|v| v.is_finite())
        {
            return bad("squared edge");
        }
        if !sol.residual.is_finite() {
            return bad("residual");
        }
        if let Feasibility::NotRealizable { eigenvalue: v }
        | Feasibility::NoMotionReprojects { error: v } = sol.feasibility
            && !v.is_finite()
        {
            return bad("feasibility measure");
        }
    }
    for st in s.structures.iter().flatten() {
        if !st.points.iter().flatten().all(|v| v.is_finite()) || !st.reprojection_error.is_finite()
        {
            return bad("body coordinate");
        }
    }
    if s.output.condition.is_some_and(|c| !c.is_finite()) {
        return bad("condition number");
    }
    if let Some(v) = &s.validation
        && !v.max_relative_disagreement.is_finite()
    {
        return bad("route disagreement");
    }
    Ok(())
}
