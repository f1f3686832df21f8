//! The judges of the noise claims: small pure functions from numbers to a `Decision`, by
//! the rule of `docs/verdicts.md` ("Statistical claims"), each tested on both sides of its
//! threshold.

use crate::check::{Power, Verdict};
use crate::derivations::noise::LevelResult;
use crate::studies::noise::RunErrors;
use serde::Deserialize;

/// Below or above.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum Direction {
    /// The error is below the bound.
    Below,
    /// The error is above the bound.
    Above,
}

/// The central band of the seeded distribution a printed "e.g." run must fall in (as
/// fractions): a run outside it under every noise model is not what the stated noise gives.
pub(crate) const TYPICAL_BAND: (f64, f64) = (0.025, 0.975);
/// A Monte Carlo proportion nearer its threshold than this many binomial standard errors
/// (√(p(1−p)/n) at the threshold) is too close to call.
const CLOSE_SE: f64 = 2.0;
/// The threshold mutant: a "below" bound is divided, an "above" bound multiplied by this.
const MUTANT_FACTOR: f64 = 2.0;

/// The outcome of one judge.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Decision {
    /// The reading holds.
    Holds,
    /// The reading fails.
    Fails,
    /// Within the rounding of the printed digits or the sampling error of the trials.
    TooClose,
}

impl Decision {
    pub(crate) fn verdict(self) -> Verdict {
        match self {
            Decision::Holds => Verdict::StatisticalHolds,
            Decision::Fails => Verdict::StatisticalFails,
            Decision::TooClose => Verdict::Inconclusive,
        }
    }

    pub(crate) fn name(self) -> &'static str {
        match self {
            Decision::Holds => "holds",
            Decision::Fails => "fails",
            Decision::TooClose => "too close to call",
        }
    }
}

/// An error whose range (over the rounding of the printed digits) is `range`, against a
/// `bound` the paper says it is below or above.
pub(crate) fn judge_bound(range: (f64, f64), bound: f64, direction: Direction) -> Decision {
    let (lo, hi) = range;
    let (holds, fails) = match direction {
        Direction::Below => (hi < bound, lo >= bound),
        Direction::Above => (lo > bound, hi <= bound),
    };
    match (holds, fails) {
        (true, _) => Decision::Holds,
        (_, true) => Decision::Fails,
        _ => Decision::TooClose,
    }
}

/// Two binomial standard errors of a proportion of `n` trials at `p`.
pub(crate) fn margin(p: f64, n: usize) -> f64 {
    CLOSE_SE * (p * (1.0 - p) / n as f64).sqrt()
}

/// A printed run at percentile rank `p` (fraction of `n` trials not above it): inside the
/// typical band, outside it, or too near an edge for the trial count.
pub(crate) fn judge_band(p: f64, n: usize) -> Decision {
    if n == 0 {
        return Decision::TooClose;
    }
    let (lo, hi) = TYPICAL_BAND;
    let (ml, mh) = (margin(lo, n), margin(hi, n));
    if p > lo + ml && p < hi - mh {
        Decision::Holds
    } else if p < lo - ml || p > hi + mh {
        Decision::Fails
    } else {
        Decision::TooClose
    }
}

/// The median trial against a bound: `rank` is the fraction of the `n` trials not above the
/// bound, so the median is below it when more than half are.
pub(crate) fn judge_median(rank: f64, n: usize, direction: Direction) -> Decision {
    if n == 0 {
        return Decision::TooClose;
    }
    let m = margin(0.5, n);
    let below = match direction {
        Direction::Below => rank - 0.5,
        Direction::Above => 0.5 - rank,
    };
    if below > m {
        Decision::Holds
    } else if below < -m {
        Decision::Fails
    } else {
        Decision::TooClose
    }
}

/// The paper does not say which noise model it used: a reading holds when it holds under
/// one of them, fails when it fails under all.
pub(crate) fn any_model(ds: impl IntoIterator<Item = Decision>) -> Decision {
    let ds: Vec<Decision> = ds.into_iter().collect();
    if ds.contains(&Decision::Holds) {
        Decision::Holds
    } else if ds.is_empty() || ds.contains(&Decision::TooClose) {
        Decision::TooClose
    } else {
        Decision::Fails
    }
}

/// A sentence that leaves its reading open (squares or lengths, the largest or the mean
/// error over the edges) holds when it holds under every reading, fails when it fails under
/// every one, and is too close to call when the readings disagree.
pub(crate) fn every_reading(ds: impl IntoIterator<Item = Decision>) -> Decision {
    let ds: Vec<Decision> = ds.into_iter().collect();
    match ds.first() {
        Some(&d) if d != Decision::TooClose && ds.iter().all(|&x| x == d) => d,
        _ => Decision::TooClose,
    }
}

/// Both parts of a claim must hold; either failing fails it.
pub(crate) fn both(a: Decision, b: Decision) -> Decision {
    match (a, b) {
        (Decision::Fails, _) | (_, Decision::Fails) => Decision::Fails,
        (Decision::Holds, Decision::Holds) => Decision::Holds,
        _ => Decision::TooClose,
    }
}

/// What a level's claim says, read by the rule of `docs/verdicts.md`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Claim {
    /// An "e.g." run with words only: the run is a typical outcome of the stated noise.
    Typical,
    /// A bound on the printed run's error, and the run typical.
    Example(f64, Direction),
    /// A bound on the median trial's error ("the average performance").
    Median(f64, Direction),
}

impl Claim {
    /// The claim with its bound moved by [`MUTANT_FACTOR`] against the paper (a "below" bound
    /// lowered, an "above" bound raised); `None` without a bound.
    pub(crate) fn mutant(self) -> Option<Claim> {
        let moved = |b: f64, d: Direction| match d {
            Direction::Below => b / MUTANT_FACTOR,
            Direction::Above => b * MUTANT_FACTOR,
        };
        match self {
            Claim::Typical => None,
            Claim::Example(b, d) => Some(Claim::Example(moved(b, d), d)),
            Claim::Median(b, d) => Some(Claim::Median(moved(b, d), d)),
        }
    }

    pub(crate) fn bound(self) -> Option<f64> {
        match self {
            Claim::Typical => None,
            Claim::Example(b, _) | Claim::Median(b, _) => Some(b),
        }
    }
}

/// The numbers one level's claim is judged on.
pub(crate) struct Facts<'a> {
    /// The metric of the reading (index into [`METRICS`]).
    pub metric: usize,
    /// The printed run's errors (`None` when its digits cannot be read as squares).
    pub run: Option<&'a RunErrors>,
    /// The seeded distributions, one per noise model (or scene).
    pub dists: &'a [LevelResult],
}

/// One noise model's part in a decision: where the judge reads the model's distribution, and
/// what it decides there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Part {
    /// The fraction of the model's trials not above the value the judge reads: the bound, for
    /// a claim on the median trial; the printed run's error otherwise (`None` when the run's
    /// digits cannot be read).
    pub rank: Option<f64>,
    /// What the model decides: the median against the bound, or the run inside the typical
    /// band.
    pub decision: Decision,
}

/// Each model's part in the decision of `claim`, in the order of `f.dists`.
pub(crate) fn parts(claim: Claim, f: &Facts) -> Vec<Part> {
    let m = f.metric;
    f.dists
        .iter()
        .map(|r| {
            let n = r.sorted[m].len();
            match (claim, f.run) {
                (Claim::Median(bound, d), _) => {
                    let rank = r.rank_of(m, bound);
                    Part {
                        rank: Some(rank),
                        decision: judge_median(rank, n, d),
                    }
                }
                (_, Some(run)) => {
                    let rank = r.rank_of(m, run.metrics[m]);
                    Part {
                        rank: Some(rank),
                        decision: judge_band(rank, n),
                    }
                }
                (_, None) => Part {
                    rank: None,
                    decision: Decision::TooClose,
                },
            }
        })
        .collect()
}

/// The printed run's error (over the rounding of its digits) against a bound; too close to
/// call without a readable run.
pub(crate) fn on_run(f: &Facts, bound: f64, direction: Direction) -> Decision {
    f.run.map_or(Decision::TooClose, |r| {
        judge_bound(r.ranges[f.metric], bound, direction)
    })
}

/// The judge of a level's claim: the models' parts (one model suffices), and for a bound on
/// the printed run, the run's error against it as well.
pub(crate) fn decide(claim: Claim, f: &Facts) -> Decision {
    let models = any_model(parts(claim, f).into_iter().map(|p| p.decision));
    match claim {
        Claim::Example(bound, d) => both(on_run(f, bound, d), models),
        Claim::Typical | Claim::Median(..) => models,
    }
}

/// A level's claim, the facts it is judged on, and the judge's decision: what the result
/// reports and the figure shows.
pub(crate) struct Judged<'a> {
    /// The claim as read.
    pub claim: Claim,
    /// Its facts.
    pub facts: Facts<'a>,
    /// The judge's decision ([`decide`]).
    pub decision: Decision,
}

impl<'a> Judged<'a> {
    /// `claim` judged on `facts`.
    pub(crate) fn new(claim: Claim, facts: Facts<'a>) -> Self {
        let decision = decide(claim, &facts);
        Judged {
            claim,
            facts,
            decision,
        }
    }
}

/// The negative control: the same judge on the claim with its bound moved, or, for a claim
/// without a bound, on the distributions of the neighbouring printed level (ten times more or
/// less noise) must fail.
pub(crate) fn power(claim: Claim, f: &Facts, neighbour: Option<&[LevelResult]>) -> Power {
    if let Some(mutant) = claim.mutant() {
        let rejected = decide(mutant, f) == Decision::Fails;
        return Power::mutant(
            rejected,
            "the same judge with the paper's bound moved by a factor 2 against it (a 'below' bound halved, an 'above' bound doubled)",
        );
    }
    match neighbour {
        Some(dists) => {
            let g = Facts { dists, ..*f };
            Power::mutant(
                decide(claim, &g) == Decision::Fails,
                "the same judge with the printed run placed in the distributions of the neighbouring printed noise level",
            )
        }
        None => Power::none("no bound to move and no neighbouring level"),
    }
}

pub(crate) fn metric_phrase(m: usize) -> &'static str {
    [
        "largest relative error over the edges, in squares",
        "mean relative error over the edges, in squares",
        "largest relative error over the edges, in lengths",
        "mean relative error over the edges, in lengths",
    ][m]
}

#[cfg(test)]
mod tests {
    use super::*;
    use Decision::{Fails, Holds, TooClose};

    #[test]
    fn bound_on_the_run_both_sides_and_the_rounding() {
        let (below, above) = (Direction::Below, Direction::Above);
        assert_eq!(judge_bound((0.29, 0.295), 0.3, below), Holds);
        assert_eq!(judge_bound((0.31, 0.32), 0.3, below), Fails);
        assert_eq!(judge_bound((0.3, 0.32), 0.3, below), Fails);
        assert_eq!(judge_bound((0.29, 0.31), 0.3, below), TooClose);
        assert_eq!(judge_bound((0.31, 0.32), 0.3, above), Holds);
        assert_eq!(judge_bound((0.28, 0.29), 0.3, above), Fails);
        assert_eq!(judge_bound((0.29, 0.31), 0.3, above), TooClose);
    }

    #[test]
    fn band_inside_outside_and_near_an_edge() {
        let n = 10_000;
        // two standard errors at 2.5 % of 10⁴ trials: 0.31 percentile points
        assert_eq!(judge_band(0.5, n), Holds);
        assert_eq!(judge_band(0.03, n), Holds);
        assert_eq!(judge_band(0.02, n), Fails);
        assert_eq!(judge_band(0.025, n), TooClose);
        assert_eq!(judge_band(0.97, n), Holds);
        assert_eq!(judge_band(0.98, n), Fails);
        assert_eq!(judge_band(0.5, 0), TooClose);
    }

    #[test]
    fn median_against_a_bound() {
        let n = 10_000; // two standard errors at 50 %: 1 percentile point
        assert_eq!(judge_median(0.52, n, Direction::Below), Holds);
        assert_eq!(judge_median(0.48, n, Direction::Below), Fails);
        assert_eq!(judge_median(0.505, n, Direction::Below), TooClose);
        assert_eq!(judge_median(0.48, n, Direction::Above), Holds);
        assert_eq!(judge_median(0.52, n, Direction::Above), Fails);
    }

    #[test]
    fn models_and_parts_combine() {
        assert_eq!(any_model([Fails, Holds]), Holds);
        assert_eq!(any_model([Fails, TooClose]), TooClose);
        assert_eq!(any_model([Fails, Fails]), Fails);
        assert_eq!(any_model([]), TooClose);
    }

    #[test]
    fn every_reading_must_agree() {
        assert_eq!(every_reading([Holds, Holds, Holds, Holds]), Holds);
        assert_eq!(every_reading([Fails, Fails]), Fails);
        assert_eq!(every_reading([Holds, Fails, Holds, Holds]), TooClose);
        assert_eq!(every_reading([Holds, TooClose]), TooClose);
        assert_eq!(every_reading([TooClose, TooClose]), TooClose);
        assert_eq!(every_reading([]), TooClose);
        assert_eq!(both(Holds, Holds), Holds);
        assert_eq!(both(Holds, Fails), Fails);
        assert_eq!(both(TooClose, Fails), Fails);
        assert_eq!(both(Holds, TooClose), TooClose);
    }

    /// A level whose every metric is uniform on 1..=n thousandths.
    fn uniform(n: usize) -> LevelResult {
        let v: Vec<f64> = (1..=n).map(|i| i as f64 / 1000.0).collect();
        LevelResult {
            level: 0.0,
            model: "test".into(),
            trials: n,
            failures: 0,
            sorted: std::array::from_fn(|_| v.clone()),
            ratios: Vec::new(),
            edges: 3,
            sums: None,
        }
    }

    fn run(err: f64) -> RunErrors {
        RunErrors {
            metrics: [err; 4],
            ranges: [(err, err); 4],
            edge_squares: vec![err; 3],
            edge_lengths: vec![err; 3],
        }
    }

    #[test]
    fn decide_and_its_mutants() {
        let d = [uniform(10_000)];
        let r = run(4.0); // rank 0.4
        let f = Facts {
            metric: 0,
            run: Some(&r),
            dists: &d,
        };
        assert_eq!(decide(Claim::Typical, &f), Holds);
        assert_eq!(decide(Claim::Example(5.0, Direction::Below), &f), Holds);
        assert_eq!(decide(Claim::Example(3.0, Direction::Below), &f), Fails);
        // the median is 5: below 6 holds, below 4 fails, above 4 holds
        assert_eq!(decide(Claim::Median(6.0, Direction::Below), &f), Holds);
        assert_eq!(decide(Claim::Median(4.0, Direction::Below), &f), Fails);
        assert_eq!(decide(Claim::Median(4.0, Direction::Above), &f), Holds);
        // halving "below 5" to "below 2.5" fails: the power is not weak
        assert!(!power(Claim::Example(5.0, Direction::Below), &f, None).weak);
        // "below 50" halved is still above the run: weak
        assert!(power(Claim::Example(50.0, Direction::Below), &f, None).weak);
        // a run far outside the band is not typical
        let far = run(9.9);
        let g = Facts {
            run: Some(&far),
            ..f
        };
        assert_eq!(decide(Claim::Typical, &g), Fails);
        // the neighbouring level rejects the run: typical claim has power
        // ten times the spread: the run at 0.9 ranks 0.009 there, outside the band
        let shifted = [uniform(100_000)];
        let near = run(0.9);
        let h = Facts {
            run: Some(&near),
            ..f
        };
        assert_eq!(decide(Claim::Typical, &h), Holds);
        assert!(!power(Claim::Typical, &h, Some(&shifted)).weak);
        assert!(power(Claim::Typical, &h, Some(&d)).weak);
    }

    #[test]
    fn parts_are_read_where_the_judge_reads() {
        let d = [uniform(10_000), uniform(20_000)];
        let r = run(4.0);
        let f = Facts {
            metric: 0,
            run: Some(&r),
            dists: &d,
        };
        // the run: its rank in each model, inside the band
        let p = parts(Claim::Example(5.0, Direction::Below), &f);
        assert_eq!(p.len(), 2);
        assert_eq!(p[0].rank, Some(0.4));
        assert_eq!(p[1].rank, Some(0.2));
        assert!(p.iter().all(|x| x.decision == Holds));
        // the median: the bound's rank (0.6 and 0.3), above and below one half
        let p = parts(Claim::Median(6.0, Direction::Below), &f);
        assert_eq!((p[0].rank, p[0].decision), (Some(0.6), Holds));
        assert_eq!((p[1].rank, p[1].decision), (Some(0.3), Fails));
        let j = Judged::new(
            Claim::Median(6.0, Direction::Below),
            Facts { metric: 0, ..f },
        );
        assert_eq!(j.decision, Holds);
        // no readable run: nothing to read
        let g = Facts { run: None, ..f };
        assert!(parts(Claim::Typical, &g).iter().all(|x| x.rank.is_none()));
        assert_eq!(decide(Claim::Typical, &g), TooClose);
        assert_eq!(on_run(&g, 5.0, Direction::Below), TooClose);
    }
}
