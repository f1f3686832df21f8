//! FormulaReading the case's formulas as the paper defines them. A text reads the names bound before
//! it: the macros (`definitions`, in order), then each formula that `defines` a name (its
//! corrected form when it has one). Each text is read once, when a formula being judged needs
//! it, and only the names it uses are looked up: one formula judged alone is read exactly as
//! in the whole audit, and formulas that do not depend on each other are read in parallel.

use std::sync::OnceLock;

use crate::algebra::RatFn;
use crate::claims::formula_audit::FormulaAuditCase;
use crate::error::{Error, ParseError, Result};

/// A text of the case.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Text {
    /// The macro definition `definitions[k]`.
    Definition(usize),
    /// The printed form of `formulas[i]`.
    Printed(usize),
    /// The corrected form of `formulas[i]`.
    Corrected(usize),
}

/// A text's reading, or where it failed.
type Read = std::result::Result<RatFn, ParseError>;

/// The case's texts, each read at most once.
pub(super) struct FormulaReading<'a> {
    case: &'a FormulaAuditCase,
    /// A formula keeps its `symbols` free (the macro level), or every bound name is
    /// substituted (the expanded level).
    keep_symbols: bool,
    definitions: Vec<OnceLock<Read>>,
    printed: Vec<OnceLock<Read>>,
    corrected: Vec<OnceLock<Read>>,
}

impl<'a> FormulaReading<'a> {
    /// Nothing read yet. `keep_symbols`: whether a formula's `symbols` stay free.
    pub(super) fn new(case: &'a FormulaAuditCase, keep_symbols: bool) -> FormulaReading<'a> {
        let slots = |n: usize| (0..n).map(|_| OnceLock::new()).collect();
        FormulaReading {
            case,
            keep_symbols,
            definitions: slots(case.definitions.len()),
            printed: slots(case.formulas.len()),
            corrected: slots(case.formulas.len()),
        }
    }

    /// The text of `t`, `None` where the formula has no such form.
    fn text(&self, t: Text) -> Option<&'a str> {
        match t {
            Text::Definition(k) => Some(&self.case.definitions[k].printed),
            Text::Printed(i) => self.case.formulas[i].printed.as_deref(),
            Text::Corrected(i) => self.case.formulas[i].corrected.as_deref(),
        }
    }

    /// `t` read (`None` where there is no such text), with the error that names its text.
    pub(super) fn read(&self, t: Text) -> Result<Option<RatFn>> {
        let Some(text) = self.text(t) else {
            return Ok(None);
        };
        match self.value(t, text) {
            Ok(v) => Ok(Some(v.clone())),
            Err(source) => Err(Error::Formula {
                formula: text.to_string(),
                source: source.clone(),
            }),
        }
    }

    /// The reading of `t`, whose text is `text`: each name it uses that is bound before it
    /// (and not kept free) stands for that binding's reading.
    fn value(&self, t: Text, text: &str) -> &Read {
        let slot = match t {
            Text::Definition(k) => &self.definitions[k],
            Text::Printed(i) => &self.printed[i],
            Text::Corrected(i) => &self.corrected[i],
        };
        slot.get_or_init(|| {
            let keep: &[String] = match t {
                Text::Printed(i) | Text::Corrected(i) if self.keep_symbols => {
                    &self.case.formulas[i].symbols
                }
                _ => &[],
            };
            let mut bound: Vec<(String, &RatFn)> = Vec::new();
            for name in RatFn::identifiers(text)? {
                if keep.contains(&name) {
                    continue;
                }
                if let Some(b) = self.binding(&name, t)
                    && let Some(b_text) = self.text(b)
                {
                    let v = self.value(b, b_text).as_ref().map_err(Clone::clone)?;
                    bound.push((name, v));
                }
            }
            RatFn::parse_looking_up(text, &|name| {
                bound.iter().find(|(n, _)| n == name).map(|(_, v)| *v)
            })
        })
    }

    /// What `name` stands for where `at` is read: the last formula before it that defines
    /// the name and has a form (its corrected one when it has one), else the last macro
    /// definition of the name before it (a definition reads only the definitions before it).
    fn binding(&self, name: &str, at: Text) -> Option<Text> {
        let (formulas, definitions) = match at {
            Text::Definition(k) => (0, k),
            Text::Printed(i) | Text::Corrected(i) => (i, self.case.definitions.len()),
        };
        let by_formula = self.case.formulas[..formulas]
            .iter()
            .enumerate()
            .rev()
            .find(|(_, f)| {
                f.defines.as_deref() == Some(name) && (f.corrected.is_some() || f.printed.is_some())
            })
            .map(|(j, f)| match f.corrected {
                Some(_) => Text::Corrected(j),
                None => Text::Printed(j),
            });
        by_formula.or_else(|| {
            self.case.definitions[..definitions]
                .iter()
                .rposition(|d| d.name == name)
                .map(Text::Definition)
        })
    }
}
