//! Presentation: renderers of claim results. No computation happens here.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

use serde::Serialize;

use crate::cases::Case;
use crate::check::{run_case, ClaimResult, Verdict};
use crate::error::Result;

/// The paper under audit.
#[derive(Clone, Debug, Serialize)]
pub struct Paper {
    /// Title.
    pub title: &'static str,
    /// Author.
    pub author: &'static str,
}

/// The paper this tool audits.
pub const PAPER: Paper = Paper {
    title: "Distribution of degrees of freedom over structure and motion of rigid bodies",
    author: "Mieczyslaw A. Kłopotek",
};

/// The whole report: what `report.json` holds.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// The paper.
    pub paper: Paper,
    /// Tool name and version.
    pub tool: String,
    /// Every claim result, in case order.
    pub claims: Vec<ClaimResult>,
    /// Count per verdict (every verdict listed, zeros included).
    pub summary: BTreeMap<String, usize>,
}

impl Report {
    /// Build a report from claim results.
    pub fn new(claims: Vec<ClaimResult>) -> Report {
        let mut summary: BTreeMap<String, usize> = Verdict::ALL
            .iter()
            .map(|v| (v.name().to_string(), 0))
            .collect();
        for c in &claims {
            *summary.entry(c.verdict.name().to_string()).or_default() += 1;
        }
        Report {
            paper: PAPER,
            tool: format!("orthocheck {}", env!("CARGO_PKG_VERSION")),
            claims,
            summary,
        }
    }

    /// Run every case.
    pub fn from_cases(cases: &[Case]) -> Result<Report> {
        let mut claims = Vec::new();
        for case in cases {
            claims.extend(run_case(case)?);
        }
        Ok(Report::new(claims))
    }

    /// Pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

    /// Markdown: a summary table of verdict counts, then the claims grouped by section.
    pub fn to_markdown(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "# Reproducibility report\n");
        let _ = writeln!(s, "*{}* — {}\n", self.paper.title, self.paper.author);
        let _ = writeln!(s, "Produced by {}.\n", self.tool);
        let _ = writeln!(s, "## Summary\n\n| verdict | claims |\n|---|---|");
        for v in Verdict::ALL {
            let _ = writeln!(
                s,
                "| {} | {} |",
                v.name(),
                self.summary.get(v.name()).copied().unwrap_or(0)
            );
        }
        let mut sections: BTreeMap<&str, Vec<&ClaimResult>> = BTreeMap::new();
        for c in &self.claims {
            sections.entry(c.section.as_str()).or_default().push(c);
        }
        for (section, claims) in sections {
            let _ = writeln!(s, "\n## Section {section}\n");
            for c in claims {
                s.push_str(&claim_markdown(c));
            }
        }
        s
    }

    /// Write `report.md` and `report.json` into `dir` (created if missing).
    pub fn write(&self, dir: &Path) -> Result<()> {
        let io = |source| crate::error::Error::Io {
            path: dir.to_path_buf(),
            source,
        };
        std::fs::create_dir_all(dir).map_err(io)?;
        std::fs::write(dir.join("report.md"), self.to_markdown()).map_err(io)?;
        std::fs::write(dir.join("report.json"), self.to_json()).map_err(io)?;
        Ok(())
    }
}

/// One claim as Markdown.
pub fn claim_markdown(c: &ClaimResult) -> String {
    let mut s = String::new();
    let _ = writeln!(s, "### `{}` — **{}**\n", c.id, c.verdict.name());
    let _ = writeln!(s, "> {} (lines {})\n", c.quote, c.lines);
    let _ = writeln!(s, "- paper: {}", c.paper_value);
    let _ = writeln!(s, "- computed: {}", c.computed_value);
    if let Some(t) = &c.tolerance {
        let _ = writeln!(s, "- tolerance: {} ({})", t.value, t.source);
    }
    let _ = writeln!(s, "- method: {}", c.evidence.method);
    for d in &c.evidence.details {
        let _ = writeln!(s, "  - {}: {}", d.name, d.value);
    }
    s.push('\n');
    s
}

/// The `dof --table` grid as text: counted against the real (Jacobian) rank.
pub fn dof_table_text(rows: &[crate::derivations::dof::Identifiability]) -> String {
    let mut s = String::from(
        "  p  k  unknowns  measurements  balance  rank  deficiency  count says  rank says\n",
    );
    for r in rows {
        let c = &r.count;
        let _ = writeln!(
            s,
            "{:>3}{:>3}{:>10}{:>14}{:>9}{:>6}{:>12}  {:<10}  {}",
            c.points,
            c.frames,
            c.unknowns,
            c.measurements,
            c.balance,
            r.exact_rank,
            r.deficiency,
            if c.balance >= 0 { "enough" } else { "too few" },
            if r.deficiency == 0 {
                "identifiable"
            } else {
                "ambiguous"
            }
        );
    }
    s
}

/// One `dof` cell as text.
pub fn dof_text(r: &crate::derivations::dof::Identifiability) -> String {
    let c = &r.count;
    format!(
        "points {p}, frames {k}\n\
         unknowns      -1+3p+5(k-1) = {u}\n\
         measurements  2kp          = {m}\n\
         balance                    = {b}\n\
         jacobian rank (svd)        = {jr} of {n} parameters (condition {cond})\n\
         exact rank                 = {er} ({method:?})\n\
         deficiency                 = {d}  ({verdict})\n",
        p = c.points,
        k = c.frames,
        u = c.unknowns,
        m = c.measurements,
        b = c.balance,
        jr = r.jacobian_rank,
        n = r.parameters,
        cond = r
            .condition
            .map_or("- (rank-deficient)".into(), crate::numfmt::sig),
        er = r.exact_rank,
        method = r.exact_method,
        d = r.deficiency,
        verdict = if r.deficiency == 0 {
            "finitely many solutions near this scene".to_string()
        } else {
            format!(
                "a {}-dimensional family of scenes gives the same images",
                r.deficiency
            )
        }
    )
}

/// `orthocheck audit twofold-squared` as text.
pub fn twofold_text(a: &crate::check::TwofoldAudit) -> String {
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
         random rational points: {agree}/{n} agree (seed {seed})\n\
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
