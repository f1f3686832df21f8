//! Errata of the text: findings of a line-by-line reading of the LaTeX source, each quoted
//! exactly at its lines with the words at fault, the correction and, where one exists, the
//! computation that decides it. The findings are judged from this transcription; given the
//! paper's LaTeX source (`--paper FILE`), the verification checks every quote at its lines
//! and the source facts the findings record ([`SourceErrataCase::source_checks`]).

use std::collections::BTreeMap;

use serde::Deserialize;

use crate::cases::{parse_lines, ClaimRef, Printed, SourceCheck, SourceFact, Validator};
use crate::error::Result;

/// The errata of the text.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct SourceErrataCase {
    /// The findings, in the order of the source.
    pub findings: Vec<Finding>,
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
    /// The words at fault, each as it stands in the quote (white space aside): the check
    /// finds every one in the quote and none in the corrected text.
    pub at_fault: Vec<String>,
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
    /// which naming of the labels the drawings fit (`figure_labels`).
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

impl SourceErrataCase {
    /// The source facts the findings record beyond their quotes: every coordinate of a
    /// picture within its lines, and the strings recorded as absent from the whole source.
    /// The quotes themselves are verified with every other quote of the cases.
    pub fn source_checks(&self) -> Vec<SourceCheck> {
        let base = "check.source_errata.findings";
        let mut out = Vec::new();
        for (i, f) in self.findings.iter().enumerate() {
            let claim = f.claim.claim.clone();
            match &f.decide {
                Some(Decision::FigureLabels { pictures, .. }) => {
                    for (j, p) in pictures.iter().enumerate() {
                        out.extend(picture_strings(p).into_iter().map(|needle| SourceCheck {
                            claim: claim.clone(),
                            field: format!("{base}[{i}].decide.figure_labels.pictures[{j}]"),
                            fact: SourceFact::Within {
                                lines: p.lines.clone(),
                                needle,
                            },
                        }));
                    }
                }
                Some(Decision::NotInSource { strings }) => {
                    out.extend(strings.iter().enumerate().map(|(j, s)| SourceCheck {
                        claim: claim.clone(),
                        field: format!("{base}[{i}].decide.not_in_source.strings[{j}]"),
                        fact: SourceFact::Absent { needle: s.clone() },
                    }));
                }
                _ => {}
            }
        }
        out
    }
}

/// Result ids unique, line ranges that parse, a correction and a reading for each finding.
pub(super) fn checks(c: &SourceErrataCase, v: &Validator) -> Result<()> {
    let base = "findings";
    let mut seen = std::collections::BTreeSet::new();
    for (i, f) in c.findings.iter().enumerate() {
        if !seen.insert((f.claim.claim.as_str(), f.id.as_str())) {
            return v.err(
                &format!("{base}[{i}].id"),
                format!("{}/{} appears twice", f.claim.claim, f.id),
            );
        }
        let ranges = std::iter::once(&f.claim.lines).chain(f.also.iter().map(|p| &p.lines));
        if let Some(bad) = ranges.clone().find(|l| parse_lines(l).is_none()) {
            return v.err(
                &format!("{base}[{i}].claim.lines"),
                format!("`{bad}` is not a line range a-b"),
            );
        }
        if f.at_fault.is_empty() || f.at_fault.iter().any(|w| w.trim().is_empty()) {
            return v.err(
                &format!("{base}[{i}].at_fault"),
                "name the words at fault, each as it stands in the quote".into(),
            );
        }
        if f.corrected.trim().is_empty() || f.defect.trim().is_empty() {
            return v.err(
                &format!("{base}[{i}].corrected"),
                "say the defect and the correction".into(),
            );
        }
        match &f.decide {
            Some(Decision::DofCount {
                printed, corrected, ..
            }) if corrected.is_empty() || printed == corrected => {
                return v.err(
                    &format!("{base}[{i}].decide"),
                    "the corrected reading must name configurations, other than the printed".into(),
                );
            }
            Some(Decision::FigureLabels {
                origin,
                points,
                pictures,
                ..
            }) => {
                figure_labels(origin, points, pictures, v, &format!("{base}[{i}].decide"))?;
            }
            _ => {}
        }
    }
    Ok(())
}

/// Coordinates of the right lengths; every label (as printed and as renamed) names a point.
fn figure_labels(
    origin: &str,
    points: &[NamedPoint],
    pictures: &[LabelPicture],
    v: &Validator,
    field: &str,
) -> Result<()> {
    let known = |n: &str| points.iter().any(|p| p.name == n);
    if !known(origin) || points.iter().any(|p| p.at.len() != 3) {
        return v.err(
            field,
            "the points need three coordinates each, the origin among them".into(),
        );
    }
    for (j, p) in pictures.iter().enumerate() {
        let shapes = p.corner.len() == 2
            && p.ends.len() == 3
            && p.ends.iter().all(|e| e.len() == 2)
            && p.labels.iter().all(|l| l.at.len() == 2);
        let named = p.labels.iter().all(|l| known(&l.name))
            && p.rename.values().all(|n| known(n))
            && p.rename
                .keys()
                .all(|k| p.labels.iter().any(|l| &l.name == k))
            && p.labels.iter().any(|l| l.name == origin);
        if !shapes || !named {
            return v.err(
                &format!("{field}.figure_labels.pictures[{j}]"),
                "a picture needs a corner, three edge ends, labels of known points (the origin's among them)".into(),
            );
        }
    }
    Ok(())
}
