//! `orthocheck audit`: the paper's printed formulas, machine-checked.

use std::path::PathBuf;

use orthocheck::cases::{Case, CaseCheck, TwofoldCase};
use orthocheck::report::Report;
use orthocheck::{cases, check, report, Error};

use super::{emit, out};

/// Arguments of `audit`.
#[derive(clap::Args)]
pub struct Args {
    /// An item id (p3f3sqr, appA-coefficients/f_cb, …) or a claim id (all its items);
    /// `twofold-squared` shows eq. p3f3sqr in full.
    #[arg(required_unless_present = "all")]
    id: Option<String>,
    /// Every item.
    #[arg(long, conflicts_with = "id")]
    all: bool,
    /// Folder of case files (the printed formulas are read from there).
    #[arg(long, default_value = "paper_cases")]
    cases: PathBuf,
    /// JSON output.
    #[arg(long)]
    json: bool,
    /// The errata list of the whole report as Markdown (what docs/errata.md holds).
    #[arg(long, conflicts_with_all = ["json", "id"])]
    markdown: bool,
}

/// The twofold-squared case named `id`, if `id` names one: it is shown in full.
fn twofold_case<'a>(loaded: &'a [Case], id: &str) -> Option<&'a TwofoldCase> {
    loaded.iter().find_map(|c| match &c.check {
        CaseCheck::TwofoldSquared(t) if c.id == id => Some(t),
        _ => None,
    })
}

/// One twofold-squared case in full, the errata list, or the items an id names.
pub fn run(a: Args) -> Result<(), Error> {
    let loaded = cases::load_all(&a.cases)?;
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
