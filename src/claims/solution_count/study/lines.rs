//! Ullman's lines-first construction for three points in three orthographic views, exactly:
//! the branches Knill and Ramirez-Herran count, and their map onto the reconstructions.
//!
//! Two image planes meet in a line through the body's centre. Projected onto it, the body
//! looks the same in both images: with the images of Q − P and R − P as the columns of Aᵢ,
//! a unit 2-vector v in image i and w in image j with vᵀAᵢ = wᵀAⱼ, so w = Nv with
//! N = (AᵢAⱼ⁻¹)ᵀ, and |w| = |v| asks vᵀ(NᵀN − I)v = 0: a quadratic form on the circle, whose
//! real null lines (two when its discriminant Δ is positive) give two unit directions each.
//! A branch picks one signed direction per camera pair (4³ = 64 when every Δ > 0).
//!
//! A choice of one line per pair fixes the three intersection lines u₁₂, u₁₃, u₂₃ up to
//! sign: their Gram matrix G is read off the images (u₁₂·u₁₃ in image 1, and so on), the
//! projections s = Uᵀe of an edge e onto them too, and |e|² = sᵀG⁻¹s. Every quantity is
//! homogeneous of degree zero in each direction's length, so the directions need no
//! normalising, and they lie in ℚ(√Δ₁₂, √Δ₁₃, √Δ₂₃), where the arithmetic and every sign
//! are exact ([`Multiquad`]). The choice gives a real body exactly when G is positive
//! definite, and then two, mirror images of each other.

use std::rc::Rc;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use super::{constant_of, RationalScene};
use crate::algebra::{rat, Multiquad, MultiquadField, Poly, UPoly};

type M2 = [[BigRational; 2]; 2];
type V2 = [Multiquad; 2];

/// The camera pairs, in the order of the branches.
pub const PAIRS: [(usize, usize); 3] = [(0, 1), (0, 2), (1, 2)];

/// The lines-first construction at one three-point instance.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct LinesFirst {
    /// Seed of the scene.
    pub seed: u64,
    /// Real lines of each camera pair (0, 1 or 2); `None` when every line is one (the two
    /// images congruent).
    pub lines: [Option<usize>; 3],
    /// Signed directions, one per pair: ∏ 2·lines.
    pub branches: usize,
    /// Choices of one line per pair.
    pub choices: usize,
    /// Choices whose Gram matrix is positive definite: real bodies up to the reflection.
    pub real_choices: usize,
    /// Real choices per real root of the polynomial in c², lowest root first.
    pub per_root: Vec<usize>,
    /// Whether every real choice's squared edges solve the paper's system exactly (c² a root
    /// of its polynomial, a² and b² its linear part at c²).
    pub edges_solve: bool,
    /// Whether the scene's own intersection lines are one of the choices.
    pub truth_among: bool,
}

/// Aᵢ: the images of Q − P and R − P in frame `i`, as columns.
fn differences(s: &RationalScene, i: usize) -> M2 {
    let p = s.image(i, 0);
    let col = |k: usize| {
        let x = s.image(i, k);
        [&x[0] - &p[0], &x[1] - &p[1]]
    };
    let (a, b) = (col(1), col(2));
    [[a[0].clone(), b[0].clone()], [a[1].clone(), b[1].clone()]]
}

fn mul(a: &M2, b: &M2) -> M2 {
    std::array::from_fn(|i| std::array::from_fn(|j| &a[i][0] * &b[0][j] + &a[i][1] * &b[1][j]))
}

fn transpose(a: &M2) -> M2 {
    std::array::from_fn(|i| std::array::from_fn(|j| a[j][i].clone()))
}

fn inverse(a: &M2) -> Option<M2> {
    let det = &a[0][0] * &a[1][1] - &a[0][1] * &a[1][0];
    if det.is_zero() {
        return None;
    }
    Some([
        [&a[1][1] / &det, -&a[0][1] / &det],
        [-&a[1][0] / &det, &a[0][0] / &det],
    ])
}

/// N = (AᵢAⱼ⁻¹)ᵀ, carrying a direction of image i to the same line's in image j.
fn carry(s: &RationalScene, i: usize, j: usize) -> Option<M2> {
    Some(transpose(&mul(
        &differences(s, i),
        &inverse(&differences(s, j))?,
    )))
}

/// The form NᵀN − I, and its discriminant q₀₁² − q₀₀q₁₁.
fn form(n: &M2) -> (M2, BigRational) {
    let mut f = mul(&transpose(n), n);
    f[0][0] -= rat(1, 1);
    f[1][1] -= rat(1, 1);
    let disc = &f[0][1] * &f[0][1] - &f[0][0] * &f[1][1];
    (f, disc)
}

/// The real null lines of the form, as directions over `field` (`root`: √Δ in it), or `None`
/// when the form vanishes.
fn null_lines(
    f: &M2,
    disc: &BigRational,
    field: &Rc<MultiquadField>,
    root: usize,
) -> Option<Vec<V2>> {
    let c = |x: &BigRational| Multiquad::constant(field, x.clone());
    if f.iter().flatten().all(Zero::is_zero) {
        return None;
    }
    if disc.is_negative() {
        return Some(Vec::new());
    }
    let (a, b, d) = (&f[0][0], &f[0][1], &f[1][1]);
    if a.is_zero() {
        // v₁(2b·v₀ + d·v₁) = 0
        let mut lines = vec![[c(&rat(1, 1)), c(&rat(0, 1))]];
        if !b.is_zero() {
            lines.push([c(d), c(&(-b * rat(2, 1)))]);
        }
        return Some(lines);
    }
    // a v₀² + 2b v₀v₁ + d v₁² = 0 at v = (−b ± √Δ, a)
    if disc.is_zero() {
        return Some(vec![[c(&-b), c(a)]]);
    }
    let r = Multiquad::root(field, root);
    Some(
        [&r, &-&r]
            .map(|sr| [&c(&-b) + sr, c(a)])
            .into_iter()
            .collect(),
    )
}

fn dot(a: &V2, b: &V2) -> Multiquad {
    &(&a[0] * &b[0]) + &(&a[1] * &b[1])
}

fn apply(n: &M2, v: &V2) -> V2 {
    std::array::from_fn(|i| &v[0].scale(&n[i][0]) + &v[1].scale(&n[i][1]))
}

fn project(v: &V2, d: &[BigRational; 2]) -> Multiquad {
    &v[0].scale(&d[0]) + &v[1].scale(&d[1])
}

/// The Gram matrix of the three lines and the three edges' projections onto them, for one
/// line per pair (`v[p]`: the direction of pair `p` in its first image).
struct Choice {
    gram: [[Multiquad; 3]; 3],
    edges: [[Multiquad; 3]; 3],
}

fn choice(s: &RationalScene, carries: &[M2; 3], v: [&V2; 3]) -> Choice {
    let w: [V2; 3] = std::array::from_fn(|p| apply(&carries[p], v[p]));
    // u₀₁·u₀₂ in image 0, u₀₁·u₁₂ in image 1, u₀₂·u₁₂ in image 2
    let (g01, g02, g12) = (dot(v[0], v[1]), dot(&w[0], v[2]), dot(&w[1], &w[2]));
    let diag: [Multiquad; 3] = std::array::from_fn(|p| dot(v[p], v[p]));
    let gram = [
        [diag[0].clone(), g01.clone(), g02.clone()],
        [g01, diag[1].clone(), g12.clone()],
        [g02, g12, diag[2].clone()],
    ];
    let (d0, d1) = (differences(s, 0), differences(s, 1));
    let column = |d: &M2, k: usize| [d[0][k].clone(), d[1][k].clone()];
    // the projections of Q − P (k = 0) and R − P (k = 1) onto the three lines
    let onto = |k: usize| {
        [
            project(v[0], &column(&d0, k)),
            project(v[1], &column(&d0, k)),
            project(v[2], &column(&d1, k)),
        ]
    };
    let (sq, sr) = (onto(0), onto(1));
    let qr = std::array::from_fn(|i| &sr[i] - &sq[i]);
    Choice {
        gram,
        edges: [sq, qr, sr],
    }
}

impl Choice {
    /// The adjugate of G (symmetric) and its determinant.
    fn adjugate(&self) -> ([[Multiquad; 3]; 3], Multiquad) {
        let g = &self.gram;
        let cof = |i: usize, j: usize| {
            let (r, c) = ([(1, 2), (0, 2), (0, 1)][i], [(1, 2), (0, 2), (0, 1)][j]);
            let m = &(&g[r.0][c.0] * &g[r.1][c.1]) - &(&g[r.0][c.1] * &g[r.1][c.0]);
            if (i + j).is_multiple_of(2) {
                m
            } else {
                -&m
            }
        };
        let adj: [[Multiquad; 3]; 3] = std::array::from_fn(|i| std::array::from_fn(|j| cof(j, i)));
        let det = (0..3).fold(Multiquad::constant(g[0][0].squares(), rat(0, 1)), |s, j| {
            &s + &(&g[0][j] * &adj[j][0])
        });
        (adj, det)
    }

    /// Positive definite: the leading minors positive.
    fn is_real(&self, det: &Multiquad) -> bool {
        let g = &self.gram;
        let minor = &(&g[0][0] * &g[1][1]) - &(&g[0][1] * &g[0][1]);
        use std::cmp::Ordering::Greater;
        g[0][0].sign() == Greater && minor.sign() == Greater && det.sign() == Greater
    }

    /// The numerators eᵀ adj(G) e of the squared edges PQ, QR, RP (each over det G).
    fn squares(&self, adj: &[[Multiquad; 3]; 3]) -> [Multiquad; 3] {
        self.edges.clone().map(|e| {
            let f = e[0].squares();
            (0..3).fold(Multiquad::constant(f, rat(0, 1)), |s, i| {
                (0..3).fold(s, |s, j| &s + &(&(&adj[i][j] * &e[i]) * &e[j]))
            })
        })
    }
}

/// Whether `n / d` is a root of `p` (d ≠ 0): Σ cₖ nᵏ d^(deg − k) = 0, by Horner's rule in
/// homogeneous form (2·deg products, not deg²).
fn is_root(p: &UPoly, n: &Multiquad, d: &Multiquad) -> bool {
    let f = n.squares();
    let Some((top, rest)) = p.coeffs().split_last() else {
        return true;
    };
    let mut d_power = Multiquad::constant(f, rat(1, 1));
    let mut sum = Multiquad::constant(f, top.clone());
    for c in rest.iter().rev() {
        d_power = &d_power * d;
        sum = &(&sum * n) + &d_power.scale(c);
    }
    sum.is_zero()
}

/// `α z + β` of a polynomial linear in z, at z = n/d, times d.
fn linear_at(p: &Poly, n: &Multiquad, d: &Multiquad) -> Multiquad {
    let cs = p.coefficients_in("z");
    let at = |k: usize| cs.get(k).map(constant_of).unwrap_or_else(BigRational::zero);
    &n.scale(&at(1)) + &d.scale(&at(0))
}

/// The index of the real root of `roots` that n/d (a root, d > 0) is: the number of
/// isolating intervals wholly below it.
fn root_index(roots: &[crate::algebra::RealRoot], n: &Multiquad, d: &Multiquad) -> usize {
    roots
        .iter()
        .filter(|r| (n - &d.scale(&r.hi())).sign() == std::cmp::Ordering::Greater)
        .count()
}

/// Whether the direction `v` (image i) is that of the scene's own line of pair (i, j):
/// kᵢ × kⱼ, the third rows of the rotations, seen in image i.
fn is_true_line(s: &RationalScene, (i, j): (usize, usize), v: &V2) -> bool {
    let (ki, kj) = (&s.rotations[i][2], &s.rotations[j][2]);
    let u: [BigRational; 3] = std::array::from_fn(|a| {
        &ki[(a + 1) % 3] * &kj[(a + 2) % 3] - &ki[(a + 2) % 3] * &kj[(a + 1) % 3]
    });
    let r = &s.rotations[i];
    let t: [BigRational; 2] =
        std::array::from_fn(|row| (0..3).fold(rat(0, 1), |acc, k| acc + &r[row][k] * &u[k]));
    (&v[0].scale(&t[1]) - &v[1].scale(&t[0])).is_zero()
}

/// The construction at one scene; `xz`, `yz` and `poly`: the paper's elimination (a² and b²
/// as linear polynomials in z = c², and the polynomial in z).
pub fn lines_first(
    s: &RationalScene,
    seed: u64,
    xz: &Poly,
    yz: &Poly,
    poly: &UPoly,
) -> Option<LinesFirst> {
    let carries: [M2; 3] = PAIRS
        .iter()
        .map(|&(i, j)| carry(s, i, j))
        .collect::<Option<Vec<_>>>()?
        .try_into()
        .ok()?;
    let forms = carries.clone().map(|n| form(&n));
    let field = Multiquad::field(
        forms
            .iter()
            .map(|(_, d)| {
                if d.is_positive() {
                    d.clone()
                } else {
                    rat(1, 1)
                }
            })
            .collect(),
    );
    let lines: Vec<Option<Vec<V2>>> = (0..3)
        .map(|p| null_lines(&forms[p].0, &forms[p].1, &field, p))
        .collect();
    let counts: [Option<usize>; 3] = std::array::from_fn(|p| lines[p].as_ref().map(Vec::len));
    let mut out = LinesFirst {
        seed,
        lines: counts,
        branches: counts.iter().map(|c| c.map_or(0, |c| 2 * c)).product(),
        choices: counts.iter().map(|c| c.unwrap_or(0)).product(),
        real_choices: 0,
        per_root: Vec::new(),
        edges_solve: true,
        truth_among: false,
    };
    let [Some(a), Some(b), Some(c)] = [&lines[0], &lines[1], &lines[2]] else {
        return Some(out);
    };
    out.truth_among = [a, b, c]
        .iter()
        .zip(PAIRS)
        .all(|(ls, pair)| ls.iter().any(|v| is_true_line(s, pair, v)));
    let roots = poly.real_roots();
    out.per_root = vec![0; roots.len()];
    for va in a {
        for vb in b {
            for vc in c {
                tally(
                    &mut out,
                    &choice(s, &carries, [va, vb, vc]),
                    (xz, yz, poly),
                    &roots,
                );
            }
        }
    }
    Some(out)
}

/// Count one choice: real or not, and where real, which root its edges are, checking that
/// they solve the system.
fn tally(
    out: &mut LinesFirst,
    ch: &Choice,
    (xz, yz, poly): (&Poly, &Poly, &UPoly),
    roots: &[crate::algebra::RealRoot],
) {
    let (adj, det) = ch.adjugate();
    if !ch.is_real(&det) {
        return;
    }
    out.real_choices += 1;
    let [x, y, z] = ch.squares(&adj);
    let solves = is_root(poly, &z, &det)
        && (&x - &linear_at(xz, &z, &det)).is_zero()
        && (&y - &linear_at(yz, &z, &det)).is_zero();
    out.edges_solve &= solves;
    if solves && let Some(n) = out.per_root.get_mut(root_index(roots, &z, &det)) {
        *n += 1;
    }
}

/// The lines-first construction at `instances` seeded scenes (seeds `seed`, `seed + 1`, …,
/// the scenes of [`super::p3f3_count`]).
pub fn lines_first_count(instances: usize, seed: u64) -> Vec<LinesFirst> {
    use rayon::prelude::*;
    (0..instances as u64)
        .into_par_iter()
        .filter_map(|t| {
            let seed = seed.wrapping_add(t);
            let s = RationalScene::random(3, 3, seed);
            let l = s.triangle_squares();
            let (poly, xz, yz) = crate::derivations::p3f3::exact_elimination_parts(&l)?;
            lines_first(&s, seed, &xz, &yz, &poly)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::claims::solution_count::study::{cayley, mat_mul, p3f3_instance};

    #[test]
    fn sixty_four_branches_onto_the_sixteen_reconstructions() {
        // seed 1500: both edge solutions feasible; 1501: one
        for (seed, real) in [(1500, 8), (1501, 4)] {
            let l = &lines_first_count(1, seed)[0];
            let i = p3f3_instance(&RationalScene::random(3, 3, seed), seed).unwrap();
            assert_eq!((l.lines, l.branches, l.choices), ([Some(2); 3], 64, 8));
            assert_eq!(l.real_choices, real);
            assert_eq!(2 * l.real_choices, i.sm_real);
            assert_eq!(
                l.per_root.iter().filter(|&&n| n == 4).count(),
                i.edge_feasible
            );
            assert!(l.edges_solve && l.truth_among);
        }
    }

    #[test]
    fn congruent_images_leave_every_line() {
        let mut s = RationalScene::random(3, 3, 1500);
        let turn = cayley(&[rat(0, 1), rat(0, 1), BigRational::new(2.into(), 5.into())]);
        s.rotations[2] = mat_mul(&turn, &s.rotations[1]);
        let l = s.triangle_squares();
        let poly = crate::derivations::p3f3::exact_elimination(&l).unwrap_or(UPoly::new(vec![]));
        let got = lines_first(&s, 0, &Poly::zero(), &Poly::zero(), &poly).unwrap();
        assert_eq!(got.lines[2], None);
        assert_eq!(got.branches, 0);
    }
}
