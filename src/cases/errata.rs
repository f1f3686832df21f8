//! Errata of the text: findings of a line-by-line reading of the LaTeX source, each quoted
//! exactly at its lines, with the correction and, where one exists, the computation that
//! decides it. Given the paper's LaTeX source (`--paper FILE`), every quote is verified at
//! its lines as the case is read; without it the findings stand on the transcription alone.

use std::path::Path;

use std::collections::BTreeMap;

use serde::Deserialize;

use super::load::invalid;
use super::{ClaimRef, Printed};
use crate::error::Result;

/// The errata of the text.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct SourceErrataCase {
    /// The findings, in the order of the source.
    pub findings: Vec<Finding>,
    /// The source's lines, attached by [`load_case_with`](super::load_case_with) when the
    /// source is given (absent otherwise: the quotes are then unverified).
    #[serde(skip)]
    pub text: Option<SourceText>,
}

/// The lines of the LaTeX source.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SourceText {
    /// Line `n` (1-based) is `lines[n - 1]`.
    pub lines: Vec<String>,
}

/// Whether a finding changes what the text says.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum FindingKind {
    /// Read literally, the text says something else than the corrected text, or nothing,
    /// or admits more than one reading.
    Erratum,
    /// A defect whose intended reading is unique and has the same content.
    Note,
}

/// One finding.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Finding {
    /// The claim: its `lines` and `quote` are the exact source text of the finding (white
    /// space aside), starting on the first line and ending on the last.
    pub claim: ClaimRef,
    /// The result id's suffix.
    pub id: String,
    /// Erratum or note.
    pub kind: FindingKind,
    /// The defect, in words.
    pub defect: String,
    /// As it should read.
    pub corrected: String,
    /// Other places of the source that decide the reading, each quoted at its lines too.
    #[serde(default)]
    pub also: Vec<Place>,
    /// The computation that decides the correction, where one exists.
    #[serde(default)]
    pub decide: Option<Decision>,
}

/// A quoted place of the source.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct Place {
    /// Line range ("119-122" or "157").
    pub lines: String,
    /// The exact source text.
    pub quote: String,
    /// What it shows.
    pub shows: String,
}

/// A configuration of the degree-of-freedom count of §2.1.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Configuration {
    /// p.
    pub points: usize,
    /// k.
    pub frames: usize,
}

/// What the count must show of each configuration a reading names.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Balance {
    /// More pieces of information than unknowns (2kp > −1 + 3p + 5(k − 1)).
    Surplus,
    /// At least as many (2kp ≥ −1 + 3p + 5(k − 1)).
    Enough,
}

/// The computations that decide a textual finding.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(rename_all = "snake_case", deny_unknown_fields)]
pub enum Decision {
    /// §2.1's count over the configurations each reading names: the corrected reading's
    /// configurations all have the balance, and the printed reading names other ones.
    DofCount {
        /// What the count must show.
        balance: Balance,
        /// The configurations the text names as printed.
        printed: Vec<Configuration>,
        /// The configurations the corrected text names.
        corrected: Vec<Configuration>,
    },
    /// Strings the source must not hold anywhere (an absence the finding states).
    NotInSource {
        /// The strings.
        strings: Vec<String>,
    },
    /// The labels of drawings of a cube [−s, s]³ around `origin` and the points of a body:
    /// which naming of the labels the drawings fit (`studies::figure_labels`).
    FigureLabels {
        /// s, half the side of the drawn cube.
        half_side: Printed,
        /// The point at the cube's centre (its label is the reference).
        origin: String,
        /// The printed 3-D points.
        points: Vec<NamedPoint>,
        /// The pictures.
        pictures: Vec<LabelPicture>,
    },
}

/// A printed 3-D point.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct NamedPoint {
    /// Its name.
    pub name: String,
    /// Its coordinates as printed.
    pub at: Vec<Printed>,
}

/// One picture of a drawn cube with labels.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct LabelPicture {
    /// Its lines in the source (every coordinate below is found there as printed).
    pub lines: String,
    /// The corner the three thin edges leave (`\put(x,y){\special{em:moveto} }`).
    pub corner: Vec<Printed>,
    /// The other ends of those edges (`\put(x,y){\special{em:lineto} }`).
    pub ends: Vec<Vec<Printed>>,
    /// The labels (`\put(x,y){$name$}`).
    pub labels: Vec<PrintedLabel>,
    /// The corrected naming: label → the point it shows (labels not listed are right).
    #[serde(default)]
    pub rename: BTreeMap<String, String>,
}

/// A printed label.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct PrintedLabel {
    /// The label as printed.
    pub name: String,
    /// Its position as printed.
    pub at: Vec<Printed>,
}

/// A line range `a-b` (or `a`), 1-based, inclusive.
pub fn parse_lines(s: &str) -> Option<(usize, usize)> {
    let s = s.trim();
    let (a, b) = match s.split_once(['-', '–']) {
        Some((a, b)) => (a.trim().parse().ok()?, b.trim().parse().ok()?),
        None => {
            let a = s.parse().ok()?;
            (a, a)
        }
    };
    (a >= 1 && a <= b).then_some((a, b))
}

/// Whether `quote` (white space collapsed) stands in `lines[first..=last]`, starting on the
/// first line and ending on the last: a quote at the wrong lines, or at lines wider than it,
/// is not found.
pub fn quote_at(text: &SourceText, first: usize, last: usize, quote: &str) -> bool {
    let want: Vec<char> = collapse(quote).chars().collect();
    if want.is_empty() || first == 0 || last > text.lines.len() || first > last {
        return false;
    }
    // the collapsed text of the range, each character with its source line
    let mut chars: Vec<(char, usize)> = Vec::new();
    for n in first..=last {
        for w in text.lines[n - 1].split_whitespace() {
            if !chars.is_empty() {
                chars.push((' ', n));
            }
            chars.extend(w.chars().map(|c| (c, n)));
        }
    }
    chars.windows(want.len()).any(|win| {
        win[0].1 == first
            && win[want.len() - 1].1 == last
            && win.iter().zip(&want).all(|((c, _), w)| c == w)
    })
}

/// Whether `needle` (white space collapsed) stands anywhere within `lines[first..=last]`.
pub fn quote_within(text: &SourceText, first: usize, last: usize, needle: &str) -> bool {
    let want = collapse(needle);
    if want.is_empty() || first == 0 || last > text.lines.len() || first > last {
        return false;
    }
    collapse(&text.lines[first - 1..last].join("\n")).contains(&want)
}

/// The source strings of a picture's printed coordinates: its corner, edge ends and labels.
fn picture_strings(p: &LabelPicture) -> Vec<String> {
    let xy = |v: &[Printed]| {
        v.iter()
            .map(|c| c.text.clone())
            .collect::<Vec<_>>()
            .join(",")
    };
    let mut out = vec![format!(
        "\\put({}){{\\special{{em:moveto}} }}",
        xy(&p.corner)
    )];
    out.extend(
        p.ends
            .iter()
            .map(|e| format!("\\put({}){{\\special{{em:lineto}} }}", xy(e))),
    );
    out.extend(
        p.labels
            .iter()
            .map(|l| format!("\\put({}){{${}$}}", xy(&l.at), l.name)),
    );
    out
}

/// White space runs as one space, trimmed.
fn collapse(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Verify every quote of the case at its lines of `latex` and attach the source's lines: a
/// quote that is not there is an input error naming the field.
pub(super) fn attach_source(
    c: &mut SourceErrataCase,
    case_text: &str,
    case_path: &Path,
    latex: &super::LatexSource,
) -> Result<()> {
    let path = &latex.path;
    let text = latex.text.clone();
    let base = "check.source_errata.findings";
    for (i, f) in c.findings.iter().enumerate() {
        let mut places = vec![(
            format!("{base}[{i}].claim.quote"),
            &f.claim.lines,
            &f.claim.quote,
        )];
        for (j, p) in f.also.iter().enumerate() {
            places.push((format!("{base}[{i}].also[{j}].quote"), &p.lines, &p.quote));
        }
        if let Some(Decision::FigureLabels { pictures, .. }) = &f.decide {
            for (j, p) in pictures.iter().enumerate() {
                let (a, b) = parse_lines(&p.lines).unwrap_or((0, 0));
                if let Some(missing) = picture_strings(p)
                    .into_iter()
                    .find(|q| !quote_within(&text, a, b, q))
                {
                    return Err(invalid(
                        case_text,
                        case_path,
                        &format!("{base}[{i}].decide.figure_labels.pictures[{j}]"),
                        format!(
                            "`{missing}` is not within lines {} of {}",
                            p.lines,
                            path.display()
                        ),
                    ));
                }
            }
        }
        for (field, lines, quote) in places {
            let found = parse_lines(lines).is_some_and(|(a, b)| quote_at(&text, a, b, quote));
            if !found {
                return Err(invalid(
                    case_text,
                    case_path,
                    &field,
                    format!("the quote is not at lines {lines} of {}", path.display()),
                ));
            }
        }
    }
    c.text = Some(text);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text() -> SourceText {
        SourceText {
            lines: ["one two", "  three\tfour ", "five", ""]
                .iter()
                .map(|s| s.to_string())
                .collect(),
        }
    }

    #[test]
    fn line_ranges_parse() {
        assert_eq!(parse_lines("119-122"), Some((119, 122)));
        assert_eq!(parse_lines("157"), Some((157, 157)));
        assert_eq!(parse_lines("12–10"), None);
        assert_eq!(parse_lines("0"), None);
        assert_eq!(parse_lines("x"), None);
    }

    #[test]
    fn a_quote_is_found_only_at_its_own_lines() {
        let t = text();
        assert!(quote_at(&t, 1, 2, "two three four"));
        assert!(quote_at(&t, 2, 2, "three four"));
        assert!(quote_at(&t, 1, 3, "two\n three four five"));
        // wider or shifted ranges, a changed word, an empty quote: not found
        assert!(!quote_at(&t, 1, 3, "two three four"));
        assert!(!quote_at(&t, 2, 3, "two three four"));
        assert!(!quote_at(&t, 1, 2, "two three fours"));
        assert!(!quote_at(&t, 1, 2, "  "));
        assert!(!quote_at(&t, 3, 9, "five"));
    }
}
