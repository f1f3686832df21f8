//! A printed noise level judged against its seeded distributions, under every reading its
//! sentence leaves open (the rule of `docs/verdicts.md`, "Statistical claims"): what every
//! kind with noise runs shares.

use super::{claim_of, claims_of, readings, Direction, NoiseLevel, Quantity as Symbols};
use crate::check::noise::{
    decide, every_reading, judge_bound, margin, metric_phrase, power, Claim, Decision, Facts,
    Judged, TYPICAL_BAND,
};
use crate::check::Role;
use crate::check::{
    ClaimResult, Evidence, Power, ResultBuilder, Tolerance, ToleranceSource, Value, Verdict,
};
use crate::derivations::noise::{LevelResult, METRICS, QUANTILES};
use crate::studies::noise::{edge_medians, run_errors, SymbolDistances};

/// What every level of a study is judged against.
pub(crate) struct Context<'a> {
    /// True squared edges.
    pub truth: &'a [f64],
    /// Edge names.
    pub names: &'a [String],
    /// Trials per distribution.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
    /// The scene in words, for the figures' titles ("three points, four frames").
    pub setting: String,
    /// Whether each level's last distribution is the paper's own scene (§4): the trials a
    /// sentence about "the average" speaks of were run there.
    pub scene: bool,
}

/// The scene of a study in words: its points (from its `edges`, all pairs) and `frames`.
pub(crate) fn setting(edges: usize, frames: usize) -> String {
    let points = (2usize..).find(|&p| p * (p - 1) / 2 >= edges).unwrap_or(2);
    format!(
        "{} points, {} frames",
        count_word(points),
        count_word(frames)
    )
}

/// A small count as a word, a larger one in digits.
fn count_word(n: usize) -> String {
    const WORDS: [&str; 11] = [
        "no", "one", "two", "three", "four", "five", "six", "seven", "eight", "nine", "ten",
    ];
    WORDS
        .get(n)
        .map_or_else(|| n.to_string(), |w| (*w).to_string())
}

impl Context<'_> {
    /// The results of one printed level against its distributions `res` (one per noise model
    /// or scene); `repeated` when the claim is quoted at several levels (each gets its own
    /// id); `neighbour` the distributions of the next printed level, for the power.
    pub(crate) fn level(
        &self,
        b: &ResultBuilder,
        lv: &NoiseLevel,
        repeated: bool,
        res: &[LevelResult],
        neighbour: Option<&[LevelResult]>,
    ) -> Vec<ClaimResult> {
        let level_id = format!("eps-{}", lv.level.text);
        let suffix = |s: Option<&str>| match (repeated, s) {
            (true, Some(s)) => Some(format!("{level_id}/{s}")),
            (true, None) => Some(level_id.clone()),
            (false, s) => s.map(str::to_string),
        };
        let first = lv.printed.first().map_or(&[][..], |v| v.as_slice());
        let values: Vec<f64> = first.iter().map(|p| p.to_f64()).collect();
        let half: Vec<f64> = first.iter().map(|p| p.half_unit()).collect();
        let dist = SymbolDistances::of(&values, self.truth);
        let read_as = if dist.are_squares() {
            Symbols::Squares
        } else {
            Symbols::Lengths
        };
        let mut out = Vec::new();
        if read_as != lv.labelled_as {
            out.push(self.symbols_result(b, lv, suffix(Some("symbols")), dist, read_as));
        }
        let run = run_errors(&values, &half, dist.are_squares(), self.truth);
        // every reading the sentence leaves open decides; the first is the one shown
        let metrics = readings(lv.statement.as_ref(), read_as);
        let at = |metric: usize| {
            let facts = Facts {
                metric,
                run: run.as_ref(),
                dists: res,
            };
            Judged::new(claim_of(lv), facts)
        };
        let all: Vec<Judged> = (0..METRICS.len()).map(at).collect();
        let judged = at(metrics[0]);
        let claims = claims_of(lv);
        let trials = self.trial_dists(res);
        // the other subjects the words leave open, under every metric they read
        let extra: Vec<Judged> = claims[1..]
            .iter()
            .flat_map(|&c| metrics.iter().map(move |&m| (c, m)))
            .map(|(c, metric)| {
                let dists = if matches!(c, Claim::Median(..)) {
                    trials
                } else {
                    res
                };
                Judged::new(
                    c,
                    Facts {
                        metric,
                        run: run.as_ref(),
                        dists,
                    },
                )
            })
            .collect();
        let reading = Readings {
            metrics: &metrics,
            all: &all,
            extra: &extra,
            argued: lv.statement.as_ref().map(|s| s.argued.as_str()),
        };
        let result = self.main_result(b, lv, suffix(None), read_as, &judged, &reading, neighbour);
        b.figure(super::figure::figure(
            &result,
            &self.setting,
            (lv, &judged, &reading),
            (self.trials, self.seed),
        ));
        out.push(result);
        out
    }

    /// The printed symbols (a, b, c or a², b², c²) against what the values are.
    fn symbols_result(
        &self,
        b: &ResultBuilder,
        lv: &NoiseLevel,
        suffix: Option<String>,
        dist: SymbolDistances,
        read_as: Symbols,
    ) -> ClaimResult {
        let lengths: Vec<f64> = self.truth.iter().map(|t| t.sqrt()).collect();
        // the same test on the true lengths must read them as lengths
        let control = !SymbolDistances::of(&lengths, self.truth).are_squares();
        let mut r = b.claim(&lv.claim);
        if let Some(s) = &suffix {
            r = r.suffix(s);
        }
        r = r.printed("symbols", symbols_name(lv.labelled_as));
        for p in lv.printed.first().into_iter().flatten() {
            r = r.printed("value", p);
        }
        r.computed(
            "largest relative distance to the true squares",
            dist.to_squares,
        )
        .computed(
            "largest relative distance to the true lengths",
            dist.to_lengths,
        )
        .computed("the values are", symbols_name(read_as))
        .detail_as(
            "defect",
            Value::label(format!(
                "the values are labelled {} but are {}: the printed run is nearer the true {}",
                symbols_name(lv.labelled_as),
                symbols_name(read_as),
                match read_as {
                    Symbols::Squares => "squares",
                    Symbols::Lengths => "lengths",
                }
            )),
            Role::Defect,
        )
        .correction(symbols_name(read_as))
        .tolerance(Tolerance::exact("the nearer of the two readings"))
        .power(Power::mutant(
            control,
            "the same test reads the true lengths themselves as lengths",
        ))
        .method(
            "relative distance of the printed values to the true lengths and to the true squares",
        )
        .detail("true squares", Value::reals(self.truth))
        .detail("true lengths", Value::reals(&lengths))
        .verdict(Verdict::Erratum)
    }

    /// The level's claim: its details as [`Judged`] under the reading shown, its decision
    /// from every reading the sentence leaves open.
    #[allow(clippy::too_many_arguments)]
    fn main_result(
        &self,
        b: &ResultBuilder,
        lv: &NoiseLevel,
        suffix: Option<String>,
        read_as: Symbols,
        judged: &Judged,
        reading: &Readings,
        neighbour: Option<&[LevelResult]>,
    ) -> ClaimResult {
        let (claim, decision, f) = (judged.claim, reading.decision(), &judged.facts);
        let mut r = b.claim(&lv.claim).printed("ε", &lv.level);
        if let Some(s) = &suffix {
            r = r.suffix(s);
        }
        for (k, sol) in lv.printed.iter().enumerate() {
            for (p, n) in sol.iter().zip(self.names) {
                r = r.printed(&format!("run, solution {}, {n}", k + 1), p);
            }
        }
        if let Some(st) = &lv.statement {
            r = r.printed(direction_name(st.direction), &st.bound);
        }
        let m = f.metric;
        r = r
            .computed("the values are", symbols_name(read_as))
            .computed("reading", metric_phrase(m));
        if let Some(run) = f.run {
            r = r.computed("printed run: error", run.metrics[m]);
            for d in f.dists {
                r = r.computed_cell(
                    &d.model,
                    "percentile of the printed run",
                    100.0 * d.rank_of(m, run.metrics[m]),
                );
            }
        }
        if let Claim::Median(bound, _) = claim {
            for d in f.dists {
                if let Some(q) = d.quantile(m, 0.5) {
                    r = r.computed_cell(&d.model, "median trial's error", q);
                }
                r = r.computed_cell(
                    &d.model,
                    "percentile rank of the bound",
                    100.0 * d.rank_of(m, bound),
                );
            }
        }
        if let (Some(words), None) = (&lv.unjudged, &lv.statement) {
            r = r.computed(
                "claim as read",
                Value::label(format!(
                    "the printed run is a typical outcome of noise up to ε; \"{words}\" names no bound and is not judged"
                )),
            );
        }
        let mut ev = reading.table(self.evidence(lv, claim, f, decision, neighbour), f.run);
        if let Some(words) = &lv.unjudged {
            ev = ev.with(
                "words that name no bound (not judged)",
                Value::quote(words.clone()),
            );
        }
        let r = r
            .undecided(reading.undecided())
            .tolerance(self.tolerance(claim, f))
            .power(power(claim, f, neighbour))
            .evidence(ev);
        r.verdict(decision.verdict())
    }

    /// The distributions the trials of a sentence were run in: the paper's own scene where
    /// there is one, else every noise model (the paper does not say which).
    fn trial_dists<'r>(&self, res: &'r [LevelResult]) -> &'r [LevelResult] {
        match (self.scene, res.len()) {
            (true, n) if n > 0 => &res[n - 1..],
            _ => res,
        }
    }

    /// The Monte Carlo tolerance of a decision: the sampling margin at the threshold that
    /// decides it (a band edge, or the median).
    fn tolerance(&self, claim: Claim, f: &Facts) -> Tolerance {
        let n = f
            .dists
            .iter()
            .map(|d| d.sorted[f.metric].len())
            .min()
            .unwrap_or(0)
            .max(1);
        let (p, how) = match claim {
            Claim::Median(..) => (
                0.5,
                "the bound's percentile rank must differ from 50 by more than two binomial standard errors (the bound, in percentile points)",
            ),
            _ => (
                TYPICAL_BAND.1,
                "the printed run's percentile must lie inside the 2.5–97.5 band of one model by more than two binomial standard errors (the bound, in percentile points, at the upper edge)",
            ),
        };
        Tolerance::bound(
            100.0 * margin(p, n),
            ToleranceSource::MonteCarlo {
                percentile: crate::check::Real(100.0 * p),
                trials: self.trials as u64,
            },
            how,
        )
    }
}

/// A level's claim under each reading of its sentence.
pub(super) struct Readings<'a> {
    /// The metrics of the readings the sentence leaves open (or the one it names).
    pub metrics: &'a [usize],
    /// The claim judged under every metric, in the order of [`METRICS`].
    pub all: &'a [Judged<'a>],
    /// The other subjects the sentence leaves open (the trials besides the printed run),
    /// each under every metric read.
    pub extra: &'a [Judged<'a>],
    /// The reading argued from the sentence's words.
    pub argued: Option<&'a str>,
}

/// The subject of a claim in words: what the reading is about.
fn subject_words(c: Claim) -> &'static str {
    match c {
        Claim::Typical => "the printed run as a typical one",
        Claim::Example(..) => "the printed run",
        Claim::Median(..) => "the median trial",
    }
}

impl Readings<'_> {
    /// Every reading read, the drawn subject's first.
    pub(super) fn read(&self) -> impl Iterator<Item = &Judged<'_>> {
        self.metrics.iter().map(|&m| &self.all[m]).chain(self.extra)
    }

    /// The decision from every reading the sentence leaves open ([`every_reading`]).
    pub fn decision(&self) -> Decision {
        every_reading(self.read().map(|j| j.decision))
    }

    /// Why the readings together decide nothing: they disagree, or one is too close to call.
    fn undecided(&self) -> String {
        let each: Vec<String> = self
            .read()
            .map(|j| {
                format!(
                    "{} as the {} of {}",
                    j.decision.name(),
                    metric_phrase(j.facts.metric),
                    subject_words(j.claim)
                )
            })
            .collect();
        let split = self.read().any(|j| j.decision == Decision::Holds)
            && self.read().any(|j| j.decision == Decision::Fails);
        if split {
            format!(
                "the sentence does not say which error it means, and the readings disagree: {}",
                each.join("; ")
            )
        } else {
            format!("too close to call: {}", each.join("; "))
        }
    }

    /// The readings as a table, one row per reading: whether the sentence leaves it open,
    /// the printed run's error, the median trial's error where the reading is about the
    /// trials, and its decision (or that the sentence names another reading).
    fn table(&self, mut ev: Evidence, run: Option<&crate::studies::noise::RunErrors>) -> Evidence {
        const TABLE: &str = "readings";
        if let Some(words) = self.argued {
            ev = ev.with(
                "reading, argued from the sentence's words",
                Value::label(words),
            );
        }
        let drawn = self
            .all
            .iter()
            .enumerate()
            .map(|(m, j)| (m, j, self.metrics.contains(&m)));
        let extra = self.extra.iter().map(|j| (j.facts.metric, j, true));
        for (m, j, read) in drawn.chain(extra) {
            let row = format!("{}, {}", subject_words(j.claim), metric_phrase(m));
            if let Some(run) = run {
                ev = ev.with_entry(TABLE, &row, "printed run's error", run.metrics[m]);
            }
            if let Claim::Median(..) = j.claim {
                for d in j.facts.dists {
                    if let Some(q) = d.quantile(m, 0.5) {
                        let column = format!("median trial's error, {}", d.model);
                        ev = ev.with_entry(TABLE, &row, &column, q);
                    }
                }
            }
            let decides = if read {
                j.decision.name()
            } else {
                "not read: the sentence names another"
            };
            ev = ev.with_entry(TABLE, &row, "decision", decides);
        }
        ev
    }
}

fn symbols_name(q: Symbols) -> &'static str {
    match q {
        Symbols::Squares => "a², b², c² (squared lengths)",
        Symbols::Lengths => "a, b, c (lengths)",
    }
}

fn direction_name(d: Direction) -> &'static str {
    match d {
        Direction::Below => "error below",
        Direction::Above => "error above",
    }
}

const METHOD: &str =
    "seeded Monte Carlo: the body under uniformly random rotations in every frame \
(or at the paper's own scene where the model says so), P at the origin, noise, the solver, and the \
real solution nearest the truth; errors relative to the truth; percentiles among the trials with a \
real solution";

impl Context<'_> {
    /// The evidence of a level: the printed run under every reading, the distributions.
    fn evidence(
        &self,
        lv: &NoiseLevel,
        claim: Claim,
        f: &Facts,
        decision: Decision,
        neighbour: Option<&[LevelResult]>,
    ) -> Evidence {
        let m = f.metric;
        let mut ev = Evidence::new(METHOD)
            .with_role("trials per model", self.trials, Role::Trials)
            .with("seed", self.seed)
            .with("decision", decision.name());
        if let Some(run) = f.run {
            ev = ev.with(
                "printed run: error over the rounding of its digits",
                Value::interval(run.ranges[m].0, run.ranges[m].1),
            );
            if let Claim::Example(bound, d) = claim {
                ev = ev.with(
                    "bound on the printed run",
                    judge_bound(run.ranges[m], bound, d).name(),
                );
            }
            if !matches!(claim, Claim::Median(..)) {
                let band = decide(Claim::Typical, f);
                ev = ev.with("printed run inside the typical band", band.name());
            }
            if self.truth.len() > 3 {
                ev = ev
                    .with(
                        "printed run, per edge: error in squares",
                        Value::reals(&run.edge_squares),
                    )
                    .with(
                        "printed run, per edge: error in lengths",
                        Value::reals(&run.edge_lengths),
                    );
            }
        }
        for d in f.dists {
            ev = self.dist_evidence(ev, claim, m, d);
        }
        if let Some(mb) = claim.mutant().and_then(Claim::bound) {
            ev = ev.with("mutant bound", mb);
        }
        if let (Claim::Typical, Some(run), Some(ns)) = (claim, f.run, neighbour) {
            if let Some(d) = ns.first() {
                ev = ev.with_cell("mutant", "the neighbouring level's ε", d.level);
            }
            for d in ns {
                ev = ev.with_cell(
                    "mutant",
                    &format!("percentile of the printed run there, {}", d.model),
                    100.0 * d.rank_of(m, run.metrics[m]),
                );
            }
        }
        if lv.printed.len() > 1 {
            ev = ev.with(
                "the run's other solutions",
                "cannot be checked: the paper does not print the noisy projections of its runs",
            );
        }
        ev
    }

    /// One distribution's evidence: failures, quantiles and mean of the reading's metric,
    /// the share of trials the bound holds for, the medians under every reading.
    fn dist_evidence(&self, mut ev: Evidence, claim: Claim, m: usize, d: &LevelResult) -> Evidence {
        let model = &d.model;
        ev = ev.with_cell(
            model,
            "trials without a real solution",
            Value::count_of(d.failures, d.trials),
        );
        let qs: Vec<f64> = QUANTILES.iter().filter_map(|&q| d.quantile(m, q)).collect();
        ev = ev.with_quantiles(model, "5/25/50/75/95/99 % quantiles", &QUANTILES, &qs);
        if !d.sorted[m].is_empty() {
            ev = ev.with_cell(model, "mean over the trials", d.mean(m));
        }
        if let Some(bound) = claim.bound() {
            let below = d.rank_of(m, bound);
            let share = match claim {
                Claim::Example(_, Direction::Above) | Claim::Median(_, Direction::Above) => {
                    1.0 - below
                }
                _ => below,
            };
            ev = ev.with_cell(model, "share of trials for which the bound holds", share);
        }
        if matches!(claim, Claim::Median(..)) {
            let med: Vec<f64> = (0..METRICS.len())
                .filter_map(|k| d.quantile(k, 0.5))
                .collect();
            ev = ev.with_cell(
                model,
                "median trial under every reading (max/mean in squares, max/mean in lengths)",
                Value::reals(&med),
            );
        }
        if self.truth.len() > 3 {
            let [sq, ln] = edge_medians(d);
            ev = ev
                .with_cell(model, "median error per edge, squares", Value::reals(&sq))
                .with_cell(model, "median error per edge, lengths", Value::reals(&ln));
        }
        ev
    }
}
