//! Tests of `orthocheck_core::studies::joint_fit::jacobian`.

use orthocheck_core::algebra::central_jacobian;
use orthocheck_core::derivations::rounding::RoundingBox;
use orthocheck_core::studies::joint_fit::jacobian::*;
use orthocheck_core::studies::joint_fit::scaled;
use orthocheck_core::studies::joint_fit::JointInput;
use orthocheck_core::studies::printed_matrix::RowMatch;

/// A body, three cameras and a figure and rows near (not at) their projections: the
/// analytic Jacobian agrees with the central-difference one.
#[test]
fn the_analytic_jacobian_matches_central_differences() {
    let edges: Vec<(f64, f64)> = [4.0, 9.0, 12.0, 20.0, 21.0, 18.0]
        .iter()
        .map(|s| (s - 0.01, s + 0.02))
        .collect();
    let figure = RoundingBox {
        center: (0..24).map(|i| (i as f64 * 0.37).sin() * 3.0).collect(),
        half: vec![0.005; 24],
    };
    let rows: Vec<[f64; 7]> = (0..4)
        .map(|i| std::array::from_fn(|j| (i * 7 + j) as f64 * 0.1))
        .collect();
    let half: Vec<[f64; 7]> = (0..4)
        .map(|i| std::array::from_fn(|j| if (i + j) % 3 == 0 { 0.0 } else { 0.005 }))
        .collect();
    let matches: Vec<RowMatch> = [([0, 1, 2], 1, 2), ([0, 3, 4], 2, 3), ([1, 4, 5], 3, 1)]
        .iter()
        .chain(&[([2, 3, 5], 1, 3)])
        .zip([1.0, -0.5, 2.0, -1.0])
        .map(|((triangle, first, second), factor)| RowMatch {
            triangle: *triangle,
            first: *first,
            second: *second,
            factor,
            deviation: 0.0,
        })
        .collect();
    let inp = JointInput {
        figure: &figure,
        rows: &rows,
        half: &half,
        edges: &edges,
    };
    let mut p = vec![0.3, -0.2, 0.5, 0.1, -0.4, 0.2];
    // the second camera's rotation vector is tiny: the series branch of J_l
    for c in [
        [0.4, -0.3, 1.1, 0.2, -0.1],
        [1e-3, 2e-3, -1e-3, 0.0, 0.5],
        [-1.5, 0.7, 0.2, 1.0, 0.3],
    ] {
        p.extend(c);
    }
    let f = |q: &[f64]| scaled(&inp, &matches, q);
    let fd =
        central_jacobian(&f, &p, |_, x| 1e-6 * x.abs().max(1.0)).unwrap_or_else(|| unreachable!());
    let an = scaled_jacobian(&inp, &matches, &p).unwrap_or_else(|| unreachable!());
    assert_eq!((fd.nrows(), fd.ncols()), (an.nrows(), an.ncols()));
    let scale = fd.amax();
    for (a, b) in an.iter().zip(fd.iter()) {
        assert!((a - b).abs() <= 1e-6 * scale, "{a} vs {b} (scale {scale})");
    }
}
