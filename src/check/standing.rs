//! The standing of a main result: what the verdicts of everything it rests on, transitively,
//! make of it (docs/verdicts.md, "Main results").

use serde::Serialize;

use super::{ClaimResult, Verdict};

/// A main result's standing.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Standing {
    /// Every result it rests on holds.
    Holds,
    /// It holds once the errata in its support are corrected (each correction verified).
    HoldsOnceCorrected,
    /// A result it rests on fails.
    Fails,
    /// A result it rests on is `inconclusive` or `not-reproducible`, or a support has none.
    Undecided,
}

impl Standing {
    /// The name in the report.
    pub fn name(self) -> &'static str {
        match self {
            Standing::Holds => "holds",
            Standing::HoldsOnceCorrected => "holds-once-corrected",
            Standing::Fails => "fails",
            Standing::Undecided => "undecided",
        }
    }
}

/// A result that decides a standing.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Decider {
    /// The result id, or the claim id of a support without a result.
    pub id: String,
    /// Its verdict; none for a support without a result.
    pub verdict: Option<Verdict>,
}

/// A standing and the results that decide it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Decided {
    /// The standing.
    pub standing: Standing,
    /// What decides it: the failing results; else the undecided ones (and the supports with
    /// no result); else the errata; else the weakest holding ones.
    pub deciding: Vec<Decider>,
}

/// One of the paper's main results, with its standing.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct MainResult {
    /// The claim id, or the result id of one restatement.
    pub id: String,
    /// The claim id.
    pub claim: String,
    /// Paper section.
    pub section: String,
    /// Line range in the paper's source.
    pub lines: String,
    /// The paper's words.
    pub quote: String,
    /// The standing.
    pub standing: Standing,
    /// The results that decide it.
    pub deciding: Vec<Decider>,
    /// The claims it rests on directly.
    pub rests_on: Vec<String>,
    /// Claims it rests on, transitively.
    pub support_claims: usize,
    /// Results counted: its own and those of every claim it rests on.
    pub support_results: usize,
}

/// Holding verdicts, weakest first.
const HOLDING_WEAKEST_FIRST: [Verdict; 5] = [
    Verdict::HoldsGenerically,
    Verdict::StatisticalHolds,
    Verdict::ReproducedWithinRounding,
    Verdict::Reproduced,
    Verdict::IdentityVerified,
];

/// The rule: `fails` when any result fails (`contradicted`, `statistical-fails`); else
/// `undecided` when any is `inconclusive` or `not-reproducible`, or a support has no result
/// (`missing`); else `holds-once-corrected` when any is an `erratum`; else `holds`. A `note`
/// (a defect that changes no meaning) decides nothing.
pub fn standing(results: &[&ClaimResult], missing: &[String]) -> Decided {
    let with = |vs: &[Verdict]| -> Vec<Decider> {
        results
            .iter()
            .filter(|r| vs.contains(&r.verdict))
            .map(|r| Decider {
                id: r.id.clone(),
                verdict: Some(r.verdict),
            })
            .collect()
    };
    let failing = with(&[Verdict::Contradicted, Verdict::StatisticalFails]);
    if !failing.is_empty() {
        return Decided {
            standing: Standing::Fails,
            deciding: failing,
        };
    }
    let mut open = with(&[Verdict::Inconclusive, Verdict::NotReproducible]);
    open.extend(missing.iter().map(|c| Decider {
        id: c.clone(),
        verdict: None,
    }));
    if !open.is_empty() {
        return Decided {
            standing: Standing::Undecided,
            deciding: open,
        };
    }
    let errata = with(&[Verdict::Erratum]);
    if !errata.is_empty() {
        return Decided {
            standing: Standing::HoldsOnceCorrected,
            deciding: errata,
        };
    }
    let weakest = HOLDING_WEAKEST_FIRST
        .iter()
        .map(|v| with(&[*v]))
        .find(|d| !d.is_empty())
        .unwrap_or_default();
    Decided {
        standing: Standing::Holds,
        deciding: weakest,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::{Evidence, Power};

    fn result(id: &str, verdict: Verdict) -> ClaimResult {
        ClaimResult {
            id: id.into(),
            claim: id.split('/').next().unwrap_or(id).into(),
            case: "c".into(),
            section: "2".into(),
            lines: "1".into(),
            quote: "q".into(),
            verdict,
            printed: Vec::new(),
            computed: Vec::new(),
            tolerance: None,
            power: Power::exact_value("d"),
            correction: None,
            undecided: None,
            rests_on: Vec::new(),
            evidence: Evidence::new("m"),
        }
    }

    fn decide(vs: &[(&str, Verdict)], missing: &[&str]) -> (Standing, Vec<String>) {
        let rs: Vec<ClaimResult> = vs.iter().map(|(i, v)| result(i, *v)).collect();
        let refs: Vec<&ClaimResult> = rs.iter().collect();
        let missing: Vec<String> = missing.iter().map(|m| m.to_string()).collect();
        let d = standing(&refs, &missing);
        (d.standing, d.deciding.into_iter().map(|x| x.id).collect())
    }

    #[test]
    fn every_branch_of_the_rule() {
        use Verdict::*;
        // holds: the weakest holding results decide; a note decides nothing
        let all_hold = [("a", Reproduced), ("b", HoldsGenerically), ("c", Note)];
        assert_eq!(decide(&all_hold, &[]), (Standing::Holds, vec!["b".into()]));
        // an erratum among holding ones: holds once corrected, the erratum named
        let corrected = [
            ("a", Reproduced),
            ("b/eq", Erratum),
            ("c", IdentityVerified),
        ];
        assert_eq!(
            decide(&corrected, &[]),
            (Standing::HoldsOnceCorrected, vec!["b/eq".into()])
        );
        // inconclusive, not reproducible or a support with no result: undecided, each named
        let open = [("a", Erratum), ("b", Inconclusive), ("c", NotReproducible)];
        assert_eq!(
            decide(&open, &["d"]),
            (
                Standing::Undecided,
                vec!["b".into(), "c".into(), "d".into()]
            )
        );
        assert_eq!(
            decide(&[("a", Reproduced)], &["d"]),
            (Standing::Undecided, vec!["d".into()])
        );
        // a failure outranks everything
        let failing = [
            ("a", Inconclusive),
            ("b", Contradicted),
            ("c", StatisticalFails),
        ];
        assert_eq!(
            decide(&failing, &[]),
            (Standing::Fails, vec!["b".into(), "c".into()])
        );
    }
}
