//! Tests of `orthocheck_core::sfm`.

mod covariance;
mod gaps;
mod judge;
mod metric;
mod missing;
mod robust;
mod threshold;
