//! Checks serde cannot express: counts, sign patterns, formulas that parse.

use std::path::Path;

use super::formula_size;
use super::load::invalid;
use super::*;
use crate::algebra::Poly;
use crate::error::Result;

/// The case file being validated: turns a field path and a message into a located error.
/// A kind sees it scoped to its own fields (`check.<kind>`), so it names fields as its schema
/// does.
pub struct Validator<'a> {
    text: &'a str,
    path: &'a Path,
    at: String,
}

impl<'a> Validator<'a> {
    /// The same file, with every field below `scope` (a dotted path from the case's top).
    pub fn at(&self, scope: &str) -> Validator<'a> {
        Validator {
            text: self.text,
            path: self.path,
            at: self.path_of(scope),
        }
    }

    fn path_of(&self, field: &str) -> String {
        match (self.at.is_empty(), field.is_empty()) {
            (true, _) => field.to_string(),
            (false, true) => self.at.clone(),
            (false, false) => format!("{}.{field}", self.at),
        }
    }

    /// An input error at `field` (empty: the scope itself), located by its line in the case
    /// text.
    pub fn err<T>(&self, field: &str, message: String) -> Result<T> {
        Err(invalid(self.text, self.path, &self.path_of(field), message))
    }

    /// A count of trials (points, instances) at `field` of at least 1: a check over no trials
    /// holds vacuously.
    pub fn positive(&self, field: &str, n: usize) -> Result<()> {
        let name = field.rsplit('.').next().unwrap_or(field);
        crate::limits::count(name, n, usize::MAX).or_else(|m| {
            self.err(
                field,
                format!("{m}: a check over no trials holds vacuously"),
            )
        })
    }

    /// One identifiability decision of `p` points in `k` frames within the limits.
    pub fn dof(&self, field: &str, p: usize, k: usize) -> Result<()> {
        use crate::limits::{DOF_FRAMES, DOF_POINTS, DOF_POINTS_TIMES_FRAMES};
        self.limit(field, "points", p, DOF_POINTS)?;
        self.limit(field, "frames", k, DOF_FRAMES)?;
        self.limit(
            field,
            "points × frames",
            p.saturating_mul(k),
            DOF_POINTS_TIMES_FRAMES,
        )
    }

    /// Significant digits a table was printed with, within 1 ..= the limit.
    pub fn digits(&self, field: &str, d: u32) -> Result<()> {
        let most = crate::limits::SIGNIFICANT_DIGITS;
        if d == 0 || d > most {
            return self.err(
                field,
                format!("significant digits must lie in 1 ..= {most}"),
            );
        }
        Ok(())
    }

    /// `value` of `what` at `field` within `limit` (`docs/limits.md`).
    pub fn limit(&self, field: &str, what: &str, value: usize, limit: usize) -> Result<()> {
        crate::limits::at_most(what, value, limit).or_else(|m| self.err(field, m))
    }

    /// A list at `field` of at most [`crate::limits::CASE_LIST`] entries.
    pub fn list(&self, field: &str, len: usize) -> Result<()> {
        self.limit(field, "the list's length", len, crate::limits::CASE_LIST)
    }

    /// Names at `field`: none empty, none twice.
    pub fn names(&self, field: &str, names: &[String]) -> Result<()> {
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
    pub fn formula_size(
        &self,
        field: &str,
        f: &str,
        defs: &std::collections::BTreeMap<String, formula_size::Size>,
    ) -> Result<formula_size::Size> {
        formula_size::check(f, defs).or_else(|m| self.err(field, m))
    }

    /// The polynomial at `field` must parse.
    pub fn formula(&self, field: &str, f: &str) -> Result<()> {
        self.formula_size(field, f, &Default::default())?;
        match Poly::parse(f) {
            Ok(_) => Ok(()),
            Err(e) => self.err(field, format!("formula does not parse: {e}")),
        }
    }

    /// The rational function at `field` must parse.
    pub fn rat_formula(&self, field: &str, f: &str) -> Result<()> {
        self.formula_size(field, f, &Default::default())?;
        match crate::algebra::RatFn::check(f) {
            Ok(()) => Ok(()),
            Err(e) => self.err(field, format!("formula does not parse: {e}")),
        }
    }
}

/// Checks serde cannot express: a case's id, then its check's own (counts, limits, formulas).
pub(super) fn validate<C: Schema>(case: &Case<C>, text: &str, path: &Path) -> Result<()> {
    let v = &Validator {
        text,
        path,
        at: String::new(),
    };
    if case.id.trim().is_empty() {
        return v.err("id", "must not be empty".into());
    }
    case.check.validate(v)
}
