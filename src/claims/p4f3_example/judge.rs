//! Claims of §4: the edge table, the figure, the printed coefficient matrix and solution,
//! the conditioning, and the uniqueness of the linear system. Computation lives in
//! `study`, `printed_matrix` and `studies::census`; here the verdicts.

use crate::cases::Printed;
use crate::check::figure::{Figure, Layer, Plot, Shape, Style};
use crate::check::noise::metric_phrase;
use crate::check::Role;
use crate::check::{
    alternative_verdict, excluded_by, ClaimBuilder, ClaimResult, Power, ResultBuilder, Tolerance,
    ToleranceSource, Value, Verdict,
};
use crate::claims::p4f3_example::joint as p4f3_joint;
use crate::claims::p4f3_example::study::{self as ex4, Conditioning, FigureFit, SolutionCheck};
use crate::claims::p4f3_example::P4f3ExampleCase;
use crate::claims::shared::{setting, Context};
use crate::derivations::noise::{LevelResult, Study, METRICS};
use crate::derivations::solver::default_edge_names;
use crate::error::Result;
use crate::model::Body;
use crate::studies::noise::run_both;
use crate::studies::printed_matrix::{self, Audit};
use crate::studies::rounding::Acceptance;
use crate::studies::rounding::RoundingBox;

/// A noise claim of "sensitivity" holds when the median relative error of the worst squared
/// edge is at least this many times the relative coordinate error ε (an order of magnitude:
/// docs/verdicts.md).
const SENSITIVE_AMPLIFICATION: f64 = 10.0;

/// Half a unit in the last significant digit printed, or 0 for a printed exact zero (the
/// matrix's structural zeros).
fn half(p: &Printed, digits: u32) -> f64 {
    if p.to_f64() == 0.0 {
        0.0
    } else {
        p.half_unit_significant(digits)
    }
}

/// Whether every |value| ≤ its bound.
fn all_within(values: &[f64], bounds: &[f64]) -> bool {
    values.len() == bounds.len() && values.iter().zip(bounds).all(|(v, b)| v.abs() <= *b)
}

/// The verdict on a matrix audit: a witness and every mutant rejected.
fn matrix_verdict(witness: bool) -> Verdict {
    if witness {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Contradicted
    }
}

/// Whether a system amplifies relative error ε into `median_error` by the sensitivity rule.
fn sensitive(median_error: f64, eps: f64) -> bool {
    median_error >= SENSITIVE_AMPLIFICATION * eps
}

pub(super) fn results(b: &ResultBuilder, case: &P4f3ExampleCase) -> Result<Vec<ClaimResult>> {
    let digits = case.body.significant_digits.unwrap_or(6);
    let squares: Vec<f64> = case.body.squares.iter().map(Printed::to_f64).collect();
    let sq_half: Vec<f64> = case
        .body
        .squares
        .iter()
        .map(|s| s.half_unit_significant(digits))
        .collect();
    let (center, halves) = case.figure.rounding_box();
    let figure_box = RoundingBox {
        center,
        half: halves,
    };
    let fit = ex4::figure_fit(&figure_box, &squares, &sq_half);
    let mdig = case.matrix.significant_digits;
    let rows: Vec<[f64; 7]> = case
        .matrix
        .rows
        .iter()
        .map(|r| std::array::from_fn(|j| r[j].to_f64()))
        .collect();
    let rh: Vec<[f64; 7]> = case
        .matrix
        .rows
        .iter()
        .map(|r| std::array::from_fn(|j| half(&r[j], mdig)))
        .collect();
    let shared = p4f3_joint::Shared {
        figure_box: &figure_box,
        rows: &rows,
        half: &rh,
    };
    let fs = p4f3_joint::figure_system_of(case, &shared);
    let mut out = vec![
        p4f3_joint::body_result(b, case, &shared),
        figure_result(b, case, &fit, &sq_half, &figure_box, fs.x.as_ref()),
    ];
    out.extend(p4f3_joint::figure_system_result(b, case, &fs));
    figure(b, case, &figure_box, &fit);
    let audit = printed_matrix::audit(&printed_matrix::PrintedSystem {
        figure_box: &figure_box,
        points: 4,
        rows: &rows,
        half: &rh,
        mutant_half_units: &case.matrix_mutant_half_units,
    });
    out.push(matrix_result(b, case, &audit));
    let xs = &case.solution.values[0];
    let sdig = case.solution.significant_digits;
    let x: Vec<f64> = xs.iter().map(Printed::to_f64).collect();
    let xh: Vec<f64> = xs.iter().map(|p| p.half_unit_significant(sdig)).collect();
    let aq: Vec<Vec<_>> = case
        .matrix
        .rows
        .iter()
        .map(|r| r.iter().map(|p| p.value.clone()).collect())
        .collect();
    let sol = ex4::solution_check(&aq, &rh, &x, &xh);
    out.push(solution_result(b, case, &sol, (&x, &xh), fs.x.as_ref()));
    let levels: Vec<f64> = case.noise.iter().map(|l| l.level.to_f64()).collect();
    let cond = fit
        .witness
        .as_ref()
        .map(|w| ex4::conditioning(&w.point, &squares, &levels, case.trials, case.seed));
    out.push(conditioning_result(b, case, cond.as_ref(), sol.condition));
    let scene_results: Vec<LevelResult> = cond
        .map(|c| c.levels.into_iter().map(|l| l.2).collect())
        .unwrap_or_default();
    out.extend(noise_results(
        b,
        case,
        &fit.realization.points,
        &squares,
        &scene_results,
    ));
    Ok(out)
}

/// The acceptance interval of the widest of `acc` as a power statement (allowed: one half unit).
fn widest_power(acc: &[Acceptance], values: &[f64], units: &[f64], what: &str) -> Power {
    let k = (0..acc.len())
        .max_by(|x, y| acc[*x].outer().total_cmp(&acc[*y].outer()))
        .unwrap_or(0);
    match acc.get(k) {
        Some(a) => {
            let (lo, hi) = a.interval(values[k], units[k]);
            Power::interval(lo, hi, values[k], units[k], &format!("{what} {}: the same search with it moved along the ladder of half units fails first at this interval", k + 1))
        }
        None => Power::none("no acceptance computed"),
    }
}

/// `ex4-figure`: exact views of the table's body inside the figure's rounding, and the
/// named alternative the search must not also reproduce there: the body of the squares the
/// figure's own digits give through the paper's system (`alternative`, the body a reader
/// would take from the figure; none when that system is singular).
fn figure_result(
    b: &ResultBuilder,
    case: &P4f3ExampleCase,
    fit: &FigureFit,
    sq_half: &[f64],
    figure_box: &RoundingBox,
    alternative: Option<&[f64; 6]>,
) -> ClaimResult {
    let squares: Vec<f64> = case.body.squares.iter().map(Printed::to_f64).collect();
    let mut r = b
        .claim(&case.figure.claim)
        .printed("squares of the edge table", Value::label(Printed::join(&case.body.squares)))
        .computed("largest view misfit at the printed coordinates", fit.misfit_at_printed)
        .computed("exact views inside the rounding box", Value::flag(fit.witness.is_some()))
        .tolerance(Tolerance::bound(1.0, ToleranceSource::Propagated, "coordinates within half a unit of their printed digits; view residuals within κ(XXᵀ)·64ε·size"))
        .power(widest_power(&fit.acceptance, &squares, sq_half, "square"))
        .method("per frame the affine camera fitted to the body, its misfit and the orthonormality of its rows; minimum-norm Gauss–Newton over the rounding box for coordinates where they vanish; the same search for the body with one square moved");
    if let Some(w) = &fit.witness {
        r = r.detail(
            "largest shift of the exact views (units of half a unit)",
            w.shift_ratio,
        );
    }
    for (e, a) in fit.acceptance.iter().enumerate() {
        let (lo, hi) = a.interval(squares[e], sq_half[e]);
        r = r.cell(
            &format!("square {}", e + 1),
            "accepted region",
            Value::interval(lo, hi),
        );
    }
    let alternative = alternative.map(|a| (a, ex4::reproduces(figure_box, a)));
    // a singular figure system gives no body to mistake for the table's
    let excluded = !alternative.is_some_and(|(_, found)| found);
    if let Some((alt, found)) = alternative {
        r = r
            .computed(
                "alternative: the squares the figure's digits give through the paper's system",
                Value::reals(alt),
            )
            .computed(
                "exact views of the alternative's body inside the rounding box",
                Value::flag(found),
            );
        if found {
            r = r.undecided("the same search finds exact views of the body the figure's digits give: the check cannot tell it from the table's body");
        }
    }
    r.verdict(alternative_verdict(
        if fit.witness.is_some() {
            Verdict::ReproducedWithinRounding
        } else {
            Verdict::Contradicted
        },
        excluded,
    ))
}

fn figure(b: &ResultBuilder, case: &P4f3ExampleCase, figure_box: &RoundingBox, fit: &FigureFit) {
    let unflat = |x: &[f64], f: usize| -> Vec<[f64; 2]> {
        (0..4)
            .map(|j| [x[8 * f + 2 * j], x[8 * f + 2 * j + 1]])
            .collect()
    };
    let tetra = |fr: &[[f64; 2]], name: &str, style: Style| -> Vec<Layer> {
        vec![
            Layer::new(
                name,
                Shape::Line,
                style,
                vec![fr[0], fr[1], fr[2], fr[0], fr[3], fr[1]],
            )
            .labelled(&["P", "Q", "R", "", "T", ""]),
            Layer::new(name, Shape::Line, style, vec![fr[2], fr[3]]),
        ]
    };
    let panels = (0..case.figure.frames.len())
        .map(|i| {
            // the printed views beneath, wide: the exact views drawn on them leave both visible
            let mut layers: Vec<Layer> =
                tetra(&unflat(&figure_box.center, i), "printed", Style::Printed)
                    .into_iter()
                    .map(Layer::beneath)
                    .collect();
            if let Some(w) = &fit.witness {
                layers.extend(tetra(
                    &unflat(&w.point, i),
                    "exact view within rounding",
                    Style::Computed,
                ));
            }
            Plot::image(&format!("frame {}", i + 1), layers)
        })
        .collect();
    b.figure(Figure {
        id: "fig-ex4-figure".into(),
        claim: case.figure.claim.claim.clone(),
        title: "§4: the three projections of the tetrahedron".into(),
        caption: "The printed figure coordinates (wide, pale, beneath) and the nearest exact orthographic views of the body of the edge table within their rounding (dashed, on top); equal scales on both axes.".into(),
        panels,
    });
}

fn matrix_result(b: &ResultBuilder, case: &P4f3ExampleCase, a: &Audit) -> ClaimResult {
    let largest = case
        .matrix_mutant_half_units
        .iter()
        .fold(0.0, |m: f64, v| m.max(*v));
    let at_largest: Vec<_> = a
        .mutants
        .iter()
        .filter(|m| m.shift.abs() == largest)
        .collect();
    let rejected = at_largest.iter().filter(|m| m.rejected).count();
    let all_rejected = rejected == at_largest.len() && !at_largest.is_empty();
    let widest = a
        .enclosure_half_units
        .iter()
        .flatten()
        .fold(0.0, |m: f64, v| m.max(*v));
    let mut r = b
        .claim(&case.matrix.claim)
        .printed("significant digits", case.matrix.significant_digits)
        .computed("largest deviation at the printed coordinates (half units)", a.at_printed)
        .computed("a point of the rounding box reproduces every entry within its half unit", Value::flag(a.witness.is_some()))
        .tolerance(Tolerance::bound(1.0, ToleranceSource::PrintedPrecision, "half a unit in the last significant digit of every nonzero entry, at one point of the figure's rounding box"))
        .power(Power::mutant(all_rejected, &format!("every nonzero entry moved alone by ± {largest} of its half units: the same search finds no point of the box ({rejected} of {} mutants rejected; those accepted at smaller shifts are listed)", at_largest.len())))
        .method("each printed row matched against every triangle, ordered frame pair and factor ±1, ±½, ±2 at the printed coordinates; then a witness search (minimum-norm Gauss–Newton over the box of half a unit of each coordinate) for coordinates whose rows reproduce all 24 nonzero entries within half a unit of their sixth significant digit; the same search for single-entry mutants")
        .cell("old check", "widest interval enclosure over the box, in half units of its entry", widest);
    for (i, m) in a.matches.iter().enumerate() {
        r = r
            .cell(
                &format!("row {}", i + 1),
                "triangle edges",
                Value::label(format!("{:?}", m.triangle)),
            )
            .cell(
                &format!("row {}", i + 1),
                "frames (first − second)",
                Value::label(format!("F{} − F{}", m.first, m.second)),
            )
            .cell(&format!("row {}", i + 1), "factor", m.factor);
    }
    if let Some(w) = &a.witness {
        r = r
            .cell(
                "witness",
                "largest shift (units of half a unit)",
                w.shift_ratio,
            )
            .cell("witness", "largest entry residual (half units)", w.residual);
    }
    for shift in &case.matrix_mutant_half_units {
        let of: Vec<_> = a
            .mutants
            .iter()
            .filter(|m| m.shift.abs() == *shift)
            .collect();
        let n = of.iter().filter(|m| m.rejected).count();
        r = r.detail(
            &format!("mutants rejected at ± {shift} half units"),
            Value::count_of(n, of.len()),
        );
    }
    for m in a.mutants.iter().filter(|m| !m.rejected) {
        r = r.detail(
            "mutant accepted (row, column, shift in half units)",
            Value::reals(&[m.row as f64 + 1.0, m.column as f64 + 1.0, m.shift]),
        );
    }
    r.verdict(matrix_verdict(a.witness.is_some()))
}

/// `ex4-solution`: the printed x against the printed matrix, and the named alternative it
/// must exclude, the solution of the same system built from the figure's digits
/// (`alternative`).
fn solution_result(
    b: &ResultBuilder,
    case: &P4f3ExampleCase,
    s: &SolutionCheck,
    (x, xh): (&[f64], &[f64]),
    alternative: Option<&[f64; 6]>,
) -> ClaimResult {
    let xs = &case.solution.values[0];
    let res_ok = all_within(&s.residuals, &s.residual_bounds);
    let exact = s.exact.clone().unwrap_or_default();
    let diff: Vec<f64> = exact.iter().zip(x).map(|(a, b)| a - b).collect();
    let solve_ok = all_within(&diff, &s.bounds);
    let table_equal = xs
        .iter()
        .zip(&case.body.squares)
        .all(|(a, b)| a.value == b.value);
    // the weakest unknown: the widest acceptance relative to its half unit
    let k = (0..s.bounds.len())
        .max_by(|a, b| (s.bounds[*a] / xh[*a]).total_cmp(&(s.bounds[*b] / xh[*b])))
        .unwrap_or(0);
    let centre = exact.get(k).copied().unwrap_or(x[k]);
    let mut r = b.claim(&case.solution.claim);
    for p in xs {
        r = r.printed("x", p);
    }
    let r = r.computed("exact solution of the printed matrix over ℚ", Value::reals(&exact))
        .computed("printed x satisfies the printed matrix within its precision", Value::flag(res_ok))
        .computed("exact solution within the propagated precision of the printed x", Value::flag(solve_ok))
        .computed("x equals the table's squares digit for digit", Value::flag(table_equal))
        .tolerance(Tolerance::bound(s.bounds[k], ToleranceSource::Propagated, "first-order propagation |A⁻¹|(|δA||x| + |δb|) of half a unit in the matrix's last digit, plus the printed x's half unit (the widest unknown)"))
        .power(Power::interval(centre - s.bounds[k], centre + s.bounds[k], x[k], xh[k], &format!("printed x{} accepted against the printed matrix", k + 1)))
        .method("residuals of the printed x in the printed matrix; Gauss–Jordan elimination over ℚ on the printed digits")
        .detail("residuals", Value::reals(&s.residuals))
        .detail("residual bounds", Value::reals(&s.residual_bounds))
        .detail("propagated bounds per unknown", Value::reals(&s.bounds))
        .detail("exact solution minus printed x", Value::reals(&diff))
        .detail("condition number of the printed matrix", s.condition.unwrap_or(f64::INFINITY).min(f64::MAX));
    let (r, excluded) = figure_alternative(r, &exact, &s.bounds, alternative);
    r.verdict(alternative_verdict(
        Verdict::holds(res_ok && solve_ok && table_equal),
        excluded,
    ))
}

/// The named alternative of `ex4-solution`: had the paper printed the solution of its system
/// built from the figure's digits, would the check have told? Excluded when one unknown of
/// it lies outside that unknown's accepted region (the exact solution ± its bound).
fn figure_alternative<'b>(
    mut r: ClaimBuilder<'b>,
    exact: &[f64],
    bounds: &[f64],
    alternative: Option<&[f64; 6]>,
) -> (ClaimBuilder<'b>, bool) {
    // a singular system from the figure's digits has no solution to mistake for the printed x
    let Some(alt) = alternative else {
        return (r, true);
    };
    let regions: Vec<(f64, f64)> = exact
        .iter()
        .zip(bounds)
        .map(|(c, h)| (c - h, c + h))
        .collect();
    let by = excluded_by(&regions, alt);
    r = r.computed(
        "alternative: the solution of the system built from the figure's digits",
        Value::reals(alt),
    );
    match by {
        Some(k) => {
            r = r.computed(
                "alternative excluded by",
                Value::label(format!("x{}", k + 1)),
            );
        }
        None => {
            r = r.undecided("every unknown's accepted region holds the solution from the figure's digits: the check cannot tell the two apart");
        }
    }
    (r, by.is_some())
}

/// The readings of "the sensitivity to measurement errors" as rows of a table: the median
/// error at the smallest printed level and the decision of each.
fn reading_rows<'b>(
    mut r: crate::check::ClaimBuilder<'b>,
    each: &[(usize, Option<f64>, bool)],
) -> crate::check::ClaimBuilder<'b> {
    for (m, median, ok) in each {
        let row = metric_phrase(*m);
        r = r
            .entry(
                "readings",
                row,
                "median at the smallest printed level",
                median.unwrap_or(f64::MAX),
            )
            .entry(
                "readings",
                row,
                "decision",
                Value::label(if *ok { "holds" } else { "fails" }),
            );
    }
    r
}

fn conditioning_result(
    b: &ResultBuilder,
    case: &P4f3ExampleCase,
    c: Option<&Conditioning>,
    printed_cond: Option<f64>,
) -> ClaimResult {
    let r = b
        .claim(&case.conditioning)
        .suffix("conditioning")
        .printed("statement", Value::label(case.conditioning.quote.clone()));
    let Some(c) = c else {
        return r
            .method("no exact scene inside the rounding box: nothing to propagate")
            .power(Power::none("no scene"))
            .verdict(Verdict::Inconclusive);
    };
    // the rule at the smallest printed level: the median error against ε, under every
    // reading of "sensitivity to measurement errors" (squares or lengths, the worst edge or
    // the mean over the edges: the sentence names none)
    let first = c.levels.iter().min_by(|a, b| a.0.total_cmp(&b.0));
    let each: Vec<(usize, Option<f64>, bool)> = (0..METRICS.len())
        .map(|m| {
            let median = first.and_then(|(_, _, res)| res.quantile(m, 0.5));
            let ok = first
                .zip(median)
                .is_some_and(|((eps, _, _), q)| sensitive(q, *eps));
            (m, median, ok)
        })
        .collect();
    let holds = each.iter().all(|(_, _, ok)| *ok);
    let mut r = r
        .computed("condition number at the paper's scene", c.condition.unwrap_or(f64::MAX))
        .computed("condition number of the printed matrix", printed_cond.unwrap_or(f64::MAX))
        .tolerance(Tolerance::bound(SENSITIVE_AMPLIFICATION, ToleranceSource::MonteCarlo { percentile: crate::check::Real(50.0), trials: case.trials as u64 }, "the median relative error under each reading, in units of ε, at the smallest printed level"))
        .power(Power::mutant(!sensitive(c.direct_amplification, 1.0), "the same rule applied to the projected squares read directly off the image (first-order amplification of ε) says: not sensitive"))
        .method("the paper's scene: the body of the edge table and each frame's camera fitted to the exact views inside the figure's rounding box, P at the origin; first-order propagation of relative coordinate noise through the 6×6 solve, against seeded Monte Carlo of the same noise at the same scene")
        .cell("control", "amplification of the directly measured squares", c.direct_amplification)
        .detail_as("trials per level", case.trials, Role::Trials)
        .detail("seed", case.seed)
        .detail("reading, argued from the sentence's words", Value::label("\"the sensitivity to measurement errors\" names neither squares nor lengths nor how the edges' errors combine: all four readings are read, each against 10 ε at the smallest printed level"));
    r = reading_rows(r, &each);
    for (eps, pred, res) in &c.levels {
        r = r
            .detail("ε", *eps)
            .detail(
                "predicted relative σ per squared edge",
                Value::reals(pred.as_ref().map_or(&[][..], |p| &p[..])),
            )
            .detail(
                "Monte Carlo median of the worst edge's relative error",
                res.quantile(0, 0.5).unwrap_or(f64::MAX),
            )
            .detail(
                "Monte Carlo 95 % of the worst edge's relative error",
                res.quantile(0, 0.95).unwrap_or(f64::MAX),
            )
            .detail("failed trials", Value::count_of(res.failures, res.trials));
    }
    r.verdict(Verdict::statistical(holds))
}

/// The printed noise runs: the edge table's body under random motions (both noise models)
/// and at the paper's own scene (`scene_results[i]` for level `i`), each level judged by the
/// shared noise judge.
fn noise_results(
    b: &ResultBuilder,
    case: &P4f3ExampleCase,
    body: &[nalgebra::Vector3<f64>],
    squares: &[f64],
    scene_results: &[LevelResult],
) -> Vec<ClaimResult> {
    let random = Study {
        solver: crate::model::StudySolver::P4f3,
        body: Body::new(body.to_vec()),
        frames: 3,
        trials: case.trials,
        seed: case.seed,
        motions: None,
    };
    let eps: Vec<f64> = case.noise.iter().map(|l| l.level.to_f64()).collect();
    let all: Vec<Vec<LevelResult>> = run_both(&random, &eps)
        .into_iter()
        .enumerate()
        .map(|(i, pair)| {
            let mut v = pair.to_vec();
            v.extend(scene_results.get(i).cloned());
            v
        })
        .collect();
    let ctx = Context {
        truth: squares,
        names: &default_edge_names(squares.len()),
        trials: case.trials,
        seed: case.seed,
        setting: setting(squares.len(), random.frames),
        scene: !scene_results.is_empty(),
    };
    let mut out = Vec::new();
    for (i, (lv, res)) in case.noise.iter().zip(&all).enumerate() {
        let neighbour = all.get(i + 1).or(i.checked_sub(1).and_then(|j| all.get(j)));
        out.extend(ctx.level(b, lv, false, res, neighbour.map(|n| n.as_slice())));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_structural_zero_has_no_half_unit() {
        let z = Printed::parse("0").unwrap_or_else(|| unreachable!());
        let v = Printed::parse("-0.123456").unwrap_or_else(|| unreachable!());
        assert_eq!(half(&z, 6), 0.0);
        approx::assert_relative_eq!(half(&v, 6), 5e-7, max_relative = 4.0 * f64::EPSILON);
    }

    #[test]
    fn bounds_decide_on_both_sides() {
        assert!(all_within(&[0.9, -1.0], &[1.0, 1.0]));
        assert!(!all_within(&[1.1, 0.0], &[1.0, 1.0]));
        assert!(!all_within(&[0.0], &[1.0, 1.0]));
    }

    #[test]
    fn sensitivity_is_an_order_of_magnitude() {
        assert!(sensitive(0.0101, 0.001));
        assert!(!sensitive(0.0099, 0.001));
        assert_eq!(matrix_verdict(true), Verdict::ReproducedWithinRounding);
        assert_eq!(matrix_verdict(false), Verdict::Contradicted);
    }
}
