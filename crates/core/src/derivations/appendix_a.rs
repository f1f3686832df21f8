//! Appendix A: eliminating a² between the twofold-squared equations of frames 1 and 2,
//! which leaves an equation quadratic in b² and in c² (used by the point-identity test, §5.2).
//!
//! F₁ − F₂ is linear in a² (the a⁴ terms cancel): a² = p b² + q c² + r with rational
//! functions p, q, r of the projections. Substituted into F₁:
//! f_{b²} b⁴ + b² (c² f_cb + f_b) + (c² f_c + c⁴ f_{c²} + f_Cst) = 0.

use std::collections::BTreeMap;

use num_rational::BigRational;
use num_traits::{Signed, Zero};

use crate::algebra::{Poly, RatFn};
use crate::derivations::twofold::frame_equation;

/// The coefficients of the eliminated equation, as rational functions of the projections
/// (variables `a_1, b_1, c_1, a_2, b_2, c_2`).
#[derive(Clone, Debug)]
pub struct Eliminated {
    /// The whole equation F₁(a² = p b² + q c² + r), in `b`, `c` and the projections.
    pub equation: RatFn,
    /// a² = p b² + q c² + r: (p, q, r).
    pub a_squared: [RatFn; 3],
    /// f_{b²}: the coefficient of b⁴.
    pub f_b2: RatFn,
    /// f_{c²}: the coefficient of c⁴.
    pub f_c2: RatFn,
    /// f_cb: the coefficient of b²c².
    pub f_cb: RatFn,
    /// f_b: the coefficient of b².
    pub f_b: RatFn,
    /// f_c: the coefficient of c².
    pub f_c: RatFn,
    /// f_Cst: the constant.
    pub f_cst: RatFn,
}

/// Replace every `v^(2k)` by `x^k`; `None` if `v` has an odd power.
pub fn in_squares(p: &Poly, v: &str, x: &str) -> Option<Poly> {
    let c = p.coefficients_in(v);
    let mut out = Poly::zero();
    for (e, ce) in c.iter().enumerate() {
        if ce.is_zero() {
            continue;
        }
        if e % 2 == 1 {
            return None;
        }
        out = &out + &(ce * &Poly::var(x).pow(e as u32 / 2));
    }
    Some(out)
}

/// The coefficient of `v^e` in a rational function whose denominator is free of `v`.
fn coefficient(f: &RatFn, v: &str, e: usize) -> RatFn {
    RatFn {
        num: f.num.coefficients_in(v).get(e).cloned().unwrap_or_default(),
        den: f.den.clone(),
    }
}

/// Eliminate a² from frames 1 and 2, the appendix's way: from F₁ − F₂ (linear in a²),
/// substituted into F₁.
///
/// # Example
/// ```
/// use orthocheck_core::derivations::appendix_a::eliminate;
/// let e = eliminate();
/// // quadratic in b² and in c²
/// assert_eq!(e.equation.num.degree_in("b"), 4);
/// assert_eq!(e.equation.num.degree_in("c"), 4);
/// ```
pub fn eliminate() -> Eliminated {
    let sq = |p: &Poly| -> Poly {
        let p = in_squares(p, "a", "x").unwrap_or_default();
        let p = in_squares(&p, "b", "y").unwrap_or_default();
        in_squares(&p, "c", "z").unwrap_or_default()
    };
    eliminate_from(
        &sq(&frame_equation(["a", "b", "c"], "1")),
        &sq(&frame_equation(["a", "b", "c"], "2")),
    )
}

/// The same elimination with the coefficients of each frame's equation as symbols, the
/// paper's macros: Fₖ = x² + y² + z² − 2xy − 2xz − 2yz + facCstₖ + facaₖ x + facbₖ y + faccₖ z
/// with x = a², y = b², z = c² (so facaₖ = 2(−aₖ² + bₖ² + cₖ²), …). Much smaller than in the
/// projections, and what the appendix's printed coefficients are written in. Computed once
/// per process (every appendix item and the audit's expansions read it).
pub fn eliminate_symbolic() -> &'static Eliminated {
    static ONCE: std::sync::OnceLock<Eliminated> = std::sync::OnceLock::new();
    ONCE.get_or_init(symbolic)
}

fn symbolic() -> Eliminated {
    let frame = |k: u32| -> Poly {
        Poly::parse(&format!(
            "x^2+y^2+z^2-2x y-2x z-2y z + facCst{k} + faca{k} x + facb{k} y + facc{k} z"
        ))
        .unwrap_or_default()
    };
    eliminate_from(&frame(1), &frame(2))
}

/// Eliminate x = a² between two frame equations in the squares x, y, z.
fn eliminate_from(f1: &Poly, f2: &Poly) -> Eliminated {
    let diff = f1 - f2;
    let lin = diff.coefficients_in("x");
    let (rest, slope) = (lin[0].clone(), lin.get(1).cloned().unwrap_or_default());
    // x = −rest / slope, rest affine in y and z
    let x = RatFn {
        num: -&rest,
        den: slope,
    };
    let eq = RatFn::from(f1.clone()).substitute("x", &x);
    // back to b and c
    let back = |f: &RatFn| RatFn {
        num: f
            .num
            .substitute("y", &Poly::var("b").pow(2))
            .substitute("z", &Poly::var("c").pow(2)),
        den: f.den.clone(),
    };
    let by = |f: &RatFn, y: usize, z: usize| {
        let cy = coefficient(f, "y", y);
        coefficient(&cy, "z", z)
    };
    Eliminated {
        f_b2: by(&eq, 2, 0),
        f_c2: by(&eq, 0, 2),
        f_cb: by(&eq, 1, 1),
        f_b: by(&eq, 1, 0),
        f_c: by(&eq, 0, 1),
        f_cst: by(&eq, 0, 0),
        a_squared: [by(&x, 1, 0), by(&x, 0, 1), by(&x, 0, 0)],
        equation: back(&eq),
    }
}

impl Eliminated {
    /// Δ_b = (c² f_cb + f_b)² − 4 f_{b²} (c² f_c + c⁴ f_{c²} + f_Cst), a rational function of c.
    pub fn delta_b(&self) -> RatFn {
        let c2 = RatFn::from(Poly::var("c").pow(2));
        let b = &(&c2 * &self.f_cb) + &self.f_b;
        let c = &(&(&c2 * &self.f_c) + &(&c2.pow(2) * &self.f_c2)) + &self.f_cst;
        &b.pow(2) - &(&RatFn::int(4) * &(&self.f_b2 * &c))
    }
}

/// The root formula of a quadratic, checked symbolically: with X = (σ·B ± s)/(2A) and
/// s² = B² − κ·A·C, whether 4A·(A X² + B X + C) reduces to zero for both signs of s. The
/// quadratic formula is σ = −1, κ = 4 (Appendix A's b² with A = f_{b²}, B = c² f_cb + f_b);
/// other values are its mutants.
///
/// # Example
/// ```
/// use orthocheck_core::derivations::appendix_a::quadratic_formula_solves;
/// assert!(quadratic_formula_solves(-1, 4));
/// assert!(!quadratic_formula_solves(1, 4));
/// ```
pub fn quadratic_formula_solves(sigma: i64, kappa: i64) -> bool {
    let (a, b, c, s) = (
        Poly::var("A"),
        Poly::var("B"),
        Poly::var("C"),
        Poly::var("s"),
    );
    let int = |k: i64| Poly::int(k);
    let delta = &(&b * &b) - &(&int(kappa) * &(&a * &c));
    [1i64, -1].iter().all(|pm| {
        // 2A·X = σB ± s, and 4A·(A X² + B X + C) = (2AX)² + 2B·(2AX) + 4AC
        let x2a = &(&int(sigma) * &b) + &(&int(*pm) * &s);
        let e = &(&(&x2a * &x2a) + &(&int(2) * &(&b * &x2a))) + &(&int(4) * &(&a * &c));
        in_squares(&e, "s", "S")
            .map(|p| p.substitute("S", &delta))
            .is_some_and(|p| p.is_zero())
    })
}

/// Δ_b at exact data: a quadratic D₀ + D₁C + D₂C² in C = c², from the symbolic elimination
/// evaluated over ℚ, with the ratio f_cb / f_{b²} of the eliminated equation.
#[derive(Clone, Debug, PartialEq)]
pub struct ExactDeltaB {
    /// (D₀, D₁, D₂).
    pub coefficients: [BigRational; 3],
    /// f_cb / f_{b²}; `None` when f_{b²} = 0.
    pub f_cb_over_f_b2: Option<BigRational>,
}

impl ExactDeltaB {
    /// Δ_b at C = c².
    pub fn eval(&self, c2: &BigRational) -> BigRational {
        let [d0, d1, d2] = &self.coefficients;
        d0 + c2 * (d1 + c2 * d2)
    }

    /// The sign of Δ_b just above C = c² (on (C, C + δ) for every small δ > 0): the first
    /// nonzero of Δ_b(C), Δ_b′(C), D₂; 0 when Δ_b vanishes identically.
    pub fn sign_above(&self, c2: &BigRational) -> i8 {
        let [_, d1, d2] = &self.coefficients;
        let two = BigRational::from_integer(2.into());
        let slope = d1 + &two * c2 * d2;
        [self.eval(c2), slope, d2.clone()]
            .iter()
            .find(|x| !x.is_zero())
            .map_or(0, |x| if x.is_positive() { 1 } else { -1 })
    }

    /// Whether Δ_b < 0 for every C > `c2`: negative just above and D₂ ≤ 0 (a quadratic
    /// negative just above C with a non-positive leading coefficient stays negative, since
    /// its derivative there is then negative too).
    pub fn negative_beyond(&self, c2: &BigRational) -> bool {
        self.sign_above(c2) < 0 && !self.coefficients[2].is_positive()
    }
}

/// The frame coefficients the symbolic elimination is written in, from the squared
/// projections (a², b², c²) of one frame: faca = 2(−a² + b² + c²), facb, facc likewise,
/// facCst = a⁴ + b⁴ + c⁴ − 2a²b² − 2a²c² − 2b²c².
fn frame_symbols(k: u32, [a, b, c]: &[BigRational; 3], out: &mut BTreeMap<String, BigRational>) {
    let two = BigRational::from_integer(2.into());
    out.insert(format!("faca{k}"), &two * (b + c - a));
    out.insert(format!("facb{k}"), &two * (a + c - b));
    out.insert(format!("facc{k}"), &two * (a + b - c));
    let cst = a * a + b * b + c * c - &two * (a * b + a * c + b * c);
    out.insert(format!("facCst{k}"), cst);
}

/// Δ_b of the appendix's quadratic over ℚ, for the squared projections of PQ, QR, RP in
/// frames 1 and 2; `e` is [`eliminate_symbolic`]. `None` where the elimination divides by
/// zero (equal coefficients of a² in the two frames).
pub fn exact_delta_b(
    e: &Eliminated,
    sq1: &[BigRational; 3],
    sq2: &[BigRational; 3],
) -> Option<ExactDeltaB> {
    let mut vals = BTreeMap::new();
    frame_symbols(1, sq1, &mut vals);
    frame_symbols(2, sq2, &mut vals);
    let at = |f: &RatFn| f.eval(&vals);
    let (fb2, fcb, fb, fc, fc2, fcst) = (
        at(&e.f_b2)?,
        at(&e.f_cb)?,
        at(&e.f_b)?,
        at(&e.f_c)?,
        at(&e.f_c2)?,
        at(&e.f_cst)?,
    );
    let four = BigRational::from_integer(4.into());
    let two = BigRational::from_integer(2.into());
    // (C f_cb + f_b)² − 4 f_b² (C f_c + C² f_c² + f_Cst)
    let coefficients = [
        &fb * &fb - &four * &fb2 * &fcst,
        &two * &fcb * &fb - &four * &fb2 * &fc,
        &fcb * &fcb - &four * &fb2 * &fc2,
    ];
    let f_cb_over_f_b2 = (!fb2.is_zero()).then(|| &fcb / &fb2);
    Some(ExactDeltaB {
        coefficients,
        f_cb_over_f_b2,
    })
}
