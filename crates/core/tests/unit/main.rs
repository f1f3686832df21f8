//! The unit tests of `orthocheck-core`, one module per module of the library (as an
//! integration test they link the optimised library instead of compiling it a second time).

mod algebra;
/// Property tests of the exact and floating algebra.
mod algebra_props;
mod derivations;
mod limits;
mod model;
mod sfm;
/// Property tests of the solvers on seeded random scenes, generic and degenerate.
mod solver_props;
mod studies;
