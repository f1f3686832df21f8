//! §2.2 in exact arithmetic: the three frame equations over ℚ, the elimination to one
//! univariate polynomial, and the validation of the floating solver against it.

use super::*;

/// The three frames' equations F₁, F₂, F₃ as exact polynomials in x = a², y = b², z = c².
pub fn exact_equations(l: &[[num_rational::BigRational; 3]; 3]) -> [crate::algebra::Poly; 3] {
    use crate::algebra::Poly;
    let (x, y, z) = (Poly::var("x"), Poly::var("y"), Poly::var("z"));
    std::array::from_fn(|i| {
        let [a2, b2, c2] = &l[i];
        let c = |v: num_rational::BigRational| Poly::constant(v);
        let two = num_rational::BigRational::from_integer(2.into());
        let alpha = c(-a2.clone() + b2 + c2);
        let beta = c(a2 - b2 + c2);
        let gamma = c(a2 + b2 - c2);
        let k = c(a2 * a2 + b2 * b2 + c2 * c2 - &two * a2 * b2 - &two * a2 * c2 - &two * b2 * c2);
        let quad = &(&(&(&x * &x) + &(&y * &y)) + &(&z * &z))
            - &(&(&(&x * &y) + &(&x * &z)) + &(&y * &z)).scale(&two);
        let lin = &(&(&alpha * &x) + &(&beta * &y)) + &(&gamma * &z);
        &(&quad + &k) + &lin.scale(&two)
    })
}

/// The linear part of the elimination from the equations [`exact_equations`] gives: x and y
/// as polynomials in z from F₁ − F₃ = F₂ − F₃ = 0, or `None` when the differences do not
/// determine them.
fn linear_part_of(
    [f1, f2, f3]: &[crate::algebra::Poly; 3],
) -> Option<(crate::algebra::Poly, crate::algebra::Poly)> {
    use crate::algebra::Poly;
    use num_traits::Zero;
    let l1 = f1 - f3;
    let l2 = f2 - f3;
    // coefficient of a variable in a linear polynomial, and its z-and-constant rest
    let coef = |p: &Poly, v: &str| {
        p.coefficients_in(v)
            .get(1)
            .and_then(|c| c.terms().next().map(|(_, k)| k.clone()))
            .unwrap_or_else(num_rational::BigRational::zero)
    };
    let rest = |p: &Poly| p.coefficients_in("x")[0].coefficients_in("y")[0].clone();
    let (a1, b1, r1) = (coef(&l1, "x"), coef(&l1, "y"), rest(&l1));
    let (a2, b2, r2) = (coef(&l2, "x"), coef(&l2, "y"), rest(&l2));
    let det = &a1 * &b2 - &a2 * &b1;
    if det.is_zero() {
        return None;
    }
    // a1 x + b1 y = −r1, a2 x + b2 y = −r2
    let inv = <num_rational::BigRational as num_traits::One>::one() / &det;
    let xz = &(-&r1).scale(&(&b2 * &inv)) + &r2.scale(&(&b1 * &inv));
    let yz = &(-&r2).scale(&(&a1 * &inv)) + &r1.scale(&(&a2 * &inv));
    Some((xz, yz))
}

/// Direct elimination over ℚ: solve F₁ − F₃ = F₂ − F₃ = 0 for x and y as polynomials in z,
/// substitute into F₃, and return the resulting polynomial in z (exact), or `None` when the
/// differences do not determine x and y.
pub fn exact_elimination(l: &[[num_rational::BigRational; 3]; 3]) -> Option<crate::algebra::UPoly> {
    exact_elimination_parts(l).map(|(q, _, _)| q)
}

/// [`exact_elimination`] with the linear part it substituted (x and y as polynomials in z
/// from F₁ − F₃ = F₂ − F₃ = 0), the equations expanded once for both.
pub fn exact_elimination_parts(
    l: &[[num_rational::BigRational; 3]; 3],
) -> Option<(
    crate::algebra::UPoly,
    crate::algebra::Poly,
    crate::algebra::Poly,
)> {
    use crate::algebra::UPoly;
    use num_traits::Zero;
    let equations = exact_equations(l);
    let (xz, yz) = linear_part_of(&equations)?;
    let q = equations[2].substitute("x", &xz).substitute("y", &yz);
    let coeffs = q.coefficients_in("z");
    let c: Vec<num_rational::BigRational> = coeffs
        .iter()
        .map(|p| {
            p.terms()
                .next()
                .map(|(_, k)| k.clone())
                .unwrap_or_else(Zero::zero)
        })
        .collect();
    Some((UPoly::new(c), xz, yz))
}

/// Independent routes to the same c² roots, and their largest disagreement with the solver.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Validation {
    /// The solver's real c² values.
    pub solver: Vec<f64>,
    /// Exact elimination over ℚ then Sturm isolation (midpoints of intervals narrower than
    /// 10⁻³⁰ relative): `None` when the exact differences are singular.
    pub exact: Option<Vec<f64>>,
    /// The `roots` crate's closed form on the solver's quadratic.
    pub closed_form: Vec<f64>,
    /// Companion-matrix eigenvalues of the solver's quadratic (real ones).
    pub companion: Vec<f64>,
    /// Largest |solver − other| / |other| over matched roots and routes.
    pub max_relative_disagreement: f64,
    /// Whether every route found the same number of real roots.
    pub same_count: bool,
}

/// Validate one p3f3 solve of exact rational input against the independent routes.
pub fn validate(l: &[[num_rational::BigRational; 3]; 3]) -> Validation {
    use num_traits::ToPrimitive;
    let lf: [[f64; 3]; 3] =
        std::array::from_fn(|i| std::array::from_fn(|e| l[i][e].to_f64().unwrap_or(f64::NAN)));
    let core = solve_core(&lf);
    let mut solver: Vec<f64> = (0..core.count)
        .filter(|&k| core.imag[k][2] == 0.0)
        .map(|k| core.squares[k][2])
        .collect();
    solver.sort_by(f64::total_cmp);
    solver.dedup();
    let exact = exact_elimination(l).map(|p| {
        let width = num_rational::BigRational::new(
            1.into(),
            num_traits::pow(num_bigint::BigInt::from(10), 30),
        );
        p.real_roots_within(&width)
            .iter()
            .map(|r| r.to_f64())
            .collect::<Vec<f64>>()
    });
    let (closed_form, companion) = match core.elimination {
        Some(e) => {
            let to_z = |t: f64| e.slope[2] * t + e.intercept[2];
            let mut cf: Vec<f64> = crate::algebra::closed_form_real(&e.quadratic)
                .into_iter()
                .map(to_z)
                .collect();
            cf.sort_by(f64::total_cmp);
            let agreement = crate::algebra::compare_methods(&e.quadratic, 0.0);
            let mut cm: Vec<f64> = agreement.companion_real.into_iter().map(to_z).collect();
            cm.sort_by(f64::total_cmp);
            (cf, cm)
        }
        None => (Vec::new(), Vec::new()),
    };
    let mut worst: f64 = 0.0;
    let mut same = true;
    for other in [exact.as_ref(), Some(&closed_form), Some(&companion)]
        .into_iter()
        .flatten()
    {
        if other.len() != solver.len() {
            same = false;
        }
        for (a, b) in solver.iter().zip(other) {
            worst = worst.max((a - b).abs() / b.abs().max(f64::MIN_POSITIVE));
        }
    }
    Validation {
        solver,
        exact,
        closed_form,
        companion,
        max_relative_disagreement: worst,
        same_count: same,
    }
}
