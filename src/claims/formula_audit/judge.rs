//! The formula audit, judged: every displayed formula, printed arithmetic, dedicated
//! computation and textual erratum of `formula_audit.yaml` becomes a claim result. The
//! computations are the study's; here they are only compared and judged.

use num_rational::BigRational;
use num_traits::One;

use crate::algebra::RatFn;
use crate::check::Role;
use crate::check::{
    points_details, points_tolerance, ClaimBuilder, ClaimResult, Power, ResultBuilder, Tolerance,
    Value, Verdict,
};
use crate::claims::audit::Shown;
use crate::claims::formula_audit::study::{
    arithmetic, computed, expanded, formulas, ArithmeticFinding, ExpandedFinding, Form,
    FormulaFinding, Judged,
};
use crate::claims::formula_audit::{ArithmeticItem, FormulaAuditCase, FormulaItem, TextItem};
use crate::derivations::formulas::NAMES;
use crate::error::Result;

/// Longest expansion shown in full; longer ones are named by their size only.
const SHOWN: usize = 400;

fn show(f: &RatFn) -> String {
    let s = match f.to_poly() {
        Some(p) => p.to_string(),
        None => format!("({}) / ({})", f.num, f.den),
    };
    if s.len() <= SHOWN {
        s
    } else {
        format!("{} terms over {} terms", f.num.len(), f.den.len())
    }
}

/// The judge of a formula: the accepted form must agree at every random point and be
/// quadratic where the paper says so; printed → identity verified, corrected → erratum.
fn formula_verdict(f: &FormulaFinding) -> Verdict {
    match &f.accepted {
        None => Verdict::Contradicted,
        Some(a) if !a.points.all_agree() || a.quadratic.iter().any(|q| !q.1) => {
            Verdict::Contradicted
        }
        Some(a) if a.form == Form::Printed => Verdict::IdentityVerified,
        Some(_) => Verdict::Erratum,
    }
}

fn formula_power(f: &FormulaFinding) -> Power {
    let Some(a) = &f.accepted else {
        return Power::none("no form of the formula matched the derivation");
    };
    let Some(m) = &a.mutant else {
        return Power::none("the formula is zero: no term to change");
    };
    let which = match a.form {
        Form::Printed => "the printed formula",
        Form::Corrected => "the corrected formula",
    };
    Power::mutant(
        m.rejected(),
        &format!(
            "{which} with the sign of its term {} flipped: the exact comparison rejects it and the random points disagree",
            Power::term_text(&m.term)
        ),
    )
}

/// One verdict from the two levels of a formula's check: where they differ, neither decides.
fn both_levels(macro_level: Verdict, expanded: Verdict) -> Verdict {
    if macro_level == expanded {
        macro_level
    } else {
        Verdict::Inconclusive
    }
}

/// A formula's claim: the macro-level check, with its expansion to the end (the `/expanded`
/// audit item) as evidence, so that one defect is one erratum.
fn formula_result(
    b: &ResultBuilder,
    f: &FormulaItem,
    x: &FormulaFinding,
    e: &ExpandedFinding,
) -> (ClaimResult, Shown) {
    let what = NAMES.iter().find(|n| n.0 == f.derived).map_or("", |n| n.1);
    let verdict = both_levels(formula_verdict(x), expanded_verdict(e));
    let mut r = expanded_evidence(b.claim(&f.claim).suffix(&f.id), e).undecided(format!(
        "the check over the macros says {} and the check with every macro expanded says {}",
        formula_verdict(x).name(),
        expanded_verdict(e).name()
    ));
    if let Some(p) = &f.printed {
        r = r.printed("formula", Value::formula(p.clone()));
    }
    if let Some(t) = &f.printed_text {
        r = r.printed_as(
            "as printed (LaTeX)",
            Value::formula(t.clone()),
            Role::AsPrinted,
        );
    }
    if let Some(m) = x.printed_matches {
        r = r.computed("printed = derivation", m);
    }
    if let Some(m) = x.corrected_matches {
        r = r.computed("corrected = derivation", m);
    }
    r = r
        .method("exact expansion over ℚ (rational functions compared by cross-multiplication), then Schwartz–Zippel evaluation at seeded random points modulo 61-bit primes, as many as the height of the difference asks; a mutant of the accepted form through the same checks")
        .detail("where", f.place.to_string())
        .power(formula_power(x));
    if let Some(d) = &f.defect {
        r = r.detail_as("defect", d, Role::Defect);
    }
    let should_be = match (&verdict, &f.corrected) {
        (Verdict::Erratum, Some(c)) => format!("{c}   (= {what})"),
        _ => format!("{what}: {}", show(&x.target)),
    };
    if let Some(a) = &x.accepted {
        if a.ratio != BigRational::one() {
            r = r.computed("ratio to the derivation", Value::exact(&a.ratio));
        }
        r = r.computed(
            "random points agreeing",
            Value::count_of(a.points.agreeing, a.points.points),
        );
        for (group, q) in &a.quadratic {
            r = r.computed(
                &format!("quadratic in the squares of {}", group.join(", ")),
                *q,
            );
        }
        r = points_details(r.tolerance(points_tolerance(&a.points)), &a.points);
        if let Some(m) = &a.mutant {
            r = r
                .cell("mutant", "exact comparison rejects", m.exact_rejected)
                .cell(
                    "mutant",
                    "random points agreeing",
                    Value::count_of(m.points.agreeing, m.points.points),
                );
        }
    } else {
        r = r.tolerance(Tolerance::exact("exact comparison over ℚ"));
    }
    finish_formula(r, f, verdict, should_be)
}

/// The end of every formula item, macro-level or expanded: the correction of an erratum (or
/// what it should be, for the rest), the verdict, and the line the audit table shows.
fn finish_formula(
    r: ClaimBuilder<'_>,
    f: &FormulaItem,
    verdict: Verdict,
    should_be: String,
) -> (ClaimResult, Shown) {
    let r = if verdict == Verdict::Erratum {
        r.correction(should_be.clone())
    } else {
        r.detail_as(
            "should be",
            Value::formula(should_be.clone()),
            Role::ShouldBe,
        )
    };
    let shown = Shown {
        place: f.place.clone(),
        printed: f
            .printed
            .clone()
            .or_else(|| f.printed_text.clone())
            .unwrap_or_default(),
        defect: f.defect.clone(),
        should_be,
    };
    (r.verdict(verdict), shown)
}

/// The judge of printed arithmetic: every step equals the printed value exactly.
fn arithmetic_verdict(x: &ArithmeticFinding, printed: &BigRational) -> Verdict {
    let ok = !x.steps.is_empty() && x.steps.iter().all(|s| s.as_ref() == Some(printed));
    if ok {
        Verdict::Reproduced
    } else {
        Verdict::Erratum
    }
}

fn arithmetic_result(b: &ResultBuilder, a: &ArithmeticItem) -> (ClaimResult, Shown) {
    let x = arithmetic(a);
    let verdict = arithmetic_verdict(&x, &a.equals.value);
    let mut r = b
        .claim(&a.claim)
        .suffix(&a.id)
        .printed("steps", Value::formula(a.steps.join(" = ")))
        .printed("value", &a.equals)
        .tolerance(Tolerance::exact("exact rational arithmetic"))
        .power(Power::exact_value(
            "only the exact value passes: a printed value off by any amount, even in the last digit, is an erratum",
        ))
        .method("exact evaluation of every printed step over ℚ")
        .detail("where", a.place.to_string());
    for (k, v) in &a.values {
        r = r.detail(k, *v);
    }
    let values: Vec<Value> = x
        .steps
        .iter()
        .map(|s| {
            s.as_ref()
                .map_or(Value::label("does not evaluate"), Value::exact)
        })
        .collect();
    for (s, v) in a.steps.iter().zip(&values) {
        r = r.computed(s, v.clone());
    }
    let should_be = x
        .steps
        .iter()
        .map(|s| {
            s.as_ref()
                .map_or("does not evaluate".into(), ToString::to_string)
        })
        .collect::<Vec<String>>()
        .join(" = ");
    if verdict == Verdict::Erratum {
        r = r.correction(should_be.clone());
    }
    let shown = Shown {
        place: a.place.clone(),
        printed: format!("{} = {}", a.steps.join(" = "), a.equals.text),
        defect: None,
        should_be,
    };
    (r.verdict(verdict), shown)
}

fn text_result(b: &ResultBuilder, t: &TextItem) -> (ClaimResult, Shown) {
    let r = b
        .claim(&t.claim)
        .suffix(&t.id)
        .printed("text", Value::label(t.printed.clone()))
        .computed("effect", Value::label(t.effect.clone()))
        .correction(t.corrected.clone())
        .power(Power::none("a reading, not a computation"))
        .method("reading against the rest of the paper and the computations")
        .detail("where", t.place.to_string());
    let shown = Shown {
        place: t.place.clone(),
        printed: t.printed.clone(),
        defect: None,
        should_be: t.corrected.clone(),
    };
    (r.verdict(Verdict::Erratum), shown)
}

/// Every item of the case, judged (of the formulas, those `judged` selects), with what its
/// audit line shows: with `twins`, each formula's `/expanded` item after it (the audit lists both levels; as claims, the expansion
/// is evidence of its formula).
fn items(
    b: &ResultBuilder,
    case: &FormulaAuditCase,
    twins: bool,
    judged: Judged,
) -> Result<Vec<(ClaimResult, Shown)>> {
    use rayon::prelude::*;
    let mut out = Vec::new();
    // the two levels of the formulas and the dedicated computations are independent
    let (levels, tests) = rayon::join(
        || match case.formulas.iter().any(judged) {
            // no formula asked: nothing to expand (the macros' expansions cost milliseconds)
            false => Ok((Vec::new(), Vec::new())),
            true => match rayon::join(|| formulas(case, judged), || expanded(case, judged)) {
                (Ok(f), Ok(e)) => Ok((f, e)),
                (Err(e), _) | (_, Err(e)) => Err(e),
            },
        },
        || {
            case.computed
                .par_iter()
                .map(|c| computed(&c.test))
                .collect::<Vec<_>>()
        },
    );
    let (found, expansions) = levels?;
    let asked = case.formulas.iter().filter(|f| judged(f));
    for ((f, x), e) in asked.zip(found).zip(expansions) {
        out.push(formula_result(b, f, &x, &e));
        if twins {
            out.push(expanded_result(b, f, &e));
        }
    }
    out.extend(case.arithmetic.iter().map(|a| arithmetic_result(b, a)));
    out.extend(
        case.computed
            .iter()
            .zip(tests)
            .map(|(c, t)| computed_result(b, c, &t)),
    );
    out.extend(case.text.iter().map(|t| text_result(b, t)));
    for (r, s) in &mut out {
        // the audit spans the paper: each item belongs to its own section
        r.section = s.place.section.clone();
    }
    Ok(out)
}

/// The items `orthocheck audit` lists: both levels of every formula `select` selects.
pub(super) fn judged(
    b: &ResultBuilder,
    case: &FormulaAuditCase,
    select: Judged,
) -> Result<Vec<(ClaimResult, Shown)>> {
    items(b, case, true, select)
}

/// The audit as claim results: one per item, a formula's expansion in its evidence.
pub(super) fn results(b: &ResultBuilder, case: &FormulaAuditCase) -> Result<Vec<ClaimResult>> {
    Ok(items(b, case, false, &|_| true)?
        .into_iter()
        .map(|(r, _)| r)
        .collect())
}

mod computed;
mod expanded;
use computed::computed_result;
use expanded::{expanded_evidence, expanded_result, expanded_verdict};

#[cfg(test)]
mod tests {
    use super::computed::computed_verdict;
    use super::*;
    use crate::algebra::rat;
    use crate::claims::formula_audit::study::ComputedFinding;
    use crate::claims::formula_audit::ComputedTest;
    use crate::studies::points::PointCheck;

    #[test]
    fn the_two_levels_of_a_formula_decide_only_together() {
        let (iv, e) = (Verdict::IdentityVerified, Verdict::Erratum);
        assert_eq!(both_levels(iv, iv), iv);
        assert_eq!(both_levels(e, e), e);
        assert_eq!(both_levels(iv, e), Verdict::Inconclusive);
        assert_eq!(both_levels(e, Verdict::Contradicted), Verdict::Inconclusive);
    }

    fn points(agreeing: usize) -> PointCheck {
        PointCheck {
            points: 4,
            seed: 1,
            agreeing,
            primes: vec![7],
            height_bits: 3,
            degree: 2,
            free_points: 0,
            per_point_bound: 2.0 / 7.0,
        }
    }

    fn finding(form: Form, agreeing: usize, quadratic: bool) -> FormulaFinding {
        FormulaFinding {
            target: RatFn::var("x"),
            printed_matches: Some(form == Form::Printed),
            corrected_matches: None,
            accepted: Some(crate::claims::formula_audit::study::Accepted {
                form,
                ratio: rat(1, 1),
                points: points(agreeing),
                quadratic: vec![(vec!["c".into()], quadratic)],
                mutant: None,
            }),
        }
    }

    #[test]
    fn the_formula_judge_on_both_sides() {
        assert_eq!(
            formula_verdict(&finding(Form::Printed, 4, true)),
            Verdict::IdentityVerified
        );
        assert_eq!(
            formula_verdict(&finding(Form::Corrected, 4, true)),
            Verdict::Erratum
        );
        // one random point disagreeing, or a formula not quadratic, contradicts
        assert_eq!(
            formula_verdict(&finding(Form::Printed, 3, true)),
            Verdict::Contradicted
        );
        assert_eq!(
            formula_verdict(&finding(Form::Printed, 4, false)),
            Verdict::Contradicted
        );
        let mut none = finding(Form::Printed, 4, true);
        none.accepted = None;
        assert_eq!(formula_verdict(&none), Verdict::Contradicted);
    }

    #[test]
    fn the_arithmetic_judge_on_both_sides() {
        let x = ArithmeticFinding {
            steps: vec![Some(rat(18, 1)), Some(rat(18, 1))],
        };
        assert_eq!(arithmetic_verdict(&x, &rat(18, 1)), Verdict::Reproduced);
        assert_eq!(arithmetic_verdict(&x, &rat(17, 1)), Verdict::Erratum);
        let bad = ArithmeticFinding {
            steps: vec![Some(rat(18, 1)), None],
        };
        assert_eq!(arithmetic_verdict(&bad, &rat(18, 1)), Verdict::Erratum);
    }

    #[test]
    fn the_b_formula_solves_its_quadratic_and_its_mutant_does_not() {
        let x = computed(&ComputedTest::BFormula);
        assert!(matches!(
            x,
            ComputedFinding::BFormula {
                solves: true,
                mutant_rejected: true
            }
        ));
        assert_eq!(computed_verdict(&x), Verdict::IdentityVerified);
    }

    #[test]
    fn the_quadruple_judge_on_both_sides() {
        let ok = ComputedFinding::OrderedQuadruples {
            rows: vec![(4, 24, 24)],
            printed_matches: true,
        };
        assert_eq!(computed_verdict(&ok), Verdict::Reproduced);
        let off = ComputedFinding::OrderedQuadruples {
            rows: vec![(4, 24, 24)],
            printed_matches: false,
        };
        assert_eq!(computed_verdict(&off), Verdict::Contradicted);
    }
}
