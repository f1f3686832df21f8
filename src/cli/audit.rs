//! `orthocheck audit`: the paper's printed formulas, machine-checked.

use std::io::Write as _;
use std::path::{Path, PathBuf};

use orthocheck::claims::twofold_squared::TwofoldCase;
use orthocheck::claims::{Case, Check};
use orthocheck::report::Report;
use orthocheck::{cases, check, report, studies, Error};

use super::{emit, out};

/// Arguments of `audit`.
#[derive(clap::Args)]
pub struct Args {
    /// An item id (p3f3sqr, appA-coefficients/f_cb, …) or a claim id (all its items);
    /// `twofold-squared` shows eq. p3f3sqr in full.
    #[arg(required_unless_present_any = ["all", "export"])]
    id: Option<String>,
    /// Every item.
    #[arg(long, conflicts_with = "id")]
    all: bool,
    /// Folder of case files (the printed formulas are read from there), instead of the
    /// paper's cases built into the binary.
    #[arg(long)]
    cases: Option<PathBuf>,
    /// The paper's LaTeX source: verifies the transcription, and decides the errata of the
    /// text in `--markdown` (default: the file ORTHOCHECK_PAPER names, else none).
    #[arg(long, value_name = "FILE")]
    paper: Option<PathBuf>,
    /// JSON output.
    #[arg(long)]
    json: bool,
    /// The errata list of the whole report as Markdown (what docs/errata.md holds).
    #[arg(long, conflicts_with_all = ["json", "id"])]
    markdown: bool,
    /// Write one self-contained SymPy script per identity into `--out`: `sympy` for the
    /// items the id (or `--all`) selects, `all` for every identity.
    #[arg(long, value_enum, requires = "out", conflicts_with_all = ["json", "markdown"])]
    export: Option<Export>,
    /// Folder for the exported scripts (created when missing; an existing file is never
    /// overwritten: the export refuses and writes nothing).
    #[arg(long, requires = "export")]
    out: Option<PathBuf>,
}

/// What `--export` writes.
#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum Export {
    /// SymPy scripts of the selected items.
    Sympy,
    /// SymPy scripts of every identity.
    All,
}

/// Whether the script `script_id` belongs to the selection `id` (an item id, its
/// `/expanded` sibling, or a claim id).
fn selected(script_id: &str, id: &str) -> bool {
    script_id == id
        || script_id == format!("{id}/expanded")
        || script_id.split('/').next() == Some(id)
}

/// Write the SymPy scripts the arguments select into `dir`, refusing before writing
/// anything when one of the files exists.
fn export(loaded: &[Case], a: &Args, dir: &Path) -> Result<(), Error> {
    let mut scripts = Vec::new();
    for case in loaded {
        if let Check::FormulaAudit(c) = &case.check {
            scripts.extend(studies::audit::sympy_scripts(c)?);
        }
    }
    if a.export == Some(Export::Sympy) && !a.all {
        let Some(id) = &a.id else {
            return Err(Error::InvalidInput(
                "--export sympy needs an item id or --all (or use --export all)".into(),
            ));
        };
        scripts.retain(|s| selected(&s.id, id));
        if scripts.is_empty() {
            return Err(Error::InvalidInput(format!(
                "no identity `{id}` to export (try `orthocheck audit --all`)"
            )));
        }
    }
    let write_err = |path: &Path, e: &dyn std::fmt::Display| Error::Write {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    std::fs::create_dir_all(dir).map_err(|e| write_err(dir, &e))?;
    if let Some(s) = scripts.iter().find(|s| dir.join(&s.file).exists()) {
        return Err(write_err(
            &dir.join(&s.file),
            &"the file exists and is not overwritten; nothing was written (choose an empty folder)",
        ));
    }
    let mut listing = String::new();
    for s in &scripts {
        let path = dir.join(&s.file);
        let mut f = std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(&path)
            .map_err(|e| write_err(&path, &e))?;
        f.write_all(s.source.as_bytes())
            .map_err(|e| write_err(&path, &e))?;
        listing.push_str(&format!("{}  {}\n", s.id, path.display()));
    }
    out(&listing)
}

/// The twofold-squared case named `id`, if `id` names one: it is shown in full.
fn twofold_case<'a>(loaded: &'a [Case], id: &str) -> Option<&'a TwofoldCase> {
    loaded.iter().find_map(|c| match &c.check {
        Check::TwofoldSquared(t) if c.id == id => Some(t),
        _ => None,
    })
}

/// One twofold-squared case in full, the errata list, or the items an id names.
pub fn run(a: Args) -> Result<(), Error> {
    let origin = cases::CaseOrigin::from_arg(a.cases.as_deref());
    let source = cases::source_path(a.paper.as_deref());
    let loaded = cases::load_inputs::<Check>(&origin, source.as_deref())?.cases;
    if let Some(dir) = &a.out {
        return export(&loaded, &a, dir);
    }
    if a.markdown {
        let r = Report::from_cases(&loaded)?;
        out(&report::errata_markdown(&r.claims))?;
        return Ok(());
    }
    if let Some(case) = a.id.as_deref().and_then(|id| twofold_case(&loaded, id)) {
        let audit = check::audit_twofold(case)?;
        emit(a.json, &audit, report::twofold_text)?;
        return Ok(());
    }
    let mut items = check::audit_all(&loaded)?;
    if let Some(id) = &a.id {
        items.retain(|it| &it.id == id || &it.claim == id);
        if items.is_empty() {
            return Err(Error::InvalidInput(format!(
                "no audit item or claim `{id}` (try `orthocheck audit --all`)"
            )));
        }
    }
    emit(a.json, &items, |items| report::audit_text(items, !a.all))?;
    Ok(())
}
