//! The figure of one noise level: per noise model, the distribution of the relative error over
//! the edges, in percent as the paper speaks of it, with the printed run and the paper's bound
//! drawn as vertical lines, the points where the judge reads each curve marked, and a caption
//! that says in the judge's numbers why the level holds or fails.

use super::judge::Readings;
use super::{Direction, NoiseLevel};
use crate::check::figure::{ecdf, percent_text, Figure, Layer, Plot, Shape, Style};
use crate::check::noise::{any_model, on_run, parts, Claim, Decision, Judged, Part, TYPICAL_BAND};
use crate::check::ClaimResult;
use crate::derivations::noise::LevelResult;
use crate::numfmt::sig;
use crate::numfmt::{sampled_digits, sig_digits};

/// Steps drawn per distribution.
const STEPS: usize = 200;

/// Relative errors are drawn in percent.
const PERCENT: f64 = 100.0;

/// Where the bound's label sits, as a fraction of the trials: at the top of the curves.
const LABEL_AT: f64 = 1.0;

/// The key's name of the printed run's line.
const RUN: &str = "the paper's test run";

/// The figure `fig-<id>` of the level whose result is `result`: `setting` the scene in words
/// ("three points, four frames"), `j` the claim as judged, `study` (trials, seed).
pub(super) fn figure(
    result: &ClaimResult,
    setting: &str,
    (lv, j, reading): (&NoiseLevel, &Judged, &Readings),
    study: (usize, u64),
) -> Figure {
    let bound = bound_layer(lv, j.claim);
    let panels = drawn_metrics(j.facts.metric)
        .into_iter()
        .map(|m| panel(m, j, bound.as_ref()))
        .collect();
    Figure {
        id: format!("fig-{}", result.id.replace('/', "-")),
        claim: result.id.clone(),
        title: format!(
            "§{} ({setting}): noise up to {} %",
            result.section,
            percent_text(&lv.level)
        ),
        caption: caption(result, (lv, j, reading), study),
        panels,
    }
}

/// The metrics drawn, one panel each: the largest error in squares and in lengths, and the
/// reading the claim is judged on when it is neither (a mean over the edges).
fn drawn_metrics(judged: usize) -> Vec<usize> {
    let mut v = vec![0, 2];
    if !v.contains(&judged) {
        v.push(judged);
    }
    v
}

/// Metric `m` in words: how the edges' errors combine, and what is compared.
fn metric_words(m: usize) -> (&'static str, &'static str) {
    (
        if m.is_multiple_of(2) {
            "largest"
        } else {
            "mean"
        },
        if m < 2 { "squares" } else { "lengths" },
    )
}

fn direction_word(d: Direction) -> &'static str {
    match d {
        Direction::Below => "below",
        Direction::Above => "above",
    }
}

/// The paper's bound in its words, as the case transcribes it ("below 5 %").
fn bound_words(lv: &NoiseLevel) -> Option<String> {
    let st = lv.statement.as_ref()?;
    Some(format!(
        "{} {} %",
        direction_word(st.direction),
        percent_text(&st.bound)
    ))
}

/// The paper's bound as a vertical line labelled with its words; `None` for a level where the
/// paper gives no number. Wide and pale beneath the printed run, which may lie on it.
fn bound_layer(lv: &NoiseLevel, claim: Claim) -> Option<Layer> {
    let (words, bound) = (bound_words(lv)?, claim.bound()?);
    let label = format!("paper: {words}");
    Some(
        Layer::new(
            &format!("the paper's bound: error {words}"),
            Shape::Verticals,
            Style::Printed,
            vec![[PERCENT * bound, LABEL_AT]],
        )
        .labelled(&[label.as_str()])
        .beneath(),
    )
}

/// The panel of metric `m`: each model's distribution, the paper's bound, the printed run;
/// in the panel of the reading judged, the points where the judge reads each curve.
fn panel(m: usize, j: &Judged, bound: Option<&Layer>) -> Plot {
    let mut layers: Vec<Layer> = j
        .facts
        .dists
        .iter()
        .enumerate()
        .map(|(k, r)| {
            let steps = ecdf(&r.sorted[m], STEPS)
                .into_iter()
                .map(|[x, y]| [PERCENT * x, y])
                .collect();
            Layer::new(&series_name(&r.model), Shape::Line, Style::series(k), steps)
        })
        .collect();
    layers.extend(bound.cloned());
    if let Some(e) = j.facts.run {
        layers.push(Layer::new(
            RUN,
            Shape::Verticals,
            Style::Mark,
            vec![[PERCENT * e.metrics[m], 0.5]],
        ));
    }
    let judged = m == j.facts.metric;
    if judged {
        layers.extend(read_points(j));
    }
    let (how, what) = metric_words(m);
    Plot {
        title: format!(
            "{how} error in {what}{}",
            if judged { " (judged)" } else { "" }
        ),
        x_label: format!("{how} relative error in {what}, x (%, log scale)"),
        y_label: "fraction of trials with error ≤ x".into(),
        equal_aspect: false,
        log_x: true,
        log_y: false,
        layers,
        window: None,
    }
}

/// Per model, the point of its curve the judge reads, in the curve's own name and style: the
/// median trial (its error, at one half) for a claim on the median, the printed run's error
/// at its percentile rank otherwise.
fn read_points(j: &Judged) -> Vec<Layer> {
    let m = j.facts.metric;
    j.facts
        .dists
        .iter()
        .zip(parts(j.claim, &j.facts))
        .enumerate()
        .filter_map(|(k, (r, p))| {
            let at = match j.claim {
                Claim::Median(..) => [r.quantile(m, 0.5)?, 0.5],
                Claim::Typical | Claim::Example(..) => [j.facts.run?.metrics[m], p.rank?],
            };
            Some(Layer::new(
                &series_name(&r.model),
                Shape::Points,
                Style::series(k),
                vec![[PERCENT * at[0], at[1]]],
            ))
        })
        .collect()
}

/// What the figure draws, then why the level holds or fails, then the failed trials.
fn caption(
    result: &ClaimResult,
    (lv, j, reading): (&NoiseLevel, &Judged, &Readings),
    study: (usize, u64),
) -> String {
    let (trials, seed) = study;
    let (how, what) = metric_words(j.facts.metric);
    let also = if drawn_metrics(j.facts.metric).len() > 2 {
        format!(", and the {how} error in {what}")
    } else {
        String::new()
    };
    let lines = if bound_words(lv).is_some() {
        "the paper's printed test run and, wide and pale, the paper's bound"
    } else {
        "the paper's printed test run"
    };
    let mut s = format!(
        "For each noise model, the fraction of its successful trials whose error is at most x: the largest relative error over the edges in squared lengths and in lengths{also}, over {trials} seeded trials per model (seed {seed}). The vertical lines are {lines}; in the panel marked judged, a marker on each curve is where the judge reads it. {}",
        why(lv, j, sampled_digits(trials as u64), reading.metrics.len() == 1 && reading.extra.is_empty())
    );
    s.push_str(&other_readings(j, reading));
    if result.verdict != reading.decision().verdict() {
        s.push_str(&format!(
            " Its verdict is nevertheless {}: the negative control could not have failed it.",
            result.verdict.name()
        ));
    }
    let failures: Vec<String> = j
        .facts
        .dists
        .iter()
        .map(|r| {
            format!(
                "{} of {} with {}",
                r.failures,
                r.trials,
                series_name(&r.model)
            )
        })
        .collect();
    s.push_str(&format!(
        " Failed trials (no real solution with non-negative squares: {}) are not in the curves.",
        failures.join(", ")
    ));
    s
}

/// The readings the sentence leaves open besides the one drawn, and what they decide
/// together (empty when the sentence names its reading).
fn other_readings(j: &Judged, reading: &Readings) -> String {
    let others = reading.metrics.get(1..).unwrap_or(&[]);
    if others.is_empty() && reading.extra.is_empty() {
        return String::new();
    }
    let mut text = String::new();
    if !others.is_empty() {
        // a metric is (quantity, combination): 2·quantity + combination
        let one_quantity = reading.metrics.iter().all(|m| m / 2 == j.facts.metric / 2);
        let one_combination = reading.metrics.iter().all(|m| m % 2 == j.facts.metric % 2);
        let open = match (one_quantity, one_combination) {
            (true, _) => "how the edges' errors combine",
            (_, true) => "whether it means squares or lengths",
            _ => "whether it means squares or lengths, nor how the edges' errors combine",
        };
        let each: Vec<String> = others
            .iter()
            .map(|&m| {
                let (how, what) = metric_words(m);
                format!(
                    "{} as the {how} error in {what}",
                    decision_words(reading.all[m].decision)
                )
            })
            .collect();
        text = format!(
            " The sentence does not say {open}: under the other readings it {}",
            join_and(&each)
        );
    }
    if !reading.extra.is_empty() {
        let each: Vec<String> = reading
            .extra
            .iter()
            .map(|x| {
                let (how, what) = metric_words(x.facts.metric);
                format!(
                    "{} as the median trial's {how} error in {what}",
                    decision_words(x.decision)
                )
            })
            .collect();
        let lead = if text.is_empty() {
            " The sentence"
        } else {
            "; it"
        };
        text.push_str(&format!(
            "{lead} may also speak of the trials, not the printed run: there it {}",
            join_and(&each)
        ));
    }
    let split = reading.read().any(|x| x.decision != reading.decision());
    let end = match reading.decision() {
        Decision::TooClose if split => {
            "the readings disagree, so the claim is too close to call".to_string()
        }
        d => format!("so the claim {} under every reading", decision_words(d)),
    };
    format!("{text}; {end}.")
}

/// Why the level holds or fails, in the judge's numbers (`digits` significant digits);
/// `alone` when the sentence has this one reading.
fn why(lv: &NoiseLevel, j: &Judged, digits: usize, alone: bool) -> String {
    let f = &j.facts;
    let m = f.metric;
    let (how, what) = metric_words(m);
    let pc = |x: f64| format!("{} %", sig_digits(PERCENT * x, digits));
    let ps = parts(j.claim, f);
    let ranks = ranks_text(f.dists, &ps, digits);
    let band = band_words(any_model(ps.iter().map(|p| p.decision)));
    let between = format!(
        "between percentiles {} and {}",
        sig(PERCENT * TYPICAL_BAND.0),
        sig(PERCENT * TYPICAL_BAND.1)
    );
    let verdict = if alone {
        decision_words(j.decision).to_string()
    } else {
        format!("{} in this reading", decision_words(j.decision))
    };
    match (j.claim, f.run, bound_words(lv)) {
        (Claim::Median(..), _, Some(said)) => {
            let medians: Vec<String> = f
                .dists
                .iter()
                .filter_map(|r| {
                    let q = r.quantile(m, 0.5)?;
                    Some(format!("{} with {}", pc(q), series_name(&r.model)))
                })
                .collect();
            format!(
                "The paper says the typical trial's error is {said}, judged by the median trial's {how} error in {what}: it is {}, and the bound is at percentile {ranks}. The median must lie on the paper's side of the bound under one model at least: the claim {verdict}.",
                join_and(&medians)
            )
        }
        (Claim::Example(bound, d), Some(run), Some(said)) => format!(
            "The paper says its run's error is {said}: the run's {how} error in {what} is {}{}, so the bound {}; the run lies at percentile {ranks} (typical: {between} under one model), so it is {band}. The claim {verdict}.",
            pc(run.metrics[m]),
            range_text(run.ranges[m], digits),
            decision_words(on_run(f, bound, d))
        ),
        (Claim::Typical, Some(run), _) => format!(
            "The paper gives no number at this level: its run is judged typical when it lies {between} of the trials under one model. The run's {how} error in {what}, {}, lies at percentile {ranks}, so it is {band}. The claim {verdict}.",
            pc(run.metrics[m])
        ),
        _ => format!(
            "The printed run cannot be read as the study's quantities, so the judge has nothing to read: the claim {verdict}."
        ),
    }
}

/// An error's range over the rounding of the printed digits, when the digits shown differ.
fn range_text(range: (f64, f64), digits: usize) -> String {
    let (lo, hi) = (
        sig_digits(PERCENT * range.0, digits),
        sig_digits(PERCENT * range.1, digits),
    );
    if lo == hi {
        String::new()
    } else {
        format!(" ({lo}–{hi} % over the rounding of its printed digits)")
    }
}

/// Each model's rank of the value the judge reads, in percent: "39.2 with errors in
/// coordinates and 31.4 with errors in lengths".
fn ranks_text(dists: &[LevelResult], parts: &[Part], digits: usize) -> String {
    let each: Vec<String> = dists
        .iter()
        .zip(parts)
        .filter_map(|(r, p)| {
            Some(format!(
                "{} with {}",
                sig_digits(PERCENT * p.rank?, digits),
                series_name(&r.model)
            ))
        })
        .collect();
    join_and(&each)
}

fn join_and(v: &[String]) -> String {
    match v.split_last() {
        None => String::new(),
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
    }
}

fn decision_words(d: Decision) -> &'static str {
    match d {
        Decision::Holds => "holds",
        Decision::Fails => "fails",
        Decision::TooClose => "is too close to call",
    }
}

fn band_words(d: Decision) -> &'static str {
    match d {
        Decision::Holds => "typical",
        Decision::Fails => "not typical under any model",
        Decision::TooClose => "too near the band's edge to call",
    }
}

/// A noise model's series name, short and in the paper's words ("errors of up to x %" of
/// the coordinates or of the lengths).
fn series_name(model: &str) -> String {
    model
        .replace("relative-coordinate", "errors in coordinates")
        .replace("relative-length", "errors in lengths")
        .replace(" at the paper's scene", ", paper's scene")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_judged_mean_gets_its_own_panel() {
        assert_eq!(drawn_metrics(0), vec![0, 2]);
        assert_eq!(drawn_metrics(2), vec![0, 2]);
        assert_eq!(drawn_metrics(3), vec![0, 2, 3]);
        assert_eq!(metric_words(3), ("mean", "lengths"));
        assert_eq!(metric_words(0), ("largest", "squares"));
    }

    #[test]
    fn lists_read_as_prose() {
        let v = |s: &[&str]| s.iter().map(|x| x.to_string()).collect::<Vec<_>>();
        assert_eq!(join_and(&v(&[])), "");
        assert_eq!(join_and(&v(&["a"])), "a");
        assert_eq!(join_and(&v(&["a", "b", "c"])), "a, b and c");
        assert_eq!(range_text((0.1, 0.1), 3), "");
        assert_eq!(
            range_text((0.0611, 0.0622), 3),
            " (6.11–6.22 % over the rounding of its printed digits)"
        );
    }
}
