//! Experiments: everything seeded and repeated (noise studies, censuses, rounding boxes,
//! witnesses); studies return numbers, never text.

pub mod noise;
