//! Checks serde cannot express: counts, sign patterns, formulas that parse.

use std::path::Path;

use super::load::invalid;
use super::*;
use crate::algebra::Poly;
use crate::error::Result;

/// Checks serde cannot express: counts, sign patterns, and that every formula parses.
pub(super) fn validate(case: &Case, text: &str, path: &Path) -> Result<()> {
    let err = |field: &str, message: String| Err(invalid(text, path, field, message));
    let formula = |field: &str, f: &str| match Poly::parse(f) {
        Ok(_) => Ok(()),
        Err(e) => err(field, format!("formula does not parse: {e}")),
    };
    if case.id.trim().is_empty() {
        return err("id", "must not be empty".into());
    }
    // suffixes and the exception must name claims of the census
    let census_names = |c: &CensusCase| {
        let known = |id: &String| c.claims.iter().any(|k| &k.claim == id);
        if let Some(id) = c.suffixes.keys().find(|id| !known(id)) {
            return err("check.suffixes", format!("{id} is not one of the claims"));
        }
        match &c.exception {
            Some(e) if !known(&e.qualifies) => err(
                "check.exception.qualifies",
                format!("{} is not one of the claims", e.qualifies),
            ),
            _ => Ok(()),
        }
    };
    match &case.check {
        CaseCheck::DofCount(c) => {
            for (i, e) in c.examples.iter().enumerate() {
                if e.points == 0 || e.frames == 0 {
                    return err(
                        &format!("check.dof_count.examples[{i}].points"),
                        "points and frames must be at least 1".into(),
                    );
                }
            }
        }
        CaseCheck::DofIdentifiability(c) => {
            if c.max_points < 3 || c.max_frames < 3 {
                return err(
                    "check.dof_identifiability.max_points",
                    "the grid must reach at least 3 points and 3 frames".into(),
                );
            }
            formula(
                "check.dof_identifiability.formula.unknowns",
                &c.formula.unknowns,
            )?;
            formula(
                "check.dof_identifiability.formula.measurements",
                &c.formula.measurements,
            )?;
        }
        CaseCheck::TwofoldSquared(c) => {
            for (i, p) in c.relations.patterns.iter().enumerate() {
                if parse_signs(p).is_none() {
                    return err(
                        &format!("check.twofold_squared.relations.patterns[{i}]"),
                        format!("'{p}' is not three signs such as \"+ + -\""),
                    );
                }
            }
            formula(
                "check.twofold_squared.polynomial.printed",
                &c.polynomial.printed,
            )?;
        }
        CaseCheck::NoiseStudy(c) => {
            use crate::model::StudySolver;
            let edges = match c.solver {
                StudySolver::P3f3 | StudySolver::P3f4 => 3,
                StudySolver::P4f3 => 6,
            };
            if c.body.lengths.len() != edges
                || !(c.body.squares.is_empty() || c.body.squares.len() == edges)
            {
                return err(
                    "check.noise_study.body.lengths",
                    format!("the solver needs {edges} lengths (and {edges} squares if any)"),
                );
            }
            let frames_ok = match c.solver {
                StudySolver::P3f3 | StudySolver::P4f3 => c.frames == 3,
                StudySolver::P3f4 => c.frames >= 4,
            };
            if !frames_ok {
                return err(
                    "check.noise_study.frames",
                    "p3f3 and p4f3 need 3 frames, p3f4 at least 4".into(),
                );
            }
            for (i, l) in c.levels.iter().enumerate() {
                if l.printed.is_empty() || l.printed.iter().any(|p| p.len() != edges) {
                    return err(
                        &format!("check.noise_study.levels[{i}].printed"),
                        format!("needs solutions of {edges} values"),
                    );
                }
            }
        }
        CaseCheck::TwoFrames(c) => {
            if c.counterexample.points.len() != 5 || c.counterexample.names.len() != 5 {
                return err(
                    "check.two_frames.counterexample.points",
                    "needs the five points P, Q, R, Q′, R′".into(),
                );
            }
            if c.points < 4 || c.trials == 0 || c.curve_samples < 4 {
                return err(
                    "check.two_frames.points",
                    "needs at least 4 points, 1 trial and 4 curve samples".into(),
                );
            }
            let in_range = |b: &f64| *b > 0.0 && *b < std::f64::consts::PI;
            if c.betas.len() < 2 || !c.betas.iter().all(in_range) {
                return err(
                    "check.two_frames.betas",
                    "needs at least two angles in (0, π)".into(),
                );
            }
            if !(c.control_shift > 0.0 && c.mutant_half_units > 1.0) {
                return err(
                    "check.two_frames.control_shift",
                    "the control shift must be positive and the mutant more than one half unit"
                        .into(),
                );
            }
        }
        CaseCheck::IdentityExample(c) => {
            let f = &c.frames;
            if f.frame1.len() != 4 || f.frame2.len() != 4 || f.figure_labels.len() != 4 {
                return err(
                    "check.identity_example.frames.frame1",
                    "needs two frames of 4 points and 4 figure labels".into(),
                );
            }
            let t = &c.table;
            let n = t.columns.len();
            if n != 6
                || [&t.real, &t.real2, &t.squared, &t.projected1, &t.projected2]
                    .iter()
                    .any(|r| r.len() != n)
                || t.columns.iter().any(|h| h.chars().count() != 2)
            {
                return err(
                    "check.identity_example.table.columns",
                    "needs 6 two-letter columns and 6 values per row".into(),
                );
            }
            if let Some(i) = c
                .panels
                .items
                .iter()
                .position(|p| p.points.len() != 4 || p.segment.len() != 2)
            {
                return err(
                    &format!("check.identity_example.panels.items[{i}].points"),
                    "needs 4 points and a segment of 2".into(),
                );
            }
            let names = &t.point_names;
            let mut order = c.debug.program_order.clone();
            order.sort();
            let mut sorted = names.clone();
            sorted.sort();
            if names.len() != 4 || order != sorted {
                return err(
                    "check.identity_example.debug.program_order",
                    "needs four point names, and the program order a permutation of them".into(),
                );
            }
            if c.debug.quantities.len() != 12 || c.debug.mutant_half_units <= 1.0 {
                return err(
                    "check.identity_example.debug.quantities",
                    "needs the 12 labels of a block's recomputed numbers and a mutant of more than one half unit".into(),
                );
            }
            if c.census_c_factor.is_nan() || c.census_c_factor < 1.0 {
                return err(
                    "check.identity_example.census_c_factor",
                    "must be at least 1".into(),
                );
            }
        }
        CaseCheck::Restatements(c) => {
            if let Some(i) = c
                .items
                .iter()
                .position(|r| r.restates.is_empty() == r.out_of_scope.is_none())
            {
                return err(
                    &format!("check.restatements.items[{i}].restates"),
                    "give either the claims it restates or why it is out of scope".into(),
                );
            }
        }
        CaseCheck::IdentityCensus(c) => {
            if c.trials == 0
                || c.c_factors.is_empty()
                || c.c_factors.iter().any(|f| f.is_nan() || *f < 1.0)
                || c.control_shift.is_nan()
                || c.control_shift <= 0.0
            {
                return err(
                    "check.identity_census.c_factors",
                    "needs trials, factors of at least 1 and a positive control shift".into(),
                );
            }
        }
        CaseCheck::P4f3Census(c) => {
            if c.trials == 0 || c.claims.is_empty() || c.frames != 3 {
                return err("check", "needs a claim, a trial and 3 frames".into());
            }
            census_names(c)?;
        }
        CaseCheck::P3f3Census(c) | CaseCheck::P3f4Census(c) => {
            if c.trials == 0 || c.claims.is_empty() {
                return err("check", "needs at least one claim and one trial".into());
            }
            census_names(c)?;
            let needed = if matches!(case.check, CaseCheck::P3f3Census(_)) {
                3
            } else {
                4
            };
            if c.frames < needed || (needed == 3 && c.frames != 3) {
                return err(
                    "check",
                    format!(
                        "frames must be {}",
                        if needed == 3 { "3" } else { "at least 4" }
                    ),
                );
            }
        }
        CaseCheck::P4f3Example(c) => {
            let f = &c.figure.frames;
            if f.len() != 3 || f.iter().any(|fr| fr.len() != 4) {
                return err(
                    "check.p4f3_example.figure.frames",
                    "needs 3 frames of 4 points".into(),
                );
            }
            if c.body.lengths.len() != 6 || c.body.squares.len() != 6 {
                return err(
                    "check.p4f3_example.body.lengths",
                    "needs 6 lengths and 6 squares".into(),
                );
            }
            if c.matrix.rows.len() != 6 || c.matrix.rows.iter().any(|r| r.len() != 7) {
                return err(
                    "check.p4f3_example.matrix.rows",
                    "needs 6 rows of 7 numbers (x1 … x6 and the constant)".into(),
                );
            }
            if let Some(i) = c
                .noise
                .iter()
                .position(|l| l.printed.is_empty() || l.printed.iter().any(|p| p.len() != 6))
            {
                return err(
                    &format!("check.p4f3_example.noise[{i}].printed"),
                    "needs solutions of 6 values".into(),
                );
            }
            if c.matrix_mutant_half_units.is_empty()
                || c.matrix_mutant_half_units
                    .iter()
                    .any(|m| !(*m > 1.0 && m.is_finite()))
            {
                return err(
                    "check.p4f3_example.matrix_mutant_half_units",
                    "needs shifts of more than one half unit".into(),
                );
            }
            if c.solution.values.len() != 1 || c.solution.values[0].len() != 6 {
                return err(
                    "check.p4f3_example.solution.values",
                    "needs one solution of 6 values".into(),
                );
            }
        }
        CaseCheck::FormulaAudit(c) => {
            let parses = |field: &str, f: &str| match crate::algebra::RatFn::parse(f) {
                Ok(_) => Ok(()),
                Err(e) => err(field, format!("formula does not parse: {e}")),
            };
            for (i, d) in c.definitions.iter().enumerate() {
                parses(
                    &format!("check.formula_audit.definitions[{i}].printed"),
                    &d.printed,
                )?;
            }
            for (i, f) in c.formulas.iter().enumerate() {
                let at = |k: &str| format!("check.formula_audit.formulas[{i}].{k}");
                if let Some(p) = &f.printed {
                    parses(&at("printed"), p)?;
                }
                if let Some(p) = &f.corrected {
                    parses(&at("corrected"), p)?;
                }
                if f.printed.is_none() && f.corrected.is_none() {
                    return err(
                        &at("printed"),
                        "needs a printed or a corrected formula".into(),
                    );
                }
            }
            for (i, a) in c.arithmetic.iter().enumerate() {
                for (j, st) in a.steps.iter().enumerate() {
                    if crate::algebra::Poly::parse(st).is_err() {
                        return err(
                            &format!("check.formula_audit.arithmetic[{i}].steps[{j}]"),
                            format!("'{st}' does not parse"),
                        );
                    }
                }
            }
        }
        CaseCheck::NotReproducible(c) => {
            if let Some(i) = c.claims.iter().position(|m| m.missing.is_empty()) {
                return err(
                    &format!("check.not_reproducible.claims[{i}].missing"),
                    "say what is missing".into(),
                );
            }
        }
        CaseCheck::P3f3Example(c) => {
            let f = &c.figure.frames;
            if f.len() != 3 || f.iter().any(|fr| fr.len() != 3) {
                return err(
                    "check.p3f3_example.figure.frames",
                    "needs 3 frames of 3 points".into(),
                );
            }
            if c.body.lengths.len() != 3 || c.body.squares.len() != 3 {
                return err(
                    "check.p3f3_example.body.lengths",
                    "needs 3 lengths and 3 squares".into(),
                );
            }
            if c.solutions.values.len() > 2 || c.solutions.values.iter().any(|v| v.len() != 3) {
                return err(
                    "check.p3f3_example.solutions.values",
                    "at most 2 solutions of 3 squared edges".into(),
                );
            }
        }
    }
    Ok(())
}

/// Parse a sign pattern `"+ + -"`.
pub fn parse_signs(text: &str) -> Option<[i64; 3]> {
    let signs: Vec<i64> = text
        .split_whitespace()
        .map(|t| match t {
            "+" => Some(1),
            "-" => Some(-1),
            _ => None,
        })
        .collect::<Option<_>>()?;
    signs.try_into().ok()
}
