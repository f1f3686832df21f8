//! Limits on the work a case file asks for (`docs/limits.md`), names that must be distinct,
//! and noise levels in range: checked at load time, so a case that would run for hours,
//! exhaust memory or panic in a sampler is refused with its file, line and field.

use super::validate::Validator;
use super::*;
use crate::error::Result;
use crate::limits::{self, count};

/// Every count and list of `case` within its limit.
pub(super) fn check_sizes(case: &Case, v: &Validator) -> Result<()> {
    match &case.check {
        CaseCheck::DofCount(c) => dof_count(c, v),
        CaseCheck::DofIdentifiability(c) => dof_identifiability(c, v),
        CaseCheck::TwofoldSquared(c) => twofold_squared(c, v),
        CaseCheck::P3f3Example(c) => p3f3_example(c, v),
        CaseCheck::P4f3Example(c) => p4f3_example(c, v),
        CaseCheck::P4f3Census(c) | CaseCheck::P3f3Census(c) | CaseCheck::P3f4Census(c) => {
            v.limit("check.trials", "trials", c.trials, limits::CASE_TRIALS)?;
            v.limit("check.frames", "frames", c.frames, limits::DOF_FRAMES)
        }
        CaseCheck::FormulaAudit(c) => v.limit(
            "check.formula_audit.evaluation_points",
            "evaluation_points",
            c.evaluation_points,
            limits::EVALUATION_POINTS,
        ),
        CaseCheck::TwoFrames(c) => two_frames(c, v),
        CaseCheck::IdentityCensus(c) => {
            v.limit(
                "check.identity_census.trials",
                "trials",
                c.trials,
                limits::CASE_TRIALS,
            )?;
            v.list("check.identity_census.c_factors", c.c_factors.len())
        }
        CaseCheck::IdentityExample(c) => identity_example(c, v),
        CaseCheck::NoiseStudy(c) => noise_study(c, v),
        CaseCheck::SolutionCount(c) => v.limit(
            "check.solution_count.instances",
            "instances",
            c.instances,
            limits::COUNT_INSTANCES,
        ),
        // the study's trials, bodies and levels are limited in `cases::linearity::validate`
        CaseCheck::NotReproducible(_)
        | CaseCheck::Restatements(_)
        | CaseCheck::SourceErrata(_)
        | CaseCheck::LinearityPrice(_) => Ok(()),
    }
}

/// The sizes of a `DofCount` case.
fn dof_count(c: &DofCountCase, v: &Validator) -> Result<()> {
    for (i, e) in c.examples.iter().enumerate() {
        dof(
            v,
            &format!("check.dof_count.examples[{i}].points"),
            e.points,
            e.frames,
        )?;
    }
    Ok(())
}

/// The sizes of a `DofIdentifiability` case.
fn dof_identifiability(c: &DofIdentifiabilityCase, v: &Validator) -> Result<()> {
    let at = "check.dof_identifiability";
    v.limit(
        &format!("{at}.max_points"),
        "max_points",
        c.max_points,
        limits::DOF_GRID,
    )?;
    v.limit(
        &format!("{at}.max_frames"),
        "max_frames",
        c.max_frames,
        limits::DOF_GRID,
    )?;
    dof(
        v,
        &format!("{at}.minimum.points"),
        c.minimum.points,
        c.minimum.frames,
    )
}

/// The sizes of a `TwofoldSquared` case.
fn twofold_squared(c: &TwofoldCase, v: &Validator) -> Result<()> {
    let at = "check.twofold_squared";
    v.limit(
        &format!("{at}.evaluation_points"),
        "evaluation_points",
        c.evaluation_points,
        limits::EVALUATION_POINTS,
    )?;
    v.limit(
        &format!("{at}.relations.trials"),
        "trials",
        c.relations.trials,
        limits::CASE_TRIALS,
    )?;
    v.list(
        &format!("{at}.relations.patterns"),
        c.relations.patterns.len(),
    )
}

/// The sizes of a `P3f3Example` case.
fn p3f3_example(c: &P3f3ExampleCase, v: &Validator) -> Result<()> {
    v.limit(
        "check.p3f3_example.rounding_trials",
        "rounding_trials",
        c.rounding_trials,
        limits::ROUNDING_TRIALS,
    )?;
    digits(
        v,
        "check.p3f3_example.solutions.significant_digits",
        c.solutions.significant_digits,
    )?;
    body_digits(v, "check.p3f3_example.body.significant_digits", &c.body)
}

/// One identifiability decision of p points in k frames.
fn dof(v: &Validator, field: &str, p: usize, k: usize) -> Result<()> {
    v.limit(field, "points", p, limits::DOF_POINTS)?;
    v.limit(field, "frames", k, limits::DOF_FRAMES)?;
    v.limit(
        field,
        "points × frames",
        p.saturating_mul(k),
        limits::DOF_POINTS_TIMES_FRAMES,
    )
}

fn digits(v: &Validator, field: &str, d: u32) -> Result<()> {
    if d == 0 || d > limits::SIGNIFICANT_DIGITS {
        return v.err(
            field,
            format!(
                "significant digits must lie in 1 ..= {}",
                limits::SIGNIFICANT_DIGITS
            ),
        );
    }
    Ok(())
}

fn body_digits(v: &Validator, field: &str, b: &BodyTable) -> Result<()> {
    b.significant_digits.map_or(Ok(()), |d| digits(v, field, d))
}

/// ε of each level in [0, 1] (a negative ε empties the sampler's range).
fn levels(v: &Validator, at: &str, levels: &[NoiseLevel]) -> Result<()> {
    v.list(at, levels.len())?;
    if levels.len() > limits::NOISE_LEVELS {
        return v.err(
            at,
            format!(
                "more than {} noise levels (see docs/limits.md)",
                limits::NOISE_LEVELS
            ),
        );
    }
    for (i, l) in levels.iter().enumerate() {
        if let Err(m) = limits::noise_level("level", l.level.to_f64()) {
            return v.err(&format!("{at}[{i}].level"), m);
        }
    }
    Ok(())
}

fn noise_study(c: &NoiseStudyCase, v: &Validator) -> Result<()> {
    v.limit(
        "check.noise_study.trials",
        "trials",
        c.trials,
        limits::NOISE_TRIALS,
    )?;
    v.limit(
        "check.noise_study.frames",
        "frames",
        c.frames,
        limits::DOF_FRAMES,
    )?;
    levels(v, "check.noise_study.levels", &c.levels)?;
    c.body.significant_digits.map_or(Ok(()), |d| {
        digits(v, "check.noise_study.body.significant_digits", d)
    })
}

fn p4f3_example(c: &P4f3ExampleCase, v: &Validator) -> Result<()> {
    v.limit(
        "check.p4f3_example.trials",
        "trials",
        c.trials,
        limits::NOISE_TRIALS,
    )?;
    levels(v, "check.p4f3_example.noise", &c.noise)?;
    v.list(
        "check.p4f3_example.matrix_mutant_half_units",
        c.matrix_mutant_half_units.len(),
    )?;
    digits(
        v,
        "check.p4f3_example.matrix.significant_digits",
        c.matrix.significant_digits,
    )?;
    digits(
        v,
        "check.p4f3_example.solution.significant_digits",
        c.solution.significant_digits,
    )?;
    body_digits(v, "check.p4f3_example.body.significant_digits", &c.body)
}

fn two_frames(c: &TwoFramesCase, v: &Validator) -> Result<()> {
    let at = "check.two_frames";
    v.limit(
        &format!("{at}.points"),
        "points",
        c.points,
        limits::CASE_POINTS,
    )?;
    v.limit(
        &format!("{at}.trials"),
        "trials",
        c.trials,
        limits::CASE_TRIALS,
    )?;
    v.limit(
        &format!("{at}.curve_samples"),
        "curve_samples",
        c.curve_samples,
        limits::CURVE_SAMPLES,
    )?;
    v.list(&format!("{at}.betas"), c.betas.len())?;
    if c.betas
        .iter()
        .chain([&c.control_shift, &c.mutant_half_units])
        .any(|x| !x.is_finite())
    {
        return v.err(
            &format!("{at}.betas"),
            "angles and shifts must be finite numbers".into(),
        );
    }
    v.names(
        &format!("{at}.counterexample.names"),
        &c.counterexample.names,
    )
}

fn identity_example(c: &IdentityExampleCase, v: &Validator) -> Result<()> {
    let at = "check.identity_example";
    v.limit(
        &format!("{at}.census_trials"),
        "census_trials",
        c.census_trials,
        limits::CASE_TRIALS,
    )?;
    if !c.census_c_factor.is_finite() || !c.debug.mutant_half_units.is_finite() {
        return v.err(
            &format!("{at}.census_c_factor"),
            "must be a finite number".into(),
        );
    }
    digits(
        v,
        &format!("{at}.table.significant_digits"),
        c.table.significant_digits,
    )?;
    digits(
        v,
        &format!("{at}.debug.significant_digits"),
        c.debug.significant_digits,
    )?;
    v.names(
        &format!("{at}.frames.figure_labels"),
        &c.frames.figure_labels,
    )?;
    v.names(&format!("{at}.table.point_names"), &c.table.point_names)?;
    v.names(&format!("{at}.table.columns"), &c.table.columns)?;
    v.names(&format!("{at}.debug.program_order"), &c.debug.program_order)
}

/// Trials of every kind must be at least 1: a check over zero trials holds vacuously.
pub(super) fn trials_positive(case: &Case, v: &Validator) -> Result<()> {
    let zero = |field: &str, n: usize| -> Result<()> {
        match count(field.rsplit('.').next().unwrap_or(field), n, usize::MAX) {
            Ok(()) => Ok(()),
            Err(m) => v.err(
                field,
                format!("{m}: a check over no trials holds vacuously"),
            ),
        }
    };
    match &case.check {
        CaseCheck::NoiseStudy(c) => zero("check.noise_study.trials", c.trials),
        CaseCheck::P4f3Example(c) => zero("check.p4f3_example.trials", c.trials),
        CaseCheck::P3f3Example(c) => zero("check.p3f3_example.rounding_trials", c.rounding_trials),
        CaseCheck::TwofoldSquared(c) => {
            zero("check.twofold_squared.relations.trials", c.relations.trials)?;
            zero(
                "check.twofold_squared.evaluation_points",
                c.evaluation_points,
            )
        }
        CaseCheck::FormulaAudit(c) => {
            zero("check.formula_audit.evaluation_points", c.evaluation_points)
        }
        CaseCheck::IdentityExample(c) => {
            zero("check.identity_example.census_trials", c.census_trials)
        }
        CaseCheck::P4f3Census(c) | CaseCheck::P3f3Census(c) | CaseCheck::P3f4Census(c) => {
            zero("check.trials", c.trials)
        }
        CaseCheck::TwoFrames(c) => zero("check.two_frames.trials", c.trials),
        CaseCheck::IdentityCensus(c) => zero("check.identity_census.trials", c.trials),
        CaseCheck::SolutionCount(c) => zero("check.solution_count.instances", c.instances),
        CaseCheck::LinearityPrice(c) => zero("check.linearity_price.trials", c.trials),
        _ => Ok(()),
    }
}
