//! The noise studies of §2, §3 and §4: seeded Monte Carlo of a solver under a named noise
//! model, summarised as error distributions in squared and in plain edge lengths.
//!
//! Trials run in fixed chunks, each with its own ChaCha stream, so the result does not depend
//! on the number of threads.

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use super::solver::edges;
use super::solver::SquaredLengths;
use super::{p3f3, p3f4, p4f3};
use crate::model::{random_rotation, Body, Motion, NoiseModel};

pub use crate::model::StudySolver;

/// Error of one trial's best solution against the truth.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct TrialError {
    /// Largest relative error over the edges, in squared lengths.
    pub max_squares: f64,
    /// Mean relative error over the edges, in squared lengths.
    pub mean_squares: f64,
    /// Largest relative error over the edges, in lengths.
    pub max_lengths: f64,
    /// Mean relative error over the edges, in lengths.
    pub mean_lengths: f64,
}

impl TrialError {
    /// Errors of squared edges `s` against the true squares `t`; `None` if a square is negative.
    pub fn of(s: &[f64], t: &[f64]) -> Option<TrialError> {
        if s.iter().any(|v| *v < 0.0 || !v.is_finite()) {
            return None;
        }
        let sq: Vec<f64> = s.iter().zip(t).map(|(a, b)| (a - b).abs() / b).collect();
        let ln: Vec<f64> = s
            .iter()
            .zip(t)
            .map(|(a, b)| (a.sqrt() - b.sqrt()).abs() / b.sqrt())
            .collect();
        let n = sq.len() as f64;
        Some(TrialError {
            max_squares: sq.iter().fold(0.0, |a, b| a.max(*b)),
            mean_squares: sq.iter().sum::<f64>() / n,
            max_lengths: ln.iter().fold(0.0, |a, b| a.max(*b)),
            mean_lengths: ln.iter().sum::<f64>() / n,
        })
    }

    /// The four metrics in a fixed order: max and mean in squares, max and mean in lengths.
    pub fn metrics(&self) -> [f64; 4] {
        [
            self.max_squares,
            self.mean_squares,
            self.max_lengths,
            self.mean_lengths,
        ]
    }
}

/// Names of [`TrialError::metrics`].
pub const METRICS: [&str; 4] = ["max-squares", "mean-squares", "max-lengths", "mean-lengths"];

/// One noise level under one model.
#[derive(Clone, Debug, serde::Serialize)]
pub struct LevelResult {
    /// ε.
    pub level: f64,
    /// The noise model's name.
    pub model: String,
    /// Trials run.
    pub trials: usize,
    /// Trials without a real solution with non-negative squares.
    pub failures: usize,
    /// Errors of the successful trials, sorted per metric (`sorted[m]` for metric `m`): all
    /// of them up to [`RESERVOIR`] trials, a uniform sample of that size beyond.
    #[serde(skip)]
    pub sorted: [Vec<f64>; 4],
    /// Per kept successful trial, recovered over true squared edge for every edge
    /// (trial-major, `edges` values per trial): the per-edge errors in squares and in
    /// lengths follow.
    #[serde(skip)]
    pub ratios: Vec<f64>,
    /// Edges per trial.
    pub edges: usize,
    /// When more trials succeeded than [`RESERVOIR`] keeps: the exact sums of the four
    /// metrics over all of them and their count (the means come from these).
    #[serde(skip)]
    pub sums: Option<([f64; 4], usize)>,
}

impl LevelResult {
    /// The q-quantile of metric `m` (see [`METRICS`]).
    pub fn quantile(&self, m: usize, q: f64) -> Option<f64> {
        super::rounding::quantile(&self.sorted[m], q)
    }

    /// The mean of metric `m`.
    pub fn mean(&self, m: usize) -> f64 {
        if let Some((sums, n)) = self.sums {
            return sums[m] / n as f64;
        }
        let v = &self.sorted[m];
        if v.is_empty() {
            return f64::NAN;
        }
        v.iter().sum::<f64>() / v.len() as f64
    }

    /// The sorted relative errors of edge `e` over the successful trials, in squares
    /// (|x/t − 1|) or in lengths (|√(x/t) − 1|).
    pub fn edge_errors(&self, e: usize, lengths: bool) -> Vec<f64> {
        let mut v: Vec<f64> = self
            .ratios
            .chunks(self.edges.max(1))
            .map(|r| {
                if lengths {
                    (r[e].sqrt() - 1.0).abs()
                } else {
                    (r[e] - 1.0).abs()
                }
            })
            .collect();
        v.sort_by(f64::total_cmp);
        v
    }

    /// Fraction of successful trials with metric `m` not above `x`.
    pub fn rank_of(&self, m: usize, x: f64) -> f64 {
        super::rounding::rank_of(&self.sorted[m], x)
    }
}

/// The noise models, in report order, at level `eps`.
pub fn models(eps: f64) -> [NoiseModel; 2] {
    [
        NoiseModel::RelativeCoordinate { eps },
        NoiseModel::RelativeLength { eps },
    ]
}

/// The random stream of level `i` under model `m` (of [`models`]): the report and the
/// `noise` command use the same, so their results agree.
pub fn stream(level: usize, model: usize) -> u64 {
    (2 * level + model) as u64
}

/// Run `levels` under the models of [`models`] whose indices `keep` accepts, in order
/// (level, then model); `progress` receives finished trial counts.
pub fn run_levels(
    study: &Study,
    levels: &[f64],
    keep: impl Fn(usize) -> bool,
    progress: &(dyn Fn(usize) + Sync),
) -> Vec<LevelResult> {
    let mut out = Vec::new();
    for (i, &eps) in levels.iter().enumerate() {
        for (m, model) in models(eps).into_iter().enumerate() {
            if keep(m) {
                out.push(run_level(study, model, stream(i, m), progress));
            }
        }
    }
    out
}

/// Trials per chunk (each chunk has its own random stream).
pub const CHUNK: usize = 1024;

/// What a study runs: a body under random motions, solved by one solver.
#[derive(Clone, Debug, PartialEq)]
pub struct Study {
    /// The solver.
    pub solver: StudySolver,
    /// The body.
    pub body: Body,
    /// Frames per trial.
    pub frames: usize,
    /// Trials per level.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
    /// Fixed motions (one per frame) instead of random ones: the paper's own scene.
    pub motions: Option<Vec<Motion>>,
}

/// Chunks run in parallel before their results are folded in, in chunk order: bounds the
/// memory in flight (64 × 1024 trials) and keeps the fold independent of the thread count.
const BATCH: usize = 64;

/// Successful trials whose ratios a level keeps. Up to this many every trial is kept and the
/// quantiles are exact (the paper's studies run 10⁴ trials); beyond it a uniform reservoir
/// sample of this size is kept (Vitter's algorithm R, seeded), so a level holds at most
/// `RESERVOIR × (edges + 4) × 8` bytes (about 5 MB) whatever the trial count. A quantile
/// read off the sample then has a rank error below √(ln(2/α)/(2n)) with probability 1 − α
/// (Dvoretzky–Kiefer–Wolfowitz): n = 65,536, α = 10⁻⁶ gives 0.0105, about one percentile.
/// Means are exact over all trials (streamed sums), and the judges take the sample size as n.
pub const RESERVOIR: usize = 1 << 16;

/// What a level keeps while its trials stream past: the reservoir of ratios and exact sums.
struct Accumulator {
    /// Ratios of the kept trials, `edges` per trial.
    kept: Vec<f64>,
    /// Successful trials seen.
    seen: usize,
    /// Sums of the four metrics over every successful trial.
    sums: [f64; 4],
    /// The reservoir's own random stream (apart from the trials').
    g: ChaCha8Rng,
    edges: usize,
    /// Trials kept at most ([`RESERVOIR`] but in the unit test of the sampling itself).
    capacity: usize,
}

impl Accumulator {
    fn new(seed: u64, stream: u64, edges: usize, capacity: usize) -> Accumulator {
        let mut g = ChaCha8Rng::seed_from_u64(seed);
        // the trials use streams (stream << 32) | chunk; this one is outside them
        g.set_stream(!stream);
        Accumulator {
            kept: Vec::new(),
            seen: 0,
            sums: [0.0; 4],
            g,
            edges,
            capacity,
        }
    }

    /// One successful trial's ratios.
    fn push(&mut self, r: &[f64]) {
        use rand::Rng as _;
        let ones = vec![1.0; self.edges];
        let Some(e) = TrialError::of(r, &ones) else {
            return;
        };
        for (s, v) in self.sums.iter_mut().zip(e.metrics()) {
            *s += v;
        }
        let n = self.seen;
        self.seen += 1;
        if n < self.capacity {
            self.kept.extend_from_slice(r);
        } else {
            let j = self.g.random_range(0..=n);
            if j < self.capacity {
                self.kept[j * self.edges..(j + 1) * self.edges].copy_from_slice(r);
            }
        }
    }
}

/// Run one level: random motions of the body, noise, solve, error of the real solution
/// nearest the truth. `stream` separates levels and models; `progress` receives finished
/// trial counts. Memory is bounded by [`RESERVOIR`], not by the trial count.
pub fn run_level(
    study: &Study,
    model: NoiseModel,
    stream: u64,
    progress: &(dyn Fn(usize) + Sync),
) -> LevelResult {
    run_level_keeping(study, model, stream, progress, RESERVOIR)
}

/// [`run_level`] with a reservoir of `capacity` trials.
pub fn run_level_keeping(
    study: &Study,
    model: NoiseModel,
    stream: u64,
    progress: &(dyn Fn(usize) + Sync),
    capacity: usize,
) -> LevelResult {
    let truth: Vec<f64> = edges(study.body.points.len())
        .iter()
        .map(|&(i, j)| study.body.squared_distance(i, j))
        .collect();
    let level = match model {
        NoiseModel::RelativeCoordinate { eps } | NoiseModel::RelativeLength { eps } => eps,
    };
    let e = truth.len();
    let mut acc = Accumulator::new(study.seed, stream, e, capacity);
    let chunks = study.trials.div_ceil(CHUNK);
    for first in (0..chunks).step_by(BATCH) {
        let batch: Vec<Vec<f64>> = (first..chunks.min(first + BATCH))
            .into_par_iter()
            .map(|c| run_chunk(study, model, stream, c, &truth, progress))
            .collect();
        for r in batch.iter().flat_map(|b| b.chunks(e)) {
            acc.push(r);
        }
    }
    let ok: Vec<TrialError> = acc
        .kept
        .chunks(e)
        .filter_map(|r| TrialError::of(r, &vec![1.0; e]))
        .collect();
    let mut sorted: [Vec<f64>; 4] =
        std::array::from_fn(|m| ok.iter().map(|e| e.metrics()[m]).collect());
    for v in &mut sorted {
        v.sort_by(f64::total_cmp);
    }
    let sampled = acc.seen > capacity;
    LevelResult {
        level,
        model: model.name().to_string(),
        trials: study.trials,
        failures: study.trials - acc.seen,
        sorted,
        ratios: acc.kept,
        edges: e,
        sums: sampled.then_some((acc.sums, acc.seen)),
    }
}

/// Chunk `c` of a level: its own random stream, its successful trials' ratios, flat.
fn run_chunk(
    study: &Study,
    model: NoiseModel,
    stream: u64,
    c: usize,
    truth: &[f64],
    progress: &(dyn Fn(usize) + Sync),
) -> Vec<f64> {
    let mut g = ChaCha8Rng::seed_from_u64(study.seed);
    g.set_stream((stream << 32) | c as u64);
    let n = CHUNK.min(study.trials - c * CHUNK);
    let mut out = Vec::with_capacity(n * truth.len());
    for _ in 0..n {
        trial(
            study.solver,
            &study.body,
            study.frames,
            study.motions.as_deref(),
            model,
            truth,
            &mut g,
            &mut out,
        );
    }
    progress(n);
    out
}

/// The squared image lengths of every edge in every frame, with the model's noise, and the
/// edges: the body's images, P shifted to the origin in every frame as in the paper's
/// figures, then the noise. No names are copied (this runs once per trial, 10⁶ times).
fn noisy_lengths(
    body: &Body,
    motions: &[Motion],
    model: NoiseModel,
    g: &mut ChaCha8Rng,
) -> (Vec<Vec<f64>>, Vec<(usize, usize)>) {
    let mut images: Vec<Vec<nalgebra::Vector2<f64>>> = motions
        .iter()
        .map(|m| {
            let f: Vec<_> = body.points.iter().map(|x| m.project(x)).collect();
            f.iter().map(|p| p - f[0]).collect()
        })
        .collect();
    model.perturb_points(&mut images, g);
    let edge_list = edges(body.points.len());
    let lengths = images
        .iter()
        .map(|f| {
            let l = edge_list.iter().map(|&(i, j)| (f[i] - f[j]).norm_squared());
            l.map(|v| model.perturb_length(v.sqrt(), g).powi(2))
                .collect()
        })
        .collect();
    (lengths, edge_list)
}

/// One trial: random (or the fixed) motions, noise, solve; appends the best solution's ratios to `out`
/// (nothing when no real solution with non-negative squares exists).
#[allow(clippy::too_many_arguments)]
fn trial(
    solver: StudySolver,
    body: &Body,
    frames: usize,
    fixed: Option<&[Motion]>,
    model: NoiseModel,
    truth: &[f64],
    g: &mut ChaCha8Rng,
    out: &mut Vec<f64>,
) {
    let drawn;
    let motions = match fixed {
        Some(m) => m,
        None => {
            drawn = (0..frames)
                .map(|_| Motion {
                    rotation: random_rotation(g),
                    translation: nalgebra::Vector2::zeros(),
                })
                .collect::<Vec<_>>();
            &drawn[..]
        }
    };
    let (mut lengths, edge_list) = noisy_lengths(body, motions, model, g);
    let first3 = |i: usize| [lengths[i][0], lengths[i][1], lengths[i][2]];
    // the allocation-free cores where the frame count allows (this loop runs 10⁶ times)
    let candidates: Vec<Vec<f64>> = match (solver, frames) {
        (StudySolver::P3f3, _) => {
            let core = p3f3::solve_core(&[first3(0), first3(1), first3(2)]);
            (0..core.count)
                .filter(|&k| core.imag[k] == [0.0; 3])
                .map(|k| core.squares[k].to_vec())
                .collect()
        }
        (StudySolver::P3f4, 4) => p3f4::solve_core(&[first3(0), first3(1), first3(2), first3(3)])
            .map(|(x, _)| x.to_vec())
            .into_iter()
            .collect(),
        (StudySolver::P3f4, _) => p3f4::solve(&SquaredLengths {
            names: body.names.clone(),
            frames: std::mem::take(&mut lengths),
            edges: edge_list,
        })
        .map(|o| o.solutions.into_iter().map(|s| s.squared_edges).collect())
        .unwrap_or_default(),
        (StudySolver::P4f3, _) => {
            let l: [[f64; 6]; 3] = std::array::from_fn(|i| std::array::from_fn(|e| lengths[i][e]));
            p4f3::solve_core(&l)
                .squares
                .map(|x| x.to_vec())
                .into_iter()
                .collect()
        }
    };
    let best = candidates
        .iter()
        .filter_map(|s| TrialError::of(s, truth).map(|e| (e, s)))
        .min_by(|a, b| a.0.max_squares.total_cmp(&b.0.max_squares));
    if let Some((_, s)) = best {
        out.extend(s.iter().zip(truth).map(|(x, t)| x / t));
    }
}

/// The quantiles every summary reports.
pub const QUANTILES: [f64; 6] = [0.05, 0.25, 0.5, 0.75, 0.95, 0.99];

/// One metric's distribution, summarised.
#[derive(Clone, Debug, serde::Serialize)]
pub struct MetricSummary {
    /// The metric (see [`METRICS`]).
    pub metric: &'static str,
    /// The value at each q of [`QUANTILES`].
    pub quantiles: Vec<Quantile>,
    /// Mean over the successful trials.
    pub mean: f64,
}

/// One quantile of a distribution.
#[derive(Clone, Copy, Debug, serde::Serialize)]
pub struct Quantile {
    /// q, in [0, 1].
    pub q: f64,
    /// The value.
    pub value: f64,
}

/// A level's distributions, summarised.
#[derive(Clone, Debug, serde::Serialize)]
pub struct LevelSummary {
    /// ε.
    pub level: f64,
    /// The noise model.
    pub model: String,
    /// Trials run.
    pub trials: usize,
    /// Trials without a usable real solution.
    pub failures: usize,
    /// One summary per metric, in [`METRICS`] order.
    pub metrics: Vec<MetricSummary>,
}

impl LevelResult {
    /// Quantiles and means of every metric.
    pub fn summary(&self) -> LevelSummary {
        LevelSummary {
            level: self.level,
            model: self.model.clone(),
            trials: self.trials,
            failures: self.failures,
            // no successful trial: no distribution to summarise (and no mean to print)
            metrics: (0..METRICS.len() * usize::from(!self.sorted[0].is_empty()))
                .map(|m| MetricSummary {
                    metric: METRICS[m],
                    quantiles: QUANTILES
                        .iter()
                        .filter_map(|&q| self.quantile(m, q).map(|value| Quantile { q, value }))
                        .collect(),
                    mean: self.mean(m),
                })
                .collect(),
        }
    }
}
