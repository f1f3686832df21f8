//! The paper corrected as a patch: `errata.patch`, a unified diff of the LaTeX source that
//! applies every erratum's correction (`corrections.yml` of the cases), one hunk per erratum
//! marked with its result id.

use std::fmt::Write as _;

use crate::cases::{parse_lines, Correction, SourceText, CORRECTIONS_FILE};
use crate::check::{ClaimResult, Verdict};
use crate::error::{Error, Result};

/// Lines of context around each hunk.
const CONTEXT: usize = 1;

/// `errata.patch`: a unified diff of the source (`name`) applying every correction, one
/// hunk per correction (hunks whose context would overlap are joined), each marked with its
/// result ids; its header lists every erratum of `results` and what mends it. An error when
/// a `from` does not stand exactly once within its lines, spanning them.
pub fn errata_patch(
    source: &SourceText,
    name: &str,
    corrections: &[Correction],
    results: &[ClaimResult],
) -> Result<String> {
    let mut patched = source.lines.clone();
    let mut spans: Vec<(usize, usize, &str)> = Vec::new();
    for c in corrections {
        let (Some(lines), Some(from), Some(to)) = (&c.lines, &c.from, &c.to) else {
            continue;
        };
        let (a, b) = parse_lines(lines).unwrap_or((0, 0));
        let fault = |why: &str| {
            Error::InvalidInput(format!(
                "{CORRECTIONS_FILE}: {}: `from` {why} (lines {lines} of the source)",
                c.result
            ))
        };
        let text = patched
            .get(a.saturating_sub(1)..b)
            .filter(|_| a >= 1)
            .map(|l| l.join("\n"))
            .filter(|t| t.matches(from.as_str()).count() == 1)
            .ok_or_else(|| fault("does not stand there exactly once"))?;
        let at = text.find(from.as_str()).unwrap_or(0);
        let (before, after) = (&text[..at], &text[at + from.len()..]);
        if before.contains('\n') || after.contains('\n') {
            return Err(fault(
                "does not span its lines (they are not its tightest range)",
            ));
        }
        let new = format!("{before}{to}{after}");
        for (k, line) in new.split('\n').enumerate() {
            patched[a - 1 + k] = line.to_string();
        }
        spans.push((a - 1, b, c.result.as_str()));
    }
    let changed: Vec<usize> = (0..patched.len())
        .filter(|&i| patched[i] != source.lines[i])
        .collect();
    let mut s = header(corrections, results);
    let _ = write!(s, "--- a/{name}\n+++ b/{name}\n");
    for (lo, hi) in hunks(&changed, patched.len()) {
        let mut ids: Vec<&str> = spans
            .iter()
            .filter(|(a, b, _)| *a < hi && *b > lo)
            .map(|(_, _, id)| *id)
            .collect();
        ids.dedup();
        let _ = writeln!(
            s,
            "@@ -{0},{1} +{0},{1} @@ {2}",
            lo + 1,
            hi - lo,
            ids.join(", ")
        );
        push_body(&mut s, &source.lines[lo..hi], &patched[lo..hi]);
    }
    Ok(s)
}

/// The hunks' line ranges (0-based, end exclusive): the changed lines with [`CONTEXT`]
/// lines around, joined where their context would overlap.
fn hunks(changed: &[usize], len: usize) -> Vec<(usize, usize)> {
    let mut out: Vec<(usize, usize)> = Vec::new();
    for &i in changed {
        let (lo, hi) = (i.saturating_sub(CONTEXT), (i + 1 + CONTEXT).min(len));
        match out.last_mut() {
            Some(last) if last.1 >= lo => last.1 = hi,
            _ => out.push((lo, hi)),
        }
    }
    out
}

/// A hunk's lines: unchanged ones as context, each run of changed ones as its old lines
/// then its new ones (the line count is kept, so the runs pair up).
fn push_body(s: &mut String, old: &[String], new: &[String]) {
    let mut i = 0;
    while i < old.len() {
        if old[i] == new[i] {
            let _ = writeln!(s, " {}", old[i]);
            i += 1;
            continue;
        }
        let end = (i..old.len())
            .find(|&j| old[j] == new[j])
            .unwrap_or(old.len());
        for line in &old[i..end] {
            let _ = writeln!(s, "-{line}");
        }
        for line in &new[i..end] {
            let _ = writeln!(s, "+{line}");
        }
        i = end;
    }
}

/// The patch's header (text `patch` skips): what it mends, and the errata it cannot.
fn header(corrections: &[Correction], results: &[ClaimResult]) -> String {
    let mut s = String::from(
        "The paper corrected: each erratum of the report mended in its LaTeX source, one hunk per\n\
         erratum (marked with its result id after the @@ line). Apply with\n\
         `patch SOURCE errata.patch`. Each correction is checked by the erratum's own case.\n\n",
    );
    for r in results.iter().filter(|r| r.verdict == Verdict::Erratum) {
        let mine: Vec<&Correction> = corrections.iter().filter(|c| c.result == r.id).collect();
        let how = match mine.first() {
            None => "not patchable: no correction transcribed".to_string(),
            Some(c) => match &c.not_patchable {
                Some(why) => format!("not patchable: {why}"),
                None => format!(
                    "{} hunk{} at lines {}",
                    mine.len(),
                    if mine.len() == 1 { "" } else { "s" },
                    mine.iter()
                        .filter_map(|c| c.lines.as_deref())
                        .collect::<Vec<_>>()
                        .join(", ")
                ),
            },
        };
        let _ = writeln!(s, "- {} (§{}): {how}", r.id, r.section);
    }
    s.push('\n');
    s
}
