//! The audit's dedicated computations, judged.

use num_rational::BigRational;

use crate::check::{
    ClaimBuilder, ClaimResult, Power, ResultBuilder, Role, Tolerance, Value, Verdict,
};
use crate::claims::audit::Shown;
use crate::claims::formula_audit::study::ComputedFinding;
use crate::claims::formula_audit::{ComputedItem, ComputedTest};
use crate::derivations::two_frames::FourthRelation;

/// The judge of a dedicated computation.
pub(super) fn computed_verdict(x: &ComputedFinding) -> Verdict {
    match x {
        ComputedFinding::FourthRelation(r) => identity(signed_dependent(r)),
        ComputedFinding::FourthRelationSquared(r) => squared_verdict(r),
        ComputedFinding::BFormula { solves, .. } => identity(*solves),
        ComputedFinding::SignedRelation {
            three_edges,
            per_sign,
            ..
        } => identity(*three_edges && !per_sign.is_empty() && per_sign.iter().all(|x| *x)),
        ComputedFinding::ConstantSymbols { missing, extra } => {
            if missing.is_empty() && extra.is_empty() {
                Verdict::Reproduced
            } else {
                Verdict::Erratum
            }
        }
        ComputedFinding::OrderedQuadruples {
            rows,
            printed_matches,
        } => Verdict::holds(*printed_matches && rows.iter().all(|r| r.1 == r.2)),
    }
}

/// In the signed depth differences (the paper's square roots with their signs) PQR's loop lies
/// in the span of the other three, and the mutant with one sign changed does not.
fn signed_dependent(r: &FourthRelation) -> bool {
    let s = &r.signed;
    s.rank_three == 3 && s.rank_four == s.rank_three && s.mutant_rank > s.rank_four
}

/// After twofold squaring: not a linear combination, and an exact point where the three hold
/// and the fourth does not.
fn independent_after_squaring(r: &FourthRelation) -> bool {
    let zero = BigRational::from_integer(0.into());
    let v = &r.counterexample_values;
    !r.linear && v.len() == 4 && v[..3].iter().all(|x| *x == zero) && v[3] != zero
}

/// The relation dropped as dependent, in the squared system §5 solves: an erratum when the
/// signed relations are dependent but the squared ones do not imply it (exact point), the
/// identity when they do imply it, contradicted when not even the signed ones are dependent.
fn squared_verdict(r: &FourthRelation) -> Verdict {
    match (signed_dependent(r), independent_after_squaring(r)) {
        (true, true) => Verdict::Erratum,
        (true, false) => Verdict::IdentityVerified,
        (false, _) => Verdict::Contradicted,
    }
}

fn identity(ok: bool) -> Verdict {
    if ok {
        Verdict::IdentityVerified
    } else {
        Verdict::Contradicted
    }
}

/// What each computation's audit line says it should be.
fn should_be(test: &ComputedTest) -> String {
    match test {
        ComputedTest::FourthRelation { .. } => FOURTH.into(),
        ComputedTest::FourthRelationSquared { .. } => SQUARED.into(),
        ComputedTest::BFormula => "b² = (−(c² f_cb + f_b) ± √Δ_b) / (2 f_{b²}) solves f_{b²} b⁴ + b² (c² f_cb + f_b) + (…) = 0; b is its square root where that is non-negative".into(),
        ComputedTest::SignedRelation { edges } => format!(
            "eq. p3f3sqr of the triangle with edges {} (every sign choice)",
            edges.join(", ")
        ),
        ComputedTest::ConstantSymbols { used, .. } => {
            format!("the symbols the expression uses: {}", used.join(", "))
        }
        ComputedTest::OrderedQuadruples { .. } => {
            "n(n−1)(n−2)(n−3) ordered choices of four of n points".into()
        }
    }
}

const FOURTH: &str = "in the signed depth differences the relation of PQR is the sum of those of PQT, QRT and RPT (linearly dependent, as the paper says); after twofold squaring, the form §5 goes on to solve, it is neither a linear combination of the other three nor implied by them: dropping it there admits sign choices no body has";

const SQUARED: &str = "keep the relation of PQR (its sign pattern) beside the three twofold-squared relations: it is implied by the three only before squaring";

/// What the squared system loses: the exact point where the three squared relations hold and
/// the fourth does not.
fn squared<'b>(r: ClaimBuilder<'b>, x: &FourthRelation, seed: u64) -> ClaimBuilder<'b> {
    let value = x
        .counterexample_values
        .get(3)
        .map_or_else(String::new, ToString::to_string);
    let mut r = fourth(r, x, seed);
    if independent_after_squaring(x) {
        r = r
            .detail_as(
                "defect",
                Value::label(format!(
                    "the relation is dropped as linearly dependent, which holds of the signed relations; but §5 goes on to solve the twofold-squared ones, which neither combine linearly into it nor imply it: at an exact point the three vanish and the fourth is {}, so dropping it admits sign choices no body has",
                    value
                )),
                Role::Defect,
            )
            .correction(SQUARED.to_string());
    }
    r
}

fn fourth<'b>(r: ClaimBuilder<'b>, x: &FourthRelation, seed: u64) -> ClaimBuilder<'b> {
    let s = &x.signed;
    let mut r = r
        .method("(0) each triangle's loop Σ ±(z_i − z_j) = 0 as a row over the six signed depth differences, exact ranks of the three loops and of all four; then the twofold-squared forms: (1) F_PQR = λ₁F_PQT + λ₂F_QRT + λ₃F_RPT solved for λ over the rational functions of the projections, monomial by monomial, exactly; (2) an exact point where the three relations hold and the fourth does not; (3) exact ranks of the frame-differenced equations of two frames at a rational scene")
        .computed("rank of the signed loops, three triangles", s.rank_three)
        .computed("rank of the signed loops, with PQR", s.rank_four)
        .computed_cell("after squaring", "a linear combination exists", x.linear)
        .computed_cell("after squaring", "implied by the other three", !independent_after_squaring(x))
        .tolerance(Tolerance::exact("exact arithmetic over ℚ"))
        .power(Power::mutant(
            s.mutant_rank > s.rank_four,
            "PQR's loop with the sign of its last difference changed (a relation no body satisfies) raises the rank: the same rank test rejects it",
        ))
        .detail("scene seed", seed);
    if let Some(o) = &x.obstruction {
        r = r.computed("obstruction", Value::formula(o.clone()));
    }
    for (k, v) in &x.counterexample {
        r = r.detail(&format!("counterexample {k}"), Value::exact(v));
    }
    for (name, v) in ["F_PQT", "F_QRT", "F_RPT", "F_PQR"]
        .iter()
        .zip(&x.counterexample_values)
    {
        r = r.computed(&format!("{name} at the counterexample"), Value::exact(v));
    }
    r.computed_cell("after squaring", "rank, three triangles", x.rank_three)
        .computed_cell("after squaring", "rank, with PQR", x.rank_four)
}

fn describe<'b>(r: ClaimBuilder<'b>, test: &ComputedTest, x: &ComputedFinding) -> ClaimBuilder<'b> {
    match (test, x) {
        (ComputedTest::FourthRelation { seed }, ComputedFinding::FourthRelation(f)) => {
            fourth(r, f, *seed).detail("reading", Value::label(FOURTH))
        }
        (ComputedTest::FourthRelationSquared { seed }, ComputedFinding::FourthRelationSquared(f)) => {
            squared(r, f, *seed)
        }
        (_, ComputedFinding::BFormula { solves, mutant_rejected }) => r
            .method("with A = f_{b²}, B = c² f_cb + f_b, C = the constant part and s = √Δ_b: 4A(AX² + BX + C) for X = (−B ± s)/(2A), reduced by s² = B² − 4AC, exactly over ℚ")
            .computed("both signs solve the quadratic", *solves)
            .tolerance(Tolerance::exact("exact polynomial reduction over ℚ"))
            .power(Power::mutant(*mutant_rejected, "the root with +B in place of −B, X = (B ± s)/(2A): the same reduction leaves a non-zero remainder")),
        (_, ComputedFinding::SignedRelation { per_sign, mutant_rejected, .. }) => {
            let mut r = r
                .method("each of the four sign choices squared twice symbolically, against the triangle's twofold-squared polynomial, exactly over ℚ")
                .tolerance(Tolerance::exact("exact polynomial identity over ℚ"))
                .power(Power::mutant(*mutant_rejected, "the relation with the coefficient of its last radical changed from ±1 to 2: its twofold squaring differs from the triangle's polynomial"));
            for (signs, ok) in ["+ +", "+ −", "− +", "− −"].iter().zip(per_sign) {
                r = r.computed(&format!("signs {signs} give the polynomial"), *ok);
            }
            r
        }
        (ComputedTest::ConstantSymbols { used, also, .. }, ComputedFinding::ConstantSymbols { missing, extra }) => {
            let list = |v: &[String]| if v.is_empty() { "none".to_string() } else { v.join(", ") };
            let mut r = r
                .method("the listed symbols against those of the printed expression")
                .computed("not listed", Value::label(list(missing)))
                .computed("listed but not in the expression", Value::label(list(extra)))
                .tolerance(Tolerance::exact("sets of symbols"))
                .power(Power::exact_value("any symbol missing from the list or listed without use is an erratum"));
            for p in also {
                r = r.detail(&format!("the same list, lines {}", p.lines), Value::quote(p.quote.clone()));
            }
            if missing.is_empty() && extra.is_empty() {
                r
            } else {
                r.detail_as(
                    "defect",
                    Value::label(format!(
                        "the list of constant symbols leaves out {} (used in the expression) and names {} (not in it)",
                        list(missing),
                        list(extra)
                    )),
                    Role::Defect,
                )
                .correction(format!("constant symbols {}", used.join(", ")))
            }
        }
        (_, ComputedFinding::OrderedQuadruples { rows, printed_matches }) => {
            let mut r = r
                .method("the formula against an enumeration of the ordered choices")
                .computed("printed value = the formula's", *printed_matches)
                .tolerance(Tolerance::exact("integer counts"))
                .power(Power::exact_value("only the exact count passes: any other printed integer, or a formula differing from the enumeration at any n, is contradicted"));
            for (n, f, e) in rows {
                r = r.computed("n", *n).computed("formula", *f).computed("enumerated", *e);
            }
            r
        }
        _ => r.power(Power::none("the case's test and its finding do not correspond")),
    }
}

/// One dedicated computation as a claim result and its audit line.
pub(super) fn computed_result(
    b: &ResultBuilder,
    c: &ComputedItem,
    x: &ComputedFinding,
) -> (ClaimResult, Shown) {
    let verdict = computed_verdict(x);
    let r = b
        .claim(&c.claim)
        .suffix(&c.id)
        .printed("statement", Value::label(c.printed.clone()))
        .detail("where", c.place.to_string());
    let r = describe(r, &c.test, x);
    let shown = Shown {
        place: c.place.clone(),
        printed: c.printed.clone(),
        defect: None,
        should_be: should_be(&c.test),
    };
    (r.verdict(verdict), shown)
}
