//! `orthocheck audit`: the paper's printed formulas, machine-checked.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use crate::check::{ClaimResult, Verdict};
use crate::claims::audit::{InFull, Shown, Wanted};
use crate::claims::shared::Place;
use crate::claims::twofold_squared::TwofoldAudit;
use crate::claims::{CaseCheck, PaperCase};
use crate::report::values::quantities_text;
use crate::{cases, report, Error};
use serde::Serialize;

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
fn export(loaded: &[PaperCase], a: &Args, dir: &Path) -> Result<(), Error> {
    let mut scripts = Vec::new();
    for case in loaded {
        scripts.extend(case.check.kind().sympy_scripts()?);
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
    // every name checked first without following links; nothing written on refusal
    let files: Vec<(String, String)> = scripts
        .iter()
        .map(|s| (s.file.clone(), s.source.clone()))
        .collect();
    crate::files::write_new_set(dir, &files)?;
    let mut listing = String::new();
    for s in &scripts {
        listing.push_str(&format!("{}  {}\n", s.id, dir.join(&s.file).display()));
    }
    out(&listing)
}

/// What the case named `id` shows in full, if `id` names a case that does.
fn in_full(loaded: &[PaperCase], id: &str) -> Option<Result<InFull, Error>> {
    loaded
        .iter()
        .filter(|c| c.id == id)
        .find_map(|c| c.check.kind().audit_in_full())
}

/// One twofold-squared case in full, the errata list, or the items an id names.
pub fn run(a: Args) -> Result<(), Error> {
    let origin = cases::CaseOrigin::from_arg(a.cases.as_deref());
    let audited = crate::claims::audited_kinds();
    let source = cases::source_path(a.paper.as_deref());
    // the errata list runs the whole paper; the items need the audited kinds' cases only
    let kinds = match a.markdown {
        true => cases::Kinds::All,
        false => cases::Kinds::Only(&audited),
    };
    let inputs = cases::load_inputs_of::<CaseCheck>(&origin, source.as_deref(), kinds)?;
    let loaded = &inputs.cases;
    if let Some(dir) = &a.out {
        return export(loaded, &a, dir);
    }
    if a.markdown {
        let run = crate::claims::run_paper(&inputs, &|_, _| {})?;
        let r = crate::report::Report::from_run(run, Default::default());
        out(&report::errata_markdown(&r.claims))?;
        return Ok(());
    }
    if let Some(full) = a.id.as_deref().and_then(|id| in_full(loaded, id)) {
        match full? {
            InFull::TwofoldSquared(audit) => emit(a.json, &audit, twofold_text)?,
        }
        return Ok(());
    }
    let wanted = a.id.as_deref().map_or(Wanted::All, Wanted::Id);
    let mut items: Vec<AuditItem> = crate::claims::audit::audit_all(loaded, wanted)?
        .into_iter()
        .map(|(r, s)| item(&r, s))
        .collect();
    if let Some(id) = &a.id {
        items.retain(|it| &it.id == id || &it.claim == id);
        if items.is_empty() {
            return Err(Error::InvalidInput(format!(
                "no audit item or claim `{id}` (try `orthocheck audit --all`)"
            )));
        }
    }
    emit(a.json, &items, |items| audit_text(items, !a.all))?;
    Ok(())
}

/// `orthocheck audit twofold-squared` as text.
fn twofold_text(a: &TwofoldAudit) -> String {
    let ratios: Vec<String> = a
        .ratios
        .iter()
        .map(|r| r.clone().unwrap_or_else(|| "not a multiple".into()))
        .collect();
    format!(
        "eq. p3f3sqr (twofold squaring of ±√(a²−aᵢ²) ± √(b²−bᵢ²) ± √(c²−cᵢ²) = 0)\n\
         printed:  {transcription} = 0\n\
         expanded: {printed} = 0\n\
         derived:  {derived} = 0\n\
         method:   symbolic squaring with √A, √B, √C as variables, (√X)² = X; exact expansion over ℚ\n\
         derived / printed per sign pattern: {ratios}\n\
         product over the four sign classes / printed: {prod}\n\
         quadratic in a², b², c²: {quad}\n\
         random points (modulo primes): {agree}/{n} agree (seed {seed})\n\
         verdict:  {verdict}\n",
        transcription = a.transcription,
        printed = a.printed,
        derived = a.derived,
        ratios = ratios.join(", "),
        prod = a.product_ratio.clone().unwrap_or_else(|| "not a multiple".into()),
        quad = a.quadratic_in_squares,
        agree = a.evaluation.2,
        n = a.evaluation.0,
        seed = a.evaluation.1,
        verdict = a.verdict.name()
    )
}

/// `orthocheck audit` as text: one block per item when `detailed`, else one line each.
fn audit_text(items: &[AuditItem], detailed: bool) -> String {
    let mut s = String::new();
    for it in items {
        if detailed {
            let _ = writeln!(s, "{} — {}", it.id, it.verdict.name());
            let _ = writeln!(s, "  where:     {} (lines {})", it.place, it.lines);
            let _ = writeln!(s, "  printed:   {}", it.printed);
            if let Some(d) = &it.defect {
                let _ = writeln!(s, "  defect:    {d}");
            }
            let _ = writeln!(s, "  should be: {}", it.should_be);
            let _ = writeln!(s, "  method:    {}", it.method);
            let _ = writeln!(s, "  found:     {}", it.finding);
            let _ = writeln!(s, "  verdict:   {}\n", it.verdict.name());
        } else {
            let _ = writeln!(s, "{:<26} {}", it.verdict.name(), it.id);
        }
    }
    if !detailed {
        let counts: Vec<String> = counts(items)
            .iter()
            .map(|(v, n)| format!("{}: {n}", v.name()))
            .collect();
        let _ = writeln!(s, "\n{} items; {}", items.len(), counts.join(", "));
    }
    s
}

/// One audited item: what `orthocheck audit` prints.
#[derive(Clone, Debug, Serialize)]
pub struct AuditItem {
    /// The result id (`claim/suffix`).
    pub id: String,
    /// The claim id (paper_cases/claims.md).
    pub claim: String,
    /// Where it is.
    #[serde(rename = "where")]
    pub place: Place,
    /// Lines.
    pub lines: String,
    /// As printed.
    pub printed: String,
    /// The defect, if any.
    pub defect: Option<String>,
    /// What it should be.
    pub should_be: String,
    /// How it was checked.
    pub method: String,
    /// What the check found.
    pub finding: String,
    /// The verdict.
    pub verdict: Verdict,
}

fn item(r: &ClaimResult, s: Shown) -> AuditItem {
    AuditItem {
        id: r.id.clone(),
        claim: r.claim.clone(),
        place: s.place,
        lines: r.lines.clone(),
        printed: s.printed,
        defect: s.defect,
        should_be: s.should_be,
        method: r.evidence.method.clone(),
        finding: quantities_text(&r.computed),
        verdict: r.verdict,
    }
}

/// Verdict counts for the audit, in report order.
fn counts(items: &[AuditItem]) -> Vec<(Verdict, usize)> {
    Verdict::ALL
        .iter()
        .map(|v| (*v, items.iter().filter(|i| i.verdict == *v).count()))
        .filter(|(_, n)| *n > 0)
        .collect()
}
