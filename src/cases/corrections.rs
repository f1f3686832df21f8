//! The paper corrected: `corrections.yml` of a cases folder, each erratum's replacement in the
//! LaTeX source (the report writes them as `errata.patch`). Not a case: it checks nothing;
//! the errata are decided by their cases, and this file only mends the text.

use serde::Deserialize;

use super::load::{invalid, parse_yaml};
use super::{parse_lines, CaseOrigin};
use crate::error::{Error, Result};

/// The file of a cases folder that holds the corrections.
pub const CORRECTIONS_FILE: &str = "corrections.yml";

/// Lines of context around each hunk.

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    corrections: Vec<Correction>,
}

/// One replacement in the source, or why an erratum has none.
#[derive(Clone, Debug, Deserialize, PartialEq, Eq)]
#[serde(deny_unknown_fields)]
pub struct Correction {
    /// The erratum's result id.
    pub result: String,
    /// The lines `from` spans (`a-b`), tightly.
    #[serde(default)]
    pub lines: Option<String>,
    /// The text replaced, byte for byte.
    #[serde(default)]
    pub from: Option<String>,
    /// Its replacement.
    #[serde(default)]
    pub to: Option<String>,
    /// Why, and what the correction rests on.
    #[serde(default)]
    pub note: Option<String>,
    /// Why no text can mend the erratum (instead of `lines`, `from`, `to`).
    #[serde(default)]
    pub not_patchable: Option<String>,
}

/// The corrections of a cases folder (none when it has no [`CORRECTIONS_FILE`]); each is
/// a replacement (`lines`, `from`, `to`, the line count kept) or a reason it cannot be one.
pub fn corrections_of(origin: &CaseOrigin) -> Result<Vec<Correction>> {
    let (path, text) = match origin.file(CORRECTIONS_FILE) {
        Ok(f) => f,
        Err(Error::Io { .. }) => return Ok(Vec::new()),
        Err(e) => return Err(e),
    };
    let file: File = parse_yaml(&text, &path)?;
    for (i, c) in file.corrections.iter().enumerate() {
        let field = |f: &str| format!("corrections[{i}].{f}");
        let fault = match (&c.lines, &c.from, &c.to, &c.not_patchable) {
            (Some(l), Some(from), Some(to), None) => match parse_lines(l) {
                None => Some((field("lines"), "a line range `a-b` or `a`".to_string())),
                Some(_) if from.is_empty() => Some((field("from"), "must not be empty".into())),
                Some(_) if from.lines().count() != to.lines().count() => Some((
                    field("to"),
                    "must keep the line count of `from` (the report's lines stay the paper's)"
                        .into(),
                )),
                Some(_) => None,
            },
            (None, None, None, Some(_)) => None,
            _ => Some((
                field("result"),
                "give `lines`, `from` and `to`, or `not_patchable` alone".into(),
            )),
        };
        if let Some((f, message)) = fault {
            return Err(invalid(&text, &path, &f, message));
        }
    }
    Ok(file.corrections)
}
