#![doc = include_str!("../README.md")]
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod cases;
pub mod check;
pub mod claims;
mod cli;
pub mod files;
pub mod input;
pub mod mathtext;
pub mod provenance;
pub mod report;
pub mod seeds;

pub use orthocheck_core::{algebra, derivations, error, limits, model, numfmt, sfm, studies};

pub use cli::run_command_line;
pub use error::{Error, Result};
