//! Judgement: a case runs into claim results, each a comparison of what the paper printed
//! with what the derivations compute, ending in a [`Verdict`].

pub mod figure;
pub mod noise;
mod points;

pub use points::{points_details, points_tolerance, prime_details};

mod evidence;
mod resolution;
mod result;
pub mod standing;
pub use evidence::Evidence;
pub use resolution::{alternative_verdict, excluded_by, Resolution};
pub use result::{
    ClaimResult, Power, PowerKind, Quantity, Real, Role, Tolerance, ToleranceSource, Value, Verdict,
};

use crate::cases::Case;
use crate::cases::ClaimRef;

/// Builds results (and figures) for one case.
pub struct ResultBuilder<'a> {
    case: Whose<'a>,
    figures: std::cell::RefCell<Vec<figure::Figure>>,
}

impl<'a> ResultBuilder<'a> {
    /// Results of `case`'s claims (each names the case, and its section unless the claim has
    /// its own).
    pub fn new<C>(case: &'a Case<C>) -> Self {
        ResultBuilder {
            case: Whose {
                id: &case.id,
                section: &case.source.section,
            },
            figures: std::cell::RefCell::new(Vec::new()),
        }
    }

    /// The figures the case's checks drew.
    pub fn into_figures(self) -> Vec<figure::Figure> {
        self.figures.into_inner()
    }

    /// Keep a figure for the report.
    pub fn figure(&self, f: figure::Figure) {
        self.figures.borrow_mut().push(f);
    }

    /// Start a result for `claim`.
    pub fn claim<'b>(&'b self, claim: &'b ClaimRef) -> ClaimBuilder<'b> {
        ClaimBuilder {
            case: self.case,
            claim,
            suffix: None,
            printed: Vec::new(),
            computed: Vec::new(),
            tolerance: None,
            power: None,
            correction: None,
            undecided: None,
            evidence: Evidence::new(""),
        }
    }
}

/// The case a result belongs to: its id and section.
#[derive(Clone, Copy)]
struct Whose<'a> {
    id: &'a str,
    section: &'a str,
}

/// One claim result under construction.
pub struct ClaimBuilder<'b> {
    case: Whose<'b>,
    claim: &'b ClaimRef,
    suffix: Option<String>,
    printed: Vec<Quantity>,
    computed: Vec<Quantity>,
    tolerance: Option<Tolerance>,
    power: Option<Power>,
    correction: Option<String>,
    undecided: Option<String>,
    evidence: Evidence,
}

impl ClaimBuilder<'_> {
    /// Make the id `claim/suffix`.
    pub fn suffix(mut self, s: &str) -> Self {
        self.suffix = Some(s.into());
        self
    }

    /// What the paper printed.
    pub fn printed(mut self, name: &str, v: impl Into<Value>) -> Self {
        self.printed.push(Quantity::new(name, v));
        self
    }

    /// What the computation gives.
    pub fn computed(mut self, name: &str, v: impl Into<Value>) -> Self {
        self.computed.push(Quantity::new(name, v));
        self
    }

    /// The tolerance of the comparison.
    pub fn tolerance(mut self, t: Tolerance) -> Self {
        self.tolerance = Some(t);
        self
    }

    /// The negative control.
    pub fn power(mut self, p: Power) -> Self {
        self.power = Some(p);
        self
    }

    /// The corrected form of an erratum.
    pub fn correction(mut self, c: impl Into<String>) -> Self {
        self.correction = Some(c.into());
        self
    }

    /// The method.
    pub fn method(mut self, m: &str) -> Self {
        self.evidence.method = m.into();
        self
    }

    /// What the paper printed, in `role`.
    pub fn printed_as(mut self, name: &str, v: impl Into<Value>, role: Role) -> Self {
        self.printed.push(Quantity::with_role(name, v, role));
        self
    }

    /// What the computation gives, as one cell of a table: `statistic` of `model`.
    pub fn computed_cell(mut self, model: &str, statistic: &str, v: impl Into<Value>) -> Self {
        self.computed.push(Quantity::cell(model, statistic, v));
        self
    }

    /// One piece of evidence, one entry of the named table `table`.
    pub fn entry(mut self, table: &str, row: &str, column: &str, v: impl Into<Value>) -> Self {
        self.evidence
            .details
            .push(Quantity::entry(table, row, column, v));
        self
    }

    /// One piece of evidence, one cell of a table: `statistic` of `model`.
    pub fn cell(mut self, model: &str, statistic: &str, v: impl Into<Value>) -> Self {
        self.evidence
            .details
            .push(Quantity::cell(model, statistic, v));
        self
    }

    /// One piece of evidence in `role`.
    pub fn detail_as(mut self, name: &str, v: impl Into<Value>, role: Role) -> Self {
        self.evidence
            .details
            .push(Quantity::with_role(name, v, role));
        self
    }

    /// One piece of evidence.
    pub fn detail(mut self, name: &str, v: impl Into<Value>) -> Self {
        self.evidence.details.push(Quantity::new(name, v));
        self
    }

    /// The whole evidence at once.
    pub fn evidence(mut self, e: Evidence) -> Self {
        self.evidence = e;
        self
    }

    /// Why the judge could not decide, should it return `inconclusive` (kept only then).
    pub fn undecided(mut self, why: impl Into<String>) -> Self {
        self.undecided = Some(why.into());
        self
    }

    /// Finish with `verdict`. A positive verdict whose power is weak (or missing) becomes
    /// `inconclusive`: a check that could not have failed confirms nothing. A `reproduced`
    /// whose acceptance interval resolves fewer digits than the paper printed becomes
    /// `reproduced-within-rounding`: it agrees at the resolution its inputs' rounding allows.
    pub fn verdict(self, verdict: Verdict) -> ClaimResult {
        let weak = self.power.as_ref().is_none_or(|p| p.weak);
        let coarse = self.power.as_ref().is_some_and(Power::coarser_than_printed);
        let v = if verdict.is_positive() && weak {
            Verdict::Inconclusive
        } else if verdict == Verdict::Reproduced && coarse {
            Verdict::ReproducedWithinRounding
        } else {
            verdict
        };
        self.verdict_unchecked(v)
    }

    fn verdict_unchecked(self, verdict: Verdict) -> ClaimResult {
        let claim = self.claim;
        ClaimResult {
            id: match &self.suffix {
                Some(s) => format!("{}/{s}", claim.claim),
                None => claim.claim.clone(),
            },
            claim: claim.claim.clone(),
            case: self.case.id.to_string(),
            section: claim
                .section
                .clone()
                .unwrap_or_else(|| self.case.section.to_string()),
            lines: claim.lines.clone(),
            quote: claim.quote.clone(),
            verdict,
            printed: self.printed,
            computed: self.computed,
            tolerance: self.tolerance,
            power: self
                .power
                .unwrap_or_else(|| Power::none("no negative control")),
            correction: self.correction,
            undecided: self.undecided.filter(|_| verdict == Verdict::Inconclusive),
            rests_on: Vec::new(),
            evidence: self.evidence,
        }
    }
}

/// The verdict of a restatement from the verdicts of what it restates: the worst of them, by
/// a fixed order (contradicted, then statistical failure, inconclusive, not reproducible, then
/// the positive ones from the weakest); an erratum in a restated formula does not make the
/// restated statement false.
pub fn restated_verdict(verdicts: impl Iterator<Item = Verdict>, missing: bool) -> Verdict {
    const WORST_FIRST: [Verdict; 9] = [
        Verdict::Contradicted,
        Verdict::StatisticalFails,
        Verdict::Inconclusive,
        Verdict::NotReproducible,
        Verdict::HoldsGenerically,
        Verdict::StatisticalHolds,
        Verdict::ReproducedWithinRounding,
        Verdict::Reproduced,
        Verdict::IdentityVerified,
    ];
    let seen: Vec<Verdict> = verdicts.collect();
    if missing || seen.is_empty() {
        return Verdict::NotReproducible;
    }
    let worst = WORST_FIRST
        .iter()
        .find(|v| seen.contains(v))
        .copied()
        .unwrap_or(Verdict::Reproduced);
    match worst {
        Verdict::IdentityVerified | Verdict::ReproducedWithinRounding => Verdict::Reproduced,
        v => v,
    }
}
