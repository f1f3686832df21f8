//! The paper's own metadata, `paper_cases/paper.yml`: its title and author.
//!
//! A separate file, not a case: the paper-case harness takes every `paper_cases/*.yaml` as a
//! case, and this file checks nothing.

use std::path::Path;

use serde::{Deserialize, Serialize};

use super::load::{invalid, parse_yaml};
use crate::error::Result;

/// The file of a cases folder that names the paper.
pub const PAPER_FILE: &str = "paper.yml";

/// The paper under audit, as the report names it.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq, Eq)]
#[serde(deny_unknown_fields)]
pub struct Paper {
    /// Title.
    pub title: String,
    /// Author.
    pub author: String,
    /// The LaTeX source the transcription was made from (its name, hash and length).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub source: Option<super::SourceRecord>,
    /// The paper's main results (the abstract's claims, the conclusions'): claim ids, the
    /// report's first screen, each with its standing.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub main_results: Vec<String>,
    /// The paper's sections in reading order, with their titles (the report's table of
    /// contents).
    #[serde(default)]
    pub sections: Vec<SectionTitle>,
    /// How the report names the paper's `\label` names ("zweiframeseins" → "Fig. 3").
    #[serde(default, skip_serializing_if = "std::collections::BTreeMap::is_empty")]
    pub labels: std::collections::BTreeMap<String, String>,
    /// The paper's own `\newcommand` definitions, verbatim (the report expands them to show
    /// printed formulas readably).
    #[serde(default, skip_serializing_if = "String::is_empty")]
    pub macros: String,
}

/// One section of the paper as its `\section` command titles it.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq, Eq)]
#[serde(deny_unknown_fields)]
pub struct SectionTitle {
    /// The number as the cases write it ("2.1", "A").
    pub number: String,
    /// The title as printed.
    pub title: String,
    /// The line of the sectioning command in the LaTeX source.
    pub line: u32,
}

impl Paper {
    /// The title of section `number`, when the paper file names it.
    pub fn section_title(&self, number: &str) -> Option<&str> {
        self.sections
            .iter()
            .find(|s| s.number == number)
            .map(|s| s.title.as_str())
    }
}

/// Sort key of a section number: numbers numerically, then the appendix.
pub fn section_key(s: &str) -> (u32, Vec<u32>, String) {
    if s.chars().next().is_some_and(|c| c.is_ascii_digit()) {
        (
            0,
            s.split(['.', '-']).filter_map(|p| p.parse().ok()).collect(),
            String::new(),
        )
    } else {
        (1, Vec::new(), s.to_string())
    }
}

/// The depth of a section number as the cases write it: "2" is a section (1), "2.1" a
/// subsection (2), "A" the appendix (1).
pub fn section_depth(number: &str) -> usize {
    1 + number.matches('.').count().min(1)
}

/// Read [`PAPER_FILE`] of the cases folder `dir`.
pub fn load_paper(dir: &Path) -> Result<Paper> {
    paper_of(&super::CaseOrigin::Folder(dir.to_path_buf()))
}

/// Read [`PAPER_FILE`] of the cases, embedded or in a folder.
pub fn paper_of(origin: &super::CaseOrigin) -> Result<Paper> {
    let (path, text) = origin.file(PAPER_FILE)?;
    parse_paper(&text, &path)
}

/// Parse the paper metadata; `path` names the file in errors. Title and author must say
/// something.
pub fn parse_paper(text: &str, path: &Path) -> Result<Paper> {
    let paper: Paper = parse_yaml(text, path)?;
    for (field, value) in [("title", &paper.title), ("author", &paper.author)] {
        if value.trim().is_empty() {
            return Err(invalid(text, path, field, "must not be empty".into()));
        }
    }
    Ok(paper)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_paper_file_parses() {
        let p = parse_paper("title: T\nauthor: A\n", Path::new("p.yml")).unwrap();
        assert_eq!((p.title.as_str(), p.author.as_str()), ("T", "A"));
    }

    #[test]
    fn errors_name_file_line_and_field() {
        let e = parse_paper("title: T\nauthor: \"\"\n", Path::new("p.yml")).unwrap_err();
        assert_eq!(e.to_string(), "p.yml:2: field `author`: must not be empty");
        let e = parse_paper("title: T\nauthor: A\nyear: 1\n", Path::new("p.yml")).unwrap_err();
        assert!(e.to_string().starts_with("p.yml:3:"), "{e}");
        let e = parse_paper("title: T\n", Path::new("p.yml")).unwrap_err();
        assert!(e.to_string().contains("author"), "{e}");
    }
}
