//! Tests of `orthocheck_core::derivations`.

mod appendix_a;
mod degenerate;
mod dof;
mod formulas;
mod fourth_relation;
mod identity;
mod noise;
mod p3f3;
mod p3f4;
mod p4f3;
mod scale;
mod two_frames;
mod twofold;
