//! Tests of `orthocheck_core::studies::view_bounds`: brackets against sampled exact views of
//! a seeded body.

use nalgebra::Vector3;
use orthocheck_core::derivations::p3f3::solve_core;
use orthocheck_core::model::{random_rotation, rng, squared_lengths};
use orthocheck_core::studies::exact_views::{rigidity, solve_ry};
use orthocheck_core::studies::rounding::RoundingBox;
use orthocheck_core::studies::view_bounds::*;
use rand::Rng;

/// A triangle's squares (PQ², QR², RP²) and three seeded views of it rounded to two
/// decimals, P at the exact origin.
fn figure(seed: u64) -> ([f64; 3], RoundingBox) {
    let tri = [
        Vector3::zeros(),
        Vector3::new(2.2, 0.0, 0.0),
        Vector3::new(1.1, 3.4, 0.0),
    ];
    let body = [0.0, 1.0, 2.0].map(|i: f64| {
        let (a, b) = (tri[i as usize], tri[(i as usize + 1) % 3]);
        (a - b).norm_squared()
    });
    let mut g = rng(seed);
    let (mut center, mut half) = (Vec::new(), Vec::new());
    for _ in 0..3 {
        let r = random_rotation(&mut g);
        for (k, p) in tri.iter().enumerate() {
            let y = r * p;
            let h = if k == 0 { 0.0 } else { 0.005 };
            center.extend([(y.x * 100.0).round() / 100.0, (y.y * 100.0).round() / 100.0]);
            half.extend([h, h]);
        }
    }
    (body, RoundingBox { center, half })
}

/// Seeded exact views rounding to the figure: per frame (qx, qy, rx) uniform until ry,
/// solved, lands in its rounding.
fn samples(body: [f64; 3], b: &RoundingBox, n: usize) -> Vec<Vec<f64>> {
    let mut g = rng(7);
    let mut out = Vec::new();
    'sample: for _ in 0..n {
        let mut x = b.center.clone();
        for f in 0..3 {
            let view = (0..10_000).find_map(|_| {
                let mut u = |k: usize| b.center[k] + g.random_range(-b.half[k]..=b.half[k]);
                let (qx, qy, rx) = (u(6 * f + 2), u(6 * f + 3), u(6 * f + 4));
                let (c, h) = (b.center[6 * f + 5], b.half[6 * f + 5]);
                let y = solve_ry(body, [qx, qy], rx, c - h, c + h)
                    .first()
                    .copied()?;
                Some([qx, qy, rx, y])
            });
            let Some(v) = view else { break 'sample };
            x[6 * f + 2..6 * f + 6].copy_from_slice(&v);
        }
        out.push(x);
    }
    out
}

/// The other solution (the one farther from the body) at flat coordinates `x`.
fn other(body: [f64; 3], x: &[f64]) -> Option<[f64; 3]> {
    let l: [[f64; 3]; 3] = std::array::from_fn(|f| {
        let pts: Vec<[f64; 2]> = (0..3)
            .map(|j| [x[6 * f + 2 * j], x[6 * f + 2 * j + 1]])
            .collect();
        let s = squared_lengths(&pts);
        [s[0], s[1], s[2]]
    });
    let c = solve_core(&l);
    let d = |v: &[f64; 3]| (0..3).map(|e| (v[e] - body[e]).abs()).fold(0.0, f64::max);
    (c.count == 2 && c.imag[0][0] == 0.0).then(|| {
        if d(&c.squares[0]) > d(&c.squares[1]) {
            c.squares[0]
        } else {
            c.squares[1]
        }
    })
}

/// The separation of the other solution from the body in c² at a sampled view.
fn sampled_separation(body: [f64; 3], x: &[f64]) -> f64 {
    other(body, x).map_or(f64::NAN, |o| o[2] - body[2])
}

#[test]
fn a_proven_positive_separation_is_below_every_sampled_view() {
    let (body, b) = figure(9);
    let v = Views::new(&b, body).unwrap_or_else(|| unreachable!());
    let e = separation(&v);
    assert!(e.proves_distinct() && !e.maximum && e.proven > 0.0, "{e:?}");
    let views = samples(body, &b, 300);
    assert_eq!(views.len(), 300);
    for x in &views {
        let s = sampled_separation(body, x);
        assert!(s >= e.proven, "sampled {s} below the proven {}", e.proven);
    }
}

#[test]
fn a_proven_negative_separation_is_above_every_sampled_view_and_attained_at_one() {
    let (body, b) = figure(2);
    let v = Views::new(&b, body).unwrap_or_else(|| unreachable!());
    let e = separation(&v);
    let attained = e.attained.unwrap_or(f64::NAN);
    assert!(
        e.proves_distinct() && e.maximum && attained <= e.proven,
        "{e:?}"
    );
    let views = samples(body, &b, 30);
    assert_eq!(views.len(), 30);
    for x in &views {
        let s = sampled_separation(body, x);
        assert!(s <= e.proven, "sampled {s} above the proven {}", e.proven);
    }
    // the attained end is an exact view inside the figure's rounding
    let at = e.at.unwrap_or_default();
    assert_eq!(at.len(), 18);
    for f in 0..3 {
        let (q, r) = (
            [at[6 * f + 2], at[6 * f + 3]],
            [at[6 * f + 4], at[6 * f + 5]],
        );
        let miss = [1.0, -1.0]
            .iter()
            .filter_map(|s| rigidity(body, q, r, *s))
            .fold(f64::INFINITY, |m, v| m.min(v.abs()));
        assert!(miss < 1e-9, "frame {f}: rigidity off by {miss}");
        for k in 2..6 {
            assert!((at[6 * f + k] - b.center[6 * f + k]).abs() <= b.half[6 * f + k]);
        }
    }
}

#[test]
fn a_separation_taking_both_signs_proves_nothing() {
    // seed 11: the sampled views put the other solution on both sides of the body in c²
    let (body, b) = figure(11);
    let s: Vec<f64> = samples(body, &b, 300)
        .iter()
        .map(|x| sampled_separation(body, x))
        .collect();
    assert!(s.iter().any(|v| *v > 0.0) && s.iter().any(|v| *v < 0.0));
    let v = Views::new(&b, body).unwrap_or_else(|| unreachable!());
    let e = separation(&v);
    // decided by a view on the far side of 0, not by the budget
    assert!(
        !e.proves_distinct() && e.maximum && e.attained.is_some_and(|a| a >= 0.0),
        "{e:?}"
    );
    assert!(e.cells < 2 * CELL_BUDGET);
}

#[test]
fn distinct_solutions_need_a_proven_bound_beyond_0_and_a_view() {
    let e = |maximum: bool, proven: f64, attained: Option<f64>| Extreme {
        maximum,
        proven,
        attained,
        at: None,
        cells: 1,
    };
    assert!(e(false, 0.01, Some(0.1)).proves_distinct());
    assert!(e(true, -0.01, Some(-0.1)).proves_distinct());
    // a minimum's bound below 0 proves nothing, whatever view was found
    assert!(!e(false, -0.1, Some(-0.01)).proves_distinct());
    assert!(!e(false, 0.0, Some(0.1)).proves_distinct());
    assert!(!e(true, 0.01, Some(0.1)).proves_distinct());
    assert!(!e(false, 0.01, None).proves_distinct());
}

#[test]
fn a_figure_without_p_at_the_exact_origin_or_of_another_size_has_no_views() {
    let (body, mut b) = figure(9);
    b.half[0] = 0.005;
    assert!(Views::new(&b, body).is_none());
    let empty = RoundingBox {
        center: Vec::new(),
        half: Vec::new(),
    };
    assert!(Views::new(&empty, body).is_none());
}
