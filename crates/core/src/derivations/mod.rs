//! The paper, as code: one module per section or equation. Derivations compute; they never
//! read files, print, or know what the paper printed.

pub mod appendix_a;
pub mod degenerate;
pub mod dof;
pub mod formulas;
pub mod fourth_relation;
pub mod identity;
pub mod identity5;
pub mod noise;
pub mod p3f3;
pub mod p3f4;
pub mod p4f3;
pub mod rounding;
pub mod scale;
pub mod solver;
pub mod two_frames;
pub mod twofold;
