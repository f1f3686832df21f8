//! Claims of §2.1 and the abstract's minimality and two-frame statements.

use std::collections::BTreeMap;

use num_bigint::BigInt;
use num_rational::BigRational;

use super::{ClaimResult, Evidence, OldTolerance, Power, ResultBuilder, Tolerance, Verdict};
use crate::algebra::Poly;
use crate::cases::{DofCountCase, DofIdentifiabilityCase};
use crate::derivations::dof::{count, identifiability, table, Identifiability};
use crate::error::{Error, Result};
use crate::numfmt::sig;

fn rank_evidence(e: Evidence, r: &Identifiability) -> Evidence {
    e.with(
        "jacobian",
        format!("{} × {}", r.count.measurements, r.parameters),
    )
    .with("svd rank", r.jacobian_rank)
    .with("exact rank", r.exact_rank)
    .with("exact rank method", format!("{:?}", r.exact_method))
    .with("deficiency (dimension of the ambiguity)", r.deficiency)
    .with(
        "condition number",
        r.condition.map_or("— (rank-deficient)".into(), sig),
    )
    .with("scene seed", r.seed)
}

/// The printed worked counts.
pub(super) fn check_count(b: &ResultBuilder, case: &DofCountCase) -> Result<Vec<ClaimResult>> {
    let mut out = Vec::new();
    for ex in &case.examples {
        let c = count(ex.points, ex.frames);
        let printed_u = ex.unknowns.to_integer();
        let printed_m = ex.measurements.to_integer();
        let agree = printed_u == Some(BigInt::from(c.unknowns))
            && printed_m == Some(BigInt::from(c.measurements));
        let r = identifiability(ex.points, ex.frames, case.seed)?;
        let result = b
            .claim(&ex.claim)
            .printed("unknowns", &ex.unknowns)
            .printed("measurements", &ex.measurements)
            .computed("unknowns", c.unknowns)
            .computed("measurements", c.measurements)
            .computed("jacobian rank", r.exact_rank)
            .computed("parameters", r.parameters)
            .computed("deficiency", r.deficiency)
            .tolerance(Tolerance::exact("integer counts"))
            .power(Power::exact_value(&format!(
                "only unknowns {} and measurements {} pass; any other printed integer is contradicted",
                c.unknowns, c.measurements
            )))
            .evidence(rank_evidence(
                Evidence::new("the paper's count evaluated exactly; Jacobian rank at a generic rational scene as the real answer")
                    .with("points", ex.points)
                    .with("frames", ex.frames)
                    .with("balance (measurements − unknowns)", c.balance),
                &r,
            ))
            .verdict(Verdict::holds(agree));
        out.push(result);
    }
    Ok(out)
}

fn parse_formula(text: &str) -> Result<Poly> {
    Poly::parse(text).map_err(|source| Error::Formula {
        formula: text.to_string(),
        source,
    })
}

fn eval_pk(p: &Poly, points: usize, frames: usize) -> Option<BigRational> {
    let values = BTreeMap::from([
        ("p".to_string(), BigRational::from_integer(points.into())),
        ("k".to_string(), BigRational::from_integer(frames.into())),
    ]);
    p.eval(&values)
}

fn cells(list: &[&Identifiability]) -> String {
    if list.is_empty() {
        return "none".into();
    }
    list.iter()
        .map(|r| format!("(p={}, k={})", r.count.points, r.count.frames))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The count formula, the minimum, and two-frame insufficiency, over the grid.
pub(super) fn check_identifiability(
    b: &ResultBuilder,
    case: &DofIdentifiabilityCase,
) -> Result<Vec<ClaimResult>> {
    let grid = table(case.max_points, case.max_frames, case.seed)?;
    let grid_desc = format!(
        "p = 1..{}, k = 1..{}, seed {}",
        case.max_points, case.max_frames, case.seed
    );
    let mut out = Vec::new();
    let cat = |pred: &dyn Fn(&crate::derivations::dof::Identifiability) -> bool| -> Vec<[f64; 2]> {
        grid.iter()
            .filter(|r| pred(r))
            .map(|r| [r.count.points as f64, r.count.frames as f64])
            .collect()
    };
    b.figure(super::figure::Figure {
        id: "fig-dof-grid".into(),
        claim: case.formula.claim.claim.clone(),
        title: "§2.1: the count against the Jacobian rank".into(),
        caption: format!("Every p and k of the grid ({grid_desc}): what the paper's count says, and what the exact rank of the Jacobian decides."),
        panels: vec![super::figure::Plot {
            title: "points and frames".into(),
            x_label: "points p".into(),
            y_label: "frames k".into(),
            equal_aspect: false,
            log_x: false,
            layers: vec![
                super::figure::Layer::new("count: too few", super::figure::Shape::Points, super::figure::Style::Other, cat(&|r| r.count.balance < 0)),
                super::figure::Layer::new("count: enough, rank: ambiguous", super::figure::Shape::Points, super::figure::Style::Mark, cat(&|r| r.count.balance >= 0 && r.deficiency > 0)),
                super::figure::Layer::new("count: enough, rank: identifiable", super::figure::Shape::Points, super::figure::Style::Computed, cat(&|r| r.count.balance >= 0 && r.deficiency == 0)),
            ],
            // room below the grid for the legend
            window: Some((
                [0.5, case.max_points as f64 + 0.5],
                [-2.5, case.max_frames as f64 + 0.5],
            )),
        }],
    });

    // The printed formula against the parametrisation's size, and balance as a necessary
    // (not sufficient) condition.
    let unknowns = parse_formula(&case.formula.unknowns)?;
    let measurements = parse_formula(&case.formula.measurements)?;
    let formula_matches = grid.iter().all(|r| {
        eval_pk(&unknowns, r.count.points, r.count.frames)
            == Some(BigRational::from_integer(r.parameters.into()))
            && eval_pk(&measurements, r.count.points, r.count.frames)
                == Some(BigRational::from_integer(
                    (2 * r.count.points * r.count.frames).into(),
                ))
    });
    let identifiable_unbalanced: Vec<&Identifiability> = grid
        .iter()
        .filter(|r| r.deficiency == 0 && r.count.balance < 0)
        .collect();
    let balanced_deficient: Vec<&Identifiability> = grid
        .iter()
        .filter(|r| r.count.balance >= 0 && r.deficiency > 0)
        .collect();
    let ranks_agree = grid.iter().all(|r| r.jacobian_rank == r.exact_rank);
    out.push(
        b.result(
            &case.formula.claim,
            None,
            Verdict::holds(formula_matches && identifiable_unbalanced.is_empty() && ranks_agree),
            format!(
                "unknowns {}, measurements {}; balance needed",
                case.formula.unknowns, case.formula.measurements
            ),
            format!(
            "the formulas count the Jacobian's columns and rows in every cell: {formula_matches}; \
             identifiable yet unbalanced cells: {}; balance is necessary but not sufficient \
             (balanced yet rank-deficient: {})",
            cells(&identifiable_unbalanced),
            cells(&balanced_deficient)
        ),
            Some(OldTolerance::exact("integer counts and exact ranks")),
            Evidence::new(
                "printed formulas evaluated exactly over the grid; exact Jacobian rank per cell",
            )
            .with("grid", &grid_desc)
            .with("float rank = exact rank in every cell", ranks_agree),
        ),
    );

    // The minimum: the smallest p and k with deficiency 0, among bodies with a shape (p ≥ 2).
    // A single point has nothing to recover but its image position, so (p=1, k=1) is
    // trivially "identifiable" and says nothing about structure and motion.
    let identifiable: Vec<&Identifiability> = grid
        .iter()
        .filter(|r| r.deficiency == 0 && r.count.points >= 2)
        .collect();
    let trivial: Vec<&Identifiability> = grid
        .iter()
        .filter(|r| r.deficiency == 0 && r.count.points < 2)
        .collect();
    let min_p = identifiable.iter().map(|r| r.count.points).min();
    let min_k = identifiable.iter().map(|r| r.count.frames).min();
    let claimed_ok = grid.iter().any(|r| {
        r.count.points == case.minimum.points
            && r.count.frames == case.minimum.frames
            && r.deficiency == 0
    });
    let minimal = min_p == Some(case.minimum.points) && min_k == Some(case.minimum.frames);
    out.push(b.result(
        &case.minimum.claim,
        None,
        Verdict::holds(claimed_ok && minimal),
        format!(
            "{} points and {} frames are the minimum",
            case.minimum.points, case.minimum.frames
        ),
        format!(
            "smallest identifiable p = {}, smallest identifiable k = {}; (p={}, k={}) identifiable: {}",
            min_p.map_or("none".into(), |v| v.to_string()),
            min_k.map_or("none".into(), |v| v.to_string()),
            case.minimum.points,
            case.minimum.frames,
            claimed_ok
        ),
        Some(OldTolerance::exact("exact ranks")),
        Evidence::new("deficiency 0 (finitely many solutions near a generic scene) decided by exact Jacobian rank over the grid")
            .with("grid", &grid_desc)
            .with("identifiable cells (p ≥ 2)", cells(&identifiable))
            .with("excluded single-point cells with deficiency 0 (nothing to recover)", cells(&trivial)),
    ));

    // Two frames: deficient for every p, although the count balances from p = 4.
    let two: Vec<&Identifiability> = grid.iter().filter(|r| r.count.frames == 2).collect();
    let all_deficient = two.iter().all(|r| r.deficiency > 0);
    let balanced_two: Vec<&Identifiability> = two
        .iter()
        .copied()
        .filter(|r| r.count.balance >= 0)
        .collect();
    let deficiencies: Vec<String> = two
        .iter()
        .map(|r| format!("p={}: {}", r.count.points, r.deficiency))
        .collect();
    out.push(
        b.result(
            &case.two_frames,
            None,
            Verdict::holds(all_deficient),
            "no number of points recovers structure and motion from two frames".into(),
            format!(
            "k = 2 is rank-deficient for every p in the grid, although the count balances for {}",
            cells(&balanced_two)
        ),
            Some(OldTolerance::exact("exact ranks")),
            Evidence::new("exact Jacobian rank for k = 2 and each p of the grid")
                .with("grid", &grid_desc)
                .with("deficiency by p", deficiencies.join("; ")),
        ),
    );
    Ok(out)
}
