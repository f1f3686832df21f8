//! The floors of docs/architecture.md, read from the sources: every path a file names
//! (`crate::…`, `super::…`, and `orthocheck::…` in `main.rs`) runs down a floor or sideways
//! along an edge the table allows, never up; no kind's folder names another kind; and inside
//! `report` the shared presentation lies below the outputs, without a circle.
//! Comments and string literals are not read, so a doc link is not an import.

use std::path::Path;

/// The floors of `orthocheck-core`, bottom first: a module may name those of lower floors.
const CORE_FLOORS: &[(&str, u8)] = &[
    ("algebra", 0),
    ("model", 0),
    ("numfmt", 0),
    ("limits", 0),
    ("error", 0),
    ("derivations", 1),
    ("studies", 2),
    ("sfm", 3),
];

/// The floors of `orthocheck`; every module of the core (re-exported under its own name)
/// lies below them all.
const TOP_FLOORS: &[(&str, u8)] = &[
    ("mathtext", 1),
    ("cases", 1),
    ("input", 1),
    ("seeds", 1),
    ("provenance", 1),
    ("files", 1),
    ("check", 2),
    ("claims", 3),
    ("report", 4),
    ("cli", 5),
    ("main", 5),
];

/// The floor of the core's modules seen from the top crate.
const CORE_BELOW: u8 = 0;

/// Names within one floor that the architecture allows, `(from, to)`: the seeded generator
/// of `model` behind `algebra::modp`, the typed errors, and users' tracks files read with the
/// case loader's located errors.
const SIDEWAYS: &[(&str, &str)] = &[
    ("algebra", "model"),
    ("algebra", "error"),
    ("model", "error"),
    ("input", "cases"),
];

/// The floors inside `report`, bottom first: the report as data, the shared presentation,
/// then one module per output (`mod.rs` binds them into files, above them all).
const REPORT_FLOORS: &[(&str, u8)] = &[
    ("model", 0),
    ("math", 0),
    ("values", 1),
    ("layout", 1),
    ("finite", 1),
    ("evidence", 2),
    ("words", 2),
    ("argument", 2),
    ("style", 2),
    ("svg", 3),
    ("html", 3),
    ("markdown", 3),
    ("patch", 3),
];

/// Names between outputs the report allows: the page embeds the figures' SVG.
const REPORT_SIDEWAYS: &[(&str, &str)] = &[("html", "svg")];

/// Which crate a source file belongs to, and its module path within it.
#[derive(Clone, Copy, PartialEq)]
enum Crate {
    Core,
    Top,
}

/// One source file: its path relative to its crate's `src/`, and its text.
struct Source<'a> {
    krate: Crate,
    path: &'a str,
    text: &'a str,
}

/// The floor of module `name` of `krate`; `None` for a name that is no module (an item
/// re-exported at the root, `*`).
fn floor(krate: Crate, name: &str) -> Option<u8> {
    let core = CORE_FLOORS.iter().find(|(m, _)| *m == name).map(|f| f.1);
    match krate {
        Crate::Core => core,
        Crate::Top => core
            .map(|_| CORE_BELOW)
            .or_else(|| TOP_FLOORS.iter().find(|(m, _)| *m == name).map(|f| f.1)),
    }
}

/// The module path of a file relative to `src/`: `cases/load.rs` is `[cases, load]`,
/// `cases/mod.rs` is `[cases]`, `lib.rs` is `[]`; `main.rs` is the binary, `[main]`.
fn module_path(path: &str) -> Vec<String> {
    let mut parts: Vec<String> = path
        .trim_end_matches(".rs")
        .split('/')
        .map(str::to_string)
        .collect();
    if parts.last().is_some_and(|p| p == "mod" || p == "lib") {
        parts.pop();
    }
    parts
}

/// The text with comments removed and every string and character literal emptied.
fn code_only(text: &str) -> String {
    let c: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < c.len() {
        let next = c.get(i + 1).copied();
        if c[i] == '/' && next == Some('/') {
            while i < c.len() && c[i] != '\n' {
                i += 1;
            }
        } else if c[i] == '/' && next == Some('*') {
            i = c[i..]
                .windows(2)
                .position(|w| w == ['*', '/'])
                .map_or(c.len(), |p| i + p + 2);
        } else if c[i] == 'r' && (next == Some('"') || next == Some('#')) && is_raw(&c, i) {
            i = skip_raw(&c, i);
            out.push_str("\"\"");
        } else if c[i] == '"' {
            i = skip_string(&c, i);
            out.push_str("\"\"");
        } else if c[i] == '\'' {
            i = skip_char(&c, i, &mut out);
        } else {
            out.push(c[i]);
            i += 1;
        }
    }
    out
}

/// Whether `r` at `i` opens a raw string (`r"`, `r#"`), not an identifier ending in r.
fn is_raw(c: &[char], i: usize) -> bool {
    let word = i > 0 && (c[i - 1].is_alphanumeric() || c[i - 1] == '_');
    let hashes = c[i + 1..].iter().take_while(|&&x| x == '#').count();
    !word && c.get(i + 1 + hashes) == Some(&'"')
}

/// Past the raw string opening at `i`.
fn skip_raw(c: &[char], i: usize) -> usize {
    let hashes = c[i + 1..].iter().take_while(|&&x| x == '#').count();
    let mut j = i + 2 + hashes;
    while j < c.len() {
        if c[j] == '"'
            && c[j + 1..]
                .iter()
                .take(hashes)
                .filter(|&&x| x == '#')
                .count()
                == hashes
        {
            return j + 1 + hashes;
        }
        j += 1;
    }
    c.len()
}

/// Past the string opening at `i`.
fn skip_string(c: &[char], i: usize) -> usize {
    let mut j = i + 1;
    while j < c.len() && c[j] != '"' {
        j += if c[j] == '\\' { 2 } else { 1 };
    }
    j + 1
}

/// Past a character literal at `i`, or past the quote of a lifetime (kept).
fn skip_char(c: &[char], i: usize, out: &mut String) -> usize {
    match (c.get(i + 1), c.get(i + 2)) {
        // an escape: the closing quote comes after the escaped character
        (Some('\\'), _) => c
            .get(i + 3..)
            .and_then(|rest| rest.iter().position(|&x| x == '\''))
            .map_or(c.len(), |p| i + 4 + p),
        (Some(_), Some('\'')) => i + 3,
        _ => {
            out.push('\'');
            i + 1
        }
    }
}

/// The paths of a use tree starting at `i` (after `crate::` or the like), each a list of
/// segments: `{a::b, c}` gives `[a, b]` and `[c]`.
fn use_tree(c: &[char], i: &mut usize) -> Vec<Vec<String>> {
    skip_space(c, i);
    match c.get(*i) {
        Some('{') => {
            *i += 1;
            let mut all = Vec::new();
            loop {
                skip_space(c, i);
                match c.get(*i) {
                    Some('}') | None => {
                        *i += 1;
                        return all;
                    }
                    Some(',') => *i += 1,
                    _ => all.extend(use_tree(c, i)),
                }
            }
        }
        Some('*') => {
            *i += 1;
            vec![vec!["*".into()]]
        }
        _ => {
            let start = *i;
            while *i < c.len() && (c[*i].is_alphanumeric() || c[*i] == '_') {
                *i += 1;
            }
            if start == *i {
                return Vec::new();
            }
            let head: String = c[start..*i].iter().collect();
            if c.get(*i) == Some(&':') && c.get(*i + 1) == Some(&':') {
                *i += 2;
                let tails = use_tree(c, i);
                tails
                    .into_iter()
                    .map(|t| std::iter::once(head.clone()).chain(t).collect())
                    .collect()
            } else {
                vec![vec![head]]
            }
        }
    }
}

fn skip_space(c: &[char], i: &mut usize) {
    while *i < c.len() && c[*i].is_whitespace() {
        *i += 1;
    }
}

/// Every path the file names from its crate's root, resolved: `super::` against the file's
/// module, `orthocheck::` in the binary as the library's root.
fn named_paths(src: &Source) -> Vec<Vec<String>> {
    let code: Vec<char> = code_only(src.text).chars().collect();
    let module = module_path(src.path);
    let binary = src.krate == Crate::Top && (src.path == "main.rs" || src.path.starts_with("cli/"));
    let mut out = Vec::new();
    let mut i = 0;
    while i < code.len() {
        let word_start =
            i == 0 || !(code[i - 1].is_alphanumeric() || code[i - 1] == '_' || code[i - 1] == ':');
        let rest: String = code[i..code.len().min(i + 13)].iter().collect();
        let root = ["crate::", "super::", "orthocheck::"]
            .into_iter()
            .find(|r| word_start && rest.starts_with(r));
        let Some(root) = root else {
            i += 1;
            continue;
        };
        i += root.len();
        let base: Vec<String> = match root {
            "super::" => module[..module.len().saturating_sub(1)].to_vec(),
            // the binary's own modules (cli) or the library's root, both from the root
            "crate::" if binary => Vec::new(),
            "orthocheck::" if !binary => {
                continue;
            }
            _ => Vec::new(),
        };
        for tail in use_tree(&code, &mut i) {
            // a chain of supers climbs further
            let mut path = base.clone();
            for seg in tail {
                match seg.as_str() {
                    "super" => {
                        path.pop();
                    }
                    _ => path.push(seg),
                }
            }
            out.push(path);
        }
    }
    out
}

/// The floor violations of one file: each an import running up a floor or sideways along
/// an edge [`SIDEWAYS`] does not allow.
fn floor_violations(src: &Source) -> Vec<String> {
    let module = module_path(src.path);
    let Some(own) = module.first().filter(|_| !module.is_empty()) else {
        return Vec::new(); // the crate root declares the modules
    };
    let Some(from) = floor(src.krate, own) else {
        return vec![format!(
            "{}: module `{own}` has no floor in the table",
            src.path
        )];
    };
    let mut out = Vec::new();
    for path in named_paths(src) {
        let Some(to_name) = path.first() else {
            continue;
        };
        let Some(to) = floor(src.krate, to_name) else {
            continue;
        };
        let sideways = to_name == own || SIDEWAYS.contains(&(own.as_str(), to_name.as_str()));
        if to > from || (to == from && !sideways) {
            out.push(format!(
                "{}: `{own}` (floor {from}) names `{}` (floor {to})",
                src.path,
                path.join("::")
            ));
        }
    }
    out
}

/// The kind-isolation violations of one file: a file in `claims/<kind>/` naming another
/// kind's module (the registry, `claims/audit.rs` and `claims/rerun.rs` may).
fn kind_violations(src: &Source, kinds: &[String]) -> Vec<String> {
    let module = module_path(src.path);
    let own = match module.as_slice() {
        [claims, kind, ..] if claims == "claims" && kinds.contains(kind) => kind,
        _ => return Vec::new(),
    };
    named_paths(src)
        .into_iter()
        .filter(|p| p.len() > 1 && p[0] == "claims" && kinds.contains(&p[1]) && &p[1] != own)
        .map(|p| format!("{}: kind `{own}` names `{}`", src.path, p.join("::")))
        .collect()
}

/// The floor violations inside `report`: a module naming a module of its own floor (but the
/// [`REPORT_SIDEWAYS`] pairs) or above, or one the table does not know.
fn report_violations(src: &Source) -> Vec<String> {
    let module = module_path(src.path);
    let own = match module.as_slice() {
        [report, own, ..] if report == "report" && src.krate == Crate::Top => own,
        _ => return Vec::new(),
    };
    let floor = |m: &str| REPORT_FLOORS.iter().find(|f| f.0 == m).map(|f| f.1);
    let Some(from) = floor(own) else {
        return vec![format!(
            "{}: report module `{own}` has no floor in the table",
            src.path
        )];
    };
    let mut out = Vec::new();
    for path in named_paths(src) {
        let [report, to_name, ..] = path.as_slice() else {
            continue;
        };
        if report != "report" || to_name == own {
            continue;
        }
        let sideways = REPORT_SIDEWAYS.contains(&(own.as_str(), to_name.as_str()));
        match floor(to_name) {
            Some(to) if to < from || sideways => {}
            Some(to) => out.push(format!(
                "{}: report's `{own}` (floor {from}) names `{}` (floor {to})",
                src.path,
                path.join("::")
            )),
            // an item of the facade (`report::Report`) or a name no module has
            None => {}
        }
    }
    out
}

/// Every `.rs` file under `dir`, as (path relative to `dir`, text), sorted.
fn sources(dir: &Path) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        let entries = std::fs::read_dir(&d).unwrap_or_else(|e| panic!("{}: {e}", d.display()));
        for entry in entries.flatten() {
            let p = entry.path();
            if p.is_dir() {
                stack.push(p);
            } else if p.extension().is_some_and(|e| e == "rs") {
                let rel = p
                    .strip_prefix(dir)
                    .unwrap_or(&p)
                    .to_string_lossy()
                    .replace('\\', "/");
                let text = std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{rel}: {e}"));
                out.push((rel, text));
            }
        }
    }
    out.sort();
    out
}

/// The kinds: the folders of `src/claims/` but `shared`.
fn kinds(root: &Path) -> Vec<String> {
    let mut kinds: Vec<String> = std::fs::read_dir(root.join("src/claims"))
        .map(|d| {
            d.flatten()
                .filter(|e| e.path().is_dir())
                .collect::<Vec<_>>()
        })
        .unwrap_or_default()
        .iter()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|k| k != "shared")
        .collect();
    kinds.sort();
    kinds
}

#[test]
fn no_import_runs_up_a_floor_and_no_kind_names_another() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let kinds = kinds(root);
    assert!(kinds.len() >= 15, "only {} kinds found", kinds.len());
    let mut files = 0;
    let mut found = Vec::new();
    for (krate, dir) in [(Crate::Core, "crates/core/src"), (Crate::Top, "src")] {
        for (path, text) in sources(&root.join(dir)) {
            let src = Source {
                krate,
                path: &path,
                text: &text,
            };
            found.extend(floor_violations(&src));
            found.extend(kind_violations(&src, &kinds));
            found.extend(report_violations(&src));
            files += 1;
        }
    }
    // the check cannot pass by reading nothing
    assert!(files >= 200, "only {files} source files read");
    assert!(
        found.is_empty(),
        "imports against the floors:\n{}",
        found.join("\n")
    );
}

#[test]
fn a_planted_up_import_is_reported() {
    let text = "//! A loader.\nuse crate::report::Report;\n/// crate::report in a comment\nfn f() { let _ = \"crate::report\"; }\n";
    let src = Source {
        krate: Crate::Top,
        path: "cases/x.rs",
        text,
    };
    let found = floor_violations(&src);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("`report::Report`"), "{found:?}");
    // grouped, nested and relative paths are read too
    let grouped = "use crate::{cases::Case, check::{ClaimResult, Verdict}};\nuse super::super::claims::run_all;";
    let src = Source {
        krate: Crate::Top,
        path: "check/noise.rs",
        text: grouped,
    };
    let found = floor_violations(&src);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("claims::run_all"), "{found:?}");
    // the core: derivations may not name the studies above them
    let src = Source {
        krate: Crate::Core,
        path: "derivations/p3f3.rs",
        text: "use crate::studies::noise;",
    };
    assert_eq!(floor_violations(&src).len(), 1);
    // a sideways name the table does not allow
    let src = Source {
        krate: Crate::Top,
        path: "cases/x.rs",
        text: "use crate::files::write;",
    };
    assert_eq!(floor_violations(&src).len(), 1);
}

#[test]
fn a_report_circle_is_reported() {
    // the shared presentation may not name an output, nor an output the facade's renderers
    let text =
        "use crate::report::html::badge;\nuse super::model::Report;\nuse super::math::Macros;";
    let src = Source {
        krate: Crate::Top,
        path: "report/values.rs",
        text,
    };
    let found = report_violations(&src);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("`report::html::badge`"), "{found:?}");
    let text = "use crate::report::markdown::plain_text;\nuse crate::report::svg::figure_svg;";
    let src = Source {
        krate: Crate::Top,
        path: "report/html/page.rs",
        text,
    };
    let found = report_violations(&src);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("markdown"), "{found:?}");
}

#[test]
fn a_kind_naming_another_is_reported() {
    let kinds = vec!["noise_study".to_string(), "p4f3_example".to_string()];
    let text =
        "use crate::claims::{shared::Context, noise_study::judge};\nuse crate::claims::ClaimKind;";
    let src = Source {
        krate: Crate::Top,
        path: "claims/p4f3_example/judge.rs",
        text,
    };
    let found = kind_violations(&src, &kinds);
    assert_eq!(found.len(), 1, "{found:?}");
    assert!(found[0].contains("claims::noise_study::judge"), "{found:?}");
    // its own kind, the shared floor and the registry are allowed
    let own = "use crate::claims::p4f3_example::study;\nuse super::super::shared::NoiseLevel;";
    let src = Source {
        krate: Crate::Top,
        path: "claims/p4f3_example/judge.rs",
        text: own,
    };
    assert!(kind_violations(&src, &kinds).is_empty());
}

#[test]
fn literals_and_comments_are_not_read() {
    let text =
        "let a = '\"'; let b = r#\"crate::x \"# ; /* crate::y */ let c = 'static_ref; x::crate::z";
    let code = code_only(text);
    assert!(
        !code.contains("crate::x") && !code.contains("crate::y"),
        "{code}"
    );
    assert!(code.contains("'static_ref"), "{code}");
    let src = Source {
        krate: Crate::Top,
        path: "cases/x.rs",
        text,
    };
    // `x::crate::z` is no path from the root
    assert!(named_paths(&src).is_empty());
}
