#![doc = include_str!("../README.md")]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod algebra;
pub mod cases;
pub mod check;
pub mod claims;
pub mod derivations;
pub mod error;
pub mod input;
pub mod limits;
pub mod model;
pub mod numfmt;
pub mod provenance;
pub mod report;
pub mod seeds;
pub mod sfm;
pub mod studies;

pub use error::{Error, Result};
