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

/// The true squared edges of a scene's body, in the solvers' edge order.
fn truth(scene: &orthocheck_core::model::Scene) -> Vec<f64> {
    orthocheck_core::derivations::solver::edges(scene.body.points.len())
        .iter()
        .map(|&(i, j)| scene.body.squared_distance(i, j))
        .collect()
}
