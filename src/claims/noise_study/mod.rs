//! A noise study (§2, §3): the paper's statements about errors under noise.

mod case;
mod judge;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::rerun::NoiseRuns;
use crate::claims::ClaimKind;
use crate::derivations::noise::{LevelResult, Study};
use crate::error::Result;
use crate::studies::noise::{body_of, run_both};

impl ClaimKind for NoiseStudyCase {
    fn trials(&self) -> Vec<(&'static str, usize)> {
        vec![("trials", self.trials)]
    }

    fn validate(&self, v: &Validator) -> Result<()> {
        case::sizes(self, v)?;
        case::checks(self, v)
    }

    fn seeds(&self) -> Vec<u64> {
        vec![self.seed]
    }

    fn run(&self, b: &ResultBuilder, _earlier: &[ClaimResult]) -> Result<Vec<ClaimResult>> {
        judge::results(b, self)
    }

    fn noise_runs(&self) -> Option<Result<NoiseRuns>> {
        let levels = self.levels.iter().map(|l| l.level.to_f64()).collect();
        Some(study_of(self).map(|study| NoiseRuns { study, levels }))
    }
}

/// The study a noise case describes: its body, solver, frames, trials and seed.
pub fn study_of(case: &NoiseStudyCase) -> Result<Study> {
    let lengths: Vec<f64> = case.body.lengths.iter().map(|p| p.to_f64()).collect();
    let squares: Vec<f64> = case.body.squares.iter().map(|p| p.to_f64()).collect();
    Ok(Study {
        solver: case.solver,
        body: body_of(&lengths, &squares)?,
        frames: case.frames,
        trials: case.trials,
        seed: case.seed,
        motions: None,
    })
}

/// The studies a case asks for, one per level and noise model (coordinate model first).
pub fn run_study(case: &NoiseStudyCase) -> Result<Vec<[LevelResult; 2]>> {
    let study = study_of(case)?;
    let levels: Vec<f64> = case.levels.iter().map(|l| l.level.to_f64()).collect();
    Ok(run_both(&study, &levels))
}
