//! What more than one kind reads: case schema pieces (censuses, printed tables, places of
//! audit items, noise statements) and the judge of a printed noise level.

pub mod census;
mod noise;
mod place;
pub(crate) mod rank;
mod tables;

pub use census::{CensusDesign, CensusException};
pub use noise::*;
pub use place::Place;
pub use tables::{body_digits, BodyTable, FigureFrames, PrintedSolutions};
