//! Tests of `orthocheck_core::derivations::dof`.

use nalgebra::{Rotation3, Vector3};
use orthocheck_core::derivations::dof::*;

/// Image coordinates as a function of the parameters around a float scene.
fn forward(points: &[[f64; 3]], rots: &[Rotation3<f64>], params: &[f64]) -> Vec<f64> {
    let p = points.len();
    let mut xs: Vec<Vector3<f64>> = points.iter().map(|x| Vector3::from(*x)).collect();
    xs[0].x += params[0];
    xs[0].y += params[1];
    for (j, x) in xs.iter_mut().enumerate().skip(1) {
        for d in 0..3 {
            x[d] += params[3 * j - 1 + d];
        }
    }
    let mut out = Vec::new();
    for (i, r) in rots.iter().enumerate() {
        let (rot, t) = if i == 0 {
            (*r, [0.0, 0.0])
        } else {
            let c = 3 * p - 1 + 5 * (i - 1);
            let w = Vector3::new(params[c], params[c + 1], params[c + 2]);
            (Rotation3::new(w) * r, [params[c + 3], params[c + 4]])
        };
        for x in &xs {
            let y = rot * x;
            out.push(y.x + t[0]);
            out.push(y.y + t[1]);
        }
    }
    out
}

#[test]
fn analytic_jacobian_matches_central_differences() {
    let scene = orthocheck_core::model::Scene::random(4, 3, 5);
    let points: Vec<[f64; 3]> = scene.body.points.iter().map(|x| [x.x, x.y, x.z]).collect();
    let rots: Vec<Rotation3<f64>> = std::iter::once(Rotation3::identity())
        .chain(scene.motions.iter().skip(1).map(|m| m.rotation))
        .collect();
    let mats: Vec<[[f64; 3]; 3]> = rots
        .iter()
        .map(|r| std::array::from_fn(|a| std::array::from_fn(|b| r[(a, b)])))
        .collect();
    let j = to_matrix(&jacobian_generic(&points, &mats));
    let n = j.ncols();
    let h = 1e-6;
    for c in 0..n {
        let mut plus = vec![0.0; n];
        let mut minus = vec![0.0; n];
        plus[c] = h;
        minus[c] = -h;
        let fp = forward(&points, &rots, &plus);
        let fm = forward(&points, &rots, &minus);
        for r in 0..j.nrows() {
            let fd = (fp[r] - fm[r]) / (2.0 * h);
            // central differences are O(h²) ≈ 1e-12 here, well inside 1e-8
            assert!(
                (fd - j[(r, c)]).abs() < 1e-8,
                "row {r} col {c}: {fd} vs {}",
                j[(r, c)]
            );
        }
    }
}

#[test]
fn the_grid_queries_on_both_sides() {
    let grid = table(4, 4, 1).unwrap();
    let f = |t: &str| orthocheck_core::algebra::Poly::parse(t).unwrap();
    assert!(formulas_count_the_jacobian(
        &grid,
        &f("-1+3*p+5*(k-1)"),
        &f("2*k*p")
    ));
    assert!(!formulas_count_the_jacobian(
        &grid,
        &f("-1+3*p+6*(k-1)"),
        &f("2*k*p")
    ));
    let (Some(p), Some(k)) = smallest_identifiable(&grid) else {
        panic!("nothing identifiable on the grid");
    };
    assert!(is_minimum(&grid, p, k));
    assert!(!is_minimum(&grid, p, k + 1) && !is_minimum(&grid, p, k - 1));
    assert!(!is_minimum(&grid, p - 1, k));
    assert!(deficient_for_every_p(&grid, 2));
    assert!(!deficient_for_every_p(&grid, 3));
}

#[test]
fn float_and_exact_ranks_agree_on_the_grid() {
    for r in table(5, 4, 3).unwrap() {
        assert_eq!(r.jacobian_rank, r.exact_rank, "{:?}", r.count);
        assert_eq!(r.parameters as i64, r.count.unknowns);
    }
}
