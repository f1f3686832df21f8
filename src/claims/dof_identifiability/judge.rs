//! Claims of §2.1 and the abstract's minimality and two-frame statements.

use crate::algebra::Poly;
use crate::check::figure::{Figure, Layer, Plot, Shape, Style};
use crate::check::{ClaimBuilder, ClaimResult, Power, ResultBuilder, Tolerance, Value, Verdict};
use crate::claims::dof_identifiability::DofIdentifiabilityCase;
use crate::derivations::dof::{
    deficient_for_every_p, formulas_count_the_jacobian, identifiable_at, is_minimum,
    smallest_identifiable, table, Identifiability, SHAPE_POINTS,
};
use crate::error::{Error, Result};

fn parse_formula(text: &str) -> Result<Poly> {
    Poly::parse(text).map_err(|source| Error::Formula {
        formula: text.to_string(),
        source,
    })
}

/// The claim "no number of points suffices" is about two frames; the number is the claim's.
const TWO_FRAMES: usize = 2;

fn cells<'b>(b: ClaimBuilder<'b>, name: &str, list: &[&Identifiability]) -> ClaimBuilder<'b> {
    if list.is_empty() {
        return b.detail(name, Value::label("none"));
    }
    list.iter().fold(b, |b, r| {
        b.detail(
            name,
            Value::label(format!("(p={}, k={})", r.count.points, r.count.frames)),
        )
    })
}

fn grid_details<'b>(b: ClaimBuilder<'b>, case: &DofIdentifiabilityCase) -> ClaimBuilder<'b> {
    b.cell("grid", "largest p", case.max_points)
        .cell("grid", "largest k", case.max_frames)
        .cell("grid", "scene seed", case.seed)
}

fn figure(b: &ResultBuilder, case: &DofIdentifiabilityCase, grid: &[Identifiability]) {
    let cat = |pred: &dyn Fn(&Identifiability) -> bool| -> Vec<[f64; 2]> {
        grid.iter()
            .filter(|r| pred(r))
            .map(|r| [r.count.points as f64, r.count.frames as f64])
            .collect()
    };
    b.figure(Figure {
        id: "fig-dof-grid".into(),
        claim: case.formula.claim.claim.clone(),
        title: "§2.1: the count against the Jacobian rank".into(),
        caption: format!(
            "Every p and k of the grid (p = 1..{}, k = 1..{}, seed {}): what the paper's count says, and what the exact rank of the Jacobian decides. A single point has no shape: its full rank says nothing about structure or motion.",
            case.max_points, case.max_frames, case.seed
        ),
        panels: vec![Plot {
            title: "points and frames".into(),
            x_label: "points p".into(),
            y_label: "frames k".into(),
            equal_aspect: false,
            log_x: false,
            log_y: false,
            layers: vec![
                Layer::new("more df than information", Shape::Points, Style::Other, cat(&|r| r.count.balance < 0)),
                Layer::new("balance holds, not recoverable", Shape::Points, Style::Mark, cat(&|r| r.count.balance >= 0 && r.deficiency > 0)),
                Layer::new("recoverable", Shape::Points, Style::Computed, cat(&|r| r.count.balance >= 0 && r.deficiency == 0 && r.count.points >= SHAPE_POINTS)),
                // a single point has no shape: its full rank identifies nothing but its image
                Layer::new("one point: no shape", Shape::Points, Style::Third, cat(&|r| r.count.balance >= 0 && r.count.points < SHAPE_POINTS)),
            ],
            window: Some((
                [0.5, case.max_points as f64 + 0.5],
                [0.5, case.max_frames as f64 + 0.5],
            )),
        }],
    });
}

/// The judge of the count formula: it counts the Jacobian in every cell, the float and exact
/// ranks agree, and no identifiable cell is unbalanced (balance is necessary).
fn formula_holds(counts: bool, ranks_agree: bool, identifiable_unbalanced: usize) -> bool {
    counts && ranks_agree && identifiable_unbalanced == 0
}

fn formula_claim(
    b: &ResultBuilder,
    case: &DofIdentifiabilityCase,
    grid: &[Identifiability],
) -> Result<ClaimResult> {
    let unknowns = parse_formula(&case.formula.unknowns)?;
    let measurements = parse_formula(&case.formula.measurements)?;
    let counts = formulas_count_the_jacobian(grid, &unknowns, &measurements);
    // the mutant: the coefficient of k in the unknowns raised by one
    let mutant = &unknowns + &Poly::var("k");
    let mutant_counts = formulas_count_the_jacobian(grid, &mutant, &measurements);
    let unbalanced: Vec<&Identifiability> = grid
        .iter()
        .filter(|r| r.deficiency == 0 && r.count.balance < 0)
        .collect();
    let balanced_deficient: Vec<&Identifiability> = grid
        .iter()
        .filter(|r| r.count.balance >= 0 && r.deficiency > 0)
        .collect();
    let ranks_agree = grid.iter().all(|r| r.jacobian_rank == r.exact_rank);
    let holds = formula_holds(counts, ranks_agree, unbalanced.len());
    let r = b
        .claim(&case.formula.claim)
        .printed("unknowns", Value::formula(case.formula.unknowns.clone()))
        .printed("measurements", Value::formula(case.formula.measurements.clone()))
        .computed("the formulas count the Jacobian's columns and rows in every cell", counts)
        .computed("identifiable yet unbalanced cells", unbalanced.len())
        .computed("balanced yet rank-deficient cells (balance is necessary, not sufficient)", balanced_deficient.len())
        .tolerance(Tolerance::exact("integer counts and exact ranks"))
        .power(Power::mutant(
            !formula_holds(mutant_counts, ranks_agree, unbalanced.len()),
            &format!("the unknowns formula with the coefficient of k raised by one ({mutant}): it no longer counts the Jacobian's columns"),
        ))
        .method("printed formulas evaluated exactly over the grid; exact Jacobian rank per cell")
        .detail("float rank = exact rank in every cell", ranks_agree);
    let r = cells(
        grid_details(r, case),
        "identifiable yet unbalanced",
        &unbalanced,
    );
    Ok(cells(r, "balanced yet rank-deficient", &balanced_deficient).verdict(Verdict::holds(holds)))
}

fn minimum_claim(
    b: &ResultBuilder,
    case: &DofIdentifiabilityCase,
    grid: &[Identifiability],
) -> ClaimResult {
    let (p, k) = (case.minimum.points, case.minimum.frames);
    let (min_p, min_k) = smallest_identifiable(grid);
    // the same check for a claimed minimum one frame or one point smaller
    let fewer_frames = is_minimum(grid, p, k.saturating_sub(1));
    let fewer_points = is_minimum(grid, p.saturating_sub(1), k);
    let trivial: Vec<&Identifiability> = grid
        .iter()
        .filter(|r| r.deficiency == 0 && r.count.points < SHAPE_POINTS)
        .collect();
    let identifiable: Vec<&Identifiability> = grid
        .iter()
        .filter(|r| r.deficiency == 0 && r.count.points >= SHAPE_POINTS)
        .collect();
    let opt = |v: Option<usize>| v.map_or(Value::label("none"), Value::count);
    let r = b
        .claim(&case.minimum.claim)
        .printed("points", case.minimum.points)
        .printed("frames", case.minimum.frames)
        .computed("smallest identifiable p", opt(min_p))
        .computed("smallest identifiable k", opt(min_k))
        .computed("the printed cell is identifiable", identifiable_at(grid, p, k))
        .tolerance(Tolerance::exact("exact ranks"))
        .power(Power::mutant(
            !fewer_frames && !fewer_points,
            "a claimed minimum of one frame fewer, or of one point fewer, than printed: the same check rejects both",
        ))
        .method("deficiency 0 (finitely many solutions near a generic scene) decided by exact Jacobian rank over the grid, among bodies with a shape (p ≥ 2)")
        .detail("mutant with one frame fewer accepted", fewer_frames)
        .detail("mutant with one point fewer accepted", fewer_points);
    let r = cells(
        grid_details(r, case),
        "identifiable cell (p ≥ 2)",
        &identifiable,
    );
    cells(
        r,
        "excluded single-point cell with deficiency 0 (nothing to recover)",
        &trivial,
    )
    .verdict(Verdict::holds(is_minimum(grid, p, k)))
}

fn two_frames_claim(
    b: &ResultBuilder,
    case: &DofIdentifiabilityCase,
    grid: &[Identifiability],
) -> ClaimResult {
    let two: Vec<&Identifiability> = grid
        .iter()
        .filter(|r| r.count.frames == TWO_FRAMES)
        .collect();
    let balanced: Vec<&Identifiability> = two
        .iter()
        .copied()
        .filter(|r| r.count.balance >= 0)
        .collect();
    let holds = deficient_for_every_p(grid, TWO_FRAMES);
    let mutant_holds = deficient_for_every_p(grid, TWO_FRAMES + 1);
    let mut r = b
        .claim(&case.two_frames)
        .printed("statement", Value::label(case.two_frames.quote.clone()))
        .computed("rank-deficient for every p of the grid", holds)
        .computed("cells where the count balances nevertheless", balanced.len())
        .tolerance(Tolerance::exact("exact ranks"))
        .power(Power::mutant(
            !mutant_holds,
            "the same statement for one frame more: the same check rejects it (some p is identifiable)",
        ))
        .method("exact Jacobian rank for two frames and each p of the grid");
    r = grid_details(r, case);
    for c in &two {
        r = r
            .detail("p", c.count.points)
            .detail("deficiency", c.deficiency);
    }
    r.verdict(Verdict::holds(holds))
}

/// The count formula, the minimum, and two-frame insufficiency, over the grid.
pub(super) fn results(
    b: &ResultBuilder,
    case: &DofIdentifiabilityCase,
) -> Result<Vec<ClaimResult>> {
    let grid = table(case.max_points, case.max_frames, case.seed)?;
    figure(b, case, &grid);
    Ok(vec![
        formula_claim(b, case, &grid)?,
        minimum_claim(b, case, &grid),
        two_frames_claim(b, case, &grid),
    ])
}

#[cfg(test)]
mod tests {
    use super::formula_holds;

    #[test]
    fn the_formula_judge_on_both_sides() {
        assert!(formula_holds(true, true, 0));
        assert!(!formula_holds(false, true, 0));
        assert!(!formula_holds(true, false, 0));
        assert!(!formula_holds(true, true, 1));
    }
}
