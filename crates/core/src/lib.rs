//! The mathematics behind orthocheck, a crate of its own so that it can be used (and
//! optimised) apart from the claims and the report built on it:
//!
//! - [`derivations`]: the paper's equations and solvers, one module per section;
//! - [`model`]: rigid point bodies, frames and orthographic projection;
//! - [`algebra`]: the exact polynomial engine (rational and modular arithmetic, expansion,
//!   elimination, root isolation);
//! - [`sfm`]: structure from motion for tracked points;
//! - [`studies`]: the seeded engines (Monte Carlo, censuses, rounding boxes, witness searches,
//!   the joint fit of §4's printed matrix);
//! - [`numfmt`], [`limits`] and [`error`]: the float formatter, the declared limits and the
//!   error type that every layer above shares.
//!
//! The `orthocheck` crate re-exports each module under the same name.

#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod algebra;
pub mod derivations;
pub mod error;
pub mod limits;
pub mod model;
pub mod numfmt;
pub mod sfm;
pub mod studies;

pub use error::{Error, Result};
