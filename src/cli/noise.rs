//! `orthocheck noise`: a paper case's noise study with the user's levels, trials and seed.

use std::fmt::Write as _;
use std::path::PathBuf;

use crate::claims::rerun::{ModelChoice, NoiseRequest, RequestError};
use crate::claims::{CaseCheck, PaperCase};
use crate::derivations::noise::LevelSummary;
use crate::{cases, Error};
use clap::ValueEnum;

use super::emit;

/// Arguments of `noise`.
#[derive(clap::Args)]
pub struct Args {
    /// The noise study's id: ex2-noise (§2) or ex3-noise (§3), or another noise study in
    /// --cases (an unknown id lists them).
    #[arg(long)]
    case: String,
    /// Relative error levels ε, comma-separated (default: the case's).
    #[arg(long, value_delimiter = ',')]
    levels: Vec<f64>,
    /// Trials per level and model (default: the case's).
    #[arg(long, allow_negative_numbers = true)]
    trials: Option<usize>,
    /// Seed (default: the case's).
    #[arg(long, allow_negative_numbers = true, value_parser = super::SeedParser)]
    seed: Option<u64>,
    /// Noise model (default: both).
    #[arg(long, value_enum)]
    model: Option<ModelArg>,
    /// Folder of case files, instead of the paper's cases built into the binary.
    #[arg(long)]
    cases: Option<PathBuf>,
    /// Largest trial count accepted (docs/limits.md); memory stays fixed, time grows.
    #[arg(long, allow_negative_numbers = true, default_value_t = crate::limits::NOISE_TRIALS)]
    max_trials: usize,
    /// JSON output.
    #[arg(long)]
    json: bool,
}

/// The noise models, as the command line names them.
#[derive(Clone, Copy, ValueEnum)]
enum ModelArg {
    RelativeCoordinate,
    RelativeLength,
}

impl From<ModelArg> for ModelChoice {
    fn from(m: ModelArg) -> ModelChoice {
        match m {
            ModelArg::RelativeCoordinate => ModelChoice::RelativeCoordinate,
            ModelArg::RelativeLength => ModelChoice::RelativeLength,
        }
    }
}

/// Resolve the request against the cases, run it with a trial counter on a terminal, print.
pub fn run(a: Args) -> Result<(), Error> {
    check_limits(&a).map_err(Error::InvalidInput)?;
    let origin = cases::CaseOrigin::from_arg(a.cases.as_deref());
    let all = cases::load_cases::<CaseCheck>(&origin)?;
    let request = NoiseRequest {
        case: a.case.clone(),
        levels: a.levels,
        trials: a.trials,
        seed: a.seed,
        model: a.model.map(ModelChoice::from),
    };
    let study = request.resolve(&all).map_err(|e| match e {
        RequestError::NoCase => Error::InvalidInput(format!(
            "no case `{}` in {}; {}",
            a.case,
            origin.describe(),
            noise_ids(&all)
        )),
        RequestError::NotNoiseStudy => Error::InvalidInput(format!(
            "case `{}` has no noise runs; {}",
            a.case,
            noise_ids(&all)
        )),
        RequestError::BadLevel(e) => {
            Error::InvalidInput(format!("--levels: {e} is not a finite ε ≥ 0"))
        }
        RequestError::Study(e) => e,
    })?;
    let bar = super::progress::bar(study.total_trials() as u64, "trials");
    let summaries = study.run(&|n: usize| bar.inc(n as u64));
    bar.finish_and_clear();
    emit(a.json, &summaries, |s| noise_text(&a.case, s))?;
    Ok(())
}

/// The ids `--case` accepts, as a sentence for an error.
fn noise_ids(all: &[PaperCase]) -> String {
    let ids: Vec<&str> = all
        .iter()
        .filter(|c| c.check.kind().noise_runs().is_some())
        .map(|c| c.id.as_str())
        .collect();
    if ids.is_empty() {
        "no case has noise runs".into()
    } else {
        format!("the cases with noise runs are: {}", ids.join(", "))
    }
}

/// `noise` as text: one table per level and model, a row per metric, a column per quantile
/// and the mean; each column as wide as its widest cell, two spaces apart.
fn noise_text(case: &str, rows: &[LevelSummary]) -> String {
    use crate::numfmt::sig;
    let pct = |x: f64| format!("{}%", sig(100.0 * x));
    let mut t = format!("noise study {case}: relative errors against the truth\n");
    for r in rows {
        let _ = writeln!(
            t,
            "\nε = {} ({}): {} trials, {} without a usable real solution",
            sig(r.level),
            r.model,
            r.trials,
            r.failures
        );
        let Some(first) = r.metrics.first() else {
            t.push_str("  no trial gave a usable solution: nothing to summarise\n");
            continue;
        };
        let mut table: Vec<Vec<String>> = vec![std::iter::once("metric".to_string())
            .chain(first.quantiles.iter().map(|q| pct(q.q)))
            .chain(std::iter::once("mean".to_string()))
            .collect()];
        for m in &r.metrics {
            table.push(
                std::iter::once(m.metric.to_string())
                    .chain(m.quantiles.iter().map(|q| pct(q.value)))
                    .chain(std::iter::once(pct(m.mean)))
                    .collect(),
            );
        }
        t.push_str(&columns(&table));
    }
    t
}

/// Rows of cells as fixed-width columns: the first left-aligned, the rest right-aligned,
/// each as wide as its widest cell, two spaces apart; every line indented by two.
fn columns(table: &[Vec<String>]) -> String {
    let n = table.iter().map(Vec::len).max().unwrap_or(0);
    let widths: Vec<usize> = (0..n)
        .map(|j| {
            table
                .iter()
                .filter_map(|row| row.get(j))
                .map(|c| c.chars().count())
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut s = String::new();
    for row in table {
        let mut line = String::from("  ");
        for (j, (cell, w)) in row.iter().zip(widths.iter().copied()).enumerate() {
            if j == 0 {
                let _ = write!(line, "{cell:<w$}");
            } else {
                let _ = write!(line, "  {cell:>w$}");
            }
        }
        s.push_str(line.trim_end());
        s.push('\n');
    }
    s
}

/// Trials, levels and ε within `docs/limits.md` before the cases are read.
fn check_limits(a: &Args) -> Result<(), String> {
    use crate::limits::{at_most, count, noise_level, NOISE_LEVELS};
    if let Some(t) = a.trials {
        count("--trials", t, a.max_trials).map_err(|m| format!("{m}; --max-trials raises it"))?;
    }
    at_most("the number of --levels", a.levels.len(), NOISE_LEVELS)?;
    a.levels
        .iter()
        .try_for_each(|&e| noise_level("--levels", e))
}
