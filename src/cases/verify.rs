//! The transcription against the paper's LaTeX source: the section titles and macro
//! definitions of `paper.yml` at their lines, and every quote of every case at its lines.
//! The errata's quotes are verified (and refused when missing) as their case is read; this
//! counts every other quote too, verbatim or a transcription into plain notation.

use std::path::Path;

use super::load::invalid;
use super::quote::{parse_lines, quote_within};
use super::{parse_yaml, CaseOrigin, Kinds, LatexSource, Paper, PAPER_FILE};
use crate::error::{Error, InputLocation, Result};

/// What the source confirmed.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Verification {
    /// The source's SHA-256.
    pub sha256: String,
    /// Section titles found at their lines.
    pub sections: usize,
    /// Macro definitions found verbatim.
    pub macros: usize,
    /// Label names found as `\label`s.
    pub labels: usize,
    /// Quotes of the cases (every `lines` with a `quote`).
    pub quotes: usize,
    /// Of those, the ones standing verbatim (white space aside) at their lines; the others
    /// transcribe formulas into plain notation or abridge with "…".
    pub verbatim: usize,
}

impl Verification {
    /// One sentence for the report's provenance.
    pub fn sentence(&self) -> String {
        format!(
            "The transcription was verified against the paper's LaTeX source (SHA-256 {}): \
             {} section titles at their lines, {} macro definitions verbatim, {} label names, \
             and {} of the cases' {} quotes verbatim at their lines (the other {} transcribe \
             formulas into plain notation; every line range lies within the source).",
            &self.sha256[..12],
            self.sections,
            self.macros,
            self.labels,
            self.verbatim,
            self.quotes,
            self.quotes - self.verbatim
        )
    }
}

/// The provenance sentence of a run without the source.
pub fn unverified_sentence() -> String {
    "The transcription was not verified against a source: the paper's LaTeX source was not \
     given (--paper FILE, or ORTHOCHECK_PAPER), so the findings about the paper's wording are \
     inconclusive; every other claim is decided from the transcription."
        .into()
}

/// Verify `paper`'s titles and macros and count the cases' quotes at their lines; a title or
/// macro that is not in the source, or a quote whose lines lie outside it, is an error.
pub fn verify(origin: &CaseOrigin, paper: &Paper, latex: &LatexSource) -> Result<Verification> {
    let (paper_path, paper_text) = origin.file(PAPER_FILE)?;
    let lines = &latex.text.lines;
    for (i, s) in paper.sections.iter().enumerate() {
        let line = lines.get((s.line as usize).wrapping_sub(1));
        if !line.is_some_and(|l| l.contains("section") && l.contains(&s.title)) {
            return Err(invalid(
                &paper_text,
                &paper_path,
                &format!("sections[{i}]"),
                format!(
                    "line {} of {} is not the section \"{}\"",
                    s.line,
                    latex.path.display(),
                    s.title
                ),
            ));
        }
    }
    let squash = |t: &str| t.split_whitespace().collect::<String>();
    let whole = squash(&lines.join("\n"));
    let defs: Vec<String> = paper
        .macros
        .split("\\newcommand")
        .skip(1)
        .map(|d| squash(&format!("\\newcommand{d}")))
        .collect();
    if let Some(d) = defs.iter().find(|d| !whole.contains(d.as_str())) {
        return Err(invalid(
            &paper_text,
            &paper_path,
            "macros",
            format!("not in {}: {d}", latex.path.display()),
        ));
    }
    if let Some(l) = paper
        .labels
        .keys()
        .find(|l| !whole.contains(&format!("\\label{{{l}}}")))
    {
        return Err(invalid(
            &paper_text,
            &paper_path,
            &format!("labels.{l}"),
            format!("`{l}` is not a \\label of {}", latex.path.display()),
        ));
    }
    let (mut quotes, mut verbatim) = (0, 0);
    for (path, text) in origin.case_texts()? {
        let tree: serde_json::Value = parse_yaml(&text, &path)?;
        for (lines_text, quote) in quoted(&tree) {
            quotes += 1;
            let Some((a, b)) = span(&lines_text).filter(|(_, b)| *b <= lines.len()) else {
                return Err(out_of_source(&path, &lines_text, latex));
            };
            verbatim += usize::from(quote_within(&latex.text, a, b, &quote));
        }
    }
    Ok(Verification {
        sha256: latex.sha256.clone(),
        sections: paper.sections.len(),
        macros: defs.len(),
        labels: paper.labels.len(),
        quotes,
        verbatim,
    })
}

/// The first and last line of "197-326, 386-391" (one range or several, comma-separated).
fn span(lines: &str) -> Option<(usize, usize)> {
    let ranges: Option<Vec<(usize, usize)>> =
        lines.split(',').map(|r| parse_lines(r.trim())).collect();
    let ranges = ranges?;
    Some((
        ranges.iter().map(|r| r.0).min()?,
        ranges.iter().map(|r| r.1).max()?,
    ))
}

fn out_of_source(path: &Path, lines: &str, latex: &LatexSource) -> Error {
    Error::Input {
        location: InputLocation::file(path),
        message: format!(
            "the lines \"{lines}\" of a quote are not lines of {} ({} lines)",
            latex.path.display(),
            latex
                .text
                .lines
                .iter()
                .rposition(|l| !l.is_empty())
                .map_or(0, |n| n + 1)
        ),
    }
}

/// Every `(lines, quote)` pair of a parsed case, in document order.
fn quoted(v: &serde_json::Value) -> Vec<(String, String)> {
    let mut out = Vec::new();
    walk(v, &mut out);
    out
}

fn walk(v: &serde_json::Value, out: &mut Vec<(String, String)>) {
    match v {
        serde_json::Value::Object(m) => {
            if let (Some(l), Some(serde_json::Value::String(q))) = (m.get("lines"), m.get("quote"))
            {
                let l = l.as_str().map_or_else(|| l.to_string(), str::to_string);
                out.push((l, q.clone()));
            }
            m.values().for_each(|x| walk(x, out));
        }
        serde_json::Value::Array(a) => a.iter().for_each(|x| walk(x, out)),
        _ => {}
    }
}

/// What a run of the paper reads: the cases, the paper file, and, when the LaTeX source is
/// given, what it verified.
#[derive(Clone, Debug)]
pub struct PaperInputs<C> {
    /// Every case.
    pub cases: Vec<super::Case<C>>,
    /// `paper.yml`.
    pub paper: Paper,
    /// The transcription checked against the source; none without one.
    pub verification: Option<Verification>,
}

impl<C> PaperInputs<C> {
    /// The provenance sentence: what the source verified, or that none was given.
    pub fn transcription_sentence(&self) -> String {
        self.verification
            .as_ref()
            .map_or_else(unverified_sentence, Verification::sentence)
    }
}

/// Read the cases and the paper file from `origin`; with `latex` (a path to the paper's
/// LaTeX source), refuse a source of another hash and verify the transcription against it.
pub fn load_inputs<C: super::Schema>(
    origin: &CaseOrigin,
    latex: Option<&Path>,
) -> Result<PaperInputs<C>> {
    load_inputs_of(origin, latex, Kinds::All)
}

/// [`load_inputs`] reading the case files of `kinds` only, unless `latex` is given: the
/// transcription is verified whole.
pub fn load_inputs_of<C: super::Schema>(
    origin: &CaseOrigin,
    latex: Option<&Path>,
    kinds: Kinds,
) -> Result<PaperInputs<C>> {
    let kinds = if latex.is_some() { Kinds::All } else { kinds };
    // the cases first: a malformed case is the first thing a user hears of
    let unverified = super::load_cases_of::<C>(origin, None, kinds)?;
    let source = match latex {
        None => None,
        Some(p) => {
            let paper = super::paper_of(origin)?;
            let record = paper.source.as_ref().ok_or_else(|| {
                Error::InvalidInput(format!(
                    "{PAPER_FILE} records no source (`source: {{ file, sha256 }}`) to verify {} against",
                    p.display()
                ))
            })?;
            Some(LatexSource::read(p, record)?)
        }
    };
    let cases = match &source {
        Some(s) => super::load_cases(origin, Some(s))?,
        None => unverified,
    };
    let paper = super::paper_of(origin)?;
    let verification = match &source {
        Some(s) => Some(verify(origin, &paper, s)?),
        None => None,
    };
    Ok(PaperInputs {
        cases,
        paper,
        verification,
    })
}
