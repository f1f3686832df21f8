//! Experiments: seeded, repeated computations that return numbers, never text.

pub mod family_samples;
pub mod noise_request;
