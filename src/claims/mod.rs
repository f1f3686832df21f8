//! The claims of the paper, one folder per kind of case: each folder holds the kind's case
//! schema, its validation and limits, its seeds, its study (or its calls to the shared engines
//! of [`crate::studies`]), its judge and its figures. A kind's folder is named as its case
//! files name it under `check:`.
//!
//! Every kind implements [`ClaimKind`] and is registered once, in the `kinds!` list below:
//! that list is the only place where the kinds are enumerated.

use serde::Deserialize;

use crate::cases::{Disagreement, Schema, Validator};
use crate::check::{figure::Figure, ClaimResult, ResultBuilder, Verdict};
use crate::error::Result;
use crate::provenance::CaseSeeds;

pub mod audit;
pub mod dof_count;
pub mod dof_identifiability;
pub mod formula_audit;
pub mod identity_census;
pub mod identity_example;
pub mod linearity_price;
pub mod noise_study;
pub mod not_reproducible;
pub mod p3f3_census;
pub mod p3f3_example;
pub mod p3f4_census;
pub mod p4f3_census;
pub mod p4f3_example;
pub mod rerun;
pub mod restatements;
pub mod shared;
pub mod solution_count;
pub mod source_errata;
pub mod supports;
pub mod two_frames;
pub mod twofold_squared;

/// A case file with its check, one of the registered kinds.
pub type PaperCase = crate::cases::Case<CaseCheck>;

/// The cases, the paper file and the verification, the check of each case one of the kinds.
pub type PaperInputs = crate::cases::PaperInputs<CaseCheck>;

/// What every kind of claim does. The registry calls these in this order: `trials` and
/// `validate` as the file is read, then `run`, restatements last.
pub trait ClaimKind {
    /// Every count of trials, points or instances the case asks for, with its field: each must
    /// be at least 1, since a check over nothing holds vacuously. No default, so that a new
    /// kind cannot forget the rule; a kind without trials returns none.
    fn trials(&self) -> Vec<(&'static str, usize)>;

    /// What serde cannot check: counts, limits (`docs/limits.md`), formulas that parse. `v`
    /// names fields relative to `check.<kind>`.
    fn validate(&self, v: &Validator) -> Result<()>;

    /// Every seed the case sets (the report lists them, so that a run can be repeated).
    fn seeds(&self) -> Vec<u64>;

    /// The claim results (figures go to `b`). `earlier` holds the results of every kind that
    /// is not a restatement; only restatements read it.
    fn run(&self, b: &ResultBuilder, earlier: &[ClaimResult]) -> Result<Vec<ClaimResult>>;

    /// Whether the kind is decided from the other cases' results (so runs after them).
    fn restates(&self) -> bool {
        false
    }

    /// Claim ids the case restates, with the field naming each (checked against the folder).
    fn restated_ids(&self) -> Vec<(String, String)> {
        Vec::new()
    }

    /// What each of its results rests on, where a result rests on claims of its own (a
    /// restatement: the claims it restates): result id → claim ids.
    fn result_supports(&self) -> Vec<(String, Vec<String>)> {
        Vec::new()
    }

    /// Whether the kind has items for `orthocheck audit` ([`ClaimKind::audit_items`]): the
    /// command reads the case files of these kinds only.
    fn audited() -> bool
    where
        Self: Sized,
    {
        false
    }

    /// The items `orthocheck audit` shows: formulas and text the kind audits, each with what
    /// it shows beside its result, those `wanted` asks for (and only those computed). Most
    /// kinds audit nothing.
    fn audit_items(
        &self,
        _b: &ResultBuilder,
        _source: &crate::cases::Source,
        _wanted: audit::Wanted,
    ) -> Result<Vec<(ClaimResult, audit::Shown)>> {
        Ok(Vec::new())
    }

    /// What `orthocheck audit ID` shows in full when `ID` names the case, instead of its
    /// items. Most kinds show their items alone.
    fn audit_in_full(&self) -> Option<Result<audit::InFull>> {
        None
    }

    /// The SymPy scripts `orthocheck audit --export` writes, one per identity the kind
    /// audits. Most kinds export none.
    fn sympy_scripts(&self) -> Result<Vec<audit::Script>> {
        Ok(Vec::new())
    }

    /// The noise runs `orthocheck noise` reruns with the user's levels, trials and seed.
    /// Most kinds have none.
    fn noise_runs(&self) -> Option<Result<rerun::NoiseRuns>> {
        None
    }

    /// The facts of the source the case records beyond its quotes (the errata's pictures and
    /// absences), checked by the verification whenever the source is given.
    fn source_checks(&self) -> Vec<crate::cases::SourceCheck> {
        Vec::new()
    }
}

/// The registry: `name => Variant(Type)`, one line per kind, `name` its folder and the key
/// under `check:` (serde's snake case of `Variant`, tested). It declares [`CaseCheck`] and its one
/// dispatch to the kind's [`ClaimKind`].
macro_rules! kinds {
    ($($(#[$doc:meta])* $name:ident => $variant:ident($ty:ty),)*) => {
        /// The `check:` of a case file: one variant per registered kind.
        #[derive(Clone, Debug, Deserialize, PartialEq)]
        #[serde(rename_all = "snake_case", deny_unknown_fields)]
        pub enum CaseCheck {
            $($(#[$doc])* $variant($ty),)*
        }

        impl CaseCheck {
            /// The kind of this check.
            pub fn kind(&self) -> &dyn ClaimKind {
                match self { $(CaseCheck::$variant(c) => c,)* }
            }

            /// The kind's name, as case files and folders name it.
            pub fn name(&self) -> &'static str {
                match self { $(CaseCheck::$variant(_) => stringify!($name),)* }
            }
        }

        /// Every registered kind: its name and its variant's name.
        pub const KINDS: &[(&str, &str)] = &[$((stringify!($name), stringify!($variant))),*];

        /// The kinds whose case files `orthocheck audit` reads ([`ClaimKind::audited`]).
        pub fn audited_kinds() -> Vec<&'static str> {
            let mut kinds = Vec::new();
            $(if <$ty as ClaimKind>::audited() {
                kinds.push(stringify!($name));
            })*
            kinds
        }
    };
}

kinds! {
    /// §2.1's worked counts.
    dof_count => DofCount(dof_count::DofCountCase),
    /// §2.1 and the abstract: identifiability decided by Jacobian rank.
    dof_identifiability => DofIdentifiability(dof_identifiability::DofIdentifiabilityCase),
    /// Eq. p3f3sqr and the signed relations.
    twofold_squared => TwofoldSquared(twofold_squared::TwofoldSquaredCase),
    /// §2's worked example.
    p3f3_example => P3f3Example(p3f3_example::P3f3ExampleCase),
    /// §4's worked example.
    p4f3_example => P4f3Example(p4f3_example::P4f3ExampleCase),
    /// §4's uniqueness over generic and degenerate scenes.
    p4f3_census => P4f3Census(p4f3_census::P4f3CensusCase),
    /// §2.2's solution count over generic and degenerate scenes.
    p3f3_census => P3f3Census(p3f3_census::P3f3CensusCase),
    /// §3's uniqueness over generic and special motions.
    p3f4_census => P3f4Census(p3f4_census::P3f4CensusCase),
    /// Claims the paper gives no data for: what is printed and what a reproduction lacks.
    not_reproducible => NotReproducible(not_reproducible::NotReproducibleCase),
    /// Every displayed formula and derivation step, machine-checked.
    formula_audit => FormulaAudit(formula_audit::FormulaAuditCase),
    /// §5.1 and §5.4: two frames are not enough; the counterexample; curves.
    two_frames => TwoFrames(two_frames::TwoFramesCase),
    /// §5.2 and §5.3 over seeded random scenes: the identity tests.
    identity_census => IdentityCensus(identity_census::IdentityCensusCase),
    /// §5.2's example: the frames, the hidden table, the debug printouts, the panels.
    identity_example => IdentityExample(identity_example::IdentityExampleCase),
    /// Restatements (discussion, conclusions): each decided by the claims it restates.
    restatements => Restatements(restatements::RestatementsCase),
    /// A noise study (§2, §3).
    noise_study => NoiseStudy(noise_study::NoiseStudyCase),
    /// Errata of the text, each quoted at its lines of the LaTeX source.
    source_errata => SourceErrata(source_errata::SourceErrataCase),
    /// Exact solution counts of three and four points in three frames, and the literature's.
    solution_count => SolutionCount(solution_count::SolutionCountCase),
    /// §4's price of linearity: the paper's solvers against the standard method.
    linearity_price => LinearityPrice(linearity_price::LinearityPriceCase),
}

impl Schema for CaseCheck {
    fn validate(&self, v: &Validator) -> Result<()> {
        let v = v.at(&format!("check.{}", self.name()));
        for (field, n) in self.kind().trials() {
            v.positive(field, n)?;
        }
        self.kind().validate(&v)
    }

    fn source_checks(&self) -> Vec<crate::cases::SourceCheck> {
        self.kind().source_checks()
    }

    fn restated_ids(&self) -> Vec<(String, String)> {
        let at = format!("check.{}", self.name());
        self.kind()
            .restated_ids()
            .into_iter()
            .map(|(id, field)| (id, format!("{at}.{field}")))
            .collect()
    }
}

impl PaperCase {
    /// Every seed the case sets.
    pub fn seeds(&self) -> Vec<u64> {
        self.check.kind().seeds()
    }
}

/// Run one case into its claim results (a restatement has nothing to restate on its own).
pub fn run_case(case: &PaperCase) -> Result<Vec<ClaimResult>> {
    Ok(run_case_full(case, &[])?.0)
}

/// Run one case into its claim results and the figures its checks drew; `earlier` are the
/// results a restatement restates.
pub fn run_case_full(
    case: &PaperCase,
    earlier: &[ClaimResult],
) -> Result<(Vec<ClaimResult>, Vec<Figure>)> {
    let b = ResultBuilder::new(case);
    let results = case.check.kind().run(&b, earlier)?;
    Ok((results, b.into_figures()))
}

/// Run every case: first all the others, then the restatements, decided from their results.
pub fn run_all(cases: &[PaperCase]) -> Result<Vec<ClaimResult>> {
    Ok(run_all_full(cases, &[], &|_, _| {})?.0)
}

/// [`run_all`] with the figures; the claims the source disagrees with are `inconclusive`
/// ([`mark_disagreements`]) before the restatements read them; `progress` hears of each case
/// as it finishes (how many finished before it, its id).
///
/// The cases are independent (each seeds its own streams), so they run at once on rayon's
/// pool; their results are kept in the cases' order, so the output does not depend on which
/// finishes first, and the first failing case in that order is the error reported.
pub fn run_all_full(
    cases: &[PaperCase],
    disagreements: &[Disagreement],
    progress: &(dyn Fn(usize, &str) + Sync),
) -> Result<(Vec<ClaimResult>, Vec<Figure>)> {
    use rayon::prelude::*;
    let finished = std::sync::atomic::AtomicUsize::new(0);
    let runs: Vec<Result<(Vec<ClaimResult>, Vec<Figure>)>> = cases
        .par_iter()
        .map(|case| {
            let run = if case.check.kind().restates() {
                Ok((Vec::new(), Vec::new()))
            } else {
                run_case_full(case, &[])
            };
            progress(
                finished.fetch_add(1, std::sync::atomic::Ordering::Relaxed),
                &case.id,
            );
            run
        })
        .collect();
    let mut out = Vec::new();
    let mut figures = Vec::new();
    for run in runs {
        let (r, f) = run?;
        out.extend(r);
        figures.extend(f);
    }
    mark_disagreements(&mut out, disagreements);
    let mut restated = Vec::new();
    for case in cases.iter().filter(|c| c.check.kind().restates()) {
        restated.extend(run_case_full(case, &out)?.0);
    }
    out.extend(restated);
    supports::attach(&mut out, cases);
    Ok((out, figures))
}

/// The whole paper, run: every result, the figures, and the seeds each case set.
#[derive(Clone, Debug)]
pub struct PaperRun {
    /// Every claim result, restatements last.
    pub results: Vec<ClaimResult>,
    /// The figures the judges drew.
    pub figures: Vec<Figure>,
    /// Each case's seeds, with its file.
    pub seeds: Vec<CaseSeeds>,
}

/// Make the claims the paper's source disagrees with `inconclusive`, each saying where: a
/// disagreement names its claim, or (the case's own quote) every claim of its case.
pub fn mark_disagreements(results: &mut [ClaimResult], disagreements: &[Disagreement]) {
    for r in results.iter_mut() {
        let hit: Vec<String> = disagreements
            .iter()
            .filter(|d| match &d.claim {
                Some(c) => *c == r.claim,
                None => d.case == r.case,
            })
            .map(Disagreement::to_string)
            .collect();
        if !hit.is_empty() {
            r.verdict = Verdict::Inconclusive;
            r.undecided = Some(format!(
                "the transcription disagrees with the paper's source: {}",
                hit.join("; ")
            ));
        }
    }
}

/// Run every case of `inputs`, the claims its verification found in disagreement with the
/// source `inconclusive`; `progress` hears of each finished case (index, id). The report
/// renders the run ([`crate::report::Report::from_run`]).
pub fn run_paper(
    inputs: &PaperInputs,
    progress: &(dyn Fn(usize, &str) + Sync),
) -> Result<PaperRun> {
    run_cases(&inputs.cases, inputs.disagreements(), progress)
}

/// [`run_paper`] over `cases`, with the `disagreements` of their verification.
pub fn run_cases(
    cases: &[PaperCase],
    disagreements: &[Disagreement],
    progress: &(dyn Fn(usize, &str) + Sync),
) -> Result<PaperRun> {
    let (results, figures) = run_all_full(cases, disagreements, progress)?;
    Ok(PaperRun {
        results,
        figures,
        seeds: cases.iter().map(case_seeds).collect(),
    })
}

/// A case's seeds, with the case file they are set in.
fn case_seeds(c: &PaperCase) -> CaseSeeds {
    CaseSeeds {
        case: c.id.clone(),
        file: c
            .file
            .as_ref()
            .and_then(|f| f.file_name())
            .map_or_else(String::new, |f| {
                format!("paper_cases/{}", f.to_string_lossy())
            }),
        seeds: c.seeds(),
    }
}

#[cfg(test)]
mod tests {
    use super::KINDS;

    /// serde names a variant by its snake case; the registry names the folder: the same word.
    #[test]
    fn every_kind_is_named_alike_in_yaml_and_folder() {
        for (name, variant) in KINDS {
            let mut snake = String::new();
            for (i, ch) in variant.chars().enumerate() {
                if ch.is_ascii_uppercase() && i > 0 {
                    snake.push('_');
                }
                snake.push(ch.to_ascii_lowercase());
            }
            assert_eq!(&snake, name, "variant {variant}");
        }
    }
}
