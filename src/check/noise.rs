//! Claims of the noise studies (§2, §3): where the paper's runs fall in seeded distributions.

use super::figure::{ecdf, Figure, Layer, Plot, Shape, Style};
use super::{ClaimResult, Evidence, OldTolerance, ResultBuilder, Verdict};
use crate::cases::{
    Direction, NoiseLevel, NoiseStudyCase, OverEdges, Printed, Quantity, StatementSubject,
};
use crate::derivations::noise::{models, run_level, stream, LevelResult, Study, TrialError};
use crate::derivations::p4f3::realize;
use crate::error::Result;
use crate::model::Body;
use crate::numfmt::{sig, sig_list};

fn pct(x: f64) -> String {
    format!("{}%", sig(100.0 * x))
}

/// The study a noise case describes: its body, solver, frames, trials and seed.
pub fn study_of(case: &NoiseStudyCase) -> Result<Study> {
    let l: Vec<f64> = case.body.lengths.iter().map(|p| p.to_f64()).collect();
    let body = if l.len() == 3 {
        Body::triangle(l[0], l[1], l[2])?
    } else {
        // more points: realize the printed squares (or the squares of the printed lengths)
        let squares: Vec<f64> = if case.body.squares.is_empty() {
            l.iter().map(|x| x * x).collect()
        } else {
            case.body.squares.iter().map(|p| p.to_f64()).collect()
        };
        let p = (1..)
            .find(|p| p * (p - 1) / 2 >= squares.len())
            .unwrap_or(2);
        let r = realize(&squares, p);
        if !r.realizable {
            return Err(crate::error::Error::InvalidInput(format!(
                "the printed edges are not realizable in 3-D (Gram eigenvalues {:?})",
                r.eigenvalues
            )));
        }
        Body::new(r.points)
    };
    Ok(Study {
        solver: case.solver,
        body,
        frames: case.frames,
        trials: case.trials,
        seed: case.seed,
        motions: None,
    })
}

/// The studies a case asks for, one per level and noise model (coordinate model first).
/// Level `i` under model `m` uses random stream `2i + m`.
pub fn run_study(case: &NoiseStudyCase) -> Result<Vec<[LevelResult; 2]>> {
    let study = study_of(case)?;
    Ok(case
        .levels
        .iter()
        .enumerate()
        .map(|(i, lv)| {
            let models = models(lv.level.to_f64());
            std::array::from_fn(|m| run_level(&study, models[m], stream(i, m), &|_| {}))
        })
        .collect())
}

pub(super) fn check(b: &ResultBuilder, case: &NoiseStudyCase) -> Result<Vec<ClaimResult>> {
    let mut out = Vec::new();
    let lengths: Vec<f64> = case.body.lengths.iter().map(|p| p.to_f64()).collect();
    // the printed squares when there are any (the runs are compared with them), else the
    // squares of the printed lengths
    let truth: Vec<f64> = if case.body.squares.is_empty() {
        lengths.iter().map(|x| x * x).collect()
    } else {
        case.body.squares.iter().map(|p| p.to_f64()).collect()
    };
    let names = crate::derivations::solver::default_edge_names(truth.len());

    if let Some(claim) = &case.body.claim {
        let digits = case.body.significant_digits.unwrap_or(6);
        let agree: Vec<bool> = case
            .body
            .lengths
            .iter()
            .zip(&case.body.squares)
            .map(|(l, s)| {
                let sq = l.to_f64() * l.to_f64();
                (sq - s.to_f64()).abs() <= s.half_unit_significant(digits)
            })
            .collect();
        out.push(
            b.result(
                claim,
                None,
                Verdict::holds(agree.iter().all(|a| *a)),
                format!(
                    "lengths {}, squares {}",
                    Printed::join(&case.body.lengths),
                    Printed::join(&case.body.squares)
                ),
                format!("squares of the printed lengths: {}", sig_list(&truth)),
                Some(OldTolerance {
                    value: sig_list(
                        &case
                            .body
                            .squares
                            .iter()
                            .map(|s| s.half_unit_significant(digits))
                            .collect::<Vec<_>>(),
                    ),
                    source: format!(
                        "half a unit in the {digits}th significant digit of the printed squares"
                    ),
                }),
                Evidence::new("squares of the printed lengths against the printed squares"),
            ),
        );
    }

    let results = run_study(case)?;
    let judge = Judge {
        truth: &truth,
        lengths: &lengths,
        names: &names,
        trials: case.trials,
        seed: case.seed,
    };
    for (lv, res) in case.levels.iter().zip(&results) {
        // one claim quoted at several levels gets one result per level
        let repeated = case
            .levels
            .iter()
            .filter(|l| l.claim.claim == lv.claim.claim)
            .count()
            > 1;
        out.extend(judge.level(b, lv, repeated, res));
    }
    Ok(out)
}

/// What a printed noise level is judged against.
pub(super) struct Judge<'a> {
    /// True squared edges.
    pub truth: &'a [f64],
    /// True lengths.
    pub lengths: &'a [f64],
    /// Edge names.
    pub names: &'a [String],
    /// Trials per distribution.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
}

impl Judge<'_> {
    /// The results for one printed level against the distributions `res` (one per noise
    /// model or scene); `repeated` when the claim is quoted at several levels, so each
    /// level's result gets its own id.
    pub(super) fn level(
        &self,
        b: &ResultBuilder,
        lv: &NoiseLevel,
        repeated: bool,
        res: &[LevelResult],
    ) -> Vec<ClaimResult> {
        let (truth, lengths, names) = (self.truth, self.lengths, self.names);
        let mut out = Vec::new();
        let level_id = format!("eps-{}", lv.level.text);
        let suffix = |s: Option<&str>| match (repeated, s) {
            (true, Some(s)) => Some(format!("{level_id}/{s}")),
            (true, None) => Some(level_id.clone()),
            (false, s) => s.map(str::to_string),
        };
        let first: Vec<f64> = lv.printed[0].iter().map(|p| p.to_f64()).collect();
        // What are the printed numbers: squares or lengths? Decide by which truth they are near.
        let near = |t: &[f64]| {
            first
                .iter()
                .zip(t)
                .map(|(a, b)| ((a - b) / b).abs())
                .fold(0.0, f64::max)
        };
        let as_squares = near(truth) <= near(lengths);
        let quantity = if as_squares {
            Quantity::Squares
        } else {
            Quantity::Lengths
        };
        if quantity != lv.labelled_as {
            out.push(b.result(
                &lv.claim,
                suffix(Some("symbols")).as_deref(),
                Verdict::Erratum,
                format!(
                    "printed as {} = {}",
                    if lv.labelled_as == Quantity::Lengths { "a, b, c" } else { "a², b², c²" },
                    Printed::join(&lv.printed[0])
                ),
                format!(
                    "the values are {}: within {} of the true {} {}, but {} from the true {} {}; read them as {}",
                    if as_squares { "squared lengths" } else { "lengths" },
                    pct(near(if as_squares { truth } else { lengths })),
                    if as_squares { "squares" } else { "lengths" },
                    sig_list(if as_squares { truth } else { lengths }),
                    pct(near(if as_squares { lengths } else { truth })),
                    if as_squares { "lengths" } else { "squares" },
                    sig_list(if as_squares { lengths } else { truth }),
                    if as_squares { "a², b², c²" } else { "a, b, c" }
                ),
                None,
                Evidence::new("relative distance of the printed values to the true lengths and to the true squares"),
            ));
        }
        let squares_of_first: Vec<f64> = if as_squares {
            first.clone()
        } else {
            first.iter().map(|x| x * x).collect()
        };
        let example = TrialError::of(&squares_of_first, truth);
        let mut ev = Evidence::new(
            "seeded Monte Carlo: the body under uniformly random rotations in every frame (or at the \
             paper's own scene where the model says so), P at the origin, noise, the solver, and the real \
             solution nearest the truth; errors relative to the truth, largest over the edges unless said otherwise",
        )
        .with("trials per model (seed)", format!("{} ({})", self.trials, self.seed))
        .with("printed values read as", if as_squares { "squared lengths" } else { "lengths" });
        if let Some(e) = example {
            ev = ev.with(
                "printed run: largest error in squares / in lengths",
                format!("{} / {}", pct(e.max_squares), pct(e.max_lengths)),
            );
        }
        // with more than three edges, say which edges err how much
        let per_edge = truth.len() > 3;
        if let (true, Some(sq)) = (per_edge, Some(&squares_of_first)) {
            let errs: Vec<String> = names
                .iter()
                .zip(sq.iter().zip(truth))
                .map(|(n, (x, t))| {
                    format!(
                        "{n} {} / {}",
                        pct((x / t - 1.0).abs()),
                        pct(((x / t).sqrt() - 1.0).abs())
                    )
                })
                .collect();
            ev = ev.with(
                "printed run, per edge: error in squares / in lengths",
                errs.join("; "),
            );
        }
        let mut summary = Vec::new();
        for r in res {
            let q = |m: usize, p: f64| r.quantile(m, p).map_or("-".into(), pct);
            if per_edge {
                let med: Vec<String> = names
                    .iter()
                    .enumerate()
                    .map(|(e, n)| {
                        let m = |l: bool| {
                            crate::derivations::rounding::quantile(&r.edge_errors(e, l), 0.5)
                                .map_or("-".into(), pct)
                        };
                        format!("{n} {} / {}", m(false), m(true))
                    })
                    .collect();
                ev = ev.with(
                    &format!(
                        "{} model: median error per edge, squares / lengths",
                        r.model
                    ),
                    med.join("; "),
                );
            }
            ev = ev.with(
                &format!("{} model: failures", r.model),
                format!("{} of {}", r.failures, r.trials),
            );
            for (m, name) in [(0, "squares"), (2, "lengths")] {
                ev = ev.with(
                    &format!(
                        "{} model: largest error in {name}, 5/25/50/75/95/99 %",
                        r.model
                    ),
                    [0.05, 0.25, 0.5, 0.75, 0.95, 0.99]
                        .map(|p| q(m, p))
                        .join(" / "),
                );
                ev = ev.with(
                    &format!(
                        "{} model: mean over trials of the largest error in {name}",
                        r.model
                    ),
                    pct(r.mean(m)),
                );
            }
            if let Some(e) = example {
                let (ps, pl) = (r.rank_of(0, e.max_squares), r.rank_of(2, e.max_lengths));
                ev = ev.with(
                    &format!(
                        "{} model: percentile of the printed run (squares / lengths)",
                        r.model
                    ),
                    format!("{} / {}", pct(ps), pct(pl)),
                );
                summary.push(format!(
                    "{} model: printed run at percentile {} (squares), {} (lengths)",
                    r.model,
                    pct(ps),
                    pct(pl)
                ));
            }
        }
        // The statement, decided in squares and in lengths.
        let mut paper_value = format!(
            "ε = {}: {}",
            lv.level.text,
            lv.printed
                .iter()
                .map(|p| format!("({})", Printed::join(p)))
                .collect::<Vec<_>>()
                .join(", ")
        );
        if let Some(st) = &lv.statement {
            let bound = st.bound.to_f64();
            let holds = |x: f64| match st.direction {
                Direction::Below => x < bound,
                Direction::Above => x > bound,
            };
            let word = match st.direction {
                Direction::Below => "below",
                Direction::Above => "above",
            };
            paper_value.push_str(&format!("; error {word} {}", pct(bound)));
            match st.about {
                StatementSubject::Example => {
                    let (ms, ml, how) = match st.over_edges {
                        OverEdges::Max => (0, 2, "largest over the edges"),
                        OverEdges::Mean => (1, 3, "mean over the edges"),
                    };
                    if let Some(e) = example {
                        let m = e.metrics();
                        summary.push(format!(
                            "the printed run's error ({how}) is {} in squares ({word} {}: {}), {} in lengths ({})",
                            pct(m[ms]),
                            pct(bound),
                            holds(m[ms]),
                            pct(m[ml]),
                            holds(m[ml])
                        ));
                    }
                    if per_edge {
                        let which = |lengths: bool| {
                            let v: Vec<&str> = names
                                .iter()
                                .zip(squares_of_first.iter().zip(truth))
                                .filter(|(_, (x, t))| {
                                    let r = *x / *t;
                                    holds(if lengths {
                                        (r.sqrt() - 1.0).abs()
                                    } else {
                                        (r - 1.0).abs()
                                    })
                                })
                                .map(|(n, _)| n.as_str())
                                .collect();
                            if v.is_empty() {
                                "none".to_string()
                            } else {
                                v.join(", ")
                            }
                        };
                        summary.push(format!(
                            "edges whose own error is {word} {}: {} in squares, {} in lengths",
                            pct(bound),
                            which(false),
                            which(true)
                        ));
                    }
                    for r in res {
                        let frac = |m: usize| {
                            r.sorted[m].iter().filter(|x| holds(**x)).count() as f64
                                / r.trials as f64
                        };
                        ev = ev.with(
                            &format!(
                                "{} model: trials whose error ({how}) is {word} {} (squares / lengths)",
                                r.model,
                                pct(bound)
                            ),
                            format!("{} / {}", pct(frac(ms)), pct(frac(ml))),
                        );
                    }
                }
                StatementSubject::TrialMean => {
                    // "average performance": the mean over trials, of the worst edge and of
                    // the mean over the edges, in squares and in lengths
                    for r in res {
                        let said = |m: usize| format!("{} ({})", pct(r.mean(m)), holds(r.mean(m)));
                        summary.push(format!(
                            "{} model: mean error, worst edge: {} in squares, {} in lengths; \
                             mean over edges: {} in squares, {} in lengths ({word} {}?)",
                            r.model,
                            said(0),
                            said(2),
                            said(1),
                            said(3),
                            pct(bound),
                        ));
                        ev = ev.with(
                            &format!(
                                "{} model: median of the mean-over-edges error (squares / lengths)",
                                r.model
                            ),
                            format!(
                                "{} / {}",
                                r.quantile(1, 0.5).map_or("-".into(), pct),
                                r.quantile(3, 0.5).map_or("-".into(), pct)
                            ),
                        );
                    }
                }
            }
        }
        if lv.printed.len() > 1 {
            ev = ev.with(
                "the run's other solutions",
                "cannot be checked: the paper does not print the noisy projections of its runs",
            );
        }
        let result = b.result(
            &lv.claim,
            suffix(None).as_deref(),
            Verdict::StatisticalHolds,
            paper_value,
            summary.join("; "),
            None,
            ev,
        );
        // the distributions, with the printed run marked
        let panel = |m: usize, what: &str| {
            let mut layers: Vec<Layer> = res
                .iter()
                .enumerate()
                .map(|(k, r)| {
                    let style = if k == 0 {
                        Style::Computed
                    } else {
                        Style::Other
                    };
                    Layer::new(
                        &format!("{} model", r.model),
                        Shape::Line,
                        style,
                        ecdf(&r.sorted[m], 200),
                    )
                })
                .collect();
            if let Some(e) = example {
                layers.push(Layer::new(
                    "the paper's run",
                    Shape::Verticals,
                    Style::Mark,
                    vec![[e.metrics()[m], 0.5]],
                ));
            }
            Plot {
                title: format!("largest relative error in {what}"),
                x_label: format!("relative error in {what} (log)"),
                y_label: "fraction of trials".into(),
                equal_aspect: false,
                log_x: true,
                layers,
                window: None,
            }
        };
        b.figure(Figure {
            id: format!("fig-{}", result.id.replace('/', "-")),
            claim: result.id.clone(),
            title: format!("Noise {}: error distributions", lv.level.text),
            caption: format!(
                "Empirical distributions of the worst edge's relative error over {} seeded trials per model (seed {}), and the paper's printed run.",
                self.trials, self.seed
            ),
            panels: vec![panel(0, "squares"), panel(2, "lengths")],
        });
        out.push(result);
        out
    }
}
