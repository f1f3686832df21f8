//! Exact solution counts of three and four points in three orthographic views, at seeded
//! random rational scenes (rational body, rational rotations from Cayley's parametrisation, so
//! every image coordinate is an exact rational): the real edge-length solutions, the
//! structure-and-motion solutions up to rigid motion, and the complex degree of each system by
//! elimination over ℚ, with Sturm counts of the real roots.
//!
//! Three points (§2.2): the squared edges x = a², y = b², z = c² solve the three frames'
//! twofold-squared equations; the signed depth differences of frame i are sᵢ = ±√(x − aᵢ²)
//! and dᵢ = (z − cᵢ² − (x − aᵢ²) − (y − bᵢ²)) / (2sᵢ) (the loop sᵢ + dᵢ + eᵢ = 0 squared), so a
//! structure-and-motion solution (gauge: frame 1's rotation and P fixed) is a root z with one
//! sign per frame: the rotation into frame i is then unique. The polynomial whose roots are
//! t = Σ kᵢ sᵢ over all solutions is obtained by eliminating each sᵢ (a resultant with
//! sᵢ² − wᵢ) and then z (the norm from ℚ\[z\]/(q)); its square-free degree counts the complex
//! solutions, its Sturm count the real ones.

use num_rational::BigRational;
use num_traits::{One, Signed, Zero};
use rand::Rng;

use crate::algebra::{Poly, UPoly};
use crate::derivations::p3f3::{exact_elimination, exact_elimination_parts};

mod lines;
mod p4;
pub use lines::{lines_first_count, LinesFirst};
pub use p4::{p4f3_count, P4f3Count, P4f3Instance};

/// A scene in exact rational coordinates: points, proper rotations, orthographic images.
#[derive(Clone, Debug, PartialEq)]
pub struct RationalScene {
    /// The body's points.
    pub points: Vec<[BigRational; 3]>,
    /// One rotation per frame (rows), exactly orthogonal with determinant 1.
    pub rotations: Vec<[[BigRational; 3]; 3]>,
}

/// Numerators of point coordinates and Cayley vectors are drawn from `−SPREAD ..= SPREAD`.
pub const SPREAD: i64 = 12;
/// Denominators from `1 ..= DENOMINATOR`.
pub const DENOMINATOR: i64 = 7;

fn draw(r: &mut impl Rng) -> BigRational {
    BigRational::new(
        r.random_range(-SPREAD..=SPREAD).into(),
        r.random_range(1..=DENOMINATOR).into(),
    )
}

/// The rotation of the unit quaternion (1, p, q, r)/‖·‖ (Cayley's parametrisation): rational
/// for rational p, q, r, and proper.
pub fn cayley(v: &[BigRational; 3]) -> [[BigRational; 3]; 3] {
    let [p, q, r] = v;
    let one = BigRational::one();
    let two = BigRational::from_integer(2.into());
    let n = &one + p * p + q * q + r * r;
    let e = |x: BigRational| x / &n;
    [
        [
            e(&one + p * p - q * q - r * r),
            e(&two * (p * q - r)),
            e(&two * (p * r + q)),
        ],
        [
            e(&two * (p * q + r)),
            e(&one - p * p + q * q - r * r),
            e(&two * (q * r - p)),
        ],
        [
            e(&two * (p * r - q)),
            e(&two * (q * r + p)),
            e(&one - p * p - q * q + r * r),
        ],
    ]
}

/// Matrix product of two exact 3×3 matrices.
pub fn mat_mul(a: &[[BigRational; 3]; 3], b: &[[BigRational; 3]; 3]) -> [[BigRational; 3]; 3] {
    std::array::from_fn(|i| {
        std::array::from_fn(|j| (0..3).fold(BigRational::zero(), |s, k| s + &a[i][k] * &b[k][j]))
    })
}

impl RationalScene {
    /// A seeded generic scene of `points` points in `frames` frames.
    pub fn random(points: usize, frames: usize, seed: u64) -> RationalScene {
        let mut r = crate::model::rng(seed);
        let points = (0..points)
            .map(|_| std::array::from_fn(|_| draw(&mut r)))
            .collect();
        let rotations = (0..frames)
            .map(|_| cayley(&std::array::from_fn(|_| draw(&mut r))))
            .collect();
        RationalScene { points, rotations }
    }

    /// The image of point `j` in frame `i`: the first two coordinates of Rᵢ Pⱼ.
    pub fn image(&self, i: usize, j: usize) -> [BigRational; 2] {
        let (r, p) = (&self.rotations[i], &self.points[j]);
        std::array::from_fn(|row| (0..3).fold(BigRational::zero(), |s, k| s + &r[row][k] * &p[k]))
    }

    /// The squared image length of the edge {j, k} in frame `i`.
    pub fn projected_square(&self, i: usize, j: usize, k: usize) -> BigRational {
        let (a, b) = (self.image(i, j), self.image(i, k));
        (0..2).fold(BigRational::zero(), |s, c| {
            let d = &a[c] - &b[c];
            s + &d * &d
        })
    }

    /// The true squared length of the edge {j, k}.
    pub fn squared_edge(&self, j: usize, k: usize) -> BigRational {
        (0..3).fold(BigRational::zero(), |s, c| {
            let d = &self.points[j][c] - &self.points[k][c];
            s + &d * &d
        })
    }

    /// The first three frames' projected squares of the edges PQ, QR, RP.
    pub fn triangle_squares(&self) -> [[BigRational; 3]; 3] {
        std::array::from_fn(|i| {
            [(0, 1), (1, 2), (2, 0)].map(|(j, k)| self.projected_square(i, j, k))
        })
    }
}

/// The exact counts at one three-point instance.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct P3f3Instance {
    /// Seed of the scene.
    pub seed: u64,
    /// Degree of the univariate polynomial in c² after elimination (`None`: the linear part
    /// is singular, the system is not zero-dimensional).
    pub edge_degree: Option<usize>,
    /// Its square-free degree: complex edge-length solutions.
    pub edge_complex: usize,
    /// Distinct real roots (Sturm).
    pub edge_real: usize,
    /// Real roots at which every depth² of every frame is positive (decided exactly).
    pub edge_feasible: usize,
    /// Whether the true squared edges are a root.
    pub truth_is_root: bool,
    /// Degree of the structure-and-motion polynomial in t = Σ kᵢ sᵢ.
    pub sm_degree: usize,
    /// Its square-free degree: complex structure-and-motion solutions (gauge fixed).
    pub sm_complex: usize,
    /// Its distinct real roots (Sturm): real solutions.
    pub sm_real: usize,
    /// Whether it is even (the global reflection t ↦ −t maps solutions to solutions).
    pub sm_even: bool,
    /// Square-free degree in t²: complex solutions up to the global reflection.
    pub sm_up_to_reflection: usize,
}

/// The exact counts over seeded three-point instances, and a degenerate one.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct P3f3Count {
    /// One entry per instance.
    pub instances: Vec<P3f3Instance>,
    /// The same count with frame 3 = frame 2 turned in its image plane (the paper's "two
    /// frames identical up to rotation"): `None` when the system is not zero-dimensional.
    pub identical_frames_edge_degree: Option<usize>,
}

/// Square-free degree of a non-zero univariate polynomial: deg p − deg gcd(p, p′).
pub fn square_free_degree(p: &UPoly) -> usize {
    let d = p.degree().unwrap_or(0);
    if p.is_square_free() {
        return d;
    }
    d - p.gcd(&p.derivative()).degree().unwrap_or(0)
}

/// A polynomial without `name` (a constant in it) as a rational.
fn constant_of(p: &Poly) -> BigRational {
    p.terms()
        .next()
        .map(|(_, k)| k)
        .unwrap_or_else(BigRational::zero)
}

/// A polynomial in `t` only, as a [`UPoly`].
fn to_upoly(p: &Poly, t: &str) -> UPoly {
    UPoly::new(p.coefficients_in(t).iter().map(constant_of).collect())
}

/// Eliminate `s` from `p` against s² = w: the resultant Res_s(p, s² − w) = A(w)² − w·B(w)²
/// where p = A(s²) + s·B(s²).
pub fn eliminate_square_root(p: &Poly, s: &str, w: &Poly) -> Poly {
    let (mut a, mut b) = (Poly::zero(), Poly::zero());
    let mut power = Poly::int(1);
    for (e, c) in p.coefficients_in(s).iter().enumerate() {
        if e % 2 == 0 && e > 0 {
            power = &power * w;
        }
        let term = c * &power;
        if e % 2 == 0 {
            a = &a + &term;
        } else {
            b = &b + &term;
        }
    }
    &(&a * &a) - &(&(w * &b) * &b)
}

/// The norm of `p(t, z)` over the roots of `q(z)` (degree 1 or 2): Π over q's roots of p(t, zⱼ),
/// as a polynomial in t. Degree 2: p ≡ U + zV mod q, norm U² + (z₁+z₂)UV + z₁z₂V².
pub fn norm_over(p: &Poly, z: &str, q: &UPoly, t: &str) -> Option<UPoly> {
    let c = q.coeffs();
    match q.degree()? {
        1 => Some(to_upoly(
            &p.substitute(z, &Poly::constant(-&c[0] / &c[1])),
            t,
        )),
        2 => {
            // z^k ≡ α_k z + β_k mod q
            let (sum, prod) = (-&c[1] / &c[2], &c[0] / &c[2]);
            let (mut alpha, mut beta) = (BigRational::zero(), BigRational::one());
            let (mut u, mut v) = (Poly::zero(), Poly::zero());
            for coeff in p.coefficients_in(z) {
                u = &u + &coeff.scale(&beta);
                v = &v + &coeff.scale(&alpha);
                let next_alpha = &beta + &alpha * &sum;
                beta = -(&alpha * &prod);
                alpha = next_alpha;
            }
            let n = &(&(&u * &u) + &(&u * &v).scale(&sum)) + &(&v * &v).scale(&prod);
            Some(to_upoly(&n, t))
        }
        _ => None,
    }
}

/// Π over every sign pattern of (t − Σ kᵢ sᵢ) with sᵢ² = wᵢ, as a polynomial in t and the
/// variables of the wᵢ.
pub fn sign_pattern_polynomial(ws: &[Poly], k: &[i64]) -> Poly {
    let names: Vec<String> = (0..ws.len()).map(|i| format!("s{}", i + 1)).collect();
    let mut p = Poly::var("t");
    for (name, ki) in names.iter().zip(k) {
        p = &p - &Poly::var(name).scale(&BigRational::from_integer((*ki).into()));
    }
    for (name, w) in names.iter().zip(ws) {
        p = eliminate_square_root(&p, name, w);
    }
    p
}

/// Separating weights tried in turn: the count is the largest square-free degree found,
/// and it is exact once it reaches the product's degree.
pub const WEIGHTS: [[i64; 3]; 3] = [[1, 2, 3], [1, 3, 7], [2, 5, 11]];

/// Whether the linear w = s·z + c is positive at the real root `root` of `q` (exact: the
/// isolating interval is refined until it excludes the zero of w; `None` if q vanishes there).
fn positive_at(w: &Poly, root: &crate::algebra::RealRoot, q: &UPoly) -> Option<bool> {
    let cs = w.coefficients_in("z");
    let c0 = cs
        .first()
        .map(constant_of)
        .unwrap_or_else(BigRational::zero);
    let c1 = cs.get(1).map(constant_of).unwrap_or_else(BigRational::zero);
    if c1.is_zero() {
        return Some(c0.is_positive());
    }
    let zero = -&c0 / &c1;
    if q.eval(&zero).is_zero() {
        return None;
    }
    let mut r = root.clone();
    while r.lo() <= zero && zero <= r.hi() {
        let half = r.width() / BigRational::from_integer(2.into());
        r.refine(&half);
    }
    // w has the sign of c1 above its zero
    Some((r.lo() > zero) == c1.is_positive())
}

/// Count one three-point instance exactly.
pub fn p3f3_instance(scene: &RationalScene, seed: u64) -> Option<P3f3Instance> {
    let l = scene.triangle_squares();
    let (q, xz, yz) = exact_elimination_parts(&l)?;
    let zz = Poly::var("z");
    let depths: Vec<Vec<Poly>> = (0..3)
        .map(|i| {
            [&xz, &yz, &zz]
                .iter()
                .zip(&l[i])
                .map(|(e, p)| *e - &Poly::constant(p.clone()))
                .collect()
        })
        .collect();
    let roots = q.real_roots();
    let edge_feasible = roots
        .iter()
        .filter(|r| {
            depths
                .iter()
                .flatten()
                .all(|w| positive_at(w, r, &q) == Some(true))
        })
        .count();
    let truth = scene.squared_edge(2, 0);
    let ws: Vec<Poly> = depths.iter().map(|d| d[0].clone()).collect();
    let mut best: Option<UPoly> = None;
    for k in WEIGHTS {
        let p = norm_over(&sign_pattern_polynomial(&ws, &k), "z", &q, "t")?;
        let better = best
            .as_ref()
            .is_none_or(|b| square_free_degree(&p) > square_free_degree(b));
        if better {
            best = Some(p);
        }
        if best.as_ref().map(square_free_degree) == best.as_ref().and_then(UPoly::degree) {
            break;
        }
    }
    let p = best?;
    Some(P3f3Instance {
        seed,
        edge_degree: q.degree(),
        edge_complex: square_free_degree(&q),
        edge_real: roots.len(),
        edge_feasible,
        truth_is_root: q.eval(&truth).is_zero(),
        sm_degree: p.degree().unwrap_or(0),
        sm_complex: square_free_degree(&p),
        sm_real: p.real_roots().len(),
        sm_even: p.coeffs().iter().skip(1).step_by(2).all(Zero::is_zero),
        sm_up_to_reflection: square_free_degree(&even_part(&p)),
    })
}

/// The polynomial Q with P(t) = Q(t²), from the even coefficients of P.
fn even_part(p: &UPoly) -> UPoly {
    UPoly::new(p.coeffs().iter().step_by(2).cloned().collect())
}

/// Count `instances` seeded three-point scenes (seeds `seed`, `seed + 1`, …) and the
/// identical-frames degenerate scene.
pub fn p3f3_count(instances: usize, seed: u64) -> P3f3Count {
    use rayon::prelude::*;
    let instances = (0..instances as u64)
        .into_par_iter()
        .filter_map(|t| {
            let s = seed.wrapping_add(t);
            p3f3_instance(&RationalScene::random(3, 3, s), s)
        })
        .collect();
    let mut same = RationalScene::random(3, 3, seed);
    let turn = cayley(&[
        BigRational::zero(),
        BigRational::zero(),
        BigRational::new(2.into(), 5.into()),
    ]);
    same.rotations[2] = mat_mul(&turn, &same.rotations[1]);
    let identical_frames_edge_degree = exact_elimination(&same.triangle_squares())
        .filter(|q| !q.is_zero())
        .and_then(|q| q.degree());
    P3f3Count {
        instances,
        identical_frames_edge_degree,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cayley_rotations_are_exactly_orthogonal() {
        let s = RationalScene::random(3, 3, 4);
        for r in &s.rotations {
            let mut rt = r.clone();
            for i in 0..3 {
                for j in 0..3 {
                    rt[i][j] = r[j][i].clone();
                }
            }
            let id = mat_mul(r, &rt);
            for (i, row) in id.iter().enumerate() {
                for (j, x) in row.iter().enumerate() {
                    assert_eq!(x.is_one(), i == j);
                    assert_eq!(x.is_zero(), i != j);
                }
            }
        }
    }

    #[test]
    fn eliminating_a_square_root_gives_the_product_over_both_signs() {
        // t − s with s² = 4: (t − 2)(t + 2)
        let p = &Poly::var("t") - &Poly::var("s");
        let r = eliminate_square_root(&p, "s", &Poly::int(4));
        assert_eq!(to_upoly(&r, "t"), UPoly::from_i64(&[-4, 0, 1]));
    }

    #[test]
    fn three_points_have_two_edge_and_sixteen_motion_solutions() {
        let i = p3f3_instance(&RationalScene::random(3, 3, 11), 11).unwrap();
        assert_eq!(
            (i.edge_complex, i.sm_complex, i.sm_up_to_reflection),
            (2, 16, 8)
        );
        assert!(i.truth_is_root && i.sm_even);
        assert_eq!(i.sm_real, 8 * i.edge_feasible);
    }
}
