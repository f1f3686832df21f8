//! Tests of `orthocheck_core::sfm`.

mod covariance;
mod gaps;
mod groups;
mod judge;
mod metric;
mod missing;
mod pipeline;
mod robust;
mod threshold;
