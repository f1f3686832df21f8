//! The formula audit: displayed formulas, definitions, printed arithmetic, computed statements, textual errata.

use std::collections::BTreeMap;

use serde::Deserialize;

use crate::algebra::Poly;
use crate::cases::{ClaimRef, Printed, Validator};
use crate::claims::shared::Place;
use crate::derivations::formulas::NAMES;
use crate::error::Result;

/// The formula audit.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct FormulaAuditCase {
    /// Random points (modulo word primes) for the second, independent check of every identity.
    pub evaluation_points: usize,
    /// Seed of those points.
    pub seed: u64,
    /// The paper's macros (`\faca{1}` …), transcribed: names usable in every formula.
    #[serde(default)]
    pub definitions: Vec<Definition>,
    /// Displayed formulas, each compared with a derivation.
    #[serde(default)]
    pub formulas: Vec<FormulaItem>,
    /// Printed arithmetic.
    #[serde(default)]
    pub arithmetic: Vec<ArithmeticItem>,
    /// Statements decided by a dedicated computation.
    #[serde(default)]
    pub computed: Vec<ComputedItem>,
    /// Textual and typographic errata.
    #[serde(default)]
    pub text: Vec<TextItem>,
}

/// A macro of the paper, transcribed.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Definition {
    /// The name formulas use.
    pub name: String,
    /// The LaTeX macro.
    #[serde(rename = "macro")]
    pub latex: String,
    /// Its expansion, transcribed.
    pub printed: String,
}

/// How a printed formula must relate to its derivation.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Relation {
    /// The same expression.
    #[default]
    Equal,
    /// A non-zero rational multiple (an equation `= 0` printed with another sign or scale).
    Proportional,
}

/// A displayed formula.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct FormulaItem {
    /// The claim.
    pub claim: ClaimRef,
    /// The result id's suffix.
    pub id: String,
    /// Where.
    #[serde(rename = "where")]
    pub place: Place,
    /// The printed formula, transcribed faithfully (defects kept where they change the
    /// meaning); absent when it is not a formula at all.
    #[serde(default)]
    pub printed: Option<String>,
    /// The LaTeX as printed, when the transcription alone would hide the defect.
    #[serde(default)]
    pub printed_text: Option<String>,
    /// The defect, in words.
    #[serde(default)]
    pub defect: Option<String>,
    /// The corrected formula, for an erratum.
    #[serde(default)]
    pub corrected: Option<String>,
    /// The derivation it must equal (a name the formula audit knows).
    pub derived: String,
    /// Equal (default) or proportional.
    #[serde(default)]
    pub relation: Relation,
    /// Defined names kept as free symbols here.
    #[serde(default)]
    pub symbols: Vec<String>,
    /// The name this formula defines for later ones.
    #[serde(default)]
    pub defines: Option<String>,
    /// Groups of variables in whose squares the formula must be at most quadratic.
    #[serde(default)]
    pub quadratic_in: Vec<Vec<String>>,
}

/// Printed arithmetic: an expression and the value printed for it.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ArithmeticItem {
    /// The claim.
    pub claim: ClaimRef,
    /// The result id's suffix.
    pub id: String,
    /// Where.
    #[serde(rename = "where")]
    pub place: Place,
    /// The printed steps, each an expression, in order (`-1+3*p+5*(k-1)`, `-1+12+5`).
    pub steps: Vec<String>,
    /// Values of the variables.
    #[serde(default)]
    pub values: BTreeMap<String, i64>,
    /// The printed result.
    pub equals: Printed,
}

/// A statement decided by a dedicated computation.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ComputedItem {
    /// The claim.
    pub claim: ClaimRef,
    /// The result id's suffix.
    pub id: String,
    /// Where.
    #[serde(rename = "where")]
    pub place: Place,
    /// What the paper says, in its words.
    pub printed: String,
    /// The computation.
    pub test: ComputedTest,
}

/// The dedicated computations.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum ComputedTest {
    /// §5: "linearly dependent on the three previous ones".
    FourthRelation {
        /// Seed of the rational scene for the ranks.
        seed: u64,
    },
    /// §5 drops the fourth relation as dependent, then squares the other three: whether the
    /// twofold-squared system still implies it.
    FourthRelationSquared {
        /// Seed of the rational scene for the ranks.
        seed: u64,
    },
    /// The formula for b solves the quadratic in b² (Appendix A, §5.2).
    BFormula,
    /// `√(e₀² − e₀ᵢ²) = ±√(e₁² − e₁ᵢ²) ± √(e₂² − e₂ᵢ²)`, every sign choice squared twice,
    /// against eq. p3f3sqr of the triangle with these edges.
    SignedRelation {
        /// The three edge letters, the left-hand side first.
        edges: Vec<String>,
    },
    /// A list of "constant symbols" against the symbols the expression uses.
    ConstantSymbols {
        /// The symbols the text lists.
        listed: Vec<String>,
        /// The symbols the expression uses.
        used: Vec<String>,
        /// The other places that print the same list.
        #[serde(default)]
        also: Vec<crate::cases::ClaimPlace>,
    },
    /// n(n−1)(n−2)(n−3) against the number of ordered choices of four of n points.
    OrderedQuadruples {
        /// The n to check.
        n: Vec<usize>,
        /// The printed value for the first n.
        printed: Printed,
    },
}

/// A textual or typographic erratum.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct TextItem {
    /// The claim.
    pub claim: ClaimRef,
    /// The result id's suffix.
    pub id: String,
    /// Where.
    #[serde(rename = "where")]
    pub place: Place,
    /// As printed.
    pub printed: String,
    /// As it should read.
    pub corrected: String,
    /// Why it matters to a reader reproducing the result.
    pub effect: String,
}

/// Whether `wanted` asks for the item `claim/id` (as itself, its claim, or its `/expanded`
/// sibling).
pub(super) fn is_asked(claim: &ClaimRef, id: &str, wanted: crate::claims::audit::Wanted) -> bool {
    wanted.item(&format!("{}/{id}", claim.claim), &claim.claim)
}

/// The case with only the items `wanted` asks for. Every formula stays, for the judge to
/// select (see [`is_asked`]): a formula's parse substitutes the names earlier formulas
/// define, and the expansions of the macros are built from the names of them all, so one
/// item is read exactly as in the whole audit, though only it is judged.
pub(super) fn asked(
    c: &FormulaAuditCase,
    wanted: crate::claims::audit::Wanted,
) -> FormulaAuditCase {
    let keep = |claim: &ClaimRef, id: &str| is_asked(claim, id, wanted);
    FormulaAuditCase {
        arithmetic: c
            .arithmetic
            .iter()
            .filter(|a| keep(&a.claim, &a.id))
            .cloned()
            .collect(),
        computed: c
            .computed
            .iter()
            .filter(|x| keep(&x.claim, &x.id))
            .cloned()
            .collect(),
        text: c
            .text
            .iter()
            .filter(|t| keep(&t.claim, &t.id))
            .cloned()
            .collect(),
        ..c.clone()
    }
}

pub(super) fn checks(c: &FormulaAuditCase, v: &Validator) -> Result<()> {
    formula_audit_sizes(c, v)?;
    for (i, d) in c.definitions.iter().enumerate() {
        v.rat_formula(&format!("definitions[{i}].printed"), &d.printed)?;
    }
    for (i, f) in c.formulas.iter().enumerate() {
        let at = |k: &str| format!("formulas[{i}].{k}");
        if let Some(p) = &f.printed {
            v.rat_formula(&at("printed"), p)?;
        }
        if let Some(p) = &f.corrected {
            v.rat_formula(&at("corrected"), p)?;
        }
        if !NAMES.iter().any(|(n, _)| *n == f.derived) {
            return v.err(
                &at("derived"),
                format!(
                    "`{}` is not a derivation; one of: {}",
                    f.derived,
                    NAMES.iter().map(|(n, _)| *n).collect::<Vec<_>>().join(", ")
                ),
            );
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
            let field = format!("arithmetic[{i}].steps[{j}]");
            v.formula_size(&field, st, &Default::default())?;
            if Poly::parse(st).is_err() {
                return v.err(
                    &format!("arithmetic[{i}].steps[{j}]"),
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
        let field = format!("definitions[{i}].printed");
        let size = v.formula_size(&field, &d.printed, &defs)?;
        defs.insert(d.name.clone(), size);
    }
    for (i, f) in c.formulas.iter().enumerate() {
        for (k, text) in [("printed", &f.printed), ("corrected", &f.corrected)] {
            if let Some(t) = text {
                let field = format!("formulas[{i}].{k}");
                v.formula_size(&field, t, &defs)?;
            }
        }
    }
    Ok(())
}
