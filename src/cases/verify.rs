//! The transcription against the paper's LaTeX source: the section titles and macro
//! definitions of `paper.yml` at their lines, every quote of every case at the tightest range
//! of lines that holds it (verbatim, or a formula in plain notation by a normalised
//! comparison), and the other facts of the source the cases record. Verdicts never read the
//! source: what disagrees is listed, and the claims concerned are made `inconclusive`.

use std::path::Path;

use super::load::invalid;
use super::normalise::Canonical;
use super::quote::{parse_lines, quote_tight, quote_within, verbatim, SourceText};
use super::{parse_yaml, CaseOrigin, Kinds, LatexSource, Paper, Schema, PAPER_FILE};
use crate::error::{Error, Result};

/// A fact of the source that a case records beyond its quotes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SourceCheck {
    /// The claim that rests on it.
    pub claim: String,
    /// The case field that records it.
    pub field: String,
    /// The fact.
    pub fact: SourceFact,
}

/// What a case records of the source.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum SourceFact {
    /// `needle` (white space collapsed) stands within `lines`.
    Within {
        /// The line range.
        lines: String,
        /// The text.
        needle: String,
    },
    /// `needle` stands nowhere in the source.
    Absent {
        /// The text.
        needle: String,
    },
}

/// A place where the transcription and the source disagree.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Disagreement {
    /// The case file.
    pub file: String,
    /// The case's id.
    pub case: String,
    /// The claim concerned (none: the case's own place in the paper).
    pub claim: Option<String>,
    /// The field.
    pub field: String,
    /// What disagrees.
    pub message: String,
}

impl std::fmt::Display for Disagreement {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: field `{}`: {}", self.file, self.field, self.message)
    }
}

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
    /// Of those, the ones standing verbatim (white space aside) at the tightest range.
    pub verbatim: usize,
    /// The ones in plain notation found by the normalised comparison at the tightest range.
    pub normalised: usize,
    /// The other facts of the source the cases record (pictures' coordinates, absences).
    pub facts: usize,
    /// Where the transcription and the source disagree.
    pub disagreements: Vec<Disagreement>,
}

impl Verification {
    /// One sentence for the report's provenance.
    pub fn sentence(&self) -> String {
        format!(
            "This run verified the transcription against the paper's LaTeX source (SHA-256 {}): \
             {} section titles at their lines, {} macro definitions verbatim, {} label names, \
             {} quotes each at the tightest range of lines that holds it ({} verbatim, {} \
             formulas in plain notation by a normalised comparison), {} other recorded facts \
             of the source, and {} disagreements.",
            &self.sha256[..12],
            self.sections,
            self.macros,
            self.labels,
            self.verbatim + self.normalised,
            self.verbatim,
            self.normalised,
            self.facts,
            self.disagreements.len()
        )
    }
}

/// The provenance sentence of a run without the source.
pub fn unverified_sentence() -> String {
    "This run did not verify the transcription: the paper's LaTeX source was not given \
     (--paper FILE, or ORTHOCHECK_PAPER). The verdicts do not depend on it: they come from the \
     transcription in paper_cases/, which is verified, quote by quote at the tightest lines, \
     whenever the source of the recorded SHA-256 is given (as the test suite does)."
        .into()
}

/// Verify `paper`'s titles and macros, every quote of the cases and the facts `cases` record;
/// a title or macro that is not in the source is an error, a quote or fact that disagrees is
/// listed.
pub fn verify<C: Schema>(
    origin: &CaseOrigin,
    paper: &Paper,
    latex: &LatexSource,
    cases: &[super::Case<C>],
) -> Result<Verification> {
    let macros = verify_paper(origin, paper, latex)?;
    let mut v = Verification {
        sha256: latex.sha256.clone(),
        sections: paper.sections.len(),
        macros,
        labels: paper.labels.len(),
        quotes: 0,
        verbatim: 0,
        normalised: 0,
        facts: 0,
        disagreements: Vec::new(),
    };
    let canonical = Canonical::of_source(&latex.text);
    for (path, text) in origin.case_texts()? {
        let tree: serde_json::Value = parse_yaml(&text, &path)?;
        let case = tree["id"].as_str().unwrap_or_default().to_string();
        // the file as read: `paper_cases/…` when embedded, the user's path with `--cases`
        let file = path.display().to_string();
        let disagree = |claim, field, message| Disagreement {
            file: file.clone(),
            case: case.clone(),
            claim,
            field,
            message,
        };
        for q in quoted(&tree) {
            v.quotes += 1;
            match locate(&latex.text, &canonical, &q.lines, &q.quote) {
                Found::Verbatim => v.verbatim += 1,
                Found::Normalised => v.normalised += 1,
                Found::Not(m) => {
                    v.disagreements
                        .push(disagree(q.claim, format!("{}.quote", q.field), m))
                }
            }
        }
        for check in cases
            .iter()
            .filter(|c| c.id == case)
            .flat_map(|c| c.check.source_checks())
        {
            v.facts += 1;
            if let Some(m) = fact_fails(&latex.text, &check.fact) {
                v.disagreements
                    .push(disagree(Some(check.claim), check.field, m));
            }
        }
    }
    Ok(v)
}

/// The section titles at their lines, the macro definitions verbatim and the label names of
/// `paper.yml` in the source: a miss is an error at its field. The number of macros checked.
fn verify_paper(origin: &CaseOrigin, paper: &Paper, latex: &LatexSource) -> Result<usize> {
    let (paper_path, paper_text) = origin.file(PAPER_FILE)?;
    let lines = &latex.text.lines;
    let refuse = |field: &str, message: String| invalid(&paper_text, &paper_path, field, message);
    for (i, s) in paper.sections.iter().enumerate() {
        let line = lines.get((s.line as usize).wrapping_sub(1));
        if !line.is_some_and(|l| l.contains("section") && l.contains(&s.title)) {
            return Err(refuse(
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
        return Err(refuse(
            "macros",
            format!("not in {}: {d}", latex.path.display()),
        ));
    }
    if let Some(l) = paper
        .labels
        .keys()
        .find(|l| !whole.contains(&format!("\\label{{{l}}}")))
    {
        return Err(refuse(
            &format!("labels.{l}"),
            format!("`{l}` is not a \\label of {}", latex.path.display()),
        ));
    }
    Ok(defs.len())
}

/// How a quote was found at its lines.
enum Found {
    Verbatim,
    Normalised,
    Not(String),
}

/// The quote at the tightest range `lines` names: verbatim, else read in the canonical
/// notation (a formula transcribed into plain notation); where it is not, where it stands.
fn locate(text: &SourceText, canonical: &Canonical, lines: &str, quote: &str) -> Found {
    let Some((a, b)) = span(lines).filter(|(_, b)| *b <= text.lines.len()) else {
        return Found::Not(format!("\"{lines}\" are not lines of the source"));
    };
    if quote_tight(text, a, b, quote, &verbatim) {
        return Found::Verbatim;
    }
    let ranges = canonical.ranges_of(quote);
    if ranges.contains(&(a, b)) {
        return Found::Normalised;
    }
    let elsewhere = match ranges.first() {
        Some((x, y)) => format!(" (it stands at {})", range_text(*x, *y)),
        None => " (nor anywhere else in the source)".to_string(),
    };
    Found::Not(format!(
        "the quote is not at the tightest lines {lines}{elsewhere}"
    ))
}

fn range_text(a: usize, b: usize) -> String {
    if a == b {
        a.to_string()
    } else {
        format!("{a}-{b}")
    }
}

/// Why a recorded fact does not hold in the source, if it does not.
fn fact_fails(text: &SourceText, fact: &SourceFact) -> Option<String> {
    let n = text.lines.len();
    match fact {
        SourceFact::Within { lines, needle } => {
            let (a, b) = parse_lines(lines)?;
            (!quote_within(text, a, b, needle))
                .then(|| format!("`{needle}` is not within lines {lines}"))
        }
        SourceFact::Absent { needle } => quote_within(text, 1, n, needle)
            .then(|| format!("`{needle}` stands in the source, recorded as absent")),
    }
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

/// One quote of a case: its lines, its words, the claim it belongs to and its field.
struct Quoted {
    lines: String,
    quote: String,
    claim: Option<String>,
    field: String,
}

/// Every quote of a parsed case, in document order.
fn quoted(v: &serde_json::Value) -> Vec<Quoted> {
    let mut out = Vec::new();
    walk(v, None, "", &mut out);
    out
}

/// The claim an object names: its `claim:`, or its `claim.claim:` (a finding).
fn claim_of(m: &serde_json::Map<String, serde_json::Value>) -> Option<String> {
    match m.get("claim") {
        Some(serde_json::Value::String(c)) => Some(c.clone()),
        Some(serde_json::Value::Object(o)) => {
            o.get("claim").and_then(|c| c.as_str()).map(str::to_string)
        }
        _ => None,
    }
}

fn walk(v: &serde_json::Value, claim: Option<&str>, at: &str, out: &mut Vec<Quoted>) {
    match v {
        serde_json::Value::Object(m) => {
            let named = claim_of(m);
            let claim = named.as_deref().or(claim);
            if let (Some(l), Some(serde_json::Value::String(q))) = (m.get("lines"), m.get("quote"))
            {
                let lines = l.as_str().map_or_else(|| l.to_string(), str::to_string);
                out.push(Quoted {
                    lines,
                    quote: q.clone(),
                    claim: claim.map(str::to_string),
                    field: at.to_string(),
                });
            }
            for (k, x) in m {
                let here = if at.is_empty() {
                    k.clone()
                } else {
                    format!("{at}.{k}")
                };
                walk(x, claim, &here, out);
            }
        }
        serde_json::Value::Array(a) => {
            for (i, x) in a.iter().enumerate() {
                walk(x, claim, &format!("{at}[{i}]"), out);
            }
        }
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
    /// The source itself, when given.
    pub source: Option<LatexSource>,
    /// The errata's corrections in the source (`corrections.yml`).
    pub corrections: Vec<super::Correction>,
}

impl<C> PaperInputs<C> {
    /// Where the source disagreed with the transcription (none without the source).
    pub fn disagreements(&self) -> &[Disagreement] {
        self.verification
            .as_ref()
            .map_or(&[], |v| v.disagreements.as_slice())
    }

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
    let cases = super::load_cases_of::<C>(origin, kinds)?;
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
    let paper = super::paper_of(origin)?;
    let verification = match &source {
        Some(s) => Some(verify(origin, &paper, s, &cases)?),
        None => None,
    };
    let corrections = super::corrections_of(origin)?;
    Ok(PaperInputs {
        cases,
        paper,
        verification,
        source,
        corrections,
    })
}
