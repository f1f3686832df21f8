//! SymPy scripts for readers who trust another computer-algebra system: one self-contained
//! script per audited identity (macro-level and `/expanded`) that rebuilds the accepted
//! formula from its transcription and the paper's macro definitions with SymPy's own parser,
//! writes out this crate's derivation term by term, and checks
//! `sympy.expand(numerator(lhs − k·rhs)) == 0`.

use std::fmt::Write as _;

use num_rational::BigRational;

use super::expanded::Expansions;
use super::{expanded, formulas};
use crate::algebra::{Poly, RatFn};
use crate::claims::audit::Script;
use crate::claims::formula_audit::FormulaAuditCase;
use crate::derivations::formulas::derived;
use crate::error::{Error, Result};

/// The start of every script: the parser of the transcriptions' syntax.
const HEADER: &str = r#"#!/usr/bin/env python3
# orthocheck audit item {ID}: re-verified in SymPy.
# The formula is rebuilt from its transcription (paper_cases/formula_audit.yaml) and the
# paper's macros by SymPy's parser; the derivation is this crate's, written out term by term.
import re
import sys
import sympy
from sympy.parsing.sympy_parser import parse_expr, standard_transformations


def names(text, defined):
    """Every identifier of `text` is a plain symbol unless defined (no SymPy built-ins)."""
    local = dict(defined)
    for name in set(re.findall(r'[A-Za-z][A-Za-z0-9_]*', text)):
        local.setdefault(name, sympy.Symbol(name))
    return local


def parse(text, defs, keep=()):
    # the transcriptions' syntax: juxtaposition multiplies, ^ is a power
    tokens = re.findall(r'[A-Za-z][A-Za-z0-9_]*|[0-9]+(?:\.[0-9]*)?|\S', text)
    out = []
    for t in tokens:
        if out and (out[-1][-1].isalnum() or out[-1][-1] in '_)') and (t[0].isalnum() or t == '('):
            out.append('*')
        out.append('**' if t == '^' else t)
    text = ' '.join(out)
    local = names(text, {k: v for k, v in defs.items() if k not in keep})
    return parse_expr(text, local_dict=local, transformations=standard_transformations)


defs = {}
"#;

/// A polynomial as a Python/SymPy expression string: exact rationals, `**` powers.
fn py_poly(p: &Poly) -> String {
    if p.is_zero() {
        return "0".into();
    }
    let mut s = String::new();
    for (m, c) in p.terms() {
        let _ = write!(s, " + ({})", c);
        for (v, e) in m.factors() {
            let _ = if *e == 1 {
                write!(s, "*{v}")
            } else {
                write!(s, "*{v}**{e}")
            };
        }
    }
    s
}

fn py_ratfn(f: &RatFn) -> String {
    format!("({}) / ({})", py_poly(&f.num), py_poly(&f.den))
}

/// Python string literal (the transcriptions are ASCII; quotes and backslashes escaped).
fn py_str(s: &str) -> String {
    format!("{s:?}")
}

/// The script for one identity: `defs` the (name, text, kept symbols) chain the formula
/// needs, `text` its accepted form, `keep` the names left free, `target` the derivation,
/// `ratio` accepted = ratio · derivation.
fn script(
    id: &str,
    defs: &[(String, String, Vec<String>)],
    text: &str,
    keep: &[String],
    target: &RatFn,
    ratio: &BigRational,
    expanded: bool,
) -> String {
    let mut s = String::new();
    s.push_str(&HEADER.replace("{ID}", id));
    for (name, t, k) in defs {
        // expanded: every definition in full, no name left free
        let k: &[String] = if expanded { &[] } else { k };
        let _ = writeln!(
            s,
            "defs[{}] = parse({}, defs, {k:?})",
            py_str(name),
            py_str(t)
        );
    }
    let _ = writeln!(s, "lhs = parse({}, defs, {keep:?})", py_str(text));
    let _ = writeln!(
        s,
        "rhs_text = {}\nrhs = parse_expr(rhs_text, local_dict=names(rhs_text, {{}}), transformations=standard_transformations)",
        py_str(&py_ratfn(target))
    );
    let _ = writeln!(s, "k = sympy.Rational({})", py_str(&ratio.to_string()));
    let _ = writeln!(
        s,
        "num, _ = sympy.fraction(sympy.together(lhs - k * rhs))\nok = sympy.expand(num) == 0\nprint(('OK ' if ok else 'FAILED ') + {})\nsys.exit(0 if ok else 1)",
        py_str(id)
    );
    s
}

/// Scripts for every identity of the audit the case accepts (printed or corrected form),
/// macro-level and expanded.
pub fn sympy_scripts(case: &FormulaAuditCase) -> Result<Vec<Script>> {
    let exp = Expansions::new(case);
    let macro_level = formulas(case, &|_| true)?;
    let expanded_level = expanded(case, &|_| true)?;
    let mut chain: Vec<(String, String, Vec<String>)> = case
        .definitions
        .iter()
        .map(|d| (d.name.clone(), d.printed.clone(), Vec::new()))
        .collect();
    let mut out = Vec::new();
    for ((f, m), e) in case.formulas.iter().zip(&macro_level).zip(&expanded_level) {
        let form = |corrected: bool| {
            if corrected {
                f.corrected.clone()
            } else {
                f.printed.clone()
            }
        };
        let id = format!("{}/{}", f.claim.claim, f.id);
        let target = derived(&f.derived)
            .ok_or_else(|| Error::InvalidInput(format!("no derivation `{}`", f.derived)))?;
        if let (Some(a), Some(text)) = (
            &m.accepted,
            m.accepted
                .as_ref()
                .and_then(|a| form(a.form == super::Form::Corrected)),
        ) {
            let source = script(&id, &chain, &text, &f.symbols, &target, &a.ratio, false);
            out.push(named(id.clone(), source));
        }
        let accepted = e.accepted.and_then(|form_| {
            let s = match form_ {
                super::Form::Printed => e.printed.as_ref(),
                super::Form::Corrected => e.corrected.as_ref(),
            }?;
            Some((form(form_ == super::Form::Corrected)?, s.ratio.clone()?))
        });
        if let Some((text, ratio)) = accepted {
            let id = format!("{id}/expanded");
            let source = script(&id, &chain, &text, &[], &exp.expand(&target), &ratio, true);
            out.push(named(id, source));
        }
        if let (Some(name), Some(text)) = (&f.defines, f.corrected.as_ref().or(f.printed.as_ref()))
        {
            chain.push((name.clone(), text.clone(), f.symbols.clone()));
        }
    }
    Ok(out)
}

fn named(id: String, source: String) -> Script {
    Script {
        file: format!("{}.py", id.replace('/', "__")),
        id,
        source,
    }
}
