//! The audit expanded to the end: every macro of a formula (faca1 …, d_a1 …, A_c …, f_cb …)
//! and every free symbol of its derivation replaced by its expansion in the projected
//! squares a_i², b_i², c_i² and the true squares a², b², c². Each form is screened modulo
//! 61-bit primes first (a disagreement there already proves the two differ); only a form
//! that passes the screen is compared exactly, and the exact comparison decides.

use std::collections::BTreeMap;
use std::sync::OnceLock;

use num_rational::BigRational;
use num_traits::One;
use rayon::prelude::*;

use super::reading::{FormulaReading, Text};
use super::{accepted_quadratic, Form, Judged};
use crate::algebra::modp::{agree_mod_p, proportional_mod_p, ModPAgreement};
use crate::algebra::{Monomial, Poly, RatFn};
use crate::claims::formula_audit::{FormulaAuditCase, FormulaItem, Relation};
use crate::derivations::appendix_a::in_squares;
use crate::derivations::formulas::derived;
use crate::derivations::twofold::frame_equation;
use crate::error::{Error, Result};
use crate::studies::points::flip_one_term;

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
/// the paper's macros from the frame equations, the others from [`derived`]. A name's
/// expansion is computed when first asked for, once.
///
/// A name's derivation may use other names (A_c is in the d's). Its expansion substitutes
/// them level by level: first the names whose derivations use no name (level 0), then those
/// that use only names of level 0, and so on, each level in one substitution, then reduces
/// it to lowest terms.
pub(super) struct Expansions {
    /// Every name of the case, with its reduced derivation and its expansion (with its level),
    /// each computed when first asked for; `None` where the name has no derivation.
    names: BTreeMap<String, Expansion>,
    /// The derivations the formulas are compared with, expanded, each once (two formulas
    /// may share one).
    targets: BTreeMap<String, OnceLock<Option<RatFn>>>,
}

#[derive(Default)]
struct Expansion {
    derivation: OnceLock<Option<RatFn>>,
    expanded: OnceLock<Option<(RatFn, usize)>>,
}

impl Expansions {
    pub(super) fn new(case: &FormulaAuditCase) -> Expansions {
        let mut names: Vec<&String> = case.definitions.iter().map(|d| &d.name).collect();
        for f in &case.formulas {
            names.extend(&f.symbols);
            names.extend(&f.defines);
        }
        Expansions {
            names: names
                .into_iter()
                .map(|n| (n.clone(), Expansion::default()))
                .collect(),
            targets: case
                .formulas
                .iter()
                .map(|f| (f.derived.clone(), OnceLock::new()))
                .collect(),
        }
    }

    /// The derivation `name` (of [`derived`]) expanded, `None` for an unknown one.
    pub(super) fn target(&self, name: &str) -> Option<&RatFn> {
        self.targets
            .get(name)?
            .get_or_init(|| derived(name).map(|t| self.expand(&t)))
            .as_ref()
    }

    /// The name's derivation in lowest terms (while still small: in the d's, not expanded).
    fn derivation(&self, name: &str) -> Option<&RatFn> {
        let e = self.names.get(name)?;
        e.derivation
            .get_or_init(|| macro_derivation(name).map(|v| v.reduced()))
            .as_ref()
    }

    /// The name's expansion and its level.
    fn expansion(&self, name: &str) -> Option<&(RatFn, usize)> {
        let e = self.names.get(name)?;
        e.expanded
            .get_or_init(|| {
                let mut v = self.derivation(name)?.clone();
                let used: Vec<(String, &(RatFn, usize))> = v
                    .variables()
                    .into_iter()
                    .filter(|x| self.derivation(x).is_some())
                    .map(|x| self.expansion(&x).map(|e| (x, e)))
                    .collect::<Option<_>>()?;
                let top = used
                    .iter()
                    .map(|(_, (_, level))| level + 1)
                    .max()
                    .unwrap_or(0);
                for level in 0..top {
                    let at: BTreeMap<String, RatFn> = used
                        .iter()
                        .filter(|(_, (_, l))| *l == level)
                        .map(|(x, (value, _))| (x.clone(), value.clone()))
                        .collect();
                    if !at.is_empty() {
                        v = v.substitute_all(&at);
                    }
                }
                Some((v.reduced(), top))
            })
            .as_ref()
    }

    /// `f` with every name of the case it uses replaced by its expansion (at once).
    pub(super) fn expand(&self, f: &RatFn) -> RatFn {
        let values: BTreeMap<String, RatFn> = f
            .variables()
            .into_iter()
            .filter_map(|x| self.expansion(&x).map(|(v, _)| (x, v.clone())))
            .collect();
        f.substitute_all(&values)
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

/// Every formula of the case that `judged` selects, expanded to the end, in order. Each
/// formula reads, expands and checks what it needs (each text and each name's expansion is
/// computed once, by whichever formula needs it first), in parallel.
pub fn expanded(case: &FormulaAuditCase, judged: Judged) -> Result<Vec<ExpandedFinding>> {
    let (expansions, reading) = (Expansions::new(case), FormulaReading::new(case, false));
    // every formula computed, then the first error in case order (whichever finished first)
    let found: Vec<Result<ExpandedFinding>> = case
        .formulas
        .par_iter()
        .enumerate()
        .filter(|(_, f)| judged(f))
        .map(|(i, f)| {
            // the formula's forms and its target are independent
            let (forms, target) = rayon::join(
                || -> Result<_> {
                    Ok((
                        reading.read(Text::Printed(i))?,
                        reading.read(Text::Corrected(i))?,
                    ))
                },
                || expansions.target(&f.derived),
            );
            let (printed, corrected) = forms?;
            let target = target
                .ok_or_else(|| Error::InvalidInput(format!("no derivation `{}`", f.derived)))?;
            Ok(one(f, target, printed, corrected, case))
        })
        .collect();
    found.into_iter().collect()
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
            (Some(k), _) => e.is_multiple(target, k).then(|| k.clone()),
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
