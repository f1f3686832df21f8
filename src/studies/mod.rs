//! Experiments: seeded censuses, rounding propagation, witness searches and the
//! reconstruction of the author's program. Studies return numbers, never text.

pub mod author_program;
pub mod identity_census;
pub mod panels;
pub mod two_frames;
