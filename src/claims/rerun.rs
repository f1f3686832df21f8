//! `orthocheck noise`: the noise runs a case offers ([`super::ClaimKind::noise_runs`]), rerun
//! with the user's levels, trials, seed and model in place of the case's own.

use crate::claims::PaperCase;
use crate::derivations::noise::{run_levels, LevelSummary, Study};
use crate::error::Error;

/// One of the two noise models of [`crate::derivations::noise::models`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModelChoice {
    /// Relative error on every image coordinate.
    RelativeCoordinate,
    /// Relative error on every projected length.
    RelativeLength,
}

impl ModelChoice {
    /// Its index in [`crate::derivations::noise::models`].
    pub fn index(self) -> usize {
        match self {
            ModelChoice::RelativeCoordinate => 0,
            ModelChoice::RelativeLength => 1,
        }
    }
}

/// What is asked: the case and the overrides (`None` or empty: the case's own).
#[derive(Clone, Debug, Default)]
pub struct NoiseRequest {
    /// The noise case's id.
    pub case: String,
    /// Relative error levels ε; empty for the case's levels.
    pub levels: Vec<f64>,
    /// Trials per level and model.
    pub trials: Option<usize>,
    /// Seed.
    pub seed: Option<u64>,
    /// One model only; both when `None`.
    pub model: Option<ModelChoice>,
}

/// Why a request cannot be run.
#[derive(Debug)]
pub enum RequestError {
    /// No case has the id.
    NoCase,
    /// The case has no noise runs.
    NotNoiseStudy,
    /// A level is negative, NaN or infinite.
    BadLevel(f64),
    /// The case's study could not be built.
    Study(Error),
}

/// A request resolved against the cases: the study and what to run of it.
#[derive(Clone, Debug)]
pub struct NoiseRun {
    /// The study, with the overrides applied.
    pub study: Study,
    /// The levels, in order.
    pub levels: Vec<f64>,
    /// One model only; both when `None`.
    pub model: Option<ModelChoice>,
}

/// What a case offers `orthocheck noise` ([`super::ClaimKind::noise_runs`]): its noise
/// study and the levels it prints.
#[derive(Clone, Debug)]
pub struct NoiseRuns {
    /// The study as the case runs it.
    pub study: Study,
    /// The printed levels ε, in order.
    pub levels: Vec<f64>,
}

impl NoiseRequest {
    /// Find the case and apply the overrides; checks in order: the case, its kind, its
    /// study, the levels.
    pub fn resolve(&self, cases: &[PaperCase]) -> Result<NoiseRun, RequestError> {
        let case = cases
            .iter()
            .find(|c| c.id == self.case)
            .ok_or(RequestError::NoCase)?;
        let NoiseRuns {
            mut study,
            levels: case_levels,
        } = case
            .check
            .kind()
            .noise_runs()
            .ok_or(RequestError::NotNoiseStudy)?
            .map_err(RequestError::Study)?;
        study.trials = self.trials.unwrap_or(study.trials);
        study.seed = self.seed.unwrap_or(study.seed);
        let levels: Vec<f64> = if self.levels.is_empty() {
            case_levels
        } else {
            self.levels.clone()
        };
        if let Some(&e) = levels.iter().find(|e| !(e.is_finite() && **e >= 0.0)) {
            return Err(RequestError::BadLevel(e));
        }
        Ok(NoiseRun {
            study,
            levels,
            model: self.model,
        })
    }
}

impl NoiseRun {
    /// Whether model index `m` runs.
    pub fn keeps(&self, m: usize) -> bool {
        self.model.is_none_or(|c| c.index() == m)
    }

    /// Trials in the whole run (for progress).
    pub fn total_trials(&self) -> usize {
        let models = (0..2).filter(|m| self.keeps(*m)).count();
        models * self.levels.len() * self.study.trials
    }

    /// Run every level under the kept models, level by level; `progress` receives finished
    /// trial counts. The streams are the report's, so the results agree with it.
    pub fn run(&self, progress: &(dyn Fn(usize) + Sync)) -> Vec<LevelSummary> {
        run_levels(&self.study, &self.levels, |m| self.keeps(m), progress)
            .iter()
            .map(|r| r.summary())
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cases() -> Vec<PaperCase> {
        let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/paper_cases");
        crate::cases::load_all::<crate::claims::CaseCheck>(std::path::Path::new(dir)).unwrap()
    }

    /// The first case with noise runs, or without.
    fn first(cases: &[PaperCase], noise: bool) -> String {
        let is_noise = |c: &&PaperCase| c.check.kind().noise_runs().is_some();
        let c = cases.iter().find(|c| is_noise(c) == noise).unwrap();
        c.id.clone()
    }

    #[test]
    fn the_checks_come_in_order() {
        let all = cases();
        let ask = |case: String, levels: Vec<f64>| NoiseRequest {
            case,
            levels,
            ..NoiseRequest::default()
        };
        let no_such = format!("{}-no-such", first(&all, true));
        assert!(matches!(
            ask(no_such, vec![]).resolve(&all),
            Err(RequestError::NoCase)
        ));
        assert!(matches!(
            ask(first(&all, false), vec![-1.0]).resolve(&all),
            Err(RequestError::NotNoiseStudy)
        ));
        assert!(matches!(
            ask(first(&all, true), vec![0.0, f64::NAN]).resolve(&all),
            Err(RequestError::BadLevel(e)) if e.is_nan()
        ));
    }

    #[test]
    fn overrides_replace_the_case_values() {
        let all = cases();
        let run = NoiseRequest {
            case: first(&all, true),
            levels: vec![0.0, 0.01],
            trials: Some(7),
            seed: Some(9),
            model: Some(ModelChoice::RelativeLength),
        }
        .resolve(&all)
        .unwrap();
        assert_eq!((run.study.trials, run.study.seed), (7, 9));
        assert!(run.keeps(1) && !run.keeps(0));
        assert_eq!(run.total_trials(), 2 * 7);
    }
}
