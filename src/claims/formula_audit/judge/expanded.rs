//! The `/expanded` audit items: a displayed formula and its derivation with every macro
//! expanded into the projected and the true squares, judged like the macro-level item.

use super::{ClaimBuilder, ClaimResult, Power, ResultBuilder, Tolerance, Value, Verdict};
use crate::check::{prime_details, Role};
use crate::claims::audit::Shown;
use crate::claims::formula_audit::study::{ExpandedFinding, Form, Screened};
use crate::claims::formula_audit::FormulaItem;
use crate::derivations::formulas::NAMES;

/// The judge: the accepted expanded form must pass the screen and the exact comparison and
/// be quadratic where the paper says so; printed → identity verified, corrected → erratum.
pub(super) fn expanded_verdict(x: &ExpandedFinding) -> Verdict {
    match x.accepted {
        None => Verdict::Contradicted,
        Some(_) if x.quadratic.iter().any(|q| !q.1) => Verdict::Contradicted,
        Some(Form::Printed) => Verdict::IdentityVerified,
        Some(Form::Corrected) => Verdict::Erratum,
    }
}

fn expanded_power(x: &ExpandedFinding) -> Power {
    let Some(form) = x.accepted else {
        return Power::none("no form of the expanded formula matched the expanded derivation");
    };
    let Some((term, m)) = &x.mutant else {
        return Power::none("the expanded formula is zero: no term to change");
    };
    let which = match form {
        Form::Printed => "the expanded printed formula",
        Form::Corrected => "the expanded corrected formula",
    };
    Power::mutant(
        !m.holds(),
        &format!(
            "{which} with the sign of its term {} flipped: the screen modulo the primes (and, if it passed, the exact comparison) rejects it",
            Power::term_text(term)
        ),
    )
}

fn screen_details<'b>(r: ClaimBuilder<'b>, who: &str, s: &Screened) -> ClaimBuilder<'b> {
    r.computed_cell(
        who,
        "points agreeing modulo the primes",
        Value::count_of(s.screen.agreeing, s.screen.points),
    )
    .computed_cell(who, "exact comparison run", s.exact_run)
    .computed_cell(who, "exactly equal", s.ratio.is_some())
}

/// The expansion as evidence of the macro-level item: its verdict and checks, one row of
/// cells.
pub(super) fn expanded_evidence<'b>(r: ClaimBuilder<'b>, x: &ExpandedFinding) -> ClaimBuilder<'b> {
    const WHO: &str = "every macro expanded";
    let mut r = r.computed_cell(WHO, "verdict", Value::label(expanded_verdict(x).name()));
    let accepted = match x.accepted {
        Some(Form::Printed) => x.printed.as_ref(),
        Some(Form::Corrected) => x.corrected.as_ref(),
        None => None,
    };
    if let Some(s) = accepted {
        r = r
            .computed_cell(
                WHO,
                "points agreeing modulo the primes",
                Value::count_of(s.screen.agreeing, s.screen.points),
            )
            .computed_cell(WHO, "exactly equal", s.ratio.is_some());
    }
    if let Some((_, m)) = &x.mutant {
        r = r.computed_cell(WHO, "mutant rejected", !m.holds());
    }
    r
}

/// The `/expanded` item of formula `f`.
pub(super) fn expanded_result(
    b: &ResultBuilder,
    f: &FormulaItem,
    x: &ExpandedFinding,
) -> (ClaimResult, Shown) {
    let what = NAMES.iter().find(|n| n.0 == f.derived).map_or("", |n| n.1);
    let verdict = expanded_verdict(x);
    let mut r = b.claim(&f.claim).suffix(&format!("{}/expanded", f.id));
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
    if let Some(s) = &x.printed {
        r = screen_details(r, "printed, expanded", s);
    }
    if let Some(s) = &x.corrected {
        r = screen_details(r, "corrected, expanded", s);
    }
    for (group, q) in &x.quadratic {
        r = r.computed(
            &format!("quadratic in the squares of {}", group.join(", ")),
            *q,
        );
    }
    if let Some(s) = x.printed.as_ref().or(x.corrected.as_ref()) {
        r = prime_details(r, &s.screen)
            .detail("seed of the points", s.screen.seed)
            .detail(
                "degree of the cross-multiplied difference",
                s.screen.degree as usize,
            )
            .detail(
                "failure bound of the screen per point (degree / p)",
                Value::real(s.screen.per_point_bound),
            );
    }
    if let Some((_, m)) = &x.mutant {
        r = r.cell(
            "mutant",
            "points agreeing modulo the primes",
            Value::count_of(m.screen.agreeing, m.screen.points),
        );
    }
    r = r
        .method("every macro of the formula and every symbol of its derivation expanded into the projected squares aᵢ², bᵢ², cᵢ² and the true squares a², b², c²; screened at seeded random points modulo 61-bit primes, as many as the height of the difference asks (Schwartz–Zippel; a disagreement proves the forms differ), then compared exactly over ℚ by cross-multiplication, which decides; a mutant of the accepted form through the same checks")
        .tolerance(Tolerance::exact("exact comparison over ℚ of the expanded forms"))
        .detail("where", f.place.to_string())
        .detail("variables after the expansion", x.variables.len())
        .detail("terms of the expanded derivation (numerator)", x.target_terms.0)
        .detail("terms of the expanded derivation (denominator)", x.target_terms.1)
        .detail("terms of the accepted expanded form (numerator)", x.accepted_terms.0)
        .detail("terms of the accepted expanded form (denominator)", x.accepted_terms.1)
        .power(expanded_power(x));
    if let Some(d) = &f.defect {
        r = r.detail_as("defect", d, Role::Defect);
    }
    let should_be = match (&verdict, &f.corrected) {
        (Verdict::Erratum, Some(c)) => format!("{c}   (= {what}, every macro expanded)"),
        _ => format!("{what}, every macro expanded"),
    };
    super::finish_formula(r, f, verdict, should_be)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::modp::ModPAgreement;
    use crate::algebra::rat;

    fn screened(agreeing: usize, exact: bool) -> Screened {
        Screened {
            screen: ModPAgreement {
                points: 4,
                seed: 1,
                agreeing,
                primes: vec![7],
                height_bits: 3,
                degree: 2,
                free_points: 0,
                per_point_bound: 2.0 / 7.0,
            },
            exact_run: agreeing == 4,
            ratio: exact.then(|| rat(1, 1)),
        }
    }

    fn finding(accepted: Option<Form>, quadratic: bool) -> ExpandedFinding {
        ExpandedFinding {
            target_terms: (1, 1),
            variables: vec!["x".into()],
            printed: Some(screened(4, true)),
            corrected: None,
            accepted,
            accepted_terms: (1, 1),
            quadratic: vec![(vec!["c".into()], quadratic)],
            mutant: None,
        }
    }

    #[test]
    fn the_expanded_judge_on_both_sides() {
        let v = |a, q| expanded_verdict(&finding(a, q));
        assert_eq!(v(Some(Form::Printed), true), Verdict::IdentityVerified);
        assert_eq!(v(Some(Form::Corrected), true), Verdict::Erratum);
        assert_eq!(v(Some(Form::Printed), false), Verdict::Contradicted);
        assert_eq!(v(None, true), Verdict::Contradicted);
    }

    #[test]
    fn a_form_holds_only_through_both_stages() {
        assert!(screened(4, true).holds());
        // one point off modulo a prime, or the exact comparison failing, rejects
        assert!(!screened(3, true).holds());
        assert!(!screened(4, false).holds());
    }
}
