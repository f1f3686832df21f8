//! Experiments: everything seeded and repeated (Monte Carlo, censuses, rounding propagation,
//! witness searches, the reconstruction of the author's program). Studies return numbers and
//! exact values, never text.

pub mod census;
pub mod exact_views;
pub mod family_samples;
pub mod identity;
pub mod joint_fit;
pub mod noise;
pub mod points;
pub mod printed_matrix;
pub mod rounding;
pub mod view_bounds;
