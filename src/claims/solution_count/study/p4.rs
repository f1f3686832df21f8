//! Four points in three views (§4), exactly: the paper's 6×6 system over ℚ (its rank and
//! solution), then the depth-sign patterns that a proper rotation realises.
//!
//! Frame i's depths relative to P: hQ = sᵢ with sᵢ² = wᵢ = PQ² − (projected PQ)², and for
//! j = R, T the edge Qj gives hⱼ = rⱼ sᵢ / (2wᵢ) with rⱼ = wⱼ + wᵢ − (Qj² − projected Qj²).
//! The body in frame i, Xᵢ = [(Δx, Δy, h) of Q, R, T], has the same Gram matrix in every frame,
//! so Xᵢ = Rᵢ X₁ with Rᵢ orthogonal; Rᵢ is a rotation exactly when det Xᵢ = det X₁, and
//! det Xᵢ = κᵢ sᵢ with κᵢ rational. Of the 2³ sign patterns, those with κᵢ sᵢ = κ₁ s₁ remain:
//! two (the reflection pair) when the body is not planar, all eight when it is (κ = 0).

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::{sign_pattern_polynomial, square_free_degree, to_upoly, RationalScene, WEIGHTS};
use crate::algebra::{exact_rank, exact_solve, Poly, UPoly};
use crate::derivations::p3f3::exact_equations;
use crate::derivations::p4f3::PAPER_TRIANGLES;
use crate::model::edges;

/// The exact counts at one four-point instance.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct P4f3Instance {
    /// Seed of the scene.
    pub seed: u64,
    /// Exact rank of the paper's 6×6 system.
    pub edge_rank: usize,
    /// Whether its unique solution is the true squared edges (false when singular).
    pub truth_is_solution: bool,
    /// Whether every frame's depths, from the sign of hQ alone, realise all six edges.
    pub depths_consistent: bool,
    /// Depth-sign patterns (of 2³, frame 1 included) realised by proper rotations.
    pub sm_patterns: usize,
    /// Degree of the structure-and-motion polynomial in t = Σ kᵢ sᵢ.
    pub sm_degree: usize,
    /// Its square-free degree: complex structure-and-motion solutions (gauge fixed).
    pub sm_complex: usize,
    /// Its distinct real roots (Sturm).
    pub sm_real: usize,
}

/// The counts over seeded four-point instances and over planar bodies (the control).
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct P4f3Count {
    /// Generic instances.
    pub instances: Vec<P4f3Instance>,
    /// The same count for bodies made planar (T moved into the plane PQR).
    pub planar: Vec<P4f3Instance>,
}

/// The paper's system over ℚ (rows: frames 2, 3 × triangles PQT, QRT, RPT) as `A x = b`.
fn paper_system(s: &RationalScene) -> (Vec<Vec<BigRational>>, Vec<BigRational>) {
    let e = edges(4);
    let (mut a, mut b) = (Vec::new(), Vec::new());
    let lin = ["x", "y", "z"];
    for frame in [1, 2] {
        for tri in PAPER_TRIANGLES {
            let l: [[BigRational; 3]; 3] =
                std::array::from_fn(|i| tri.map(|k| s.projected_square(i, e[k].0, e[k].1)));
            let f = exact_equations(&l);
            let d = &f[frame] - &f[0];
            let mut row = vec![BigRational::zero(); 6];
            let mut rest = d.clone();
            for (v, col) in lin.iter().zip(tri) {
                let cs = rest.coefficients_in(v);
                row[col] = cs.get(1).map(super::constant_of).unwrap_or_default();
                rest = cs.into_iter().next().unwrap_or_default();
            }
            a.push(row);
            b.push(-super::constant_of(&rest));
        }
    }
    (a, b)
}

/// κᵢ, wᵢ and whether frame i's depths realise every edge, for the squared edges `sq`
/// (indexed by point pair).
fn frame_orientation(
    s: &RationalScene,
    i: usize,
    sq: &dyn Fn(usize, usize) -> BigRational,
) -> (BigRational, BigRational, bool) {
    let two = BigRational::from_integer(2.into());
    let depth2 = |j: usize, k: usize| sq(j, k) - s.projected_square(i, j, k);
    let w = depth2(0, 1);
    if w.is_zero() {
        return (BigRational::zero(), w, false);
    }
    // hⱼ = ρⱼ · s with ρ_Q = 1
    let rho = |j: usize| (depth2(0, j) + &w - depth2(1, j)) / (&two * &w);
    let (r2, r3) = (rho(2), rho(3));
    let ok = &r2 * &r2 * &w == depth2(0, 2)
        && &r3 * &r3 * &w == depth2(0, 3)
        && (&r2 - &r3) * (&r2 - &r3) * &w == depth2(2, 3);
    let p0 = s.image(i, 0);
    let d = |j: usize| {
        let pj = s.image(i, j);
        [&pj[0] - &p0[0], &pj[1] - &p0[1]]
    };
    let (q, r, t) = (d(1), d(2), d(3));
    let one = BigRational::from_integer(1.into());
    let kappa = &q[0] * (&r[1] * &r3 - &t[1] * &r2) - &q[1] * (&r[0] * &r3 - &t[0] * &r2)
        + &one * (&r[0] * &t[1] - &r[1] * &t[0]);
    (kappa, w, ok)
}

/// Count one four-point instance exactly.
pub fn p4f3_instance(s: &RationalScene, seed: u64) -> P4f3Instance {
    let (a, b) = paper_system(s);
    let (edge_rank, _) = exact_rank(&a);
    let e = edges(4);
    let truth: Vec<BigRational> = e.iter().map(|&(j, k)| s.squared_edge(j, k)).collect();
    let solved = (edge_rank == 6).then(|| exact_solve(&a, &b)).flatten();
    let truth_is_solution = solved.as_ref() == Some(&truth);
    // the depths are counted at the system's solution, or at the truth when it is singular
    let x = solved.unwrap_or(truth);
    let sq = |j: usize, k: usize| {
        let idx = e
            .iter()
            .position(|&(u, v)| (u, v) == (j, k) || (v, u) == (j, k));
        idx.map(|n| x[n].clone()).unwrap_or_default()
    };
    let frames: Vec<_> = (0..3).map(|i| frame_orientation(s, i, &sq)).collect();
    let depths_consistent = frames.iter().all(|f| f.2);
    let sign = |v: &BigRational| i8::from(v.is_positive()) - i8::from(v.is_negative());
    let sm_patterns = (0..8u8)
        .filter(|m| {
            let eps = |i: usize| if m >> i & 1 == 1 { -1 } else { 1 };
            (1..3).all(|i| eps(i) * sign(&frames[i].0) == eps(0) * sign(&frames[0].0))
        })
        .count();
    let p = motion_polynomial(&frames);
    P4f3Instance {
        seed,
        edge_rank,
        truth_is_solution,
        depths_consistent,
        sm_patterns,
        sm_degree: p.degree().unwrap_or(0),
        sm_complex: square_free_degree(&p),
        sm_real: p.real_roots().len(),
    }
}

/// The polynomial in t = Σ kᵢ sᵢ over the structure-and-motion solutions: with κ ≠ 0,
/// sᵢ = (κ₁/κᵢ) s₁ and s₁² = w₁, so t² = μ² w₁; with κ = 0 (planar) every sign pattern.
fn motion_polynomial(frames: &[(BigRational, BigRational, bool)]) -> UPoly {
    let k = WEIGHTS[0];
    if frames.iter().all(|f| !f.0.is_zero()) {
        let mu = (0..3).fold(BigRational::zero(), |m, i| {
            m + BigRational::from_integer(k[i].into()) * &frames[0].0 / &frames[i].0
        });
        return UPoly::new(vec![
            -(&mu * &mu * &frames[0].1),
            Zero::zero(),
            num_traits::One::one(),
        ]);
    }
    let ws: Vec<Poly> = frames.iter().map(|f| Poly::constant(f.1.clone())).collect();
    to_upoly(&sign_pattern_polynomial(&ws, &k), "t")
}

/// Count `instances` seeded four-point scenes and as many planar ones.
pub fn p4f3_count(instances: usize, seed: u64) -> P4f3Count {
    let run = |planar: bool| {
        (0..instances as u64)
            .map(|t| {
                let sd = seed.wrapping_add(t);
                let mut s = RationalScene::random(4, 3, sd);
                if planar {
                    // T = P + (Q − P)/3 + 2(R − P)/5: in the plane PQR
                    let (p, q, r) = (&s.points[0], &s.points[1], &s.points[2]);
                    let third = BigRational::new(1.into(), 3.into());
                    let two_fifths = BigRational::new(2.into(), 5.into());
                    s.points[3] = std::array::from_fn(|c| {
                        &p[c] + (&q[c] - &p[c]) * &third + (&r[c] - &p[c]) * &two_fifths
                    });
                }
                p4f3_instance(&s, sd)
            })
            .collect()
    };
    P4f3Count {
        instances: run(false),
        planar: run(true),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn four_points_have_one_edge_and_two_motion_solutions() {
        let c = p4f3_count(2, 21);
        for i in &c.instances {
            assert_eq!(
                (i.edge_rank, i.sm_patterns, i.sm_complex, i.sm_real),
                (6, 2, 2, 2)
            );
            assert!(i.truth_is_solution && i.depths_consistent);
        }
        for i in &c.planar {
            assert_eq!((i.edge_rank, i.sm_patterns, i.sm_complex), (5, 8, 8));
        }
    }
}
