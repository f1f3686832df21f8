//! What each claim rests on (`rests_on` of the cases), checked as the folder is read: a case
//! names only its own claims, every support is a claim of the inventory (a folder may hold
//! only some of the cases), and no claim rests on itself, directly or through others.

use std::collections::{BTreeMap, BTreeSet};
use std::path::PathBuf;

use super::load::Names;
use crate::error::{Error, InputLocation, Result};

/// One case's `rests_on`: claim id → its supports.
type RestsOn = BTreeMap<String, Vec<String>>;

/// Check every case's `rests_on` (`cases[i]` read from `texts[i]`, naming the claims
/// `named[i]`) against the inventory's `ids`; the first fault is an error at its file, line
/// and field.
pub(super) fn check(
    cases: &[&RestsOn],
    texts: &[(PathBuf, String)],
    named: &[Names],
    ids: &Names,
) -> Result<()> {
    for ((rests_on, (path, text)), own) in cases.iter().zip(texts).zip(named) {
        for (claim, supports) in rests_on.iter() {
            let fault = if !own.contains(claim) {
                Some(format!(
                    "`{claim}` is not a claim this case checks: `rests_on` names the case's own claims"
                ))
            } else if let Some(s) = supports.iter().find(|s| !ids.contains(s.as_str())) {
                Some(format!("`{s}` is not a claim of the inventory"))
            } else if supports.contains(claim) {
                Some(format!("`{claim}` cannot rest on itself"))
            } else {
                None
            };
            if let Some(message) = fault {
                return Err(at(path, text, claim, message));
            }
        }
    }
    if let Some(cycle) = first_cycle(cases) {
        let claim = &cycle[0];
        let i = cases
            .iter()
            .position(|r| r.contains_key(claim))
            .unwrap_or_default();
        let (path, text) = &texts[i];
        return Err(at(
            path,
            text,
            claim,
            format!("a cycle of supports: {}", cycle.join(" → ")),
        ));
    }
    Ok(())
}

/// The first cycle of the supports (in claim order), as the path that closes it: `a → b → a`.
fn first_cycle(cases: &[&RestsOn]) -> Option<Vec<String>> {
    let mut graph: BTreeMap<&str, BTreeSet<&str>> = BTreeMap::new();
    for r in cases {
        for (claim, supports) in r.iter() {
            graph
                .entry(claim)
                .or_default()
                .extend(supports.iter().map(String::as_str));
        }
    }
    // depth-first, each claim's supports in order; `path` is the current chain
    let mut done: BTreeSet<&str> = BTreeSet::new();
    for &start in graph.keys() {
        let mut path: Vec<&str> = Vec::new();
        let mut stack: Vec<(&str, bool)> = vec![(start, false)];
        while let Some((node, leaving)) = stack.pop() {
            if leaving {
                path.pop();
                done.insert(node);
                continue;
            }
            if let Some(at) = path.iter().position(|p| *p == node) {
                let mut cycle: Vec<String> = path[at..].iter().map(|s| s.to_string()).collect();
                cycle.push(node.to_string());
                return Some(cycle);
            }
            if done.contains(node) {
                continue;
            }
            path.push(node);
            stack.push((node, true));
            for s in graph.get(node).into_iter().flatten().rev() {
                stack.push((s, false));
            }
        }
    }
    None
}

/// An error at the line of `claim:` under the case's `rests_on:`.
fn at(path: &std::path::Path, text: &str, claim: &str, message: String) -> Error {
    let lines: Vec<&str> = text.lines().collect();
    let top = lines.iter().position(|l| l.trim_end() == "rests_on:");
    let line = top.and_then(|t| {
        (t + 1..lines.len()).find(|&i| {
            let l = lines[i].trim_start();
            l.starts_with(&format!("{claim}:")) || l.starts_with(&format!("\"{claim}\":"))
        })
    });
    Error::Input {
        location: InputLocation {
            file: path.to_path_buf(),
            line: line.or(top).map(|l| l as u64 + 1),
            column: None,
            field: Some(format!("rests_on.{claim}")),
        },
        message,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn rests(pairs: &[(&str, &[&str])]) -> RestsOn {
        pairs
            .iter()
            .map(|(c, s)| (c.to_string(), s.iter().map(|x| x.to_string()).collect()))
            .collect()
    }

    #[test]
    fn a_cycle_is_found_across_cases_and_a_chain_is_not_one() {
        let a = rests(&[("a", &["b"]), ("c", &["d"])]);
        let b = rests(&[("b", &["c"])]);
        assert_eq!(first_cycle(&[&a, &b]), None);
        let closing = rests(&[("d", &["b"])]);
        assert_eq!(
            first_cycle(&[&a, &b, &closing]).unwrap(),
            ["b", "c", "d", "b"]
        );
        // two claims resting on one: a diamond, no cycle
        let diamond = rests(&[("x", &["y", "z"]), ("y", &["w"]), ("z", &["w"])]);
        assert_eq!(first_cycle(&[&diamond]), None);
    }
}
