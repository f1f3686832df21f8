//! Typed claim results: numbers stay numbers until `report/` formats them.

use serde::{Serialize, Serializer};

use super::{Evidence, Resolution};
use crate::cases::Printed;

/// The verdicts (see DESIGN.md and `docs/verdicts.md`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    /// Agrees within the printed precision.
    Reproduced,
    /// Agrees once the rounding of the printed input data is propagated.
    ReproducedWithinRounding,
    /// A symbolic identity holds exactly over ℚ.
    IdentityVerified,
    /// True except on a degenerate set the paper never names (the evidence names it).
    HoldsGenerically,
    /// A noise claim that holds under the stated reading of the paper's words.
    StatisticalHolds,
    /// A noise claim that fails under the stated reading of the paper's words.
    StatisticalFails,
    /// The printed formula or number is wrong; the corrected form is stated and verified.
    Erratum,
    /// A defect of the text that changes no meaning (its intended reading is unique); the
    /// reading is stated and the quote verified at its lines.
    Note,
    /// The check cannot discriminate: it would accept values the paper would call wrong.
    Inconclusive,
    /// The paper lacks the data; the evidence lists what is missing and what was tried.
    NotReproducible,
    /// The paper asserts something false.
    Contradicted,
}

impl Verdict {
    /// All verdicts, in report order.
    pub const ALL: [Verdict; 11] = [
        Verdict::Reproduced,
        Verdict::ReproducedWithinRounding,
        Verdict::IdentityVerified,
        Verdict::HoldsGenerically,
        Verdict::StatisticalHolds,
        Verdict::StatisticalFails,
        Verdict::Erratum,
        Verdict::Note,
        Verdict::Inconclusive,
        Verdict::NotReproducible,
        Verdict::Contradicted,
    ];

    /// `Reproduced` when a claim decided by computation holds, `Contradicted` when not.
    pub fn holds(ok: bool) -> Verdict {
        if ok {
            Verdict::Reproduced
        } else {
            Verdict::Contradicted
        }
    }

    /// `StatisticalHolds` or `StatisticalFails`.
    pub fn statistical(holds: bool) -> Verdict {
        if holds {
            Verdict::StatisticalHolds
        } else {
            Verdict::StatisticalFails
        }
    }

    /// What the verdict means, in one sentence a reader of the report needs.
    pub fn meaning(self) -> &'static str {
        match self {
            Verdict::Reproduced => "the recomputed value agrees with the printed one within its printed precision",
            Verdict::ReproducedWithinRounding => "agrees once the rounding of the paper's printed inputs is carried through the computation",
            Verdict::IdentityVerified => "the printed formula equals its derivation exactly, by exact polynomial arithmetic",
            Verdict::HoldsGenerically => "true except on a special set of configurations the paper does not name (the evidence names it)",
            Verdict::StatisticalHolds => "a claim about noise that holds against a seeded distribution of trials, under every reasonable reading of its words",
            Verdict::StatisticalFails => "a claim about noise that the seeded distribution of trials does not bear out",
            Verdict::Erratum => "the paper prints something wrong; the corrected form is stated and checked: a finding, not a failure of the tool",
            Verdict::Note => "a slip of form with one possible reading (a subscript, a header): listed, not counted as an erratum",
            Verdict::Inconclusive => "the check could not have failed on values the paper would call wrong, so it decides nothing",
            Verdict::NotReproducible => "the paper lacks the data to decide the claim; the evidence says what is missing and what was tried",
            Verdict::Contradicted => "the paper asserts something that the computation shows to be false",
        }
    }

    /// A positive verdict says the paper's claim was confirmed by a check that could fail.
    pub fn is_positive(&self) -> bool {
        matches!(
            self,
            Verdict::Reproduced
                | Verdict::ReproducedWithinRounding
                | Verdict::IdentityVerified
                | Verdict::HoldsGenerically
                | Verdict::StatisticalHolds
        )
    }

    /// The kebab-case name.
    pub fn name(&self) -> &'static str {
        match self {
            Verdict::Reproduced => "reproduced",
            Verdict::ReproducedWithinRounding => "reproduced-within-rounding",
            Verdict::IdentityVerified => "identity-verified",
            Verdict::HoldsGenerically => "holds-generically",
            Verdict::StatisticalHolds => "statistical-holds",
            Verdict::StatisticalFails => "statistical-fails",
            Verdict::Erratum => "erratum",
            Verdict::Note => "note",
            Verdict::Inconclusive => "inconclusive",
            Verdict::NotReproducible => "not-reproducible",
            Verdict::Contradicted => "contradicted",
        }
    }
}

/// A float as the one formatter shows it: [`crate::numfmt::SIGNIFICANT`] significant digits,
/// so that `report.json` and snapshots never drift across machines.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Real(pub f64);

impl Serialize for Real {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let shown = crate::numfmt::sig(self.0);
        match shown.parse::<f64>() {
            Ok(v) if v.is_finite() => s.serialize_f64(v),
            // a non-finite number stays a number, so that the output guard
            // (`report::finite`) sees it and refuses the output: never "inf" as text
            _ => s.serialize_f64(self.0),
        }
    }
}

/// One value in a claim result.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Value {
    /// A number as the paper printed it: its digits, its exact value, half a unit of its last
    /// digit.
    Printed {
        /// The digits as printed.
        text: String,
        /// The exact rational value of those digits (`p/q`).
        exact: String,
        /// Half a unit in the last printed digit.
        half_unit: Real,
    },
    /// A computed floating-point number.
    Real {
        /// The value.
        value: Real,
    },
    /// A quantity at rounding level, shown only as the power of ten above it.
    Below {
        /// `|x| < 10^exponent`; `None` for exact zero.
        exponent: Option<i32>,
    },
    /// A list of computed numbers.
    Reals {
        /// The values.
        values: Vec<Real>,
    },
    /// A closed interval.
    Interval {
        /// Lower end.
        lo: Real,
        /// Upper end.
        hi: Real,
    },
    /// An exact rational or integer (`p/q` or `n`).
    Exact {
        /// The value.
        value: String,
    },
    /// A count, optionally out of a total.
    Count {
        /// How many.
        count: u64,
        /// Out of how many.
        #[serde(skip_serializing_if = "Option::is_none")]
        of: Option<u64>,
    },
    /// A yes/no finding.
    Flag {
        /// The finding.
        value: bool,
    },
    /// A formula in the paper's notation (plain text or LaTeX as printed).
    Formula {
        /// The formula.
        text: String,
    },
    /// A name, an id, a method, a statement of the paper: never a number.
    Label {
        /// The text.
        text: String,
    },
    /// The paper's own words, quoted from its LaTeX source (read as running text).
    Quote {
        /// The source text.
        text: String,
    },
}

impl Value {
    /// A printed number.
    pub fn printed(p: &Printed) -> Value {
        Value::Printed {
            text: p.text.clone(),
            exact: p.value.to_string(),
            half_unit: Real(p.half_unit()),
        }
    }

    /// A computed number.
    pub fn real(x: f64) -> Value {
        Value::Real { value: Real(x) }
    }

    /// A rounding-level number.
    pub fn below(x: f64) -> Value {
        Value::Below {
            exponent: (x != 0.0).then(|| x.abs().log10().floor() as i32 + 1),
        }
    }

    /// Computed numbers.
    pub fn reals(xs: &[f64]) -> Value {
        Value::Reals {
            values: xs.iter().map(|x| Real(*x)).collect(),
        }
    }

    /// An interval.
    pub fn interval(lo: f64, hi: f64) -> Value {
        Value::Interval {
            lo: Real(lo),
            hi: Real(hi),
        }
    }

    /// An exact value.
    pub fn exact(v: impl ToString) -> Value {
        Value::Exact {
            value: v.to_string(),
        }
    }

    /// A count.
    pub fn count(n: usize) -> Value {
        Value::Count {
            count: n as u64,
            of: None,
        }
    }

    /// A count out of a total.
    pub fn count_of(n: usize, of: usize) -> Value {
        Value::Count {
            count: n as u64,
            of: Some(of as u64),
        }
    }

    /// A flag.
    pub fn flag(b: bool) -> Value {
        Value::Flag { value: b }
    }

    /// A formula.
    pub fn formula(t: impl Into<String>) -> Value {
        Value::Formula { text: t.into() }
    }

    /// A label.
    pub fn label(t: impl Into<String>) -> Value {
        Value::Label { text: t.into() }
    }

    /// A quote of the paper's source.
    pub fn quote(t: impl Into<String>) -> Value {
        Value::Quote { text: t.into() }
    }

    /// Every float this value holds (for the output guard).
    pub fn floats(&self) -> Vec<f64> {
        match self {
            Value::Printed { half_unit, .. } => vec![half_unit.0],
            Value::Real { value } => vec![value.0],
            Value::Reals { values } => values.iter().map(|r| r.0).collect(),
            Value::Interval { lo, hi } => vec![lo.0, hi.0],
            _ => Vec::new(),
        }
    }
}

impl From<f64> for Value {
    fn from(x: f64) -> Value {
        Value::real(x)
    }
}

impl From<bool> for Value {
    fn from(b: bool) -> Value {
        Value::flag(b)
    }
}

impl From<usize> for Value {
    fn from(n: usize) -> Value {
        Value::count(n)
    }
}

impl From<&Printed> for Value {
    fn from(p: &Printed) -> Value {
        Value::printed(p)
    }
}

impl From<&str> for Value {
    fn from(t: &str) -> Value {
        Value::label(t)
    }
}

impl From<String> for Value {
    fn from(t: String) -> Value {
        Value::label(t)
    }
}

/// A named value, with the role the renderers read (never its name).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Quantity {
    /// What it is, in words.
    pub name: String,
    /// Its value.
    pub value: Value,
    /// What it is to the layout: a plain row unless said otherwise.
    #[serde(skip_serializing_if = "Role::is_plain")]
    pub role: Role,
}

impl Quantity {
    /// A named value, a plain row.
    pub fn new(name: &str, value: impl Into<Value>) -> Quantity {
        Quantity::with_role(name, value, Role::Plain)
    }

    /// A named value in `role`.
    pub fn with_role(name: &str, value: impl Into<Value>, role: Role) -> Quantity {
        Quantity {
            name: name.into(),
            value: value.into(),
            role,
        }
    }

    /// One entry of the table `table` (named "row: column").
    pub fn entry(table: &str, row: &str, column: &str, value: impl Into<Value>) -> Quantity {
        Quantity::with_role(
            &format!("{row}: {column}"),
            value,
            Role::Entry {
                table: table.into(),
                row: row.into(),
                column: column.into(),
            },
        )
    }

    /// One cell of a table: `statistic` of `model` (named "model: statistic").
    pub fn cell(model: &str, statistic: &str, value: impl Into<Value>) -> Quantity {
        Quantity::with_role(
            &format!("{model}: {statistic}"),
            value,
            Role::Cell {
                model: model.into(),
                statistic: statistic.into(),
                percentiles: Vec::new(),
            },
        )
    }

    /// One cell of a table whose value lists the quantiles of `model` at the probabilities
    /// `percentiles` (named "model: statistic").
    pub fn quantiles(
        model: &str,
        statistic: &str,
        percentiles: &[f64],
        values: &[f64],
    ) -> Quantity {
        Quantity::with_role(
            &format!("{model}: {statistic}"),
            Value::reals(values),
            Role::Cell {
                model: model.into(),
                statistic: statistic.into(),
                percentiles: percentiles.to_vec(),
            },
        )
    }
}

/// What a quantity is to the renderers. A renderer reads the role, never the name: renaming
/// a quantity changes words, not the layout.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Role {
    /// A row of its own.
    #[default]
    Plain,
    /// A statistic of one model (or method, or variant): where two models share a statistic,
    /// the cells form a table (models × statistics); a claim resting on Monte Carlo trials
    /// shows them with the digits its trials resolve.
    Cell {
        /// The row: the model.
        model: String,
        /// The column: the statistic.
        statistic: String,
        /// For a statistic that is a list of quantiles, the probability of each (typed for the
        /// renderers, never read from the statistic's words; not serialized: the value lists
        /// them in order).
        #[serde(skip)]
        percentiles: Vec<f64>,
    },
    /// The text as printed (the source's LaTeX): an erratum's printed side shows it alone.
    AsPrinted,
    /// What is wrong, in words (an erratum's defect).
    Defect,
    /// What the text should say.
    ShouldBe,
    /// The number of trials the claim's numbers rest on.
    Trials,
    /// A value whose name adds nothing ("paper"): alone in a line, the value is printed alone.
    ValueOnly,
    /// One entry of a named table whose rows are not models: the readings of a sentence, the
    /// paper's named quantities at an example. Rows and columns keep their first order.
    Entry {
        /// The table's caption.
        table: String,
        /// The row.
        row: String,
        /// The column.
        column: String,
    },
}

impl Role {
    /// Whether it is a plain row (not serialized, so that most quantities stay two fields).
    pub fn is_plain(&self) -> bool {
        *self == Role::Plain
    }
}

/// Where a tolerance comes from.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum ToleranceSource {
    /// Exact comparison (integers, rationals, polynomials).
    Exact,
    /// Half a unit in the last printed digit.
    PrintedPrecision,
    /// The printed input's rounding propagated (interval arithmetic, a rounding box).
    Propagated,
    /// A floating-point error bound the code derives (condition × unit roundoff × size).
    ErrorBound,
    /// A random-point screen of an identity: a false identity passes it with probability at
    /// most `10^log10` (Schwartz–Zippel); the comparison itself is exact.
    FalsePass {
        /// log₁₀ of the false-pass probability bound.
        log10: Real,
    },
    /// A percentile of a seeded Monte Carlo distribution.
    MonteCarlo {
        /// The percentile (0–100).
        percentile: Real,
        /// The trial count.
        trials: u64,
    },
}

/// How close is close enough, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Tolerance {
    /// The bound; `None` for an exact comparison.
    pub bound: Option<Real>,
    /// Where the bound comes from.
    #[serde(flatten)]
    pub source: ToleranceSource,
    /// How it was derived, in a phrase.
    pub how: String,
}

impl Tolerance {
    /// Exact comparison.
    pub fn exact(how: &str) -> Self {
        Tolerance {
            bound: None,
            source: ToleranceSource::Exact,
            how: how.into(),
        }
    }

    /// A numeric bound from `source`.
    pub fn bound(bound: f64, source: ToleranceSource, how: &str) -> Self {
        Tolerance {
            bound: Some(Real(bound)),
            source,
            how: how.into(),
        }
    }
}

/// What kind of negative control a verdict has.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PowerKind {
    /// The set of printed values the same check would accept.
    Interval,
    /// A changed formula or target that the same check rejects.
    Mutant,
    /// No negative control (allowed only for verdicts that are not positive).
    None,
}

/// The power of a verdict: what the same check would have rejected.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Power {
    /// The kind of control.
    pub kind: PowerKind,
    /// What was accepted or rejected, in a phrase.
    pub detail: String,
    /// The acceptance region, for an interval control.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub accepts: Option<Value>,
    /// How finely the acceptance region resolves the printed value, for an interval control.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub resolution: Option<Resolution>,
    /// True when the check would accept values the paper would call wrong.
    pub weak: bool,
}

impl Power {
    /// An acceptance interval `[lo, hi]` around a printed value whose half unit is `allowed`
    /// (the widest deviation its digits still call right). Its [`Resolution`] says how many
    /// of the printed digits the check resolves. It is weak when it resolves none (it would
    /// accept values that differ from the printed one in its leading digit) or is unbounded;
    /// a check that resolves some digits but not all agrees at the resolution the inputs'
    /// rounding allows (`ClaimBuilder::verdict` then says `reproduced-within-rounding`).
    pub fn interval(lo: f64, hi: f64, printed: f64, allowed: f64, detail: &str) -> Power {
        let within = printed - lo <= allowed * (1.0 + f64::EPSILON)
            && hi - printed <= allowed * (1.0 + f64::EPSILON);
        let resolution = Resolution::of(lo, hi, printed, allowed);
        // no resolution: an unbounded interval (never within), or a printed 0, which has no
        // digits to resolve, so its half unit decides
        let weak = resolution.map_or(!within, |r| r.digits == 0);
        Power {
            kind: PowerKind::Interval,
            detail: detail.into(),
            accepts: Some(Value::interval(lo, hi)),
            resolution,
            weak,
        }
    }

    /// True when the control resolves fewer digits than were printed.
    pub fn coarser_than_printed(&self) -> bool {
        self.resolution.is_some_and(|r| r.digits < r.printed)
    }

    /// An acceptance set that is exact (integers, rationals): only the computed value passes.
    pub fn exact_value(detail: &str) -> Power {
        Power {
            kind: PowerKind::Interval,
            detail: detail.into(),
            accepts: None,
            resolution: None,
            weak: false,
        }
    }

    /// A monomial as a reader writes it (`a²·aᵢ²`), for a mutant's changed term.
    pub fn term_text(term: &crate::algebra::Monomial) -> String {
        let factors: Vec<(&str, u32)> = term
            .factors()
            .iter()
            .map(|(v, e)| (v.as_str(), *e))
            .collect();
        crate::numfmt::monomial(&factors)
    }

    /// A mutant: `rejected` says whether the same check rejected it.
    pub fn mutant(rejected: bool, detail: &str) -> Power {
        Power {
            kind: PowerKind::Mutant,
            detail: detail.into(),
            accepts: None,
            resolution: None,
            weak: !rejected,
        }
    }

    /// No negative control; `why` says why none applies.
    pub fn none(why: &str) -> Power {
        Power {
            kind: PowerKind::None,
            detail: why.into(),
            accepts: None,
            resolution: None,
            weak: true,
        }
    }
}

/// The outcome for one claim.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ClaimResult {
    /// Unique result id: the claim id (paper_cases/claims.md), with a `/suffix` when one claim has several results.
    pub id: String,
    /// The claim id (paper_cases/claims.md).
    pub claim: String,
    /// The case it came from.
    pub case: String,
    /// Paper section.
    pub section: String,
    /// Line range in the paper's source.
    pub lines: String,
    /// The paper's words.
    pub quote: String,
    /// The verdict.
    pub verdict: Verdict,
    /// What the paper printed or claimed.
    pub printed: Vec<Quantity>,
    /// What the computation gives.
    pub computed: Vec<Quantity>,
    /// The tolerance, when a comparison was made.
    pub tolerance: Option<Tolerance>,
    /// What the same check would have rejected.
    pub power: Power,
    /// For an erratum: the corrected form, verified.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub correction: Option<String>,
    /// For an `inconclusive` verdict the judge reached itself (not for a weak control, which
    /// the power states): why the check could not decide.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub undecided: Option<String>,
    /// The claims it rests on in the paper's argument (the case's `rests_on`, a restatement's
    /// `restates`): claim ids, each standing for all its results.
    pub rests_on: Vec<String>,
    /// How.
    pub evidence: Evidence,
}

macro_rules! exact_from {
    ($($t:ty),*) => {$(
        impl From<$t> for Value {
            fn from(n: $t) -> Value {
                Value::exact(n)
            }
        }
    )*};
}
#[rustfmt::skip]
exact_from!(u64, u32, i64, i32, u8, num_bigint::BigInt, num_rational::BigRational);

impl From<&String> for Value {
    fn from(t: &String) -> Value {
        Value::label(t.clone())
    }
}
