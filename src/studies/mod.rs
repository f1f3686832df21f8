//! Experiments: everything seeded and repeated (Monte Carlo, censuses, rounding propagation,
//! witness searches). Studies return numbers and exact values, never text.

pub mod audit;
pub mod census;
pub mod ex2;
pub mod ex4;
pub mod family_samples;
pub mod noise;
pub mod noise_request;
pub mod points;
pub mod printed_matrix;
pub mod rounding;
pub mod twofold;
