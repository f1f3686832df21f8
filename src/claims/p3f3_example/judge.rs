//! Claims of §2's example (the body, the figure, the two printed solutions, feasibility) and
//! the censuses of §2.2 and §3. Computation lives in `study` and `studies::census`;
//! here the printed numbers are loaded, the studies called, and the verdicts judged.

use crate::algebra::Interval;
use crate::cases::Printed;
use crate::check::figure::{central_window, thin, Figure, Layer, Plot, Shape, Style};
use crate::check::{
    alternative_verdict, excluded_by, ClaimBuilder, ClaimResult, Power, ResultBuilder, Tolerance,
    ToleranceSource, Value, Verdict,
};
use crate::claims::p3f3_example::restricted as p3f3_restricted;
use crate::claims::p3f3_example::study::{self as ex2, ExampleStudy};
use crate::claims::p3f3_example::P3f3ExampleCase;
use crate::derivations::solver::first_violation;
use crate::error::{Error, Result};
use crate::numfmt::sig;
use crate::studies::rounding::{Acceptance, RoundingBox};

/// The verdict on printed solutions: agreement at the printed coordinates themselves, else a
/// witness point of the rounding box, else contradiction.
fn solutions_verdict(direct: bool, witness: bool) -> Verdict {
    if direct {
        Verdict::Reproduced
    } else if witness {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Contradicted
    }
}

/// Whether a squared edge `s` is feasible against the longest projection of its edge over
/// the rounding box: `Some(true)` when it is at least the upper end (feasible wherever in
/// the box the figure really lies), `Some(false)` below the lower end, `None` in between.
fn feasible_within(s: f64, longest: &Interval) -> Option<bool> {
    if s >= longest.hi {
        Some(true)
    } else if s < longest.lo {
        Some(false)
    } else {
        None
    }
}

/// The nearest alternative of a pair of printed solutions: the other one in place of each.
/// Per solution, the evidence row, and whether the accepted regions of its components
/// exclude it (the verdict needs both excluded).
pub(super) fn other_solution(
    acc: &[[Acceptance; 3]],
    targets: &[[f64; 3]],
    half: &[[f64; 3]],
) -> (Vec<(String, Value)>, bool) {
    let mut rows = Vec::new();
    let mut all = targets.len() == 2 && acc.len() == 2;
    for k in 0..acc.len().min(targets.len()) {
        let other = targets[1 - k.min(1)];
        let regions: Vec<(f64, f64)> = (0..3)
            .map(|e| acc[k][e].interval(targets[k][e], half[k][e]))
            .collect();
        let name = format!(
            "nearest alternative: solution {} in place of solution {}",
            2 - k.min(1),
            k + 1
        );
        let text = match excluded_by(&regions, &other) {
            Some(e) => format!(
                "excluded: component {} accepts {}–{}, the alternative is {}",
                e + 1,
                sig(regions[e].0),
                sig(regions[e].1),
                sig(other[e])
            ),
            None => {
                all = false;
                "not excluded: every component's accepted region holds it".into()
            }
        };
        rows.push((name, Value::label(text)));
    }
    (rows, all)
}

/// The nearest alternative's rows added to `r`, the reason should it not be excluded, and
/// whether it is excluded.
pub(super) fn with_alternative<'b>(
    mut r: ClaimBuilder<'b>,
    acc: &[[Acceptance; 3]],
    targets: &[[f64; 3]],
    half: &[[f64; 3]],
) -> (ClaimBuilder<'b>, bool) {
    let (rows, excluded) = other_solution(acc, targets, half);
    for (name, v) in rows {
        r = r.computed(&name, v);
    }
    if !excluded {
        r = r.undecided("the accepted regions of a solution's components hold the other solution: the check cannot tell the two apart");
    }
    (r, excluded)
}

/// The acceptance interval of one search as a power statement: weak when it reaches beyond
/// `allowed` (what the printed digits would still call right) on either side.
fn acceptance_power(a: &Acceptance, value: f64, unit: f64, allowed: f64, what: &str) -> Power {
    let (lo, hi) = a.interval(value, unit);
    Power::interval(
        lo,
        hi,
        value,
        allowed,
        &format!("{what}: the same search for the target moved along the ladder of half units fails first at this interval"),
    )
}

fn triples(v: &[Vec<Printed>]) -> Result<Vec<[f64; 3]>> {
    v.iter()
        .map(|t| match t.as_slice() {
            [a, b, c] => Ok([a.to_f64(), b.to_f64(), c.to_f64()]),
            _ => Err(Error::InvalidInput(
                "a p3f3 solution has three squares".into(),
            )),
        })
        .collect()
}

pub(super) fn results(b: &ResultBuilder, case: &P3f3ExampleCase) -> Result<Vec<ClaimResult>> {
    let (center, half) = case.figure.rounding_box();
    let figure_box = RoundingBox { center, half };
    let digits = case.solutions.significant_digits;
    let targets = triples(&case.solutions.values)?;
    let target_half: Vec<[f64; 3]> = case
        .solutions
        .values
        .iter()
        .map(|v| std::array::from_fn(|e| v[e].half_unit_significant(digits)))
        .collect();
    let body = triples(std::slice::from_ref(&case.body.squares))?[0];
    let body_half: [f64; 3] = std::array::from_fn(|e| case.body.squares[e].half_unit());
    let study = ex2::study(&ex2::ExampleData {
        figure_box: &figure_box,
        targets: &targets,
        target_half: &target_half,
        body,
        body_half,
        trials: case.rounding_trials,
        seed: case.seed,
    });
    let mut out = vec![
        body_result(b, case),
        solutions_result(b, case, &study, &targets, &target_half),
        figure_result(b, case, &study, &body_half),
        feasibility_result(b, case, &study, &targets),
    ];
    out.extend(p3f3_restricted::results(
        b,
        case,
        &figure_box,
        body,
        &targets,
        &target_half,
    ));
    figures(b, case, &figure_box, &study, &targets);
    Ok(out)
}

fn body_result(b: &ResultBuilder, case: &P3f3ExampleCase) -> ClaimResult {
    let t = &case.body;
    let squares: Vec<_> = t.lengths.iter().map(|l| &l.value * &l.value).collect();
    let ok = squares.iter().zip(&t.squares).all(|(q, s)| *q == s.value);
    let mut r = b.claim(&t.claim);
    for (l, s) in t.lengths.iter().zip(&t.squares) {
        r = r.printed("length", l).printed("square", s);
    }
    for q in &squares {
        r = r.computed("square of the printed length", q.clone());
    }
    r.tolerance(Tolerance::exact(
        "exact rational squares of the printed digits",
    ))
    .power(Power::exact_value(
        "only the exact square of each printed length passes",
    ))
    .method("exact arithmetic on the printed digits")
    .verdict(Verdict::holds(ok))
}

fn solutions_result(
    b: &ResultBuilder,
    case: &P3f3ExampleCase,
    s: &ExampleStudy,
    targets: &[[f64; 3]],
    half: &[[f64; 3]],
) -> ClaimResult {
    let direct = s.matched.as_deref().is_some_and(|m| {
        m.iter()
            .zip(targets.iter().zip(half))
            .all(|(r, (t, h))| (0..3).all(|e| (r[e] - t[e]).abs() <= h[e]))
    });
    // the weakest component: the widest acceptance relative to its own half unit
    let (k, e) = (0..targets.len())
        .flat_map(|k| (0..3).map(move |e| (k, e)))
        .max_by(|x, y| {
            s.acceptance[x.0][x.1]
                .outer()
                .total_cmp(&s.acceptance[y.0][y.1].outer())
        })
        .unwrap_or((0, 0));
    let power = acceptance_power(
        &s.acceptance[k][e],
        targets[k][e],
        half[k][e],
        half[k][e],
        &format!("solution {} component {}", k + 1, e + 1),
    );
    let mut r = b.claim(&case.solutions.claim);
    for (v, m) in case.solutions.values.iter().zip(s.matched.iter().flatten()) {
        r = r.printed("solution (a², b², c²)", Value::label(Printed::join(v)));
        r = r.computed("root at the printed coordinates", Value::reals(m));
    }
    r = r
        .computed("witness in the rounding box", Value::flag(s.witness.is_some()))
        .tolerance(Tolerance::bound(
            half[0][0],
            ToleranceSource::PrintedPrecision,
            "half a unit in the last significant digit of each printed component (the figure's coordinates varied within half a unit of theirs)",
        ))
        .power(power)
        .method("p3f3 at the printed figure coordinates; a witness search (minimum-norm Gauss–Newton over the box of half a unit of each coordinate, P exact) for coordinates whose roots match every printed component within its half unit, checked by exact elimination over ℚ; the same search for targets moved by 1 … 10⁵ half units; seeded Monte Carlo over the box")
        .cell("figure coordinates", "half a unit", figure_box_half(case))
        .detail("printed significant digits", case.solutions.significant_digits);
    if let Some(w) = &s.witness {
        r = r
            .cell(
                "witness",
                "largest shift (units of half a unit)",
                w.shift_ratio,
            )
            .cell(
                "witness",
                "largest residual (units of half a unit)",
                w.residual,
            );
    }
    if let Some(v) = &s.witness_routes {
        r = r
            .cell(
                "witness",
                "exact c² roots (Sturm)",
                Value::reals(v.exact.as_deref().unwrap_or(&[])),
            )
            .cell(
                "witness",
                "largest relative disagreement of routes",
                Value::below(v.max_relative_disagreement),
            );
    }
    r = spread_details(r, case, s, targets, half);
    let (r, excluded) = with_alternative(r, &s.acceptance, targets, half);
    r.verdict(alternative_verdict(
        solutions_verdict(direct, s.witness.is_some()),
        excluded,
    ))
}

/// Each component's accepted region, one cell per solution and component.
pub(super) fn accepted_cells<'b>(
    mut r: ClaimBuilder<'b>,
    acc: &[[Acceptance; 3]],
    targets: &[[f64; 3]],
    half: &[[f64; 3]],
) -> ClaimBuilder<'b> {
    for (k, acc) in acc.iter().enumerate() {
        for (e, a) in acc.iter().enumerate() {
            let (lo, hi) = a.interval(targets[k][e], half[k][e]);
            r = r.cell(
                &format!("solution {} component {}", k + 1, e + 1),
                "accepted region",
                Value::interval(lo, hi),
            );
        }
    }
    r
}

/// The acceptance regions and the Monte Carlo spread, as evidence.
fn spread_details<'b>(
    mut r: crate::check::ClaimBuilder<'b>,
    case: &P3f3ExampleCase,
    s: &ExampleStudy,
    targets: &[[f64; 3]],
    half: &[[f64; 3]],
) -> crate::check::ClaimBuilder<'b> {
    r = accepted_cells(r, &s.acceptance, targets, half)
        .detail("Monte Carlo samples", case.rounding_trials)
        .detail("seed", case.seed)
        .detail("samples with two real roots", s.cloud.len());
    for (k, sp) in s.spread.iter().enumerate() {
        for (e, q) in sp.iter().enumerate() {
            r = r.cell(
                &format!("root {} component {}", k + 1, e + 1),
                "5 / 50 / 95 % over the box",
                Value::reals(q),
            );
        }
    }
    r
}

fn figure_box_half(case: &P3f3ExampleCase) -> Value {
    let h = case.figure.rounding_box().1;
    Value::real(h.iter().fold(0.0, |a: f64, b| a.max(*b)))
}

fn figure_result(
    b: &ResultBuilder,
    case: &P3f3ExampleCase,
    s: &ExampleStudy,
    body_half: &[f64; 3],
) -> ClaimResult {
    let sq = &case.body.squares;
    let e = (0..3)
        .max_by(|x, y| {
            s.body_acceptance[*x]
                .outer()
                .total_cmp(&s.body_acceptance[*y].outer())
        })
        .unwrap_or(0);
    let power = acceptance_power(
        &s.body_acceptance[e],
        sq[e].to_f64(),
        body_half[e],
        body_half[e],
        &format!("body square {} ({})", e + 1, sq[e].text),
    );
    let mut r = b.claim(&case.figure.claim);
    for p in sq {
        r = r.printed("body square", p);
    }
    r = r
        .computed("eq. p3f3sqr at the body, relative to its terms, per frame", Value::reals(&s.body_residual))
        .computed("exact projection of the body inside the rounding box", Value::flag(s.body_fit.is_some()))
        .tolerance(Tolerance::bound(
            s.body_fit.as_ref().map_or(0.0, |w| w.shift_ratio),
            ToleranceSource::Propagated,
            "largest shift of the exact projection, in units of the coordinates' half unit (≤ 1: inside the box); eq. p3f3sqr to 64ε × the size of its terms",
        ))
        .power(power)
        .method("eq. p3f3sqr of each frame at the body's squares; witness search over the box of half a unit of each coordinate; the same search for the body with one square moved by 1 … 10⁵ of its half units")
        .cell("figure coordinates", "half a unit", figure_box_half(case));
    for (k, a) in s.body_acceptance.iter().enumerate() {
        let (lo, hi) = a.interval(sq[k].to_f64(), body_half[k]);
        r = r.cell(
            &format!("body square {}", k + 1),
            "accepted region",
            Value::interval(lo, hi),
        );
    }
    r.verdict(if s.body_fit.is_some() {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Contradicted
    })
}

/// The verdict on feasibility: decided over the whole box (`Reproduced`), else at the
/// witness point that reproduces the printed solutions (`ReproducedWithinRounding`).
fn feasibility_verdict(over_box: &[Option<bool>], at_witness: Option<bool>) -> Verdict {
    if over_box.iter().all(|j| *j == Some(true)) {
        Verdict::Reproduced
    } else if over_box.contains(&Some(false)) || at_witness == Some(false) {
        Verdict::Contradicted
    } else if at_witness == Some(true) {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Inconclusive
    }
}

fn feasibility_result(
    b: &ResultBuilder,
    case: &P3f3ExampleCase,
    s: &ExampleStudy,
    targets: &[[f64; 3]],
) -> ClaimResult {
    let judged: Vec<Option<bool>> = targets
        .iter()
        .flat_map(|t| (0..3).map(move |e| feasible_within(t[e], &s.longest_projection[e])))
        .collect();
    let rules =
        |t: &[f64; 3], proj: &[[f64; 3]]| first_violation(t, proj.iter().map(|p| &p[..])).is_none();
    let at_witness = s
        .witness_projections
        .as_ref()
        .map(|p| targets.iter().all(|t| rules(t, p)));
    // the control at the witness: the component closest to its longest projection there,
    // mirrored to as far below it as it lies above, must be judged infeasible
    let control = s.witness_projections.as_ref().map(|p| {
        let longest = |e: usize| p.iter().map(|f| f[e]).fold(0.0, f64::max);
        let (k, e) = (0..targets.len())
            .flat_map(|k| (0..3).map(move |e| (k, e)))
            .min_by(|x, y| {
                (targets[x.0][x.1] - longest(x.1)).total_cmp(&(targets[y.0][y.1] - longest(y.1)))
            })
            .unwrap_or((0, 0));
        let mut m = targets[k];
        m[e] = longest(e) - (targets[k][e] - longest(e)).abs();
        !rules(&m, p)
    });
    let mut r = b
        .claim(&case.feasibility)
        .printed("feasible solutions", targets.len());
    for (t, v) in targets.iter().zip(judged.chunks(3)) {
        r = r
            .computed(
                "solution feasible over the whole box",
                Value::flag(v.iter().all(|j| *j == Some(true))),
            )
            .detail("solution", Value::reals(t));
    }
    r = r.computed(
        "both feasible at the witness point",
        Value::flag(at_witness == Some(true)),
    );
    for (k, lp) in s.longest_projection.iter().enumerate() {
        r = r.detail(
            &format!("longest projection of edge {} over the box", k + 1),
            Value::interval(lp.lo, lp.hi),
        );
    }
    if let Some(p) = &s.witness_projections {
        for e in 0..3 {
            r = r.detail(
                &format!("longest projection of edge {} at the witness", e + 1),
                p.iter().map(|f| f[e]).fold(0.0, f64::max),
            );
        }
    }
    for root in &s.at_printed {
        r = r.detail("root at the printed coordinates", Value::reals(root));
    }
    r.tolerance(Tolerance::exact("interval enclosure of each projection over the figure's rounding box; exact comparison at the witness point"))
        .power(Power::mutant(
            control == Some(true),
            "the printed component nearest its longest projection at the witness, mirrored to as far below it as it lies above, is judged infeasible",
        ))
        .method("the rules of §2.2 (no negative square, no edge shorter than a projection in any frame) against the projections enclosed over the rounding box, and at the witness point whose roots are the printed solutions")
        .verdict(feasibility_verdict(&judged, at_witness))
}

fn figures(
    b: &ResultBuilder,
    case: &P3f3ExampleCase,
    figure_box: &RoundingBox,
    s: &ExampleStudy,
    targets: &[[f64; 3]],
) {
    let frame_points = |x: &[f64], i: usize| -> Vec<[f64; 2]> {
        (0..3)
            .map(|j| [x[6 * i + 2 * j], x[6 * i + 2 * j + 1]])
            .collect()
    };
    let panels = (0..case.figure.frames.len())
        .map(|i| {
            let mut layers = vec![Layer::new(
                "printed",
                Shape::Polygon,
                Style::Printed,
                frame_points(&figure_box.center, i),
            )
            .labelled(&["P", "Q", "R"])
            .beneath()];
            if let Some(w) = &s.body_fit {
                layers.push(Layer::new(
                    "exact view within rounding",
                    Shape::Polygon,
                    Style::Computed,
                    frame_points(&w.point, i),
                ));
            }
            Plot::image(&format!("frame {}", i + 1), layers)
        })
        .collect();
    b.figure(Figure {
        id: "fig-ex2-figure".into(),
        claim: case.figure.claim.claim.clone(),
        title: "§2: the three projections of the triangle".into(),
        caption: format!(
            "The printed figure coordinates (wide, pale, beneath) and the nearest exact projections of the body ({}) within their rounding (dashed, on top); equal scales on both axes.",
            Printed::join(&case.body.lengths)
        ),
        panels,
    });
    rounding_figure(b, case, s, targets);
}

/// Points of the cloud drawn per root: enough to show its shape, few enough for a page.
const DRAWN_PER_ROOT: usize = 1500;

fn rounding_figure(
    b: &ResultBuilder,
    case: &P3f3ExampleCase,
    s: &ExampleStudy,
    targets: &[[f64; 3]],
) {
    let root = |k: usize| {
        thin(
            &s.cloud
                .iter()
                .map(|m| [m[k][0], m[k][2]])
                .collect::<Vec<_>>(),
            DRAWN_PER_ROOT,
        )
    };
    let mut layers: Vec<Layer> = (0..targets.len())
        .map(|k| {
            Layer::new(
                &format!("roots near solution {}", k + 1),
                Shape::Points,
                Style::series(k),
                root(k),
            )
        })
        .collect();
    let thinned: usize = layers.iter().map(|l| l.points.len()).sum();
    layers.push(Layer::new(
        "at the printed coordinates",
        Shape::Points,
        Style::Printed,
        s.at_printed.iter().map(|r| [r[0], r[2]]).collect(),
    ));
    layers.push(Layer::new(
        "the paper's solutions",
        Shape::Points,
        Style::Mark,
        targets.iter().map(|t| [t[0], t[2]]).collect(),
    ));
    let window = central_window(
        &layers
            .iter()
            .take(targets.len())
            .flat_map(|l| l.points.iter().copied())
            .collect::<Vec<_>>(),
        0.02,
    );
    let mut plot = Plot {
        title: "roots over the rounding box".into(),
        x_label: "a²".into(),
        y_label: "c²".into(),
        equal_aspect: false,
        log_x: false,
        log_y: false,
        window,
        layers,
    };
    let dropped = plot.keep_inside();
    b.figure(Figure {
        id: "fig-ex2-rounding".into(),
        claim: case.solutions.claim.claim.clone(),
        title: "§2: where the roots go within the rounding of the figure".into(),
        caption: format!(
            "(a², c²) of both real roots over the box of half a unit around the printed coordinates. Of {} seeded points of the box (seed {}), {} give two real roots; {} of these, evenly spaced, are drawn for each root. The window holds the central 96 % of each coordinate (widened by a tenth): {} points lie outside it and are left out, {} are drawn. Also drawn: the roots at the printed coordinates, and the paper's solutions.",
            case.rounding_trials,
            case.seed,
            s.cloud.len(),
            DRAWN_PER_ROOT.min(s.cloud.len()),
            dropped,
            thinned - dropped
        ),
        panels: vec![plot],
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_other_solution_must_be_excluded() {
        let a = |r: f64| Acceptance {
            accepted: [1.0, 1.0],
            rejected: [Some(r), Some(r)],
        };
        let targets = [[1.0, 2.0, 3.0], [1.5, 2.5, 3.5]];
        let half = [[0.5e-5, 0.5e-5, 0.5e-5], [0.5e-5, 0.5e-5, 0.5e-5]];
        let narrow = [[a(3.0); 3], [a(3.0); 3]];
        let (rows, excluded) = other_solution(&narrow, &targets, &half);
        assert!(excluded && rows.len() == 2);
        // regions wide enough (10⁶ half units, ±5) to hold the other solution everywhere;
        // 3 half units (1.5e-5) hold neither
        let wide = [[a(1e6); 3], [a(1e6); 3]];
        let (rows, excluded) = other_solution(&wide, &targets, &half);
        assert!(!excluded, "{rows:?}");
        let v = Verdict::ReproducedWithinRounding;
        assert_eq!(alternative_verdict(v, true), v);
        assert_eq!(alternative_verdict(v, false), Verdict::Inconclusive);
        assert_eq!(
            alternative_verdict(Verdict::Contradicted, false),
            Verdict::Contradicted
        );
    }

    #[test]
    fn solutions_verdict_prefers_direct_agreement() {
        assert_eq!(solutions_verdict(true, true), Verdict::Reproduced);
        assert_eq!(
            solutions_verdict(false, true),
            Verdict::ReproducedWithinRounding
        );
        assert_eq!(solutions_verdict(false, false), Verdict::Contradicted);
    }

    #[test]
    fn feasibility_is_decided_only_outside_the_enclosure() {
        let lp = Interval { lo: 15.0, hi: 15.2 };
        assert_eq!(feasible_within(15.2, &lp), Some(true));
        assert_eq!(feasible_within(15.1, &lp), None);
        assert_eq!(feasible_within(14.99, &lp), Some(false));
    }

    #[test]
    fn feasibility_falls_back_to_the_witness() {
        let yes = [Some(true), Some(true)];
        let open = [Some(true), None];
        assert_eq!(feasibility_verdict(&yes, None), Verdict::Reproduced);
        assert_eq!(
            feasibility_verdict(&open, Some(true)),
            Verdict::ReproducedWithinRounding
        );
        assert_eq!(
            feasibility_verdict(&open, Some(false)),
            Verdict::Contradicted
        );
        assert_eq!(feasibility_verdict(&open, None), Verdict::Inconclusive);
        assert_eq!(
            feasibility_verdict(&[Some(false)], Some(true)),
            Verdict::Contradicted
        );
    }

    #[test]
    fn acceptance_beyond_the_half_unit_is_weak() {
        let tight = Acceptance {
            accepted: [0.0, 0.0],
            rejected: [Some(1.0), Some(1.0)],
        };
        assert!(!acceptance_power(&tight, 4.0, 0.5, 0.5, "x").weak);
        let loose = Acceptance {
            accepted: [1.0, 1.0],
            rejected: [Some(3.0), Some(3.0)],
        };
        assert!(acceptance_power(&loose, 4.0, 0.5, 0.5, "x").weak);
        let open = Acceptance {
            accepted: [1.0, 1e5],
            rejected: [Some(3.0), None],
        };
        assert!(acceptance_power(&open, 4.0, 0.5, 0.5, "x").weak);
    }
}
