//! Limits on work: every size a user controls, with the largest value the tool accepts.
//!
//! Each limit is checked where the size is read (a case file at load time, a command-line
//! argument before any work starts), so that a request too large for this machine is refused
//! in words (exit 2) instead of running for hours or exhausting memory. The table of limits,
//! with where each is checked and how to override it, is `docs/limits.md`; a test keeps the
//! two in step.
//!
//! The values are chosen from measured cost on a 2-core machine: each accepted request
//! finishes within seconds to a few minutes, and the paper's own cases sit well inside.

/// Points of a degree-of-freedom count or identifiability decision (Jacobian rank).
pub const DOF_POINTS: usize = 200;
/// Frames of a degree-of-freedom count or identifiability decision.
pub const DOF_FRAMES: usize = 200;
/// Points × frames of one identifiability decision: the Jacobian has 2pk rows and about
/// 3p + 3k columns, so its rank costs about (pk)²; p·k = 1000 takes about a second.
pub const DOF_POINTS_TIMES_FRAMES: usize = 1_000;
/// The largest p and the largest k of an identifiability grid (`dof --table`, case grids):
/// the grid runs every (p, k) up to them.
pub const DOF_GRID: usize = 20;
/// Members of the two-frame family printed by `family --samples`.
pub const FAMILY_SAMPLES: usize = 10_000;
/// `family`: points × samples (every sample places every point; about 1.3 µs each, so 5 × 10⁶
/// is about 7 s, and the output stays within a few hundred MB).
pub const FAMILY_POINTS_TIMES_SAMPLES: usize = 5_000_000;
/// `membership`: points per frame (its robust tolerance grows about as n^1.8: 32,000 points
/// take 3 s, 50,000 about 7 s).
pub const MEMBERSHIP_POINTS: usize = 50_000;
/// `identify --top`: assignments listed (each is printed with its full correspondence).
pub const IDENTIFY_TOP: usize = 10_000;
/// Points of `synth`.
pub const SYNTH_POINTS: usize = 100_000;
/// Frames of `synth`.
pub const SYNTH_FRAMES: usize = 100_000;
/// Points × frames of `synth`: the file it writes must stay readable by the tracks reader
/// ([`INPUT_BYTES`]); one image point takes about 45 bytes.
pub const SYNTH_POINTS_TIMES_FRAMES: usize = 1_000_000;
/// Monte Carlo trials per level and model of a noise study (case or `noise --trials`;
/// `noise --max-trials` raises it: the statistics are streamed, so memory stays fixed).
pub const NOISE_TRIALS: usize = 1_000_000;
/// Noise levels of one study.
pub const NOISE_LEVELS: usize = 100;
/// The largest noise level ε (relative error up to ε): beyond 1 a coordinate may change
/// sign, and ε near the largest float overflows the sampler.
pub const NOISE_LEVEL: f64 = 1.0;
/// Trials of a census and of a random-scene check (case files).
pub const CASE_TRIALS: usize = 100_000;
/// The work of a census in a case file: trials × frames (each trial solves one scene).
pub const CASE_CENSUS_WORK: usize = 5_000_000;
/// Trials of an identity census (case files): each runs every identity test on a scene.
pub const IDENTITY_CENSUS_TRIALS: usize = 5_000;
/// The work of a noise study in a case file: trials × levels × frames (each trial of a level
/// solves one scene of that many frames under both noise models).
pub const CASE_NOISE_WORK: usize = 1_500_000;
/// The work of a price-of-linearity study: trials × bodies × levels (each runs every solver
/// and a bundle adjustment on one scene).
pub const LINEARITY_RUNS: usize = 10_000;
/// Rational instances of an exact solution count (case files): each eliminates a degree-16
/// polynomial over ℚ and runs the lines-first construction, about a quarter of a second.
pub const COUNT_INSTANCES: usize = 24;
/// Monte Carlo samples of a rounding box (case files).
pub const ROUNDING_TRIALS: usize = 1_000_000;
/// Random evaluation points of an identity check (case files).
pub const EVALUATION_POINTS: usize = 10_000;
/// Points of a random-scene check (case files: the two-frame check).
pub const CASE_POINTS: usize = 100;
/// Samples along a curve (case files).
pub const CURVE_SAMPLES: usize = 100_000;
/// Entries of a list of angles, factors or shifts in a case file.
pub const CASE_LIST: usize = 1_000;
/// Significant digits a case may say a program printed with (an f64 holds 17).
pub const SIGNIFICANT_DIGITS: u32 = 17;
/// YAML values (scalars, lists, maps) of one case file; the largest paper case holds a few
/// thousand. Small enough that an alias bomb is refused within milliseconds.
pub const CASE_YAML_VALUES: usize = 50_000;
/// YAML aliases (`*name`) of one case file.
pub const CASE_YAML_ALIASES: usize = 1_000;
/// Characters of one formula.
pub const FORMULA_CHARS: usize = 20_000;
/// Nesting depth of parentheses (and unary signs) in one formula: the parser is recursive.
pub const FORMULA_DEPTH: usize = 64;
/// The largest exponent written in a formula.
pub const FORMULA_EXPONENT: u64 = 64;
/// The largest total degree a formula can reach when expanded (a bound read off its text).
pub const FORMULA_DEGREE: f64 = 256.0;
/// The most terms a formula can expand to (an upper bound read off its text, before any
/// cancellation: terms of a sum add, of a product multiply, of a power raise).
pub const FORMULA_TERMS: f64 = 1e5;
/// The most digits of a number written in a formula.
pub const FORMULA_DIGITS: usize = 100;
/// The most bits a formula's coefficients can reach (an upper bound read off its text, as a
/// quotient of integer polynomials: the bits of a product add, a power multiplies them).
pub const FORMULA_BITS: f64 = 4096.0;

/// The side of the Gram matrix `reconstruct` decomposes, min(2k, p) for p points in k frames:
/// its eigen-decomposition costs about side³ (1,000 takes about a second).
pub const RECONSTRUCT_GRAM: usize = 1_000;
/// The work of one bundle-adjustment iteration, Σ over points of (frames seeing it)²: the
/// Schur complement's accumulation costs about 37.5 scattered multiply-adds per unit, or at
/// most 4 times that in matrix products for long tracks (docs/limits.md, "Bundle adjustment's
/// cost"); beyond it
/// `reconstruct` skips the adjustment and says so in `method`.
pub const BUNDLE_WORK: usize = 10_000_000;
/// Frames of a bundle adjustment: the reduced camera system is dense, 5k × 5k, factorised in
/// about (5k)³/3 multiply-adds per iteration by a blocked Cholesky (k = 200: 3.3 × 10⁸; a whole
/// iteration at the limit takes 23.8 ms, docs/limits.md); beyond it `reconstruct` skips the
/// adjustment and says so in `method`.
pub const BUNDLE_FRAMES: usize = 200;
/// Observations of a bundle adjustment: each iteration costs about 150 multiply-adds per
/// observation beside the Schur complement, so the 200 iterations of the default limit over
/// 200,000 observations (two each of 100,000 points) take about 10 s (docs/limits.md); beyond it `reconstruct` skips the
/// adjustment and says so in `method`.
pub const BUNDLE_OBSERVATIONS: usize = 200_000;
/// Frames of a variable-projection factorisation (tracks with most entries missing): its
/// camera system is dense, 8k × 8k, (8k)³/3 multiply-adds per step (k = 100: 1.7 × 10⁸);
/// beyond it `reconstruct` grows the largest complete block instead, and says why.
pub const VARPRO_FRAMES: usize = 100;
/// The work of a variable-projection factorisation, multiply-adds by its cost model
/// (`sfm::missing::Work`: one step's normal equations and each trial's factorisation and
/// cost): the run stops, and says so, when it is spent; tracks whose least run
/// (`sfm::missing::MIN_STEPS` steps) costs more are refused before the work. Calibrated in
/// time: a run that spends it all takes at most 10 s (docs/limits.md).
pub const VARPRO_WORK: f64 = 1e10;
/// Cells (frames × points) of tracks with gaps: they are held as a dense table of optional
/// images (24 bytes a cell, so 480 MB at the limit), so a CSV whose rows each bring a new frame
/// and a new point is refused by this count before the table is made.
pub const OBSERVATION_CELLS: usize = 20_000_000;
/// RANSAC samples at most (each costs one point intersection per point and frame).
pub const RANSAC_SAMPLES: usize = 10_000;
/// Observations of `reconstruct --robust` (the images given, points × frames when no track
/// has gaps): every sample intersects every point from its images, so the worst case (no
/// good sample) costs samples × observations.
pub const RANSAC_OBSERVATIONS: usize = 100_000;
/// Observations of `reconstruct --robust` on tracks with gaps (the input's, before tracks
/// seen once are dropped): up to five fits of tracks with gaps (the fit of every
/// observation where no sample explains half of them, the first judgement's, three
/// rounds); 20,000 images take 8.9–10.8 s on turntables whose fits stop at their limits
/// (docs/limits.md).
pub const RANSAC_GAP_OBSERVATIONS: usize = 20_000;
/// Points per frame of `identify --method epipolar`: every ordered choice of four frame-2
/// points is tried, n⁴ of them; n = 40 takes about 2 s on two cores (n = 60 about 10 s).
/// `identify --max-points` raises it.
pub const IDENTIFY_POINTS_EPIPOLAR: usize = 40;
/// Points per frame of `identify --method four` (the paper's four-point test, n⁴ tries at
/// about 20 times epipolar's cost each): n = 20 takes about 2 s.
pub const IDENTIFY_POINTS_FOUR: usize = 20;
/// Points per frame of `identify --method five` (the five-point line, n⁵ tries): n = 30
/// takes about 1 s.
pub const IDENTIFY_POINTS_FIVE: usize = 30;

/// `Err` naming `what`, the value and the limit when `value > limit`.
pub fn at_most(what: &str, value: usize, limit: usize) -> Result<(), String> {
    if value > limit {
        Err(format!(
            "{what} is {value}, more than the limit of {limit} (see docs/limits.md)"
        ))
    } else {
        Ok(())
    }
}

/// `Err` naming `what` unless `value` lies in 1 ..= `limit`.
pub fn count(what: &str, value: usize, limit: usize) -> Result<(), String> {
    if value == 0 {
        return Err(format!("{what} must be at least 1"));
    }
    at_most(what, value, limit)
}

/// `Err` unless ε is a number in [0, [`NOISE_LEVEL`]].
pub fn noise_level(what: &str, eps: f64) -> Result<(), String> {
    if (0.0..=NOISE_LEVEL).contains(&eps) {
        Ok(())
    } else {
        Err(format!(
            "{what} {}: a noise level must be a relative error ε with 0 ≤ ε ≤ {NOISE_LEVEL}",
            short(eps)
        ))
    }
}

/// A number for a message: plain when ordinary, in exponent form when huge or tiny
/// (`1e308`, not 309 digits).
fn short(x: f64) -> String {
    if x != 0.0 && x.is_finite() && !(1e-4..1e6).contains(&x.abs()) {
        format!("{x:e}")
    } else {
        format!("{x}")
    }
}

/// The largest tracks file read, in bytes: a file (or device) beyond it is refused before it
/// can fill the memory.
pub const INPUT_BYTES: u64 = 64 << 20;
