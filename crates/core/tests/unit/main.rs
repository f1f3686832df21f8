//! The unit tests of `orthocheck-core`, one module per module of the library (as an
//! integration test they link the optimised library instead of compiling it a second time).

mod algebra;
/// Property tests of the exact and floating algebra.
mod algebra_props;
mod derivations;
mod limits;
mod model;
mod numfmt;
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

/// The library is built without `cfg(test)` (`[lib] test = false`): a test written inside it
/// would never run, so every unit test lives here.
#[test]
fn no_test_hides_in_the_library() {
    let mut stack = vec![std::path::PathBuf::from(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/src"
    ))];
    let mut read = 0;
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).unwrap().flatten() {
            let path = entry.path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == "rs") {
                let text = std::fs::read_to_string(&path).unwrap();
                for mark in ["#[test]", "#[cfg(test)]"] {
                    assert!(!text.contains(mark), "{} holds {mark}", path.display());
                }
                read += 1;
            }
        }
    }
    assert!(read >= 50, "only {read} files read");
}
