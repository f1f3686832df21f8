//! Tests of `orthocheck_core::sfm`.

mod gaps;
mod judge;
mod metric;
mod missing;
mod robust;
mod threshold;
