//! Experiments: everything seeded and repeated (Monte Carlo, censuses, rounding propagation,
//! witness searches, the reconstruction of the author's program). Studies return numbers and
//! exact values, never text.

pub mod audit;
pub mod author_program;
pub mod census;
pub mod drawn_member;
pub mod ex2;
pub mod ex2_restricted;
pub mod ex4;
pub mod ex4_joint;
pub mod family_samples;
pub mod figure_labels;
pub mod identity_census;
pub mod linearity;
pub mod noise;
pub mod noise_request;
pub mod panels;
pub mod points;
pub mod printed_matrix;
pub mod rounding;
pub mod solution_count;
pub mod two_frames;
pub mod twofold;
