//! Loading case files: YAML with errors that name the file, line and field.

use std::path::{Path, PathBuf};

use super::{validate::validate, Case};
use crate::error::{Error, InputLocation, Result};

/// Read and validate one case file.
pub fn load_case(path: &Path) -> Result<Case> {
    let text = std::fs::read_to_string(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let mut case = parse_case(&text, path)?;
    if let super::CaseCheck::SourceErrata(c) = &mut case.check {
        // the quotes are verified against the source as it is read
        super::errata::attach_source(c, &text, path)?;
    }
    case.file = Some(path.to_path_buf());
    Ok(case)
}

/// Parse and validate case text; `path` names the file in errors.
pub fn parse_case(text: &str, path: &Path) -> Result<Case> {
    let case: Case = parse_yaml(text, path)?;
    validate(&case, text, path)?;
    Ok(case)
}

/// Deserialize YAML with errors that name the file, line, column and field path.
pub fn parse_yaml<T: serde::de::DeserializeOwned>(text: &str, path: &Path) -> Result<T> {
    parse_yaml_limited(text, path, serde_saphyr::Budget::default().max_nodes)
}

/// [`parse_yaml`] allowing up to `max_nodes` YAML values (sequences, maps and scalars), for
/// data files larger than a case file; the parser's other limits (depth, aliases) stay.
pub fn parse_yaml_limited<T: serde::de::DeserializeOwned>(
    text: &str,
    path: &Path,
    max_nodes: usize,
) -> Result<T> {
    let mut budget = serde_saphyr::Budget::default();
    budget.max_nodes = max_nodes;
    budget.max_events = max_nodes.saturating_mul(2).max(budget.max_events);
    let options = serde_saphyr::options! { with_snippet: false, budget: Some(budget) };
    let mut field: Option<String> = None;
    let parsed = serde_saphyr::with_deserializer_from_str_with_options(text, options, |de| {
        serde_path_to_error::deserialize(de).map_err(|e| {
            let p = e.path().to_string();
            if p != "." && p != "?" {
                field = Some(p);
            }
            e.into_inner()
        })
    });
    parsed.map_err(|e| {
        let loc = e.location();
        let message = e.to_string();
        Error::Input {
            location: InputLocation {
                file: path.to_path_buf(),
                line: loc.map(|l| l.line()),
                column: loc.map(|l| l.column()),
                field: field.or_else(|| field_of(&message)),
            },
            message: plain_message(&strip_location(&message)),
        }
    })
}

/// The parser's messages in this tool's words: no advice about the parser's own options.
fn plain_message(message: &str) -> String {
    if let Some(rest) = message.strip_prefix("duplicate mapping key") {
        let key = rest
            .trim_start_matches(": ")
            .split(',')
            .next()
            .unwrap_or("")
            .trim();
        return if key.is_empty() {
            "a key appears twice".into()
        } else {
            format!("key `{key}` appears twice")
        };
    }
    if let Some(breach) = message.strip_prefix("budget breached: ") {
        let what = breach.split([' ', '{']).next().unwrap_or(breach);
        let limit = breach
            .split(|c: char| !c.is_ascii_digit())
            .find(|d| !d.is_empty())
            .unwrap_or("?");
        let kind = match what {
            "Nodes" => "values",
            "Events" => "parser events",
            "Depth" => "levels of nesting",
            "Aliases" => "aliases",
            "Anchors" => "anchors",
            "Documents" => "documents",
            _ => "elements",
        };
        return format!("the file is too large: more than {limit} {kind}");
    }
    if message.contains("from_str_multiple") {
        return "the file holds more than one YAML document".into();
    }
    message.to_string()
}

/// The field a message names (`missing field `x``, `duplicate mapping key: x`).
fn field_of(message: &str) -> Option<String> {
    if let Some(i) = message.find("field `") {
        let start = i + "field `".len();
        let end = message[start..].find('`')?;
        return Some(message[start..start + end].to_string());
    }
    let start = message.find("duplicate mapping key: ")? + "duplicate mapping key: ".len();
    let key = message[start..].split([',', ' ']).next()?;
    Some(key.to_string())
}

/// The 1-based line of a dotted field path (`check.dof_count.examples[1].points`) in
/// block-style YAML, for errors found after parsing.
pub(crate) fn line_of(text: &str, field: &str) -> Option<u64> {
    let lines: Vec<&str> = text.lines().collect();
    let indent = |l: &str| l.len() - l.trim_start().len();
    let (mut pos, mut min_indent) = (0usize, 0usize);
    for segment in field.split('.') {
        let (key, index) = match segment.split_once('[') {
            // the first index only: deeper ones sit in flow sequences on the item's line
            Some((k, i)) => (k, i.split(']').next().and_then(|n| n.parse::<usize>().ok())),
            None => (segment, None),
        };
        let found = (pos..lines.len()).find(|&i| {
            let t = lines[i].trim_start().trim_start_matches("- ");
            indent(lines[i]) >= min_indent && t.starts_with(&format!("{key}:"))
        })?;
        pos = found;
        min_indent = indent(lines[found]);
        if let Some(n) = index {
            let items: Vec<usize> = (found + 1..lines.len())
                .take_while(|&i| {
                    lines[i].trim().is_empty()
                        || indent(lines[i]) > min_indent
                        || lines[i].trim_start().starts_with('-')
                })
                .filter(|&i| lines[i].trim_start().starts_with('-'))
                .collect();
            // A flow sequence (`[..]`) has no item lines: the key's line is the best answer.
            let Some(item_indent) = items.first().map(|&i| indent(lines[i])) else {
                break;
            };
            let Some(at) = items
                .into_iter()
                .filter(|&i| indent(lines[i]) == item_indent)
                .nth(n)
            else {
                break;
            };
            pos = at;
            min_indent = item_indent;
        }
    }
    Some(pos as u64 + 1)
}

/// Drop a trailing " at line L, column C" that the location already says.
fn strip_location(message: &str) -> String {
    match message.find(" at line ") {
        Some(i) => message[..i].to_string(),
        None => message.to_string(),
    }
}

pub(super) fn invalid(text: &str, path: &Path, field: &str, message: String) -> Error {
    Error::Input {
        location: InputLocation {
            file: path.to_path_buf(),
            line: line_of(text, field),
            column: None,
            field: Some(field.to_string()),
        },
        message,
    }
}

/// All `*.yaml` files of a folder, sorted by name.
pub fn case_files(dir: &Path) -> Result<Vec<PathBuf>> {
    let entries = std::fs::read_dir(dir).map_err(|source| Error::Io {
        path: dir.to_path_buf(),
        source,
    })?;
    let mut files: Vec<PathBuf> = entries
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "yaml"))
        .collect();
    files.sort();
    Ok(files)
}

/// Load every case of a folder.
pub fn load_all(dir: &Path) -> Result<Vec<Case>> {
    case_files(dir)?.iter().map(|p| load_case(p)).collect()
}
