//! Judgement: a case runs into claim results, each a comparison of what the paper printed
//! with what the derivations compute, ending in a [`Verdict`].

mod audit;
mod dof;
pub mod figure;
mod identity;
mod identity_example;
mod noise;
mod p3f3;
mod p4f3;
mod two_frames;
mod twofold;

pub use audit::{audit as audit_formulas, audit_all, counts as audit_counts, AuditItem};
pub use noise::{run_study, study_of};
pub use twofold::{audit as audit_twofold, TwofoldAudit};

use serde::Serialize;

use crate::cases::{Case, CaseCheck, ClaimRef};
use crate::error::Result;

/// The verdicts (see DESIGN.md).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    /// Agrees within the printed precision.
    Reproduced,
    /// Agrees once the rounding of the printed input data is propagated.
    ReproducedWithinRounding,
    /// A symbolic identity holds exactly over ℚ.
    IdentityVerified,
    /// The printed formula or number is wrong; the corrected form is stated and verified.
    Erratum,
    /// A noise claim, checked against a seeded distribution.
    Statistical,
    /// The paper lacks the data.
    NotReproducible,
    /// The recomputation contradicts the claim.
    Contradicted,
}

impl Verdict {
    /// All verdicts, in report order.
    pub const ALL: [Verdict; 7] = [
        Verdict::Reproduced,
        Verdict::ReproducedWithinRounding,
        Verdict::IdentityVerified,
        Verdict::Erratum,
        Verdict::Statistical,
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

    /// The kebab-case name.
    pub fn name(&self) -> &'static str {
        match self {
            Verdict::Reproduced => "reproduced",
            Verdict::ReproducedWithinRounding => "reproduced-within-rounding",
            Verdict::IdentityVerified => "identity-verified",
            Verdict::Erratum => "erratum",
            Verdict::Statistical => "statistical",
            Verdict::NotReproducible => "not-reproducible",
            Verdict::Contradicted => "contradicted",
        }
    }
}

/// How close is close enough, and why.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Tolerance {
    /// The bound (formatted), or "exact".
    pub value: String,
    /// Where it comes from.
    pub source: String,
}

impl Tolerance {
    /// Exact comparison (integers, rationals, polynomials).
    pub fn exact(why: &str) -> Self {
        Tolerance {
            value: "exact".into(),
            source: why.into(),
        }
    }
}

/// One named piece of evidence.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EvidenceItem {
    /// What it is.
    pub name: String,
    /// Its value, formatted.
    pub value: String,
}

/// How a verdict was reached.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Evidence {
    /// The method.
    pub method: String,
    /// Supporting values, in order.
    pub details: Vec<EvidenceItem>,
}

impl Evidence {
    /// Evidence with a method and no details yet.
    pub fn new(method: &str) -> Self {
        Evidence {
            method: method.into(),
            details: Vec::new(),
        }
    }

    /// Add a detail.
    pub fn with(mut self, name: &str, value: impl ToString) -> Self {
        self.details.push(EvidenceItem {
            name: name.into(),
            value: value.to_string(),
        });
        self
    }
}

/// The outcome for one claim.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ClaimResult {
    /// Unique result id: the CLAIMS.md id, with a `/suffix` when one claim has several results.
    pub id: String,
    /// The CLAIMS.md id.
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
    pub paper_value: String,
    /// What the computation gives.
    pub computed_value: String,
    /// The tolerance, when a comparison of numbers was made.
    pub tolerance: Option<Tolerance>,
    /// How.
    pub evidence: Evidence,
}

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

    /// A result for `claim`, with `suffix` making the id unique when needed.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn result(
        &self,
        claim: &ClaimRef,
        suffix: Option<&str>,
        verdict: Verdict,
        paper_value: String,
        computed_value: String,
        tolerance: Option<Tolerance>,
        evidence: Evidence,
    ) -> ClaimResult {
        ClaimResult {
            id: match suffix {
                Some(s) => format!("{}/{s}", claim.claim),
                None => claim.claim.clone(),
            },
            claim: claim.claim.clone(),
            case: self.case.id.clone(),
            section: self.case.source.section.clone(),
            lines: claim.lines.clone(),
            quote: claim.quote.clone(),
            verdict,
            paper_value,
            computed_value,
            tolerance,
            evidence,
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
        CaseCheck::Restatements(_) => Err(crate::error::Error::InvalidInput(format!(
            "case {}: restatements are decided from the other cases' results (run_all)",
            case.id
        ))),
        CaseCheck::NotReproducible(c) => Ok(c
            .claims
            .iter()
            .map(|m| {
                b.result(
                    &m.claim,
                    None,
                    Verdict::NotReproducible,
                    m.printed.clone(),
                    format!("missing: {}", m.missing.join("; ")),
                    None,
                    Evidence::new("nothing to compute: the paper does not print the data"),
                )
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

/// A restatement is contradicted when a result of a claim it restates is; reproduced when all
/// of them hold; not reproducible when it lies outside the paper's scope.
fn restatements(
    b: &ResultBuilder,
    case: &crate::cases::RestatementsCase,
    results: &[ClaimResult],
) -> Vec<ClaimResult> {
    case.items
        .iter()
        .map(|item| {
            if let Some(why) = &item.out_of_scope {
                return b.result(
                    &item.claim,
                    Some(&item.id),
                    Verdict::NotReproducible,
                    item.claim.quote.clone(),
                    format!("outside the paper's scope: {why}"),
                    None,
                    Evidence::new("no computation: the statement concerns another model"),
                );
            }
            let mapped: Vec<&ClaimResult> = results
                .iter()
                .filter(|r| item.restates.contains(&r.claim))
                .collect();
            let against: Vec<String> = mapped
                .iter()
                .filter(|r| r.verdict == Verdict::Contradicted)
                .map(|r| r.id.clone())
                .collect();
            let missing: Vec<&String> = item
                .restates
                .iter()
                .filter(|id| !mapped.iter().any(|r| &r.claim == *id))
                .collect();
            let verdict = if !against.is_empty() {
                Verdict::Contradicted
            } else if missing.is_empty() {
                Verdict::Reproduced
            } else {
                Verdict::NotReproducible
            };
            let mut ev = Evidence::new("the verdicts of the results of the claims restated");
            for r in &mapped {
                ev = ev.with(&r.id, r.verdict.name());
            }
            b.result(
                &item.claim,
                Some(&item.id),
                verdict,
                item.claim.quote.clone(),
                if !against.is_empty() {
                    format!("contradicted by {}", against.join(", "))
                } else if missing.is_empty() {
                    format!("holds: {}", item.restates.join(", "))
                } else {
                    format!(
                        "missing results for {}",
                        missing
                            .iter()
                            .map(|s| s.as_str())
                            .collect::<Vec<_>>()
                            .join(", ")
                    )
                },
                None,
                ev,
            )
        })
        .collect()
}
