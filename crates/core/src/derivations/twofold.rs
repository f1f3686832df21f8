//! Eq. `p3f3sqr`: the twofold-squared constraint of a triangle seen in one frame.
//!
//! With A = a² − aᵢ², B = b² − bᵢ², C = c² − cᵢ² (squared depth differences), each frame
//! satisfies s_a√A + s_b√B + s_c√C = 0 for some signs. Squaring twice removes the radicals.
//! Here the squaring is carried out symbolically, with √A, √B, √C as variables reduced by
//! (√X)² = X, so the printed polynomial is compared with a derivation, not a hand expansion.

use std::sync::Mutex;

use nalgebra::Vector3;
use num_rational::BigRational;
use rand::Rng;

use crate::algebra::{Poly, Scalar};
use crate::model::{random_rotation, rng};

/// Radical symbols and what they square to, in terms of edges and projections.
fn radicals() -> [(&'static str, Poly); 3] {
    let sq = |e: &str, ei: &str| &Poly::var(e).pow(2) - &Poly::var(ei).pow(2);
    [
        ("rA", sq("a", "a_i")),
        ("rB", sq("b", "b_i")),
        ("rC", sq("c", "c_i")),
    ]
}

/// Replace every `r^e` by `X^(e div 2) · r^(e mod 2)` for each radical `r = √X`.
fn reduce(p: &Poly, rads: &[(&str, Poly)]) -> Poly {
    let mut out = p.clone();
    for (name, value) in rads {
        let coeffs = out.coefficients_in(name);
        let mut acc = Poly::zero();
        for (e, c) in coeffs.iter().enumerate() {
            let mut term = c * &value.pow((e / 2) as u32);
            if e % 2 == 1 {
                term = &term * &Poly::var(name);
            }
            acc = &acc + &term;
        }
        out = acc;
    }
    out
}

/// One squaring that removes `radical`: write `p = U + W·r`, return `U² − W²·r²`, reduced.
fn square_out(p: &Poly, radical: &str, rads: &[(&str, Poly)]) -> Poly {
    let c = p.coefficients_in(radical);
    let u = c.first().cloned().unwrap_or_default();
    let w = c.get(1).cloned().unwrap_or_default();
    let r2 = Poly::var(radical).pow(2);
    reduce(&(&(&u * &u) - &(&(&w * &w) * &r2)), rads)
}

/// The relation `s_a√A + s_b√B + s_c√C = 0` squared twice (first removing √C, then √A).
/// Signs are ±1.
///
/// # Example
/// ```
/// use orthocheck_core::{algebra::Poly, derivations::twofold::twofold_squared};
/// let p = twofold_squared([1, 1, -1]);
/// assert!(p.variables().iter().all(|v| !v.starts_with('r')));
/// assert_eq!(p.degree(), 4);
/// ```
pub fn twofold_squared(signs: [i64; 3]) -> Poly {
    // derived once per sign pattern: the audit and the census ask for the same few
    static DERIVED: Mutex<Vec<([i64; 3], Poly)>> = Mutex::new(Vec::new());
    let cache = || {
        DERIVED
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    };
    if let Some((_, p)) = cache().iter().find(|(k, _)| *k == signs) {
        return p.clone();
    }
    let p = derive_twofold_squared(signs);
    cache().push((signs, p.clone()));
    p
}

fn derive_twofold_squared(signs: [i64; 3]) -> Poly {
    let rads = radicals();
    let relation = ["rA", "rB", "rC"]
        .iter()
        .zip(signs)
        .fold(Poly::zero(), |acc, (r, s)| {
            &acc + &Poly::var(r).scale(&BigRational::from_integer(s.into()))
        });
    let once = square_out(&relation, "rC", &rads);
    square_out(&once, "rA", &rads)
}

/// Eq. p3f3sqr for a triangle with edges named `edges` (lengths `u`, `v`, `w`) in frame
/// `frame`: the projections are `u_frame`, `v_frame`, `w_frame`.
///
/// # Example
/// ```
/// use orthocheck_core::{algebra::Poly, derivations::twofold::frame_equation};
/// let f = frame_equation(["a", "g", "f"], "2");
/// assert!(f.variables().contains(&"g_2".to_string()));
/// ```
pub fn frame_equation(edges: [&str; 3], frame: &str) -> Poly {
    // derived once per naming: the audit asks for the same few many times
    static DERIVED: Mutex<Vec<([String; 4], Poly)>> = Mutex::new(Vec::new());
    let key = [edges[0], edges[1], edges[2], frame].map(String::from);
    let cache = || {
        DERIVED
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
    };
    if let Some((_, p)) = cache().iter().find(|(k, _)| *k == key) {
        return p.clone();
    }
    let p = derive_frame_equation(edges, frame);
    cache().push((key, p.clone()));
    p
}

fn derive_frame_equation(edges: [&str; 3], frame: &str) -> Poly {
    let p = relation_squared(edges, [1, 1, -1]);
    if frame == "i" {
        return p;
    }
    let names = edges.map(|e| (format!("{e}_i"), format!("{e}_{frame}")));
    let to: Vec<(&str, &str)> = names.iter().map(|(f, t)| (&**f, &**t)).collect();
    p.rename(&to)
}

/// `s₀√(e₀² − e₀ᵢ²) + s₁√(e₁² − e₁ᵢ²) + s₂√(e₂² − e₂ᵢ²) = 0` squared twice, in the edge
/// letters `edges` and frame `i`.
pub fn relation_squared(edges: [&str; 3], signs: [i64; 3]) -> Poly {
    let projections = edges.map(|e| format!("{e}_i"));
    let to = [
        ("a", edges[0]),
        ("b", edges[1]),
        ("c", edges[2]),
        ("a_i", &*projections[0]),
        ("b_i", &*projections[1]),
        ("c_i", &*projections[2]),
    ];
    twofold_squared(signs).rename(&to)
}

/// The product of `√A ± √B ± √C` over the four sign classes, reduced: the radical-free norm
/// whose vanishing is equivalent to "one of the signed relations holds".
pub fn sign_class_product() -> Poly {
    let rads = radicals();
    let mut prod = Poly::int(1);
    for (sb, sc) in [(1, 1), (1, -1), (-1, 1), (-1, -1)] {
        let f = &(&Poly::var("rA") + &Poly::var("rB").scale(&BigRational::from_integer(sb.into())))
            + &Poly::var("rC").scale(&BigRational::from_integer(sc.into()));
        prod = reduce(&(&prod * &f), &rads);
    }
    prod
}

/// How often each signed relation holds for random triangles under random rotations.
#[derive(Clone, Debug, serde::Serialize)]
pub struct RelationCensus {
    /// Trials run.
    pub trials: usize,
    /// Seed.
    pub seed: u64,
    /// For each sign pattern given (up to a global sign), the trials in which it held.
    pub held: Vec<usize>,
    /// Trials in which none of the given patterns held.
    pub none_held: usize,
    /// Largest |s_a√A + s_b√B + s_c√C| of the pattern that held, relative to the edge scale.
    pub max_residual: f64,
}

/// For seeded random triangles and rotations, find which of `patterns` holds. A pattern holds
/// when its signs (or their negation) match the signs of the depth differences
/// z_Q − z_P, z_R − z_Q, z_P − z_R, whose sum is zero.
pub fn relation_census(patterns: &[[i64; 3]], trials: usize, seed: u64) -> RelationCensus {
    let mut g = rng(seed);
    let mut held = vec![0; patterns.len()];
    let mut none_held = 0;
    let mut max_residual: f64 = 0.0;
    for _ in 0..trials {
        let pts: Vec<Vector3<f64>> = (0..3)
            .map(|_| {
                Vector3::new(
                    g.random_range(-1.0..1.0),
                    g.random_range(-1.0..1.0),
                    g.random_range(-1.0..1.0),
                )
            })
            .collect();
        let rot = random_rotation(&mut g);
        let y: Vec<Vector3<f64>> = pts.iter().map(|x| rot * x).collect();
        let edges = [(0, 1), (1, 2), (2, 0)];
        let dz: Vec<f64> = edges.iter().map(|&(i, j)| y[j].z - y[i].z).collect();
        // √(e² − eᵢ²) from lengths, as the paper's quantities
        let roots: Vec<f64> = edges
            .iter()
            .map(|&(i, j)| {
                let e2 = (pts[i] - pts[j]).norm_squared();
                let d = y[i] - y[j];
                (e2 - d.x * d.x - d.y * d.y).max(0.0).sqrt()
            })
            .collect();
        let signs: Vec<i64> = dz.iter().map(|d| if *d >= 0.0 { 1 } else { -1 }).collect();
        let matched = patterns.iter().position(|p| {
            let same = p.iter().zip(&signs).all(|(a, b)| a == b);
            let opposite = p.iter().zip(&signs).all(|(a, b)| *a == -b);
            same || opposite
        });
        match matched {
            Some(m) => {
                held[m] += 1;
                let scale = roots.iter().fold(1.0_f64, |a, b| a.max(*b));
                let r: f64 = patterns[m]
                    .iter()
                    .zip(&roots)
                    .map(|(s, v)| *s as f64 * v)
                    .sum();
                max_residual = max_residual.max(r.abs() / scale);
            }
            None => none_held += 1,
        }
    }
    RelationCensus {
        trials,
        seed,
        held,
        none_held,
        max_residual,
    }
}

/// The coefficients of eq. p3f3sqr for one frame, from the projected squared lengths
/// (aᵢ², bᵢ², cᵢ²): F(x, y, z) = x² + y² + z² − 2xy − 2xz − 2yz + K + 2αx + 2βy + 2γz with
/// x = a², y = b², z = c².
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameCoefficients {
    /// α = −aᵢ² + bᵢ² + cᵢ².
    pub alpha: f64,
    /// β = aᵢ² − bᵢ² + cᵢ².
    pub beta: f64,
    /// γ = aᵢ² + bᵢ² − cᵢ².
    pub gamma: f64,
    /// K = aᵢ⁴ + bᵢ⁴ + cᵢ⁴ − 2aᵢ²bᵢ² − 2aᵢ²cᵢ² − 2bᵢ²cᵢ² (= −16·area², zero when collinear).
    pub k: f64,
    /// aᵢ² + bᵢ² + cᵢ²: the scale against which rounding is judged.
    pub scale: f64,
}

impl FrameCoefficients {
    /// From projected squared lengths of PQ, QR, RP in one frame.
    ///
    /// # Example
    /// ```
    /// use orthocheck_core::derivations::twofold::FrameCoefficients;
    /// // a right triangle 3-4-5 seen face-on: the true squares satisfy F = 0
    /// let f = FrameCoefficients::new([9.0, 16.0, 25.0]);
    /// assert_eq!(f.eval(9.0, 16.0, 25.0), 0.0);
    /// ```
    #[inline]
    pub fn new(l: [f64; 3]) -> Self {
        let [alpha, beta, gamma, k] = frame_terms(l);
        FrameCoefficients {
            alpha,
            beta,
            gamma,
            k,
            scale: l[0] + l[1] + l[2],
        }
    }

    /// F(x, y, z).
    #[inline]
    pub fn eval(&self, x: f64, y: f64, z: f64) -> f64 {
        x * x + y * y + z * z - 2.0 * x * y - 2.0 * x * z - 2.0 * y * z
            + self.k
            + 2.0 * self.alpha * x
            + 2.0 * self.beta * y
            + 2.0 * self.gamma * z
    }

    /// ∂F/∂(x, y, z) at (x, y, z).
    #[inline]
    pub fn slope(&self, v: [f64; 3]) -> [f64; 3] {
        frame_slope(&self.coefficients(), v)
    }

    /// The sum of the absolute values of F's terms at (x, y, z): the scale of its rounding.
    #[inline]
    pub fn terms(&self, x: f64, y: f64, z: f64) -> f64 {
        x * x
            + y * y
            + z * z
            + 2.0 * ((x * y).abs() + (x * z).abs() + (y * z).abs())
            + self.k.abs()
            + 2.0 * ((self.alpha * x).abs() + (self.beta * y).abs() + (self.gamma * z).abs())
    }

    /// The linear equation F_self − F_other = 0 as (coefficients of x, y, z; constant).
    #[inline]
    pub fn difference(&self, other: &FrameCoefficients) -> ([f64; 3], f64) {
        frame_difference(&self.coefficients(), &other.coefficients())
    }

    /// (α, β, γ, K), the form the generic functions below take.
    #[inline]
    fn coefficients(&self) -> [f64; 4] {
        [self.alpha, self.beta, self.gamma, self.k]
    }
}

/// (α, β, γ, K) of [`FrameCoefficients`] from one frame's projected squared lengths, in any
/// [`Scalar`] (the solver's floats and the enclosures of `studies::view_bounds` share it).
#[inline]
pub fn frame_terms<T: Scalar>([a2, b2, c2]: [T; 3]) -> [T; 4] {
    let two = T::constant(2.0);
    [
        -a2 + b2 + c2,
        a2 - b2 + c2,
        a2 + b2 - c2,
        a2 * a2 + b2 * b2 + c2 * c2 - two * a2 * b2 - two * a2 * c2 - two * b2 * c2,
    ]
}

/// ∂F/∂(x, y, z) from a frame's (α, β, γ, K), in any [`Scalar`].
#[inline]
pub fn frame_slope<T: Scalar>(t: &[T; 4], [x, y, z]: [T; 3]) -> [T; 3] {
    let two = T::constant(2.0);
    [
        two * (x - y - z + t[0]),
        two * (y - x - z + t[1]),
        two * (z - x - y + t[2]),
    ]
}

/// The linear equation Fᵢ − Fⱼ = 0 from the (α, β, γ, K) of two frames: (coefficients of x, y,
/// z; constant).
#[inline]
pub fn frame_difference<T: Scalar>(a: &[T; 4], b: &[T; 4]) -> ([T; 3], T) {
    let two = T::constant(2.0);
    (
        [
            two * (a[0] - b[0]),
            two * (a[1] - b[1]),
            two * (a[2] - b[2]),
        ],
        a[3] - b[3],
    )
}
