//! Tests of `orthocheck_core::algebra`.

mod float_roots;
mod interval;
mod modp;
mod mpoly;
mod perm;
mod poly;
mod rank;
mod ratfn;
mod sturm;
