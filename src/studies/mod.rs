//! Experiments: everything seeded and repeated. Studies return numbers and exact values,
//! never text.

pub mod audit;
pub mod family_samples;
pub mod noise;
pub mod noise_request;
pub mod points;
pub mod twofold;
