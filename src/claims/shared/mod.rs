//! Case schema pieces more than one kind reads.

pub mod census;
mod noise;
pub(crate) mod rank;
mod tables;

pub use census::{CensusCase, CensusException};
pub use noise::*;
pub use tables::{body_digits, BodyTable, FigureFrames, PrintedSolutions};
