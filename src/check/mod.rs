//! Judgement: a case runs into claim results, each a comparison of what the paper printed
//! with what the derivations compute, ending in a [`Verdict`].

mod audit;
mod dof;
mod errata;
pub mod figure;
mod identity;
mod identity_example;
mod linearity;
mod noise;
mod p3f3;
mod p3f3_restricted;
mod p4f3;
mod p4f3_joint;
mod solution_count;
mod two_frames;
mod two_frames_member;
mod twofold;

pub use crate::studies::noise::{run_study, study_of};
pub use audit::{audit_all, counts as audit_counts, AuditItem};
pub use twofold::{audit as audit_twofold, TwofoldAudit};

mod result;
pub use result::{
    ClaimResult, Evidence, Power, PowerKind, Quantity, Real, Tolerance, ToleranceSource, Value,
    Verdict,
};

use crate::cases::{Case, CaseCheck, ClaimRef};
use crate::error::Result;

/// Builds results (and figures) for one case.
pub(crate) struct ResultBuilder<'a> {
    case: &'a Case,
    figures: std::cell::RefCell<Vec<figure::Figure>>,
}

impl<'a> ResultBuilder<'a> {
    pub(crate) fn new(case: &'a Case) -> Self {
        ResultBuilder {
            case,
            figures: std::cell::RefCell::new(Vec::new()),
        }
    }

    /// Keep a figure for the report.
    pub(crate) fn figure(&self, f: figure::Figure) {
        self.figures.borrow_mut().push(f);
    }

    /// Start a result for `claim`.
    pub(crate) fn claim<'b>(&'b self, claim: &'b ClaimRef) -> ClaimBuilder<'b> {
        ClaimBuilder {
            case: self.case,
            claim,
            suffix: None,
            printed: Vec::new(),
            computed: Vec::new(),
            tolerance: None,
            power: None,
            correction: None,
            evidence: Evidence::new(""),
        }
    }
}

/// One claim result under construction.
pub(crate) struct ClaimBuilder<'b> {
    case: &'b Case,
    claim: &'b ClaimRef,
    suffix: Option<String>,
    printed: Vec<Quantity>,
    computed: Vec<Quantity>,
    tolerance: Option<Tolerance>,
    power: Option<Power>,
    correction: Option<String>,
    evidence: Evidence,
}

impl ClaimBuilder<'_> {
    /// Make the id `claim/suffix`.
    pub(crate) fn suffix(mut self, s: &str) -> Self {
        self.suffix = Some(s.into());
        self
    }

    /// What the paper printed.
    pub(crate) fn printed(mut self, name: &str, v: impl Into<Value>) -> Self {
        self.printed.push(Quantity::new(name, v));
        self
    }

    /// What the computation gives.
    pub(crate) fn computed(mut self, name: &str, v: impl Into<Value>) -> Self {
        self.computed.push(Quantity::new(name, v));
        self
    }

    /// The tolerance of the comparison.
    pub(crate) fn tolerance(mut self, t: Tolerance) -> Self {
        self.tolerance = Some(t);
        self
    }

    /// The negative control.
    pub(crate) fn power(mut self, p: Power) -> Self {
        self.power = Some(p);
        self
    }

    /// The corrected form of an erratum.
    pub(crate) fn correction(mut self, c: impl Into<String>) -> Self {
        self.correction = Some(c.into());
        self
    }

    /// The method.
    pub(crate) fn method(mut self, m: &str) -> Self {
        self.evidence.method = m.into();
        self
    }

    /// One piece of evidence.
    pub(crate) fn detail(mut self, name: &str, v: impl Into<Value>) -> Self {
        self.evidence.details.push(Quantity::new(name, v));
        self
    }

    /// The whole evidence at once.
    pub(crate) fn evidence(mut self, e: Evidence) -> Self {
        self.evidence = e;
        self
    }

    /// Finish with `verdict`. A positive verdict whose power is weak (or missing) becomes
    /// `inconclusive`: a check that could not have failed confirms nothing.
    pub(crate) fn verdict(self, verdict: Verdict) -> ClaimResult {
        let weak = self.power.as_ref().is_none_or(|p| p.weak);
        let v = if verdict.is_positive() && weak {
            Verdict::Inconclusive
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
            case: self.case.id.clone(),
            section: claim
                .section
                .clone()
                .unwrap_or_else(|| self.case.source.section.clone()),
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
            evidence: self.evidence,
        }
    }
}

/// Run one case into its claim results.
pub fn run_case(case: &Case) -> Result<Vec<ClaimResult>> {
    Ok(run_case_full(case)?.0)
}

/// Run one case into its claim results and the figures its checks drew.
pub fn run_case_full(case: &Case) -> Result<(Vec<ClaimResult>, Vec<figure::Figure>)> {
    let b = ResultBuilder::new(case);
    let results = dispatch(&b, case)?;
    Ok((results, b.figures.into_inner()))
}

fn dispatch(b: &ResultBuilder, case: &Case) -> Result<Vec<ClaimResult>> {
    match &case.check {
        CaseCheck::DofCount(c) => dof::check_count(b, c),
        CaseCheck::DofIdentifiability(c) => dof::check_identifiability(b, c),
        CaseCheck::TwofoldSquared(c) => twofold::check(b, c),
        CaseCheck::P3f3Example(c) => p3f3::check_example(b, c),
        CaseCheck::P4f3Example(c) => p4f3::check_example(b, c),
        CaseCheck::P4f3Census(c) => p4f3::check_census(b, c),
        CaseCheck::P3f3Census(c) => p3f3::check_census(b, c),
        CaseCheck::P3f4Census(c) => p3f3::check_p3f4_census(b, c),
        CaseCheck::NoiseStudy(c) => noise::check(b, c),
        CaseCheck::FormulaAudit(c) => audit::check(b, c),
        CaseCheck::TwoFrames(c) => two_frames::check(b, c),
        CaseCheck::IdentityCensus(c) => identity::check(b, c),
        CaseCheck::IdentityExample(c) => identity_example::check(b, c),
        CaseCheck::SourceErrata(c) => errata::check(b, c),
        CaseCheck::SolutionCount(c) => solution_count::check(b, c),
        CaseCheck::LinearityPrice(c) => linearity::check(b, c),
        CaseCheck::Restatements(_) => Err(crate::error::Error::InvalidInput(format!(
            "case {}: restatements are decided from the other cases' results (run_all)",
            case.id
        ))),
        CaseCheck::NotReproducible(c) => Ok(c
            .claims
            .iter()
            .map(|m| {
                let mut r = b
                    .claim(&m.claim)
                    .printed("paper", Value::label(m.printed.clone()))
                    .method("nothing to compute: the paper does not print the data")
                    .power(Power::none("no computation to control"));
                for missing in &m.missing {
                    r = r.detail("missing", Value::label(missing.clone()));
                }
                r.verdict(Verdict::NotReproducible)
            })
            .collect()),
    }
}

/// Run every case: first all the others, then the restatements, decided from their results.
pub fn run_all(cases: &[Case]) -> Result<Vec<ClaimResult>> {
    Ok(run_all_full(cases, &|_, _| {})?.0)
}

/// [`run_all`] with the figures; `progress` hears of each case as it finishes (index, id).
pub fn run_all_full(
    cases: &[Case],
    progress: &dyn Fn(usize, &str),
) -> Result<(Vec<ClaimResult>, Vec<figure::Figure>)> {
    let mut out = Vec::new();
    let mut figures = Vec::new();
    for (i, case) in cases.iter().enumerate() {
        if !matches!(case.check, CaseCheck::Restatements(_)) {
            let (r, f) = run_case_full(case)?;
            out.extend(r);
            figures.extend(f);
        }
        progress(i, &case.id);
    }
    let mut restated = Vec::new();
    for case in cases {
        if let CaseCheck::Restatements(r) = &case.check {
            restated.extend(restatements(&ResultBuilder::new(case), r, &out));
        }
    }
    out.extend(restated);
    Ok((out, figures))
}

/// A restatement is contradicted when a result of a claim it restates is; it holds (with the
/// weakest verdict among them) when all of them hold; not reproducible when one is missing or
/// it lies outside the paper's scope.
fn restatements(
    b: &ResultBuilder,
    case: &crate::cases::RestatementsCase,
    results: &[ClaimResult],
) -> Vec<ClaimResult> {
    case.items
        .iter()
        .map(|item| restatement(b, item, results))
        .collect()
}

fn restatement(
    b: &ResultBuilder,
    item: &crate::cases::Restatement,
    results: &[ClaimResult],
) -> ClaimResult {
    let r = b
        .claim(&item.claim)
        .suffix(&item.id)
        .printed("statement", Value::label(item.claim.quote.clone()));
    if let Some(why) = &item.out_of_scope {
        return r
            .computed("outside the paper's scope", Value::label(why.clone()))
            .method("no computation: the statement concerns another model")
            .power(Power::none("outside the paper's model"))
            .verdict(Verdict::NotReproducible);
    }
    let mapped: Vec<&ClaimResult> = results
        .iter()
        .filter(|r| item.restates.contains(&r.claim) && !item.except.contains(&r.id))
        .collect();
    let missing = item
        .restates
        .iter()
        .any(|id| !mapped.iter().any(|r| &r.claim == id));
    let verdict = restated_verdict(mapped.iter().map(|r| r.verdict), missing);
    let mut r = r
        .method("the verdicts of the results of the claims restated")
        .power(Power::mutant(
            true,
            "any restated result that is contradicted, fails or is missing turns this one",
        ));
    for m in &mapped {
        r = r.computed(&m.id, Value::label(m.verdict.name()));
    }
    r.verdict(verdict)
}

/// The verdict of a restatement from the verdicts of what it restates: the worst of them, by
/// a fixed order (contradicted, then statistical failure, inconclusive, not reproducible, then
/// the positive ones from the weakest); an erratum in a restated formula does not make the
/// restated statement false.
pub(crate) fn restated_verdict(verdicts: impl Iterator<Item = Verdict>, missing: bool) -> Verdict {
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
