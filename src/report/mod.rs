//! Presentation: renderers of claim results. No computation happens here.

pub mod evidence;
mod findings;
pub mod finite;
pub mod glance;
pub mod html;
pub mod layout;
pub mod markdown;
pub use crate::mathtext as math;
pub mod style;
pub mod svg;
pub mod values;

pub use markdown::claim_markdown;

pub use svg::{figure_svg, plot_svg};

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

use serde::Serialize;

use crate::check::Role;
use crate::check::{ClaimResult, Verdict};
use crate::error::Result;

pub use crate::cases::Paper;
pub use crate::provenance::{CaseSeeds, Provenance};

/// The whole report: what `report.json` holds.
#[derive(Clone, Debug, Serialize)]
pub struct Report {
    /// The paper, as its cases folder names it ([`crate::cases::load_paper`]); none for a
    /// report built from claims alone.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub paper: Option<Paper>,
    /// Tool name and version.
    pub tool: String,
    /// Revision, date, command, seeds.
    pub provenance: Provenance,
    /// Every claim result, in case order.
    pub claims: Vec<ClaimResult>,
    /// The figures the checks drew, as data.
    pub figures: Vec<crate::check::figure::Figure>,
    /// Count per verdict (every verdict listed, zeros included).
    pub summary: BTreeMap<String, usize>,
}

impl Report {
    /// Build a report from claim results.
    pub fn new(claims: Vec<ClaimResult>) -> Report {
        Report::with(claims, Vec::new(), Provenance::default())
    }

    /// Build a report from claim results, figures and provenance.
    pub fn with(
        claims: Vec<ClaimResult>,
        figures: Vec<crate::check::figure::Figure>,
        provenance: Provenance,
    ) -> Report {
        let mut summary: BTreeMap<String, usize> = Verdict::ALL
            .iter()
            .map(|v| (v.name().to_string(), 0))
            .collect();
        for c in &claims {
            *summary.entry(c.verdict.name().to_string()).or_default() += 1;
        }
        Report {
            paper: None,
            tool: format!("orthocheck {}", env!("CARGO_PKG_VERSION")),
            provenance,
            claims,
            figures,
            summary,
        }
    }

    /// The report of the paper's run, with `provenance` completed by the run's seeds (and
    /// the report command, when it names none).
    pub fn from_run(run: crate::claims::PaperRun, mut provenance: Provenance) -> Report {
        if provenance.command.is_empty() {
            provenance.command = crate::provenance::REPORT_COMMAND.into();
        }
        provenance.seeds = run.seeds;
        Report::with(run.results, run.figures, provenance)
    }

    /// The same report, naming its paper.
    pub fn with_paper(self, paper: Paper) -> Report {
        Report {
            paper: Some(paper),
            ..self
        }
    }

    /// Pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }

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
         exact rank                 = {er} ({method})\n\
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
        method = r.exact_method.describe(),
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

/// `orthocheck solve --json`: `{"method", "why", "solutions": [{"squared_edges": {"PQ": …},
/// "feasible", "reason", "residual", …}], "degenerate": null | "…", "condition"}`.
pub fn solve_json(s: &crate::derivations::solver::Solved) -> serde_json::Value {
    use serde_json::{json, Map, Value};
    let o = &s.output;
    let solutions: Vec<Value> = o
        .solutions
        .iter()
        .zip(&s.structures)
        .map(|(sol, st)| {
            let edges: Map<String, Value> = o
                .edges
                .iter()
                .zip(&sol.squared_edges)
                .map(|(n, v)| (n.clone(), json!(v)))
                .collect();
            let mut v = json!({
                "squared_edges": edges,
                "feasible": sol.feasibility.is_feasible(),
                "reason": sol.feasibility.reason(),
                "residual": sol.residual,
                "error_bound": sol.error_bound,
            });
            if sol.imaginary.iter().any(|x| *x != 0.0) {
                let im: Map<String, Value> = o
                    .edges
                    .iter()
                    .zip(&sol.imaginary)
                    .map(|(n, v)| (n.clone(), json!(v)))
                    .collect();
                v["imaginary"] = Value::Object(im);
            }
            if let Some(st) = st {
                v["structure"] = json!(st);
            }
            v
        })
        .collect();
    json!({
        "method": o.method,
        "why": s.why,
        "solutions": solutions,
        "degenerate": o.degenerate.map(|d| d.to_string()),
        "condition": o.condition,
        "validation": s.validation,
    })
}

/// The comment block `orthocheck synth` writes above the tracks: how to make them again, and
/// the truth to compare a solve with.
pub fn synth_header(scene: &crate::model::Scene, seed: u64, noise: Option<f64>) -> String {
    // The edges among the first points only: a header listing all p(p−1)/2 edges of a large
    // scene would outgrow the tracks themselves (10,000 points: 49,995,000 edges, ~1 GB).
    const LISTED_POINTS: usize = 10;
    let b = &scene.body;
    let p = b.points.len();
    let shown = p.min(LISTED_POINTS);
    let truth: Vec<String> = crate::derivations::solver::edges(shown)
        .iter()
        .map(|&(i, j)| {
            format!(
                "{}={}",
                crate::derivations::solver::edge_name(&b.names[i], &b.names[j]),
                crate::numfmt::sig(b.squared_distance(i, j))
            )
        })
        .collect();
    let label = if shown == p {
        "true squared edges".to_string()
    } else {
        format!(
            "true squared edges among the first {shown} points ({} of {}; the same seed gives the rest)",
            truth.len(),
            p * (p - 1) / 2
        )
    };
    format!(
        "# orthocheck synth --points {p} --frames {} --seed {seed}{}\n# {label}: {}\n",
        scene.motions.len(),
        noise.map_or(String::new(), |e| format!(" --noise {e}")),
        truth.join(" ")
    )
}

/// The errata list (Markdown): every claim result whose verdict is `erratum`, `contradicted`
/// or `holds-generically` (an exception the paper never names), in report order — what
/// `docs/errata.md` holds.
pub fn errata_markdown(claims: &[ClaimResult]) -> String {
    let mut s = String::from(
        "# Errata\n\nGenerated by `orthocheck audit --all --markdown` from `paper_cases/`; do not edit.\n\
         Every entry is decided by computation; the report gives the method and the evidence.\n",
    );
    for c in claims.iter().filter(|c| {
        matches!(
            c.verdict,
            Verdict::Erratum | Verdict::Contradicted | Verdict::HoldsGenerically
        )
    }) {
        let _ = write!(
            s,
            "\n## `{}` — {} (§{}, lines {})\n\n- printed: {}\n",
            c.id,
            c.verdict.name(),
            c.section,
            c.lines,
            values::printed_text(c)
        );
        for d in c
            .evidence
            .details
            .iter()
            .filter(|d| matches!(d.role, Role::Defect | Role::ShouldBe))
        {
            let _ = writeln!(s, "- {}: {}", d.name, values::value_text(&d.value));
        }
        if let Some(corr) = &c.correction {
            let _ = writeln!(s, "- corrected: {corr}");
        }
        let _ = writeln!(s, "- found: {}", values::computed_text(c));
    }
    s
}

/// One point of `orthocheck membership`.
#[derive(Clone, Debug, Serialize)]
pub struct MemberRow {
    /// The point's name.
    pub point: String,
    /// Whether it belongs to the body.
    pub member: bool,
    /// Its epipolar distance, relative to the image size.
    pub distance: f64,
}

/// `orthocheck membership` as text.
pub fn membership_text(rows: &[MemberRow], tolerance: f64, from_data: bool) -> String {
    use crate::numfmt::sig;
    let mut s = format!(
        "members: epipolar distance at most {} of the image size{}\n",
        sig(tolerance),
        if from_data {
            " (from the data: 3 robust standard deviations of the distances; --tolerance sets it)"
        } else {
            ""
        }
    );
    for r in rows {
        let _ = writeln!(
            s,
            "{:<6} {:<9} {}",
            r.point,
            if r.member { "member" } else { "outside" },
            sig(r.distance)
        );
    }
    s
}

/// One member of the two-frame family, for display.
#[derive(Clone, Debug, Serialize)]
pub struct FamilyMember {
    /// The angle between the views.
    pub beta: f64,
    /// The points, named.
    pub points: Vec<(String, [f64; 3])>,
    /// Largest reprojection error (relative).
    pub reprojection: f64,
}

/// The family as shown: names with coordinates.
pub fn family_view(
    names: &[String],
    members: &[crate::derivations::two_frames::Member],
) -> Vec<FamilyMember> {
    members
        .iter()
        .map(|m| FamilyMember {
            beta: m.beta,
            points: names
                .iter()
                .zip(&m.points)
                .map(|(n, p)| (n.clone(), [p.x, p.y, p.z]))
                .collect(),
            reprojection: m.reprojection,
        })
        .collect()
}

/// `orthocheck family` as text.
pub fn family_text(members: &[FamilyMember]) -> String {
    use crate::numfmt::{below, sig, sig_list};
    let mut s = String::from(
        "members of the family of bodies both frames allow (frame 1's camera coordinates; the depth is fixed up to a shift)\n",
    );
    for m in members {
        let _ = writeln!(
            s,
            "β = {} rad (reprojection {}):",
            sig(m.beta),
            below(m.reprojection)
        );
        for (n, p) in &m.points {
            let _ = writeln!(s, "  {n:<6} {}", sig_list(p));
        }
    }
    s
}
