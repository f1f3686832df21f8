//! `orthocheck noise`: a paper case's noise study with the user's levels, trials and seed.

use std::path::PathBuf;

use clap::ValueEnum;
use orthocheck::studies::noise_request::{ModelChoice, NoiseRequest, RequestError};
use orthocheck::{cases, report, Error};

use super::emit;

/// Arguments of `noise`.
#[derive(clap::Args)]
pub struct Args {
    /// The noise case's id (e.g. ex2-noise, ex3-noise).
    #[arg(long)]
    case: String,
    /// Relative error levels ε, comma-separated (default: the case's).
    #[arg(long, value_delimiter = ',')]
    levels: Vec<f64>,
    /// Trials per level and model (default: the case's).
    #[arg(long)]
    trials: Option<usize>,
    /// Seed (default: the case's).
    #[arg(long)]
    seed: Option<u64>,
    /// Noise model (default: both).
    #[arg(long, value_enum)]
    model: Option<ModelArg>,
    /// Folder of case files.
    #[arg(long, default_value = "paper_cases")]
    cases: PathBuf,
    /// Largest trial count accepted (docs/limits.md); memory stays fixed, time grows.
    #[arg(long, default_value_t = orthocheck::limits::NOISE_TRIALS)]
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
    let all = cases::load_all(&a.cases)?;
    let request = NoiseRequest {
        case: a.case.clone(),
        levels: a.levels,
        trials: a.trials,
        seed: a.seed,
        model: a.model.map(ModelChoice::from),
    };
    let study = request.resolve(&all).map_err(|e| match e {
        RequestError::NoCase => {
            Error::InvalidInput(format!("no case `{}` in {}", a.case, a.cases.display()))
        }
        RequestError::NotNoiseStudy => {
            Error::InvalidInput(format!("case `{}` is not a noise study", a.case))
        }
        RequestError::BadLevel(e) => {
            Error::InvalidInput(format!("--levels: {e} is not a finite ε ≥ 0"))
        }
        RequestError::Study(e) => e,
    })?;
    let bar = super::progress::bar(study.total_trials() as u64, "trials");
    let summaries = study.run(&|n: usize| bar.inc(n as u64));
    bar.finish_and_clear();
    emit(a.json, &summaries, |s| report::noise_text(&a.case, s))?;
    Ok(())
}

/// Trials, levels and ε within `docs/limits.md` before the cases are read.
fn check_limits(a: &Args) -> Result<(), String> {
    use orthocheck::limits::{at_most, count, noise_level, NOISE_LEVELS};
    if let Some(t) = a.trials {
        count("--trials", t, a.max_trials).map_err(|m| format!("{m}; --max-trials raises it"))?;
    }
    at_most("the number of --levels", a.levels.len(), NOISE_LEVELS)?;
    a.levels
        .iter()
        .try_for_each(|&e| noise_level("--levels", e))
}
