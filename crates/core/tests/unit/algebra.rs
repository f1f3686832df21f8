//! Tests of `orthocheck_core::algebra`.

mod cholesky;
mod float_roots;
mod integer;
mod interval;
mod mix;
mod modp;
mod mpoly;
mod multiquad;
mod perm;
mod poly;
mod rank;
mod ratfn;
mod student;
mod sturm;
