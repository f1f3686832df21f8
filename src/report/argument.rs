//! The paper's argument as the report shows it: what carries each main result (one
//! sentence), and the argument map's layout (main results on top, the claims they rest on
//! below in one column per section, each claim under the claims that use it).

use std::collections::{BTreeMap, BTreeSet};

use super::Report;
use crate::cases::section_key;
use crate::check::standing::{MainResult, Standing};
use crate::check::{ClaimResult, Verdict};

/// A sentence with claim ids in it: `lead`, the ids, `tail` (renderers link the ids).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Carries {
    /// The words before the ids.
    pub lead: String,
    /// The result (or claim) ids that decide.
    pub ids: Vec<String>,
    /// The words after them.
    pub tail: String,
}

fn plural(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", if n == 1 { one } else { many })
}

/// What carries a main result, in one sentence.
pub fn carries(m: &MainResult) -> Carries {
    let ids: Vec<String> = m.deciding.iter().map(|d| d.id.clone()).collect();
    let support = if m.support_claims == 0 {
        "rests on no other claim".to_string()
    } else {
        format!(
            "rests on {} ({})",
            plural(m.support_claims, "claim", "claims"),
            plural(m.support_results, "result", "results")
        )
    };
    let (lead, tail) = match m.standing {
        Standing::Holds => {
            let weakest = m.deciding.first().and_then(|d| d.verdict).map_or("", |v| v.name());
            (
                format!("It {support}, all holding; the weakest, {weakest}: "),
                ".".to_string(),
            )
        }
        Standing::HoldsOnceCorrected => (
            format!(
                "It {support}; it holds once the {} in its support {} corrected (each correction verified): ",
                plural(ids.len(), "erratum", "errata"),
                if ids.len() == 1 { "is" } else { "are" }
            ),
            ".".to_string(),
        ),
        Standing::Fails => (format!("It {support}, and fails with "), ".".to_string()),
        Standing::Undecided => {
            let mut words: Vec<&str> = m
                .deciding
                .iter()
                .map(|d| d.verdict.map_or("without a result", |v| v.name()))
                .collect();
            words.dedup();
            (
                format!("It {support}; undecided while "),
                format!(" {} {}.", if ids.len() == 1 { "is" } else { "are" }, words.join(" or ")),
            )
        }
    };
    Carries { lead, ids, tail }
}

/// One box of the map: a main result, or a claim it rests on.
#[derive(Clone, Debug, PartialEq)]
pub struct Node {
    /// The main result's id, or the claim id.
    pub id: String,
    /// The card it links to (a result id).
    pub target: String,
    /// Its colour's name: a standing for a main result, else the claim's decisive verdict.
    pub colour: Colour,
    /// Centre, in the map's units.
    pub x: f64,
    /// Top edge.
    pub y: f64,
}

/// A node's colour: a main result's standing or a claim's decisive verdict.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Colour {
    /// A main result.
    Standing(Standing),
    /// A claim: its worst result's verdict (fails, then undecided, then erratum, then the
    /// weakest holding one).
    Verdict(Verdict),
}

/// The map: nodes, edges (from the user to the support, by node index), section columns.
#[derive(Clone, Debug, PartialEq)]
pub struct Map {
    /// Main results first, then the claims column by column.
    pub nodes: Vec<Node>,
    /// (user, support) pairs of node indices.
    pub edges: Vec<(usize, usize)>,
    /// Each section's column: its number and the left edge of its box.
    pub columns: Vec<(String, f64)>,
    /// For each main result (node index), the nodes it rests on, transitively, itself included:
    /// what the page highlights when the reader points at it.
    pub reach: Vec<BTreeSet<usize>>,
    /// The map's size.
    pub width: f64,
    /// The map's size.
    pub height: f64,
}

/// Box size and spacing, in the map's units (pixels at full size).
pub const NODE_W: f64 = 132.0;
/// A box's height.
pub const NODE_H: f64 = 22.0;
const GAP_X: f64 = 10.0;
const ROW: f64 = 30.0;
const TOP_ROWS: f64 = 2.0;
const COLUMN_TOP: f64 = 110.0;

/// The decisive verdict of a claim's results, by the standing rule's order (a note decides
/// nothing unless it is all there is).
fn decisive(results: &[&ClaimResult]) -> Verdict {
    const ORDER: [Verdict; 11] = [
        Verdict::Contradicted,
        Verdict::StatisticalFails,
        Verdict::Inconclusive,
        Verdict::NotReproducible,
        Verdict::Erratum,
        Verdict::HoldsGenerically,
        Verdict::StatisticalHolds,
        Verdict::ReproducedWithinRounding,
        Verdict::Reproduced,
        Verdict::IdentityVerified,
        Verdict::Note,
    ];
    ORDER
        .into_iter()
        .find(|v| results.iter().any(|r| r.verdict == *v))
        .unwrap_or(Verdict::NotReproducible)
}

/// The map of a report's main results: every claim they rest on, transitively.
pub fn map(r: &Report) -> Map {
    let mains = &r.main_results;
    let mut by_claim: BTreeMap<&str, Vec<&ClaimResult>> = BTreeMap::new();
    for c in &r.claims {
        by_claim.entry(c.claim.as_str()).or_default().push(c);
    }
    let start: Vec<String> = mains.iter().flat_map(|m| m.rests_on.clone()).collect();
    let claims: BTreeSet<String> = crate::claims::supports::closure(&start, &r.claims);
    let per_row = mains.len().div_ceil(TOP_ROWS as usize).max(1);
    let mut nodes: Vec<Node> = mains
        .iter()
        .enumerate()
        .map(|(i, m)| Node {
            id: m.id.clone(),
            target: r
                .claims
                .iter()
                .find(|c| c.id == m.id || c.claim == m.id)
                .map_or_else(|| m.id.clone(), |c| c.id.clone()),
            colour: Colour::Standing(m.standing),
            x: GAP_X + (i % per_row) as f64 * (NODE_W + GAP_X) + NODE_W / 2.0,
            y: 10.0 + (i / per_row) as f64 * ROW * 1.4,
        })
        .collect();
    let columns = place_claims(&claims, &by_claim, &mut nodes);
    let index: BTreeMap<String, usize> = nodes
        .iter()
        .enumerate()
        .skip(mains.len())
        .map(|(i, n)| (n.id.clone(), i))
        .collect();
    let mut edges = Vec::new();
    for (i, m) in mains.iter().enumerate() {
        edges.extend(
            m.rests_on
                .iter()
                .filter_map(|s| index.get(s))
                .map(|&j| (i, j)),
        );
    }
    for (id, &i) in &index {
        let supports: BTreeSet<&str> = by_claim
            .get(id.as_str())
            .into_iter()
            .flatten()
            .flat_map(|c| c.rests_on.iter().map(String::as_str))
            .collect();
        edges.extend(
            supports
                .iter()
                .filter_map(|s| index.get(*s))
                .map(|&j| (i, j)),
        );
    }
    let reach = mains
        .iter()
        .enumerate()
        .map(|(i, m)| {
            let mut set: BTreeSet<usize> = crate::claims::supports::closure(&m.rests_on, &r.claims)
                .iter()
                .filter_map(|c| index.get(c).copied())
                .collect();
            set.insert(i);
            set
        })
        .collect();
    let width = (columns.len() as f64 * (NODE_W + GAP_X) + GAP_X)
        .max(per_row as f64 * (NODE_W + GAP_X) + GAP_X);
    let height = nodes.iter().map(|n| n.y).fold(0.0, f64::max) + NODE_H + 12.0;
    Map {
        nodes,
        edges,
        columns,
        reach,
        width,
        height,
    }
}

/// The claims in one column per section (sections in the paper's order), each claim below
/// every claim of its column that rests on it (its depth: the longest chain of users above).
fn place_claims(
    claims: &BTreeSet<String>,
    by_claim: &BTreeMap<&str, Vec<&ClaimResult>>,
    nodes: &mut Vec<Node>,
) -> Vec<(String, f64)> {
    let section = |c: &str| {
        by_claim
            .get(c)
            .and_then(|rs| rs.first())
            .map_or_else(String::new, |r| r.section.clone())
    };
    let supports = |c: &str| -> BTreeSet<String> {
        by_claim
            .get(c)
            .into_iter()
            .flatten()
            .flat_map(|r| r.rests_on.iter().cloned())
            .collect()
    };
    // depth: 0 for a claim no claim of the map uses, else one more than its deepest user
    let mut depth: BTreeMap<&str, usize> = claims.iter().map(|c| (c.as_str(), 0)).collect();
    for _ in 0..claims.len() {
        let mut changed = false;
        for c in claims {
            let d = depth[c.as_str()];
            for s in supports(c) {
                if let Some(ds) = depth.get_mut(s.as_str())
                    && *ds < d + 1
                {
                    *ds = d + 1;
                    changed = true;
                }
            }
        }
        if !changed {
            break;
        }
    }
    let mut sections: Vec<String> = claims.iter().map(|c| section(c)).collect();
    sections.sort_by_key(|s| section_key(s));
    sections.dedup();
    let mut columns = Vec::new();
    for (k, sec) in sections.iter().enumerate() {
        let left = GAP_X + k as f64 * (NODE_W + GAP_X);
        columns.push((sec.clone(), left));
        let mut members: Vec<&String> = claims.iter().filter(|c| &section(c) == sec).collect();
        members.sort_by_key(|c| (depth[c.as_str()], (*c).clone()));
        for (row, c) in members.into_iter().enumerate() {
            let target = by_claim
                .get(c.as_str())
                .and_then(|rs| rs.first())
                .map_or_else(|| c.clone(), |r| r.id.clone());
            let results: Vec<&ClaimResult> = by_claim.get(c.as_str()).cloned().unwrap_or_default();
            nodes.push(Node {
                id: c.clone(),
                target,
                colour: Colour::Verdict(decisive(&results)),
                x: left + NODE_W / 2.0,
                y: COLUMN_TOP + 24.0 + row as f64 * ROW,
            });
        }
    }
    columns
}
