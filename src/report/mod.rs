//! Presentation: renderers of claim results. No computation happens here.
//!
//! The floors, bottom first: [`model`] (the report as data); the shared presentation
//! ([`values`]: the text of every typed value; [`layout`]: order, sections, anchors, verdict
//! groups; [`evidence`]: tables from cells; `words`: the findings' sentences; [`style`]: the
//! verdicts' colours; [`finite`]: the JSON guard); then one module per output ([`html`],
//! [`markdown`], [`svg`]). This module binds them into the report's files.

pub mod argument;
pub mod evidence;
pub mod finite;
pub mod html;
pub mod layout;
pub mod markdown;
pub mod model;
pub mod patch;
pub use crate::mathtext as math;
pub mod style;
pub mod svg;
pub mod values;
mod words;

pub use markdown::{claim_markdown, errata_markdown};
pub use model::Report;
pub use patch::errata_patch;

pub use svg::{figure_svg, plot_svg};

use std::path::Path;

use crate::error::Result;

pub use crate::cases::Paper;
pub use crate::provenance::{CaseSeeds, Provenance};

impl Report {
    /// Markdown, in the same order as the HTML page ([`markdown::render`]).
    pub fn to_markdown(&self) -> String {
        markdown::render(self)
    }

    /// Every file of the report, rendered: `report.md`, `report.json`, `report.html` and
    /// each figure as `<figure id>.svg`, in the order [`Report::write`] writes them.
    pub fn files(&self) -> Result<Vec<(String, String)>> {
        // serde_json would write a NaN as `null`: refuse before any file is touched
        if let Some(bad) = finite::first_non_finite(self) {
            return Err(crate::error::Error::Numerical(format!(
                "report: a non-finite number ({bad}) would reach report.json; nothing was written"
            )));
        }
        let mut files = vec![
            ("report.md".to_string(), self.to_markdown()),
            ("report.json".to_string(), self.to_json()),
            ("report.html".to_string(), html::render(self)),
        ];
        files.extend(svg::figure_files(&self.figures)?);
        Ok(files)
    }

    /// Write [`Report::files`] into `dir` (created if missing). Each file is written to a
    /// temporary name in `dir` first and renamed once all are complete, so a failure leaves
    /// the old report whole; a name in `dir` that is a symbolic link is refused rather than
    /// followed.
    pub fn write(&self, dir: &Path) -> Result<()> {
        prepare_output_dir(dir)?;
        write_all_atomic(dir, &self.files()?)
    }
}

pub use crate::files::{prepare_output_dir, write_all_atomic};
