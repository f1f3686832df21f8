//! Where the cases come from: the copy of `paper_cases/` embedded in the binary (so that
//! `orthocheck report` works from any folder), or a folder given as `--cases DIR`.

use std::path::{Path, PathBuf};

use crate::error::{Error, Result};

include!(concat!(env!("OUT_DIR"), "/embedded_cases.rs"));

/// The folder name the embedded files are shown under in messages.
const EMBEDDED_DIR: &str = "paper_cases";

/// Where the cases are read from.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub enum CaseOrigin {
    /// The paper's cases as the binary was built with them.
    #[default]
    Embedded,
    /// Every `*.yaml` of a folder, and its `paper.yml`.
    Folder(PathBuf),
}

impl CaseOrigin {
    /// A folder when one is given, else the embedded cases.
    pub fn from_arg(dir: Option<&Path>) -> CaseOrigin {
        dir.map_or(CaseOrigin::Embedded, |d| {
            CaseOrigin::Folder(d.to_path_buf())
        })
    }

    /// In words, for the provenance: "the cases embedded in the binary" or the folder.
    pub fn describe(&self) -> String {
        match self {
            CaseOrigin::Embedded => "the paper's cases embedded in the binary".into(),
            CaseOrigin::Folder(d) => format!("the cases of {}", d.display()),
        }
    }

    /// Every case file (`*.yaml`), sorted by name: the name messages show, and the text.
    pub fn case_texts(&self) -> Result<Vec<(PathBuf, String)>> {
        match self {
            CaseOrigin::Embedded => Ok(EMBEDDED_CASES
                .iter()
                .filter(|(n, _)| n.ends_with(".yaml"))
                .map(|(n, t)| (Path::new(EMBEDDED_DIR).join(n), (*t).to_string()))
                .collect()),
            CaseOrigin::Folder(d) => super::case_files(d)?
                .into_iter()
                .map(|p| super::load::read_case_text(&p).map(|t| (p, t)))
                .collect(),
        }
    }

    /// One named file of the cases (e.g. `paper.yml`): the name messages show, and the text.
    pub fn file(&self, name: &str) -> Result<(PathBuf, String)> {
        match self {
            CaseOrigin::Embedded => EMBEDDED_CASES
                .iter()
                .find(|(n, _)| *n == name)
                .map(|(n, t)| (Path::new(EMBEDDED_DIR).join(n), (*t).to_string()))
                .ok_or_else(|| Error::Io {
                    path: Path::new(EMBEDDED_DIR).join(name),
                    source: std::io::Error::from(std::io::ErrorKind::NotFound),
                }),
            CaseOrigin::Folder(d) => {
                let p = d.join(name);
                super::load::read_case_text(&p).map(|t| (p, t))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_embedded_cases_are_the_folder_s() {
        let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join(EMBEDDED_DIR);
        let embedded = CaseOrigin::Embedded.case_texts().unwrap();
        let folder = CaseOrigin::Folder(dir).case_texts().unwrap();
        assert!(embedded.len() >= 15, "{} embedded cases", embedded.len());
        assert_eq!(embedded.len(), folder.len());
        for ((a, ta), (b, tb)) in embedded.iter().zip(&folder) {
            assert_eq!(a.file_name(), b.file_name());
            assert_eq!(ta, tb, "{} differs from its embedded copy", b.display());
        }
        assert!(CaseOrigin::Embedded.file("paper.yml").is_ok());
        assert!(CaseOrigin::Embedded.file("claims.md").is_ok());
    }
}
