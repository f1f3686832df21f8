//! Loading case files: YAML with errors that name the file, line and field.

use std::path::{Path, PathBuf};

use super::plain_numbers::Tagged;
use super::{validate::validate, Case, CaseOrigin, Schema};
use crate::error::{Error, InputLocation, Result};

/// Read and validate one case file.
pub fn load_case<C: Schema>(path: &Path) -> Result<Case<C>> {
    let text = read_case_text(path)?;
    case_from_text(&text, &Tagged::new(&text), path)
}

/// Parse, validate and complete one case read from `path`, `tagged` its text tagged.
fn case_from_text<C: Schema>(text: &str, tagged: &Tagged, path: &Path) -> Result<Case<C>> {
    let mut case: Case<C> = parse_tagged(tagged, path, &case_budget())?;
    validate(&case, text, path)?;
    case.file = Some(path.to_path_buf());
    Ok(case)
}

/// Parse and validate case text; `path` names the file in errors.
pub fn parse_case<C: Schema>(text: &str, path: &Path) -> Result<Case<C>> {
    let case: Case<C> = parse_yaml(text, path)?;
    validate(&case, text, path)?;
    Ok(case)
}

/// Deserialize YAML with errors that name the file, line, column and field path.
/// Case files are small (the largest paper case holds a few thousand values), so their
/// budget is [`crate::limits::CASE_YAML_VALUES`] values and
/// [`crate::limits::CASE_YAML_ALIASES`] aliases: an alias bomb is refused within milliseconds.
pub fn parse_yaml<T: serde::de::DeserializeOwned>(text: &str, path: &Path) -> Result<T> {
    parse_yaml_budget(text, path, &case_budget())
}

/// The budget of a case file: [`crate::limits::CASE_YAML_VALUES`] values and
/// [`crate::limits::CASE_YAML_ALIASES`] aliases.
fn case_budget() -> serde_saphyr::Budget {
    budget_of(
        crate::limits::CASE_YAML_VALUES,
        crate::limits::CASE_YAML_ALIASES,
    )
}

fn budget_of(max_nodes: usize, max_aliases: usize) -> serde_saphyr::Budget {
    let mut budget = serde_saphyr::Budget::default();
    budget.max_nodes = max_nodes;
    budget.max_aliases = max_aliases;
    budget.max_events = max_nodes.saturating_mul(2).max(budget.max_events);
    budget
}

/// [`parse_yaml`] allowing up to `max_nodes` YAML values (sequences, maps and scalars), for
/// data files larger than a case file; the parser's other limits (depth, aliases) stay.
pub fn parse_yaml_limited<T: serde::de::DeserializeOwned>(
    text: &str,
    path: &Path,
    max_nodes: usize,
) -> Result<T> {
    let aliases = serde_saphyr::Budget::default().max_aliases;
    parse_yaml_budget(text, path, &budget_of(max_nodes, aliases))
}

/// [`parse_yaml`] with the parser's budget of values and aliases.
fn parse_yaml_budget<T: serde::de::DeserializeOwned>(
    text: &str,
    path: &Path,
    budget: &serde_saphyr::Budget,
) -> Result<T> {
    parse_tagged(&Tagged::new(text), path, budget)
}

/// [`parse_yaml_budget`] of a text already tagged.
fn parse_tagged<T: serde::de::DeserializeOwned>(
    tagged: &Tagged,
    path: &Path,
    budget: &serde_saphyr::Budget,
) -> Result<T> {
    let limits = budget.clone();
    let options = serde_saphyr::options! { with_snippet: false, budget: Some(budget.clone()) };
    // the common case first, without tracking the field path; a file that fails is read
    // again with it, for the error to name its field
    if let Ok(v) = serde_saphyr::from_str_with_options(&tagged.text, options.clone()) {
        return Ok(v);
    }
    let mut field: Option<String> = None;
    let parsed =
        serde_saphyr::with_deserializer_from_str_with_options(&tagged.text, options, |de| {
            serde_path_to_error::deserialize(de).map_err(|e| {
                // the path ends in `?` where the deserializer lost its place (a repeated key)
                let p = e.path().to_string();
                let p = p.trim_end_matches('?').trim_end_matches('.');
                if !p.is_empty() && p != "." {
                    field = Some(p.to_string());
                }
                e.into_inner()
            })
        });
    parsed.map_err(|e| {
        let loc = e
            .location()
            .map(|l| (l.line() as usize, l.column() as usize));
        let message = e.to_string();
        let refused = loc.and_then(|(l, c)| tagged.refusal(l, c));
        Error::Input {
            location: InputLocation {
                file: path.to_path_buf(),
                line: loc.map(|(l, _)| l as u64),
                column: loc.map(|(l, c)| tagged.original_column(l, c) as u64),
                field: field.or_else(|| field_of(&message)),
            },
            message: refused
                .filter(|_| message.starts_with("invalid"))
                .unwrap_or_else(|| plain_message(&strip_location(&message), &limits)),
        }
    })
}

/// The parser's messages in this tool's words: no advice about the parser's own options, no
/// parser terms ("scalar"), and a breached budget stated as the limit that was set (the
/// parser reports the count that breached it, one more).
fn plain_message(message: &str, limits: &serde_saphyr::Budget) -> String {
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
        let reached = breach
            .split(|c: char| !c.is_ascii_digit())
            .find(|d| !d.is_empty())
            .unwrap_or("?");
        let (kind, limit) = match what {
            "Nodes" => ("values", Some(limits.max_nodes)),
            "Events" => ("parser events", Some(limits.max_events)),
            "Depth" => ("levels of nesting", Some(limits.max_depth)),
            "Aliases" => ("aliases", Some(limits.max_aliases)),
            "Anchors" => ("anchors", Some(limits.max_anchors)),
            "Documents" => ("documents", Some(limits.max_documents)),
            _ => ("elements", None),
        };
        return match limit {
            Some(l) => format!("the file is too large: more than {l} {kind} (see docs/limits.md)"),
            None => format!("the file is too large: {reached} {kind}"),
        };
    }
    if let Some(what) = message
        .strip_prefix("expected ")
        .and_then(|m| m.strip_suffix(" scalar"))
    {
        return format!(
            "expected a single {} value here, not a list or a map (or an unclosed bracket)",
            if what == "string" {
                "text or number"
            } else {
                what
            }
        );
    }
    for int in [
        "u8", "u16", "u32", "u64", "usize", "i8", "i16", "i32", "i64",
    ] {
        if message.starts_with(&format!("invalid {int}")) {
            return "expected a whole number (no sign, no decimal point, no exponent) that fits"
                .into();
        }
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

pub(crate) fn invalid(text: &str, path: &Path, field: &str, message: String) -> Error {
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
pub fn load_all<C: Schema>(dir: &Path) -> Result<Vec<Case<C>>> {
    load_cases(&CaseOrigin::Folder(dir.to_path_buf()))
}

/// The `claim:` names of one case file.
pub(super) type Names = std::collections::BTreeSet<String>;

/// Which case files a command reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kinds<'a> {
    /// Every file.
    All,
    /// The files whose check is one of these kinds (a file whose kind its first lines do
    /// not tell is read too, so that its error is reported).
    Only(&'a [&'a str]),
}

impl Kinds<'_> {
    fn reads(&self, text: &str) -> bool {
        match self {
            Kinds::All => true,
            Kinds::Only(kinds) => kind_of(text).is_none_or(|k| kinds.contains(&k.as_str())),
        }
    }
}

/// The key under a case file's top-level `check:` (its kind), read from the parser's events
/// as far as that key; `None` where the text does not tell it there (no mapping at the top,
/// a syntax error before it, `check` not a mapping).
fn kind_of(text: &str) -> Option<String> {
    use granit_parser::{Event, Parser};
    // depth 1 is the document's mapping; `key`: its next node is a key; `check`: the key
    // just read there is `check`
    let (mut depth, mut key, mut check) = (0usize, true, false);
    let mut events = Parser::new_from_str(text).map(|e| e.ok().map(|(e, _)| e));
    while let Some(event) = events.next().flatten() {
        match event {
            Event::MappingStart(..) | Event::SequenceStart(..) if depth == 1 => {
                if check {
                    let first = events.next().flatten();
                    return match (event, first) {
                        (Event::MappingStart(..), Some(Event::Scalar(k, ..))) => {
                            Some(k.to_string())
                        }
                        _ => None,
                    };
                }
                if key {
                    return None;
                }
                (depth, key) = (2, true);
            }
            Event::SequenceStart(..) if depth == 0 => return None,
            Event::MappingStart(..) | Event::SequenceStart(..) => depth += 1,
            Event::MappingEnd | Event::SequenceEnd => {
                depth = depth.checked_sub(1).filter(|d| *d > 0)?;
            }
            Event::Scalar(..) | Event::Alias(..) if depth == 1 => {
                if check {
                    return None;
                }
                check = key && matches!(&event, Event::Scalar(v, ..) if v == "check");
                key = !key;
            }
            _ => {}
        }
    }
    None
}

/// Load every case: each file valid on its own, no id twice, and every claim a restatement
/// restates checked by some case.
pub fn load_cases<C: Schema>(origin: &CaseOrigin) -> Result<Vec<Case<C>>> {
    load_cases_of(origin, Kinds::All)
}

/// [`load_cases`] of the files of some kinds: the checks across files (ids, restated claims,
/// the inventory) hold among those.
pub fn load_cases_of<C: Schema>(origin: &CaseOrigin, kinds: Kinds) -> Result<Vec<Case<C>>> {
    use rayon::prelude::*;
    let mut read = origin.case_texts()?;
    read.retain(|(_, text)| kinds.reads(text));
    // the files parse independently, on every core; their errors are then taken in file
    // order, so that the first bad file is the one named, whatever finished first
    let parsed: Vec<(Result<Case<C>>, Names)> = read
        .par_iter()
        .map(|(p, text)| {
            let tagged = Tagged::new(text);
            (case_from_text(text, &tagged, p), tagged.claims)
        })
        .collect();
    let mut cases = Vec::new();
    let mut texts = Vec::new();
    let mut named = Vec::new();
    for ((p, text), (case, claims)) in read.into_iter().zip(parsed) {
        let case: Case<C> = case?;
        named.push(claims);
        if let Some(first) = cases.iter().position(|c: &Case<C>| c.id == case.id) {
            let other = cases[first].file.as_deref().unwrap_or(Path::new("?"));
            return Err(invalid(
                &text,
                &p,
                "id",
                format!(
                    "the id `{}` is already the id of {}",
                    case.id,
                    other.display()
                ),
            ));
        }
        cases.push(case);
        texts.push((p, text));
    }
    known_restated_claims(&cases, &texts, &named)?;
    let ids = inventory_claims(origin, &texts, &named)?;
    let rests_on: Vec<_> = cases.iter().map(|c| &c.rests_on).collect();
    super::supports::check(&rests_on, &texts, &named, &ids)?;
    Ok(cases)
}

/// Every `claim:` a case names must be an id of the folder's claim inventory (returned) (`claims.md`),
/// or of the paper's own, built in, when the folder has none (or `id/part`): a typo would
/// decide a claim the paper does not make.
fn inventory_claims(
    origin: &CaseOrigin,
    texts: &[(PathBuf, String)],
    named: &[Names],
) -> Result<Names> {
    let (ids, whose) = match inventory(origin)? {
        Some(ids) => (ids, "the inventory"),
        None => (
            inventory(&CaseOrigin::Embedded)?.unwrap_or_default(),
            "the paper's inventory, built in (this folder has no claims.md)",
        ),
    };
    for ((p, text), named) in texts.iter().zip(named) {
        if let Some(id) = named
            .iter()
            .find(|id| !super::refers_to_inventory(id, &ids))
        {
            // the line of this `claim:` itself (plain or quoted); a value the YAML read as
            // a number or a boolean is spelled otherwise in the file (`1.0`, `yes`): the first
            // `claim:` value the inventory does not know
            let value_at = |l: &str| {
                let v = l.trim_start().trim_start_matches("- ");
                v.strip_prefix("claim:")
                    .map(|v| v.trim().trim_matches(['"', '\'']).to_string())
            };
            let line = text
                .lines()
                .position(|l| value_at(l).is_some_and(|v| v == *id))
                .or_else(|| {
                    text.lines().position(|l| {
                        value_at(l)
                            .is_some_and(|v| !v.is_empty() && !super::refers_to_inventory(&v, &ids))
                    })
                });
            let id = line
                .and_then(|l| text.lines().nth(l))
                .and_then(value_at)
                .unwrap_or_else(|| id.clone());
            return Err(Error::Input {
                location: InputLocation {
                    file: p.clone(),
                    line: line.map(|l| l as u64 + 1),
                    column: None,
                    field: Some("claim".into()),
                },
                message: format!(
                    "`{id}` is not a claim of {whose} ({}): a claim the paper makes is listed there first",
                    super::INVENTORY_FILES.join(", ")
                ),
            });
        }
    }
    Ok(ids)
}

/// The ids of a folder's claim inventory; `None` when it has no `claims.md`.
fn inventory(origin: &CaseOrigin) -> Result<Option<std::collections::BTreeSet<String>>> {
    let mut ids = std::collections::BTreeSet::new();
    for name in super::INVENTORY_FILES {
        match origin.file(name) {
            Ok((_, text)) => ids.extend(super::inventory_ids(&text)),
            Err(Error::Io { .. }) if name != super::INVENTORY_FILES[0] => {}
            Err(Error::Io { .. }) => return Ok(None),
            Err(e) => return Err(e),
        }
    }
    Ok(Some(ids))
}

/// A case file's text, refused beyond the size limit or when it is not UTF-8.
pub(super) fn read_case_text(path: &Path) -> Result<String> {
    let bytes = super::latex::read_limited(path, crate::limits::INPUT_BYTES)?;
    String::from_utf8(bytes).map_err(|_| whole_file(path, "the file is not UTF-8 text".into()))
}

/// An error about a whole file (no line, no field).
fn whole_file(path: &Path, message: String) -> Error {
    Error::Input {
        location: InputLocation::file(path),
        message,
    }
}

/// Every id a restatement restates must be a claim some case of the folder refers to
/// (a `claim:` field anywhere in a case), or the restatement could never be decided.
fn known_restated_claims<C: Schema>(
    cases: &[Case<C>],
    texts: &[(PathBuf, String)],
    named: &[Names],
) -> Result<()> {
    let known: std::collections::BTreeSet<&str> =
        named.iter().flatten().map(String::as_str).collect();
    for (case, (p, text)) in cases.iter().zip(texts) {
        if let Some((id, field)) = case
            .check
            .restated_ids()
            .into_iter()
            .find(|(id, _)| !known.contains(id.as_str()))
        {
            return Err(invalid(
                text,
                p,
                &field,
                format!("`{id}` is not a claim any case of the folder checks"),
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::BTreeMap;

    type Any = BTreeMap<String, serde::de::IgnoredAny>;

    #[test]
    fn the_kind_is_read_from_the_first_lines() {
        let kind = |t: &str| kind_of(t);
        assert_eq!(
            kind("id: x\ncheck:\n  formula_audit:\n    seed: 1\n").as_deref(),
            Some("formula_audit")
        );
        // after collections of any depth, in flow style, behind an anchor
        assert_eq!(
            kind("id: x\nsource: {section: \"2\", lines: [1, {a: [2]}]}\nl:\n  - [a, {b: c}]\ncheck: {dof_count: {p: 3}}\n").as_deref(),
            Some("dof_count")
        );
        assert_eq!(
            kind("check: &k\n  twofold_squared: {}\n").as_deref(),
            Some("twofold_squared")
        );
        // not told: no check, check not a mapping, a sequence or a scalar at the top, a
        // syntax error first, a collection as a key, `check` only nested
        for t in [
            "id: x\n",
            "check: formula_audit\n",
            "check: [formula_audit]\n",
            "check: {}\n",
            "- check:\n    formula_audit: {}\n",
            "check",
            "id: [\ncheck:\n  formula_audit: {}\n",
            "? [a]\n: 1\ncheck:\n  formula_audit: {}\n",
            "source:\n  check:\n    formula_audit: {}\n",
        ] {
            assert_eq!(kind(t), None, "{t}");
        }
    }

    #[test]
    fn an_alias_bomb_is_refused_naming_the_limit_set() {
        let n = crate::limits::CASE_YAML_ALIASES;
        let text = format!("a: &x 1\nb: [{}]\n", vec!["*x"; n + 1].join(", "));
        let e = parse_yaml::<Any>(&text, Path::new("bomb.yaml"))
            .unwrap_err()
            .to_string();
        assert!(e.contains(&format!("more than {n} aliases")), "{e}");
    }

    #[test]
    fn a_list_where_a_value_belongs_is_said_without_parser_terms() {
        #[derive(Debug, serde::Deserialize)]
        #[allow(dead_code)]
        struct S {
            seed: String,
        }
        let e = parse_yaml::<S>("seed: [1, 2]\n", Path::new("s.yaml"))
            .unwrap_err()
            .to_string();
        assert!(!e.contains("scalar"), "{e}");
        assert!(e.contains("s.yaml") && e.contains("seed"), "{e}");
    }
}
