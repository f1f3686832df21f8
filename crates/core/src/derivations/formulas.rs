//! The paper's displayed formulas as this crate derives them, by name: the audit compares
//! each printed transcription (in `paper_cases/`) with the derivation named here.

use crate::algebra::{solve_linear, Poly, RatFn};
use crate::derivations::appendix_a::{eliminate_symbolic, in_squares};
use crate::derivations::twofold::{frame_equation, twofold_squared};

/// Every name [`derived`] knows, with what it derives.
pub const NAMES: &[(&str, &str)] = &[
    ("twofold", "eq. p3f3sqr: √A ± √B ± √C = 0 squared twice (§2.2)"),
    ("F1-F3", "frame 1's equation minus frame 3's (§2.2)"),
    ("F2-F3", "frame 2's equation minus frame 3's (§2.2)"),
    ("d_a1", "the coefficient of a² in F1 − F3"),
    ("d_b1", "the coefficient of b² in F1 − F3"),
    ("d_c1", "the coefficient of c² in F1 − F3"),
    ("d_Cst1", "the constant of F1 − F3"),
    ("d_a2", "the coefficient of a² in F2 − F3"),
    ("d_b2", "the coefficient of b² in F2 − F3"),
    ("d_c2", "the coefficient of c² in F2 − F3"),
    ("d_Cst2", "the constant of F2 − F3"),
    ("cramer_a2", "a² from d_a1 a² + d_b1 b² + d_c1 c² + d_Cst1 = 0 (and frame 2) by elimination"),
    ("cramer_b2", "b² likewise"),
    ("A_c", "the coefficient of c² in a²"),
    ("A_Cst", "the constant of a²"),
    ("B_c", "the coefficient of c² in b²"),
    ("B_Cst", "the constant of b²"),
    ("p3f3_quadratic", "F3 with a² = A_c c² + A_Cst and b² = B_c c² + B_Cst"),
    ("p3f4_difference", "F_i − F_1 (§3)"),
    ("p4f3_PQT", "F_i − F_1 of the triangle PQT, edges a, g, f (§4)"),
    ("p4f3_QRT", "F_i − F_1 of the triangle QRT, edges d, b, g (§4)"),
    ("p4f3_RPT", "F_i − F_1 of the triangle RPT, edges d, f, c (§4)"),
    ("F1_in_macros", "eq. p3f3sqr of frame 1 written with the macros: quadratic part + facCst1 + faca1 a² + facb1 b² + facc1 c²"),
    ("appA_equation", "F_1 with a² eliminated through F_1 − F_2 (Appendix A), in the macros faca1 … facCst2"),
    ("appA_f_cb", "its coefficient of b²c²"),
    ("appA_f_c", "its coefficient of c²"),
    ("appA_f_b", "its coefficient of b²"),
    ("appA_f_Cst", "its constant"),
    ("appA_f_b2", "its coefficient of b⁴"),
    ("appA_f_c2", "its coefficient of c⁴"),
    ("appA_delta_b", "the discriminant of the equation as a quadratic in b²"),
];

/// `p` in the squares x = a², y = b², z = c² (exact: the twofold equations have only even
/// powers of the edges).
fn squares(p: &Poly) -> Poly {
    let p = in_squares(p, "a", "x").unwrap_or_default();
    let p = in_squares(&p, "b", "y").unwrap_or_default();
    in_squares(&p, "c", "z").unwrap_or_default()
}

/// Back from the squares to a, b, c.
fn edges(p: &Poly) -> Poly {
    p.substitute("x", &Poly::var("a").pow(2))
        .substitute("y", &Poly::var("b").pow(2))
        .substitute("z", &Poly::var("c").pow(2))
}

/// The coefficient of a², b², c² (`e` = 0, 1, 2) or the constant (`e` = 3) of a polynomial
/// linear in the squares.
fn linear_part(p: &Poly, e: usize) -> Poly {
    let s = squares(p);
    let pick =
        |p: &Poly, v: &str, k: usize| p.coefficients_in(v).get(k).cloned().unwrap_or_default();
    match e {
        0 => pick(&pick(&pick(&s, "x", 1), "y", 0), "z", 0),
        1 => pick(&pick(&pick(&s, "x", 0), "y", 1), "z", 0),
        2 => pick(&pick(&pick(&s, "x", 0), "y", 0), "z", 1),
        _ => pick(&pick(&pick(&s, "x", 0), "y", 0), "z", 0),
    }
}

fn abc(frame: &str) -> Poly {
    frame_equation(["a", "b", "c"], frame)
}

/// a² and b² from the two difference equations with the d's as free symbols.
fn cramer() -> Option<Vec<RatFn>> {
    let v = RatFn::var;
    let m = vec![vec![v("d_a1"), v("d_b1")], vec![v("d_a2"), v("d_b2")]];
    let c2 = RatFn::from(Poly::var("c").pow(2));
    let rhs = [
        -&(&(&v("d_c1") * &c2) + &v("d_Cst1")),
        -&(&(&v("d_c2") * &c2) + &v("d_Cst2")),
    ];
    solve_linear(&m, &rhs)
}

/// The coefficient of c² (`k` = 1) or the constant (`k` = 0) of an expression affine in c².
fn in_c2(f: &RatFn, k: usize) -> RatFn {
    let num = in_squares(&f.num, "c", "z").unwrap_or_default();
    RatFn {
        num: num.coefficients_in("z").get(k).cloned().unwrap_or_default(),
        den: f.den.clone(),
    }
}

/// The derivation called `name` (see [`NAMES`]), or `None` for an unknown name.
///
/// # Example
/// ```
/// use orthocheck_core::{algebra::RatFn, derivations::formulas::derived};
/// let d = derived("d_a1").unwrap();
/// let printed = RatFn::parse("2(-a_1^2+b_1^2+c_1^2) - 2(-a_3^2+b_3^2+c_3^2)").unwrap();
/// assert!(d.equals(&printed));
/// ```
pub fn derived(name: &str) -> Option<RatFn> {
    // each derived once per process: the audit's two levels, its expansions and the census
    // ask for the same ones
    static DERIVED: std::sync::LazyLock<Vec<std::sync::OnceLock<Option<RatFn>>>> =
        std::sync::LazyLock::new(|| NAMES.iter().map(|_| std::sync::OnceLock::new()).collect());
    let at = NAMES.iter().position(|(n, _)| *n == name)?;
    DERIVED[at].get_or_init(|| derive(name)).clone()
}

fn derive(name: &str) -> Option<RatFn> {
    let diff = |i: &str, j: &str| &abc(i) - &abc(j);
    let tri = |e: [&str; 3]| &frame_equation(e, "i") - &frame_equation(e, "1");
    let app = eliminate_symbolic;
    let r: RatFn = match name {
        "twofold" => twofold_squared([1, 1, -1]).into(),
        "F1-F3" => diff("1", "3").into(),
        "F2-F3" => diff("2", "3").into(),
        "d_a1" | "d_b1" | "d_c1" | "d_Cst1" | "d_a2" | "d_b2" | "d_c2" | "d_Cst2" => {
            let d = if name.ends_with('1') {
                diff("1", "3")
            } else {
                diff("2", "3")
            };
            let e = match &name[2..name.len() - 1] {
                "a" => 0,
                "b" => 1,
                "c" => 2,
                _ => 3,
            };
            linear_part(&d, e).into()
        }
        "cramer_a2" => cramer()?.first()?.clone(),
        "cramer_b2" => cramer()?.get(1)?.clone(),
        "A_c" => in_c2(cramer()?.first()?, 1),
        "A_Cst" => in_c2(cramer()?.first()?, 0),
        "B_c" => in_c2(cramer()?.get(1)?, 1),
        "B_Cst" => in_c2(cramer()?.get(1)?, 0),
        "p3f3_quadratic" => {
            let z = Poly::var("z");
            let f3 = squares(&abc("3"))
                .substitute("x", &(&(&Poly::var("A_c") * &z) + &Poly::var("A_Cst")))
                .substitute("y", &(&(&Poly::var("B_c") * &z) + &Poly::var("B_Cst")));
            edges(&f3).into()
        }
        "p3f4_difference" => (&abc("i") - &abc("1")).into(),
        "p4f3_PQT" => tri(["a", "g", "f"]).into(),
        "p4f3_QRT" => tri(["d", "b", "g"]).into(),
        "p4f3_RPT" => tri(["d", "f", "c"]).into(),
        "F1_in_macros" => abc("1").into(),
        "appA_equation" => app().equation.clone(),
        "appA_f_cb" => app().f_cb.clone(),
        "appA_f_c" => app().f_c.clone(),
        "appA_f_b" => app().f_b.clone(),
        "appA_f_Cst" => app().f_cst.clone(),
        "appA_f_b2" => app().f_b2.clone(),
        "appA_f_c2" => app().f_c2.clone(),
        "appA_delta_b" => app().delta_b(),
        _ => return None,
    };
    Some(r)
}

/// Whether `p` is at most quadratic in the squares of each of `vars` (only even powers, at
/// most the fourth).
pub fn quadratic_in_squares(p: &Poly, vars: &[&str]) -> bool {
    let at: Vec<usize> = vars.iter().filter_map(|v| p.ring().index(v)).collect();
    let prim = p.primitive().1;
    (0..prim.len()).all(|t| {
        let e = prim.exponents(t);
        at.iter().all(|&i| e[i].is_multiple_of(2)) && at.iter().map(|&i| e[i]).sum::<u32>() <= 4
    })
}

/// The number of ordered choices of `r` distinct items out of `n`: n(n−1)⋯(n−r+1).
pub fn ordered_choices(n: usize, r: usize) -> usize {
    (0..r).map(|i| n.saturating_sub(i)).product()
}

/// The same number by enumeration: every sequence of `r` distinct indices below `n`.
pub fn ordered_choices_enumerated(n: usize, r: usize) -> usize {
    fn extend(n: usize, r: usize, used: &mut Vec<usize>) -> usize {
        if used.len() == r {
            return 1;
        }
        let mut count = 0;
        for i in 0..n {
            if !used.contains(&i) {
                used.push(i);
                count += extend(n, r, used);
                used.pop();
            }
        }
        count
    }
    extend(n, r, &mut Vec::new())
}
