//! Checks serde cannot express: counts, sign patterns, formulas that parse.

use std::path::Path;

use super::load::invalid;
use super::*;
use super::{formula_size, sizes};
use crate::algebra::Poly;
use crate::error::Result;

/// The case file being validated: turns a field path and a message into a located error.
pub(super) struct Validator<'a> {
    text: &'a str,
    path: &'a Path,
}

impl Validator<'_> {
    /// An input error at `field`, located by its line in the case text.
    pub(super) fn err<T>(&self, field: &str, message: String) -> Result<T> {
        Err(invalid(self.text, self.path, field, message))
    }

    /// `value` of `what` at `field` within `limit` (`docs/limits.md`).
    pub(super) fn limit(&self, field: &str, what: &str, value: usize, limit: usize) -> Result<()> {
        crate::limits::at_most(what, value, limit).or_else(|m| self.err(field, m))
    }

    /// A list at `field` of at most [`crate::limits::CASE_LIST`] entries.
    pub(super) fn list(&self, field: &str, len: usize) -> Result<()> {
        self.limit(field, "the list's length", len, crate::limits::CASE_LIST)
    }

    /// Names at `field`: none empty, none twice.
    pub(super) fn names(&self, field: &str, names: &[String]) -> Result<()> {
        if names.iter().any(|n| n.trim().is_empty()) {
            return self.err(field, "a name is empty".into());
        }
        if let Some((i, n)) = names
            .iter()
            .enumerate()
            .find(|(i, n)| names[..*i].contains(n))
        {
            return self.err(
                &format!("{field}[{i}]"),
                format!("the name `{n}` appears twice"),
            );
        }
        Ok(())
    }

    /// The formula at `field` within the formula limits (depth, exponents, expansion),
    /// before the recursive parser sees it; `defs` sizes the names it may use.
    fn formula_size(
        &self,
        field: &str,
        f: &str,
        defs: &std::collections::BTreeMap<String, formula_size::Size>,
    ) -> Result<formula_size::Size> {
        formula_size::check(f, defs).or_else(|m| self.err(field, m))
    }

    /// The polynomial at `field` must parse.
    fn formula(&self, field: &str, f: &str) -> Result<()> {
        self.formula_size(field, f, &Default::default())?;
        match Poly::parse(f) {
            Ok(_) => Ok(()),
            Err(e) => self.err(field, format!("formula does not parse: {e}")),
        }
    }

    /// The rational function at `field` must parse.
    fn rat_formula(&self, field: &str, f: &str) -> Result<()> {
        self.formula_size(field, f, &Default::default())?;
        match crate::algebra::RatFn::parse(f) {
            Ok(_) => Ok(()),
            Err(e) => self.err(field, format!("formula does not parse: {e}")),
        }
    }
}

/// Checks serde cannot express: counts, sign patterns, and that every formula parses.
pub(super) fn validate(case: &Case, text: &str, path: &Path) -> Result<()> {
    let v = &Validator { text, path };
    if case.id.trim().is_empty() {
        return v.err("id", "must not be empty".into());
    }
    sizes::trials_positive(case, v)?;
    sizes::check_sizes(case, v)?;
    match &case.check {
        CaseCheck::DofCount(c) => dof_count(c, v),
        CaseCheck::DofIdentifiability(c) => dof_identifiability(c, v),
        CaseCheck::TwofoldSquared(c) => twofold_squared(c, v),
        CaseCheck::NoiseStudy(c) => noise_study(c, v),
        CaseCheck::TwoFrames(c) => two_frames(c, v),
        CaseCheck::IdentityExample(c) => identity_example(c, v),
        CaseCheck::Restatements(c) => restatements(c, v),
        CaseCheck::IdentityCensus(c) => identity_census(c, v),
        CaseCheck::P4f3Census(c) => p4f3_census(c, v),
        CaseCheck::P3f3Census(c) => p3_census(c, 3, v),
        CaseCheck::P3f4Census(c) => p3_census(c, 4, v),
        CaseCheck::P4f3Example(c) => p4f3_example(c, v),
        CaseCheck::FormulaAudit(c) => formula_audit(c, v),
        CaseCheck::NotReproducible(c) => not_reproducible(c, v),
        CaseCheck::P3f3Example(c) => p3f3_example(c, v),
        CaseCheck::SourceErrata(c) => source_errata(c, v),
        CaseCheck::SolutionCount(c) => solution_count(c, v),
        CaseCheck::LinearityPrice(c) => super::linearity::validate(c, v),
    }
}

/// Suffixes and the exception must name claims of the census.
fn census_names(c: &CensusCase, v: &Validator) -> Result<()> {
    let known = |id: &String| c.claims.iter().any(|k| &k.claim == id);
    if let Some(id) = c.suffixes.keys().find(|id| !known(id)) {
        return v.err("check.suffixes", format!("{id} is not one of the claims"));
    }
    match &c.exception {
        Some(e) if !known(&e.qualifies) => v.err(
            "check.exception.qualifies",
            format!("{} is not one of the claims", e.qualifies),
        ),
        _ => Ok(()),
    }
}

fn dof_count(c: &DofCountCase, v: &Validator) -> Result<()> {
    for (i, e) in c.examples.iter().enumerate() {
        if e.points == 0 || e.frames == 0 {
            return v.err(
                &format!("check.dof_count.examples[{i}].points"),
                "points and frames must be at least 1".into(),
            );
        }
    }
    Ok(())
}

fn dof_identifiability(c: &DofIdentifiabilityCase, v: &Validator) -> Result<()> {
    if c.max_points < 3 || c.max_frames < 3 {
        return v.err(
            "check.dof_identifiability.max_points",
            "the grid must reach at least 3 points and 3 frames".into(),
        );
    }
    v.formula(
        "check.dof_identifiability.formula.unknowns",
        &c.formula.unknowns,
    )?;
    v.formula(
        "check.dof_identifiability.formula.measurements",
        &c.formula.measurements,
    )
}

fn twofold_squared(c: &TwofoldCase, v: &Validator) -> Result<()> {
    for (i, p) in c.relations.patterns.iter().enumerate() {
        if parse_signs(p).is_none() {
            return v.err(
                &format!("check.twofold_squared.relations.patterns[{i}]"),
                format!("'{p}' is not three signs such as \"+ + -\""),
            );
        }
    }
    v.formula(
        "check.twofold_squared.polynomial.printed",
        &c.polynomial.printed,
    )
}

fn noise_study(c: &NoiseStudyCase, v: &Validator) -> Result<()> {
    use crate::model::StudySolver;
    let edges = match c.solver {
        StudySolver::P3f3 | StudySolver::P3f4 => 3,
        StudySolver::P4f3 => 6,
    };
    if c.body.lengths.len() != edges
        || !(c.body.squares.is_empty() || c.body.squares.len() == edges)
    {
        return v.err(
            "check.noise_study.body.lengths",
            format!("the solver needs {edges} lengths (and {edges} squares if any)"),
        );
    }
    let frames_ok = match c.solver {
        StudySolver::P3f3 | StudySolver::P4f3 => c.frames == 3,
        StudySolver::P3f4 => c.frames >= 4,
    };
    if !frames_ok {
        return v.err(
            "check.noise_study.frames",
            "p3f3 and p4f3 need 3 frames, p3f4 at least 4".into(),
        );
    }
    for (i, l) in c.levels.iter().enumerate() {
        if l.printed.is_empty() || l.printed.iter().any(|p| p.len() != edges) {
            return v.err(
                &format!("check.noise_study.levels[{i}].printed"),
                format!("needs solutions of {edges} values"),
            );
        }
    }
    Ok(())
}

fn two_frames(c: &TwoFramesCase, v: &Validator) -> Result<()> {
    if c.counterexample.points.len() != 5 || c.counterexample.names.len() != 5 {
        return v.err(
            "check.two_frames.counterexample.points",
            "needs the five points P, Q, R, Q′, R′".into(),
        );
    }
    if c.points < 4 || c.trials == 0 || c.curve_samples < 4 {
        return v.err(
            "check.two_frames.points",
            "needs at least 4 points, 1 trial and 4 curve samples".into(),
        );
    }
    let in_range = |b: &f64| *b > 0.0 && *b < std::f64::consts::PI;
    if c.betas.len() < 2 || !c.betas.iter().all(in_range) {
        return v.err(
            "check.two_frames.betas",
            "needs at least two angles in (0, π)".into(),
        );
    }
    if !(c.control_shift > 0.0 && c.mutant_half_units > 1.0) {
        return v.err(
            "check.two_frames.control_shift",
            "the control shift must be positive and the mutant more than one half unit".into(),
        );
    }
    Ok(())
}

fn identity_example(c: &IdentityExampleCase, v: &Validator) -> Result<()> {
    let f = &c.frames;
    if f.frame1.len() != 4 || f.frame2.len() != 4 || f.figure_labels.len() != 4 {
        return v.err(
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
        return v.err(
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
        return v.err(
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
        return v.err(
            "check.identity_example.debug.program_order",
            "needs four point names, and the program order a permutation of them".into(),
        );
    }
    if c.debug.quantities.len() != 12 || c.debug.mutant_half_units <= 1.0 {
        return v.err(
            "check.identity_example.debug.quantities",
            "needs the 12 labels of a block's recomputed numbers and a mutant of more than one half unit".into(),
        );
    }
    if c.debug.printed_labels.len() != 31
        || c.debug
            .d_factors
            .iter()
            .any(|k| !(k.is_finite() && *k > 0.0))
    {
        return v.err(
            "check.identity_example.debug.printed_labels",
            "needs the 31 labels of a block's printed numbers, and positive finite d factors"
                .into(),
        );
    }
    if c.census_c_factor.is_nan() || c.census_c_factor < 1.0 {
        return v.err(
            "check.identity_example.census_c_factor",
            "must be at least 1".into(),
        );
    }
    Ok(())
}

fn restatements(c: &RestatementsCase, v: &Validator) -> Result<()> {
    if let Some(i) = c
        .items
        .iter()
        .position(|r| r.restates.is_empty() == r.out_of_scope.is_none())
    {
        return v.err(
            &format!("check.restatements.items[{i}].restates"),
            "give either the claims it restates or why it is out of scope".into(),
        );
    }
    // an exception names a result of a restated claim: `claim` or `claim/suffix`
    if let Some(i) = c.items.iter().position(|r| {
        r.except.iter().any(|e| {
            let claim = e.split('/').next().unwrap_or(e);
            !r.restates.iter().any(|x| x == claim)
        })
    }) {
        return v.err(
            &format!("check.restatements.items[{i}].except"),
            "an exception must be a result of a claim the item restates".into(),
        );
    }
    Ok(())
}

fn identity_census(c: &IdentityCensusCase, v: &Validator) -> Result<()> {
    if c.trials == 0
        || c.c_factors.is_empty()
        || c.c_factors.iter().any(|f| f.is_nan() || *f < 1.0)
        || c.control_shift.is_nan()
        || c.control_shift <= 0.0
    {
        return v.err(
            "check.identity_census.c_factors",
            "needs trials, factors of at least 1 and a positive control shift".into(),
        );
    }
    Ok(())
}

fn p4f3_census(c: &CensusCase, v: &Validator) -> Result<()> {
    if c.trials == 0 || c.claims.is_empty() || c.frames != 3 {
        return v.err("check", "needs a claim, a trial and 3 frames".into());
    }
    census_names(c, v)
}

/// The p3f3 census (`needed` 3: exactly 3 frames) and the p3f4 census (`needed` 4: at least 4).
fn p3_census(c: &CensusCase, needed: usize, v: &Validator) -> Result<()> {
    if c.trials == 0 || c.claims.is_empty() {
        return v.err("check", "needs at least one claim and one trial".into());
    }
    census_names(c, v)?;
    if c.frames < needed || (needed == 3 && c.frames != 3) {
        return v.err(
            "check",
            format!(
                "frames must be {}",
                if needed == 3 { "3" } else { "at least 4" }
            ),
        );
    }
    Ok(())
}

fn p4f3_example(c: &P4f3ExampleCase, v: &Validator) -> Result<()> {
    let f = &c.figure.frames;
    if f.len() != 3 || f.iter().any(|fr| fr.len() != 4) {
        return v.err(
            "check.p4f3_example.figure.frames",
            "needs 3 frames of 4 points".into(),
        );
    }
    if c.body.lengths.len() != 6 || c.body.squares.len() != 6 {
        return v.err(
            "check.p4f3_example.body.lengths",
            "needs 6 lengths and 6 squares".into(),
        );
    }
    if c.matrix.rows.len() != 6 || c.matrix.rows.iter().any(|r| r.len() != 7) {
        return v.err(
            "check.p4f3_example.matrix.rows",
            "needs 6 rows of 7 numbers (x1 … x6 and the constant)".into(),
        );
    }
    if let Some(i) = c
        .noise
        .iter()
        .position(|l| l.printed.is_empty() || l.printed.iter().any(|p| p.len() != 6))
    {
        return v.err(
            &format!("check.p4f3_example.noise[{i}].printed"),
            "needs solutions of 6 values".into(),
        );
    }
    if c.matrix_mutant_half_units.is_empty()
        || c.matrix_mutant_half_units
            .iter()
            .any(|m| !(*m > 1.0 && m.is_finite()))
    {
        return v.err(
            "check.p4f3_example.matrix_mutant_half_units",
            "needs shifts of more than one half unit".into(),
        );
    }
    if c.solution.values.len() != 1 || c.solution.values[0].len() != 6 {
        return v.err(
            "check.p4f3_example.solution.values",
            "needs one solution of 6 values".into(),
        );
    }
    Ok(())
}

fn formula_audit(c: &FormulaAuditCase, v: &Validator) -> Result<()> {
    formula_audit_sizes(c, v)?;
    for (i, d) in c.definitions.iter().enumerate() {
        v.rat_formula(
            &format!("check.formula_audit.definitions[{i}].printed"),
            &d.printed,
        )?;
    }
    for (i, f) in c.formulas.iter().enumerate() {
        let at = |k: &str| format!("check.formula_audit.formulas[{i}].{k}");
        if let Some(p) = &f.printed {
            v.rat_formula(&at("printed"), p)?;
        }
        if let Some(p) = &f.corrected {
            v.rat_formula(&at("corrected"), p)?;
        }
        if f.printed.is_none() && f.corrected.is_none() {
            return v.err(
                &at("printed"),
                "needs a printed or a corrected formula".into(),
            );
        }
    }
    for (i, a) in c.arithmetic.iter().enumerate() {
        for (j, st) in a.steps.iter().enumerate() {
            let field = format!("check.formula_audit.arithmetic[{i}].steps[{j}]");
            v.formula_size(&field, st, &Default::default())?;
            if Poly::parse(st).is_err() {
                return v.err(
                    &format!("check.formula_audit.arithmetic[{i}].steps[{j}]"),
                    format!("'{st}' does not parse"),
                );
            }
        }
    }
    Ok(())
}

/// The audit's formulas within the formula limits, each definition counted at its size
/// wherever a later formula names it (the audit substitutes definitions).
fn formula_audit_sizes(c: &FormulaAuditCase, v: &Validator) -> Result<()> {
    let mut defs = std::collections::BTreeMap::new();
    for (i, d) in c.definitions.iter().enumerate() {
        let field = format!("check.formula_audit.definitions[{i}].printed");
        let size = v.formula_size(&field, &d.printed, &defs)?;
        defs.insert(d.name.clone(), size);
    }
    for (i, f) in c.formulas.iter().enumerate() {
        for (k, text) in [("printed", &f.printed), ("corrected", &f.corrected)] {
            if let Some(t) = text {
                let field = format!("check.formula_audit.formulas[{i}].{k}");
                v.formula_size(&field, t, &defs)?;
            }
        }
    }
    Ok(())
}

fn not_reproducible(c: &NotReproducibleCase, v: &Validator) -> Result<()> {
    if let Some(i) = c.claims.iter().position(|m| m.missing.is_empty()) {
        return v.err(
            &format!("check.not_reproducible.claims[{i}].missing"),
            "say what is missing".into(),
        );
    }
    Ok(())
}

/// Result ids unique, line ranges that parse, a correction and a reading for each finding.
fn source_errata(c: &SourceErrataCase, v: &Validator) -> Result<()> {
    let base = "check.source_errata.findings";
    let mut seen = std::collections::BTreeSet::new();
    for (i, f) in c.findings.iter().enumerate() {
        if !seen.insert((f.claim.claim.as_str(), f.id.as_str())) {
            return v.err(
                &format!("{base}[{i}].id"),
                format!("{}/{} appears twice", f.claim.claim, f.id),
            );
        }
        let ranges = std::iter::once(&f.claim.lines).chain(f.also.iter().map(|p| &p.lines));
        if let Some(bad) = ranges.clone().find(|l| parse_lines(l).is_none()) {
            return v.err(
                &format!("{base}[{i}].claim.lines"),
                format!("`{bad}` is not a line range a-b"),
            );
        }
        if f.corrected.trim().is_empty() || f.defect.trim().is_empty() {
            return v.err(
                &format!("{base}[{i}].corrected"),
                "say the defect and the correction".into(),
            );
        }
        match &f.decide {
            Some(Decision::DofCount {
                printed, corrected, ..
            }) if corrected.is_empty() || printed == corrected => {
                return v.err(
                    &format!("{base}[{i}].decide"),
                    "the corrected reading must name configurations, other than the printed".into(),
                );
            }
            Some(Decision::FigureLabels {
                origin,
                points,
                pictures,
                ..
            }) => {
                figure_labels(origin, points, pictures, v, &format!("{base}[{i}].decide"))?;
            }
            _ => {}
        }
    }
    Ok(())
}

/// Coordinates of the right lengths; every label (as printed and as renamed) names a point.
fn figure_labels(
    origin: &str,
    points: &[NamedPoint],
    pictures: &[LabelPicture],
    v: &Validator,
    field: &str,
) -> Result<()> {
    let known = |n: &str| points.iter().any(|p| p.name == n);
    if !known(origin) || points.iter().any(|p| p.at.len() != 3) {
        return v.err(
            field,
            "the points need three coordinates each, the origin among them".into(),
        );
    }
    for (j, p) in pictures.iter().enumerate() {
        let shapes = p.corner.len() == 2
            && p.ends.len() == 3
            && p.ends.iter().all(|e| e.len() == 2)
            && p.labels.iter().all(|l| l.at.len() == 2);
        let named = p.labels.iter().all(|l| known(&l.name))
            && p.rename.values().all(|n| known(n))
            && p.rename
                .keys()
                .all(|k| p.labels.iter().any(|l| &l.name == k))
            && p.labels.iter().any(|l| l.name == origin);
        if !shapes || !named {
            return v.err(
                &format!("{field}.figure_labels.pictures[{j}]"),
                "a picture needs a corner, three edge ends, labels of known points (the origin's among them)".into(),
            );
        }
    }
    Ok(())
}

fn p3f3_example(c: &P3f3ExampleCase, v: &Validator) -> Result<()> {
    let f = &c.figure.frames;
    if f.len() != 3 || f.iter().any(|fr| fr.len() != 3) {
        return v.err(
            "check.p3f3_example.figure.frames",
            "needs 3 frames of 3 points".into(),
        );
    }
    if c.body.lengths.len() != 3 || c.body.squares.len() != 3 {
        return v.err(
            "check.p3f3_example.body.lengths",
            "needs 3 lengths and 3 squares".into(),
        );
    }
    if c.solutions.values.len() > 2 || c.solutions.values.iter().any(|s| s.len() != 3) {
        return v.err(
            "check.p3f3_example.solutions.values",
            "at most 2 solutions of 3 squared edges".into(),
        );
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

/// The printed counts must be whole numbers (they are counts of solutions).
fn solution_count(c: &SolutionCountCase, v: &Validator) -> Result<()> {
    let fields = [
        (
            "check.solution_count.three_points.at_most",
            &c.three_points.at_most,
        ),
        (
            "check.solution_count.four_points.at_most",
            &c.four_points.at_most,
        ),
        (
            "check.solution_count.literature.three_points",
            &c.literature.three_points,
        ),
        (
            "check.solution_count.literature.four_points",
            &c.literature.four_points,
        ),
    ];
    for (field, p) in fields {
        if p.to_integer().is_none() || p.value < num_rational::BigRational::from_integer(0.into()) {
            return v.err(
                field,
                format!("`{}` is not a whole number of solutions", p.text),
            );
        }
    }
    Ok(())
}
