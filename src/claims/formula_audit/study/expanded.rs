//! The audit expanded to the end: every macro of a formula (faca1 …, d_a1 …, A_c …, f_cb …)
//! and every free symbol of its derivation replaced by its expansion in the projected
//! squares a_i², b_i², c_i² and the true squares a², b², c². Each form is screened modulo
//! 61-bit primes first (a disagreement there already proves the two differ); only a form
//! that passes the screen is compared exactly, and the exact comparison decides.

use std::collections::BTreeMap;

use num_rational::BigRational;
use num_traits::One;
use rayon::prelude::*;

use super::{accepted_quadratic, flip_one_term, read_in_order, Form, Judged};
use crate::algebra::modp::{agree_mod_p, proportional_mod_p, ModPAgreement};
use crate::algebra::{Monomial, Poly, RatFn};
use crate::claims::formula_audit::{FormulaAuditCase, FormulaItem, Relation};
use crate::derivations::appendix_a::in_squares;
use crate::derivations::formulas::derived;
use crate::derivations::twofold::frame_equation;
use crate::error::{Error, Result};

/// One form run through the screen and, when it passes, the exact comparison.
#[derive(Clone, Debug)]
pub struct Screened {
    /// The screen modulo the primes.
    pub screen: ModPAgreement,
    /// The exact comparison ran (only after a passed screen).
    pub exact_run: bool,
    /// `form = ratio · derivation` exactly (`None`: rejected, or the screen already
    /// rejected it).
    pub ratio: Option<BigRational>,
}

impl Screened {
    /// The screen agreed at every point and the exact comparison holds.
    pub fn holds(&self) -> bool {
        self.screen.agreeing == self.screen.points && self.ratio.is_some()
    }
}

/// One displayed formula and its derivation, both expanded to the end.
#[derive(Clone, Debug)]
pub struct ExpandedFinding {
    /// Terms of the expanded derivation (numerator, denominator).
    pub target_terms: (usize, usize),
    /// The variables left after the expansion (projections and edges).
    pub variables: Vec<String>,
    /// The printed form, expanded (`None` when nothing was printed as a formula).
    pub printed: Option<Screened>,
    /// The corrected form, expanded (`None` when there is none).
    pub corrected: Option<Screened>,
    /// The first form that holds.
    pub accepted: Option<Form>,
    /// Terms of the accepted expanded form (numerator, denominator).
    pub accepted_terms: (usize, usize),
    /// Per `quadratic_in` group of the item: the accepted expanded form is at most quadratic
    /// in those squares.
    pub quadratic: Vec<(Vec<String>, bool)>,
    /// The accepted expanded form with one term's sign flipped, through the same check.
    pub mutant: Option<(Monomial, Screened)>,
}

/// The names a macro-level formula may leave free, each with its own derivation expanded:
/// the paper's macros from the frame equations, the others from [`derived`].
pub(super) struct Expansions(BTreeMap<String, RatFn>);

impl Expansions {
    pub(super) fn new(case: &FormulaAuditCase) -> Expansions {
        let mut names: Vec<String> = case.definitions.iter().map(|d| d.name.clone()).collect();
        for f in &case.formulas {
            names.extend(f.symbols.iter().cloned());
            names.extend(f.defines.iter().cloned());
        }
        names.sort();
        names.dedup();
        let mut out = Expansions(BTreeMap::new());
        // a name's derivation may use other names (A_c is in the d's): expand until no
        // name is left, at most once per name
        let mut pending: Vec<(String, RatFn)> = names
            .iter()
            // lowest terms while the derivation is still small (in the d's, not expanded)
            .filter_map(|n| macro_derivation(n).map(|v| (n.clone(), v.reduced())))
            .collect();
        let known: Vec<String> = pending.iter().map(|(n, _)| n.clone()).collect();
        for _ in 0..=known.len() {
            let (ready, rest): (Vec<_>, Vec<_>) = pending
                .into_iter()
                .partition(|(_, v)| v.variables().iter().all(|x| !known.contains(x)));
            for (n, v) in ready {
                out.0.insert(n, v.reduced());
            }
            pending = rest
                .into_iter()
                .map(|(n, v)| {
                    let e = v.substitute_all(&out.0);
                    (n, e)
                })
                .collect();
            if pending.is_empty() {
                break;
            }
        }
        out
    }

    pub(super) fn expand(&self, f: &RatFn) -> RatFn {
        f.substitute_all(&self.0)
    }
}

/// A macro's own derivation: faca_k, facb_k, facc_k, facCst_k are the coefficients of a²,
/// b², c² and the constant of frame k's equation p3f3sqr; every other name is a derivation
/// of [`derived`].
fn macro_derivation(name: &str) -> Option<RatFn> {
    let Some(rest) = name.strip_prefix("fac") else {
        return derived(name);
    };
    let (which, frame) = rest.split_at(rest.len().checked_sub(1)?);
    let e = match which {
        "a" => 0,
        "b" => 1,
        "c" => 2,
        "Cst" => 3,
        _ => return derived(name),
    };
    frame.parse::<u8>().ok()?;
    let f = frame_equation(["a", "b", "c"], frame);
    Some(linear_coefficient(&f, e).into())
}

/// The coefficient of a², b², c² (`e` = 0, 1, 2) or the constant (`e` = 3) of `p`.
fn linear_coefficient(p: &Poly, e: usize) -> Poly {
    let s = ["a", "b", "c"]
        .iter()
        .zip(["x", "y", "z"])
        .fold(p.clone(), |q, (v, x)| {
            in_squares(&q, v, x).unwrap_or_default()
        });
    let pick =
        |p: &Poly, v: &str, k: usize| p.coefficients_in(v).get(k).cloned().unwrap_or_default();
    let k = |i: usize| usize::from(e == i);
    pick(&pick(&pick(&s, "x", k(0)), "y", k(1)), "z", k(2))
}

/// Every formula of the case that `judged` selects, expanded to the end, in order. The
/// parses run in order (a formula reads what earlier ones define); each formula's expansion
/// and checks are independent of the others' and run in parallel.
pub fn expanded(case: &FormulaAuditCase, judged: Judged) -> Result<Vec<ExpandedFinding>> {
    let (expansions, work) = rayon::join(
        || Expansions::new(case),
        || read_in_order(case, judged, |t, defs, _| parse(t, defs)),
    );
    // every formula computed, then the first error in case order (whichever finished first)
    let found: Vec<Result<ExpandedFinding>> = work?
        .into_par_iter()
        .map(|(f, printed, corrected)| {
            let target = derived(&f.derived)
                .ok_or_else(|| Error::InvalidInput(format!("no derivation `{}`", f.derived)))?;
            let target = expansions.expand(&target);
            Ok(one(f, &target, printed, corrected, case))
        })
        .collect();
    found.into_iter().collect()
}

/// `text` read with every name defined so far substituted (the expanded level leaves no
/// symbol free).
fn parse(text: &str, defs: &BTreeMap<String, RatFn>) -> Result<RatFn> {
    RatFn::parse_with(text, defs).map_err(|source| Error::Formula {
        formula: text.to_string(),
        source,
    })
}

fn one(
    f: &FormulaItem,
    target: &RatFn,
    printed: Option<RatFn>,
    corrected: Option<RatFn>,
    case: &FormulaAuditCase,
) -> ExpandedFinding {
    let (n, seed) = (case.evaluation_points, case.seed);
    let check = |e: &RatFn| screened(e, target, f.relation, None, n, seed);
    let p = printed.as_ref().map(check);
    let c = corrected.as_ref().map(check);
    let accepted = match (&p, &c, &printed, &corrected) {
        (Some(s), _, Some(e), _) if s.holds() => Some((Form::Printed, s, e)),
        (_, Some(s), _, Some(e)) if s.holds() => Some((Form::Corrected, s, e)),
        _ => None,
    };
    let mutant = accepted.and_then(|(_, s, e)| {
        let (term, m) = flip_one_term(e)?;
        Some((
            term,
            screened(&m, target, f.relation, s.ratio.as_ref(), n, seed),
        ))
    });
    ExpandedFinding {
        target_terms: (target.num.len(), target.den.len()),
        variables: target.variables(),
        accepted_terms: accepted.map_or((0, 0), |(_, _, e)| (e.num.len(), e.den.len())),
        quadratic: accepted.map_or_else(Vec::new, |(_, _, e)| accepted_quadratic(e, f)),
        accepted: accepted.map(|(form, _, _)| form),
        printed: p,
        corrected: c,
        mutant,
    }
}

/// The screen, then (only when it passed) the exact comparison. `ratio`: the ratio of the
/// accepted form, which a mutant must meet; otherwise the item's relation says whether the
/// ratio is one or any non-zero constant.
fn screened(
    e: &RatFn,
    target: &RatFn,
    relation: Relation,
    ratio: Option<&BigRational>,
    points: usize,
    seed: u64,
) -> Screened {
    let one = BigRational::one();
    let screen = match (ratio, relation) {
        (Some(k), _) => agree_mod_p(e, target, k, points, seed),
        (None, Relation::Equal) => agree_mod_p(e, target, &one, points, seed),
        (None, Relation::Proportional) => proportional_mod_p(e, target, points, seed),
    };
    let exact_run = screen.agreeing == screen.points;
    let ratio = exact_run
        .then(|| match (ratio, relation) {
            (Some(k), _) => {
                (&e.num * &target.den == (&target.num * &e.den).scale(k)).then(|| k.clone())
            }
            (None, Relation::Equal) => e.equals(target).then_some(one),
            (None, Relation::Proportional) => e.ratio_to(target),
        })
        .flatten();
    Screened {
        screen,
        exact_run,
        ratio,
    }
}
