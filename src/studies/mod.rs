//! Experiments: seeded Monte Carlo, censuses, rounding propagation, witness searches. Studies
//! return numbers, never text.

pub mod census;
pub mod ex2;
pub mod ex4;
pub mod printed_matrix;
pub mod rounding;
