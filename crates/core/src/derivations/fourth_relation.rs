//! §5: the fourth relationship, of triangle PQR, against the three of PQT, QRT and RPT: the
//! paper says it is linearly dependent on them; this module decides it exactly.

use std::collections::{BTreeMap, BTreeSet};

use num_rational::BigRational;
use num_traits::Zero;

use crate::algebra::{exact_rank, rat, solve_linear, Monomial, Poly, RatFn};
use crate::derivations::twofold::frame_equation;
use crate::model::RationalScene;

/// The four triangles of P, Q, R, T with the paper's edge letters (a = PQ, b = QR, c = RP,
/// d = TR, f = TP, g = TQ): PQT, QRT, RPT, then PQR.
pub const TRIANGLES: [[&str; 3]; 4] = [
    ["a", "g", "f"],
    ["d", "b", "g"],
    ["d", "f", "c"],
    ["a", "b", "c"],
];

/// What decides whether the relation of PQR depends on the other three.
#[derive(Clone, Debug)]
pub struct FourthRelation {
    /// F_PQR = λ₁F_PQT + λ₂F_QRT + λ₃F_RPT has a solution with λ rational functions of the
    /// projections (so, a fortiori, with rational constants).
    pub linear: bool,
    /// Why not: a monomial whose coefficients contradict the λ forced by the others.
    pub obstruction: Option<String>,
    /// Squared depth differences (A, B, C of PQR; D, F, G of the others) where the three
    /// twofold-squared relations hold exactly and the fourth does not: it is not even
    /// implied by them. Each relation's signs are chosen on its own.
    pub counterexample: Vec<(String, BigRational)>,
    /// The four equations' values there (F_PQT, F_QRT, F_RPT, F_PQR).
    pub counterexample_values: Vec<BigRational>,
    /// Exact ranks of the frame-differenced equations of two frames at a rational scene:
    /// the three triangles of the paper, and all four.
    pub rank_three: usize,
    /// With PQR added.
    pub rank_four: usize,
    /// The reading the paper's words fit: the relations in the signed depth differences.
    pub signed: SignedDependence,
}

/// The four relations read in the signed depth differences uₑ = z_i − z_j of the edges (the
/// square roots of §5 with their signs): each triangle's loop Σ ±uₑ = 0 is a linear form in
/// the six uₑ, and dependence is a question of exact rank.
#[derive(Clone, Debug)]
pub struct SignedDependence {
    /// Rank of the loops of PQT, QRT and RPT.
    pub rank_three: usize,
    /// Rank with the loop of PQR added: equal to `rank_three` when PQR's depends on them.
    pub rank_four: usize,
    /// The mutant: PQR's loop with the sign of its last difference changed. It must raise
    /// the rank (a relation that holds on no body is not in the span).
    pub mutant_rank: usize,
}

/// Decide the dependence of the fourth relation (frame `i` for the polynomial questions; a
/// seeded rational scene for the ranks).
pub fn fourth_relation(seed: u64) -> FourthRelation {
    let f: Vec<Poly> = TRIANGLES.iter().map(|t| frame_equation(*t, "i")).collect();
    let (linear, obstruction) = linear_dependence(&f);
    let (shown, counterexample_values) = squares_counterexample(&f);
    let rows = frame_rows(seed);
    FourthRelation {
        linear,
        obstruction,
        counterexample: shown,
        counterexample_values,
        rank_three: exact_rank(&rows[..3]).0,
        rank_four: exact_rank(&rows).0,
        signed: signed_dependence(),
    }
}

/// The loops of the four triangles in the signed edge differences, and their ranks.
fn signed_dependence() -> SignedDependence {
    let loops: Vec<Vec<BigRational>> = TRIANGLES.iter().map(signed_loop).collect();
    let mut mutant = loops.clone();
    if let Some(last) = mutant[3].iter_mut().rev().find(|x| !x.is_zero()) {
        *last = -last.clone();
    }
    SignedDependence {
        rank_three: exact_rank(&loops[..3]).0,
        rank_four: exact_rank(&loops).0,
        mutant_rank: exact_rank(&mutant).0,
    }
}

/// The signs s with Σ sₖ (z_iₖ − z_jₖ) = 0 identically in the depths (the triangle's loop), as
/// a row over the six edge columns; found by trying the sign choices, first sign fixed.
fn signed_loop(t: &[&str; 3]) -> Vec<BigRational> {
    for signs in [[1, 1, 1], [1, 1, -1], [1, -1, 1], [1, -1, -1]] {
        let mut depth = [0i64; 4];
        for (e, s) in t.iter().zip(signs) {
            let (i, j) = edge_points(e);
            depth[i] += s;
            depth[j] -= s;
        }
        if depth.iter().all(|d| *d == 0) {
            let mut row = vec![BigRational::zero(); EDGES.len()];
            for (e, s) in t.iter().zip(signs) {
                let col = EDGES.iter().position(|x| x == e).unwrap_or(0);
                row[col] = rat(s, 1);
            }
            return row;
        }
    }
    vec![BigRational::zero(); EDGES.len()]
}

/// The edge letters, in the column order of the frame rows.
const EDGES: [&str; 6] = ["a", "b", "c", "d", "f", "g"];

/// The coefficients of each monomial in the edge lengths, as polynomials in the projections.
fn edge_coefficients(p: &Poly) -> BTreeMap<Monomial, Poly> {
    let mut out: BTreeMap<Monomial, Poly> = BTreeMap::new();
    for (m, c) in p.terms() {
        let (mut e, mut rest) = (Poly::int(1), Poly::constant(c.clone()));
        for (v, k) in m.factors() {
            let x = Poly::var(v).pow(*k);
            if EDGES.contains(&v.as_str()) {
                e = &e * &x;
            } else {
                rest = &rest * &x;
            }
        }
        let key = e.terms().next().map(|(m, _)| m.clone()).unwrap_or_default();
        let entry = out.entry(key).or_default();
        *entry = &*entry + &rest;
    }
    out
}

/// Whether F_PQR = λ₁F_PQT + λ₂F_QRT + λ₃F_RPT for rational functions λ, and if not, why.
fn linear_dependence(f: &[Poly]) -> (bool, Option<String>) {
    let parts: Vec<BTreeMap<Monomial, Poly>> = f.iter().map(edge_coefficients).collect();
    let monomials: BTreeSet<Monomial> = parts.iter().flat_map(|p| p.keys().cloned()).collect();
    let coef =
        |t: usize, m: &Monomial| -> RatFn { parts[t].get(m).cloned().unwrap_or_default().into() };
    // λ from the a⁴, b⁴, c⁴ coefficients (each appears in one of the three only), then every
    // monomial must agree
    let pick: Vec<Monomial> = ["a", "b", "c"]
        .iter()
        .filter_map(|v| Poly::var(v).pow(4).terms().next().map(|(m, _)| m.clone()))
        .collect();
    let m: Vec<Vec<RatFn>> = pick
        .iter()
        .map(|mm| (0..3).map(|t| coef(t, mm)).collect())
        .collect();
    let rhs: Vec<RatFn> = pick.iter().map(|mm| coef(3, mm)).collect();
    let Some(lambda) = solve_linear(&m, &rhs) else {
        return (
            false,
            Some("the a⁴, b⁴, c⁴ coefficients admit no λ".to_string()),
        );
    };
    let sum = |mm: &Monomial| {
        (0..3).fold(RatFn::default(), |acc, t| {
            &acc + &(&lambda[t] * &coef(t, mm))
        })
    };
    // the shortest contradicting coefficient makes the clearest reason
    let bad = monomials
        .iter()
        .filter(|mm| !sum(mm).equals(&coef(3, mm)))
        .min_by_key(|mm| sum(mm).num.len() + coef(3, mm).num.len());
    match bad {
        None => (true, None),
        Some(mm) => (
            false,
            Some(format!(
                "λ = (1, 1, 1) from a⁴, b⁴, c⁴, but then the coefficient of {} is {} instead of {}",
                Poly::from_monomial(mm.clone()),
                sum(mm).num,
                coef(3, mm).num
            )),
        ),
    }
}

/// Squared depth differences where the three twofold-squared relations hold and the fourth
/// does not, with the four equations' values there.
fn squares_counterexample(f: &[Poly]) -> (Vec<(String, BigRational)>, Vec<BigRational>) {
    // depth differences with signs chosen per triangle: √D = 3, √F = 2, √G = 1 and
    // √A = √G + √F, √B = √D + √G, √C = √F + √D; then ±√A ± √B ± √C = ±3 ± 4 ± 5 ≠ 0.
    // The projections are arbitrary (1, 2, … in the squares).
    let depth: [(&str, i64); 6] = [("a", 9), ("b", 16), ("c", 25), ("d", 9), ("f", 4), ("g", 1)];
    // the equations in the squares: substitute e² and eᵢ² directly
    let mut values: BTreeMap<String, BigRational> = BTreeMap::new();
    let mut shown = Vec::new();
    for (k, (e, dd)) in depth.iter().enumerate() {
        let pi2 = rat(k as i64 + 1, 1);
        values.insert(format!("{e}_i^2"), pi2.clone());
        values.insert(format!("{e}^2"), &pi2 + rat(*dd, 1));
        shown.push((format!("{}² − {}ᵢ²", e, e), rat(*dd, 1)));
    }
    let in_squares = |p: &Poly| -> Poly {
        EDGES.iter().fold(p.clone(), |q, e| {
            let q = crate::derivations::appendix_a::in_squares(&q, e, &format!("{e}^2"))
                .unwrap_or_default();
            crate::derivations::appendix_a::in_squares(&q, &format!("{e}_i"), &format!("{e}_i^2"))
                .unwrap_or_default()
        })
    };
    let counterexample_values: Vec<BigRational> = f
        .iter()
        .map(|p| {
            in_squares(p)
                .eval(&values)
                .unwrap_or_else(BigRational::zero)
        })
        .collect();
    (shown, counterexample_values)
}

/// The point indices (P, Q, R, T = 0, 1, 2, 3) of an edge letter.
fn edge_points(e: &str) -> (usize, usize) {
    match e {
        "a" => (0, 1),
        "b" => (1, 2),
        "c" => (2, 0),
        "d" => (3, 2),
        "f" => (3, 0),
        _ => (3, 1),
    }
}

/// The frame-differenced equation of each triangle at a seeded rational scene: rows
/// 2(αᵢ − α₁) … in the edge columns, constant Kᵢ − K₁ last.
fn frame_rows(seed: u64) -> Vec<Vec<BigRational>> {
    let scene = RationalScene::random(4, 2, seed);
    let proj = |fi: usize, i: usize, j: usize| -> BigRational {
        let r = &scene.rotations[fi];
        (0..2)
            .map(|row| {
                let d: BigRational = (0..3)
                    .map(|c| &r[row][c] * (&scene.points[i][c] - &scene.points[j][c]))
                    .sum();
                &d * &d
            })
            .sum()
    };
    let row = |t: &[&str; 3]| -> Vec<BigRational> {
        let l = |fi: usize| -> [BigRational; 3] {
            t.map(|e| {
                let (i, j) = edge_points(e);
                proj(fi, i, j)
            })
        };
        let ((c2, k2), (c1, k1)) = (equation_coefficients(&l(1)), equation_coefficients(&l(0)));
        let mut r = vec![BigRational::zero(); 7];
        for (k, e) in t.iter().enumerate() {
            let col = EDGES.iter().position(|x| x == e).unwrap_or(0);
            r[col] = &c2[k] - &c1[k];
        }
        r[6] = k2 - k1;
        r
    };
    TRIANGLES.iter().map(row).collect()
}

/// The coefficients of a triangle's equation in its three squared edge lengths, and its
/// constant, from the three squared projections.
fn equation_coefficients(x: &[BigRational; 3]) -> ([BigRational; 3], BigRational) {
    let two = rat(2, 1);
    (
        [
            &two * (-&x[0] + &x[1] + &x[2]),
            &two * (&x[0] - &x[1] + &x[2]),
            &two * (&x[0] + &x[1] - &x[2]),
        ],
        &x[0] * &x[0] + &x[1] * &x[1] + &x[2] * &x[2]
            - &two * (&x[0] * &x[1] + &x[0] * &x[2] + &x[1] * &x[2]),
    )
}
