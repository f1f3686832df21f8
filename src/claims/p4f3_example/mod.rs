//! §4's worked example: four points in three frames.

mod case;
pub mod joint;
mod judge;
pub mod study;

pub use case::*;

use crate::cases::Validator;
use crate::check::{ClaimResult, ResultBuilder};
use crate::claims::rerun::NoiseRuns;
use crate::claims::ClaimKind;
use crate::derivations::noise::Study;
use crate::error::Result;
use crate::model::StudySolver;
use crate::studies::noise::body_of;

impl ClaimKind for P4f3ExampleCase {
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

    /// §4's printed runs: the edge table's body under random motions, as the report runs them.
    fn noise_runs(&self) -> Option<Result<NoiseRuns>> {
        let squares: Vec<f64> = self.body.squares.iter().map(|s| s.to_f64()).collect();
        let levels = self.noise.iter().map(|l| l.level.to_f64()).collect();
        Some(body_of(&[], &squares).map(|body| NoiseRuns {
            study: Study {
                solver: StudySolver::P4f3,
                body,
                frames: 3,
                trials: self.trials,
                seed: self.seed,
                motions: None,
            },
            levels,
        }))
    }
}
