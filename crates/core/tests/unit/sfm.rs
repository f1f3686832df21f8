//! Tests of `orthocheck_core::sfm`.

mod gaps;
mod judge;
mod metric;
mod robust;
mod threshold;
