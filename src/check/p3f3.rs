//! Claims of §2's example: the body, the figure, the two printed solutions, feasibility.

use num_rational::BigRational;

use super::figure::{central_window, thin, Figure, Layer, Plot, Shape, Style};
use super::{ClaimResult, Evidence, OldTolerance, ResultBuilder, Verdict};
use crate::cases::{P3f3ExampleCase, Printed};
use crate::derivations::p3f3::{match_solutions, real_solutions_from_coordinates, validate};
use crate::derivations::rounding::{monte_carlo, quantile, witness, RoundingBox};
use crate::error::Result;
use crate::numfmt::{below, sig, sig_list};

fn triple(v: &[f64]) -> String {
    sig_list(v)
}

/// Projected squared lengths (PQ, QR, RP) per frame from flat coordinates.
fn projections(coords: &[f64]) -> Vec<[f64; 3]> {
    (0..3)
        .map(|i| {
            let p = |j: usize| (coords[6 * i + 2 * j], coords[6 * i + 2 * j + 1]);
            [(0, 1), (1, 2), (2, 0)].map(|(a, b)| {
                let (pa, pb) = (p(a), p(b));
                (pa.0 - pb.0).powi(2) + (pa.1 - pb.1).powi(2)
            })
        })
        .collect()
}

/// The paper's feasibility rules against given projections; the first violation, if any.
fn violation(s: &[f64; 3], proj: &[[f64; 3]]) -> Option<String> {
    let names = ["a² (PQ)", "b² (QR)", "c² (RP)"];
    for e in 0..3 {
        if s[e] < 0.0 {
            return Some(format!("{} negative", names[e]));
        }
        for (f, p) in proj.iter().enumerate() {
            if s[e] < p[e] {
                return Some(format!(
                    "{} shorter than its projection in frame {}",
                    names[e],
                    f + 1
                ));
            }
        }
    }
    None
}

pub(super) fn check_example(b: &ResultBuilder, case: &P3f3ExampleCase) -> Result<Vec<ClaimResult>> {
    let mut out = Vec::new();

    // The body table: the printed squares are the squares of the printed lengths.
    let sq_ok = case
        .body
        .lengths
        .iter()
        .zip(&case.body.squares)
        .all(|(l, s)| &l.value * &l.value == s.value);
    out.push(b.result(
        &case.body.claim,
        None,
        Verdict::holds(sq_ok),
        format!(
            "lengths {}, squares {}",
            Printed::join(&case.body.lengths),
            Printed::join(&case.body.squares)
        ),
        format!(
            "squares of the printed lengths: {}",
            case.body
                .lengths
                .iter()
                .map(|l| (&l.value * &l.value).to_string())
                .collect::<Vec<_>>()
                .join(", ")
        ),
        Some(OldTolerance::exact(
            "exact rational squares of the printed digits",
        )),
        Evidence::new("exact arithmetic on the printed digits"),
    ));

    let (center, halves) = case.figure.rounding_box();
    let bx = RoundingBox {
        center,
        half: halves,
    };
    let digits = case.solutions.significant_digits;
    let targets: Vec<[f64; 3]> = case
        .solutions
        .values
        .iter()
        .map(|v| [v[0].to_f64(), v[1].to_f64(), v[2].to_f64()])
        .collect();
    let tols: Vec<[f64; 3]> = case
        .solutions
        .values
        .iter()
        .map(|v| [0, 1, 2].map(|e| v[e].half_unit_significant(digits)))
        .collect();
    let min_tol = tols.iter().flatten().fold(f64::INFINITY, |a, b| a.min(*b));
    let at_printed = real_solutions_from_coordinates(&bx.center);
    let matched_printed = match_solutions(&at_printed, &targets);
    let within = |sols: &[[f64; 3]]| {
        sols.iter()
            .zip(&targets)
            .zip(&tols)
            .all(|((s, t), tol)| (0..3).all(|e| (s[e] - t[e]).abs() <= tol[e]))
    };
    let direct = matched_printed.as_deref().is_some_and(within);

    // A witness: a point of the rounding box whose exact solve gives the printed solutions.
    let residual = |x: &[f64]| -> Option<Vec<f64>> {
        let m = match_solutions(&real_solutions_from_coordinates(x), &targets)?;
        Some(
            m.iter()
                .zip(&targets)
                .flat_map(|(s, t)| (0..3).map(move |e| s[e] - t[e]))
                .collect(),
        )
    };
    // a thousandth of the printed precision: the witness reproduces every printed digit
    let wit = witness(&bx, &residual, 1e-3 * min_tol);
    let wit_inside = wit
        .as_ref()
        .filter(|w| w.shift_ratio <= 1.0 && w.residual <= 1e-3 * min_tol);
    // exact cross-check of the witness: elimination over ℚ and Sturm isolation
    let wit_validation = wit_inside.map(|w| {
        let proj = projections(&w.point);
        let exact: [[BigRational; 3]; 3] = std::array::from_fn(|i| {
            std::array::from_fn(|e| BigRational::from_float(proj[i][e]).unwrap_or_default())
        });
        validate(&exact)
    });

    // Monte Carlo over the rounding box: where the roots can go.
    let cloud = monte_carlo(&bx, case.rounding_trials, case.seed, |x| {
        match_solutions(&real_solutions_from_coordinates(x), &targets)
    });
    let with_roots: Vec<&Vec<[f64; 3]>> = cloud.iter().flatten().collect();
    let spread = |k: usize, e: usize| {
        let mut v: Vec<f64> = with_roots.iter().map(|m| m[k][e]).collect();
        v.sort_by(f64::total_cmp);
        (quantile(&v, 0.05), quantile(&v, 0.5), quantile(&v, 0.95))
    };

    let verdict = if direct {
        Verdict::Reproduced
    } else if wit_inside.is_some() {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Contradicted
    };
    let mut ev = Evidence::new(
        "p3f3 at the printed figure coordinates; rounding propagated two ways: a witness search \
         (minimum-norm Gauss–Newton over the ±0.005 box, P exact) for coordinates whose solve \
         gives the printed solutions, checked by exact elimination over ℚ; and seeded Monte Carlo \
         over the box",
    )
    .with(
        "roots at the printed coordinates",
        at_printed
            .iter()
            .map(|s| triple(s))
            .collect::<Vec<_>>()
            .join(", "),
    )
    .with(
        "printed precision",
        format!("{digits} significant digits, trailing zeros dropped"),
    );
    match &wit {
        Some(w) => {
            ev = ev
                .with("witness found", wit_inside.is_some())
                .with("witness largest shift (units of 0.005)", sig(w.shift_ratio))
                .with("witness residual", below(w.residual));
        }
        None => ev = ev.with("witness found", false),
    }
    if let Some(v) = &wit_validation {
        ev = ev
            .with(
                "witness: exact c² roots (Sturm, width 1e-30)",
                v.exact.as_deref().map_or("singular".into(), sig_list),
            )
            .with(
                "witness: largest relative disagreement of routes",
                below(v.max_relative_disagreement),
            );
    }
    ev = ev
        .with(
            "Monte Carlo samples (seed)",
            format!("{} ({})", case.rounding_trials, case.seed),
        )
        .with("samples with two real roots", with_roots.len());
    for (k, t) in targets.iter().enumerate() {
        let s = [0, 1, 2].map(|e| spread(k, e));
        ev = ev.with(
            &format!("root near {}: 5%/50%/95% of (a², b², c²)", triple(t)),
            s.iter()
                .map(|(lo, md, hi)| {
                    format!(
                        "{}/{}/{}",
                        lo.map_or("-".into(), sig),
                        md.map_or("-".into(), sig),
                        hi.map_or("-".into(), sig)
                    )
                })
                .collect::<Vec<_>>()
                .join("; "),
        );
    }
    out.push(b.result(
        &case.solutions.claim,
        None,
        verdict,
        case.solutions
            .values
            .iter()
            .map(|v| format!("({})", Printed::join(v)))
            .collect::<Vec<_>>()
            .join(" and "),
        format!(
            "at the printed coordinates: {}; {}",
            matched_printed
                .as_deref()
                .map_or("fewer than two real roots".into(), |m| m
                    .iter()
                    .map(|s| triple(s))
                    .collect::<Vec<_>>()
                    .join(" and ")),
            match wit_inside {
                Some(w) => format!(
                    "a point of the rounding box (largest shift {} of the rounding) gives both printed solutions",
                    sig(w.shift_ratio)
                ),
                None => "no point of the rounding box gives both printed solutions".into(),
            }
        ),
        Some(OldTolerance {
            value: tols
                .iter()
                .map(|t| triple(t))
                .collect::<Vec<_>>()
                .join(" and "),
            source: format!(
                "half a unit in the {digits}th significant digit of each printed value; figure coordinates ±0.005"
            ),
        }),
        ev,
    ));

    // The figure is a projection of the body: the witness reproduces (4, 9, 16) exactly, so
    // some point of the rounding box is an exact projection of it.
    let truth: Option<[f64; 3]> = case
        .body
        .squares
        .iter()
        .map(Printed::to_f64)
        .collect::<Vec<_>>()
        .try_into()
        .ok();
    let proj = projections(&bx.center);
    let f_at_printed: Vec<f64> = truth.map_or(Vec::new(), |t| {
        proj.iter()
            .map(|p| {
                let f = crate::derivations::twofold::FrameCoefficients::new(*p);
                f.eval(t[0], t[1], t[2]) / (t[0] + t[1] + t[2]).powi(2)
            })
            .collect()
    });
    let body_residual = |x: &[f64]| -> Option<Vec<f64>> {
        let t = truth?;
        Some(
            projections(x)
                .iter()
                .map(|p| {
                    crate::derivations::twofold::FrameCoefficients::new(*p).eval(t[0], t[1], t[2])
                })
                .collect(),
        )
    };
    let body_wit = witness(&bx, &body_residual, 1e-9);
    let fits = body_wit
        .as_ref()
        .is_some_and(|w| w.shift_ratio <= 1.0 && w.residual <= 1e-9);
    out.push(b.result(
        &case.figure.claim,
        None,
        if fits {
            Verdict::ReproducedWithinRounding
        } else {
            Verdict::Contradicted
        },
        format!("three projections of the body ({})", Printed::join(&case.body.squares)),
        format!(
            "relative twofold-squared residuals of the body at the printed coordinates {}; \
             within the rounding box an exact projection of the body exists: {fits}",
            sig_list(&f_at_printed)
        ),
        Some(OldTolerance {
            value: "±0.005".into(),
            source: "half a unit in the second decimal of the figure coordinates".into(),
        }),
        Evidence::new("eq. p3f3sqr of each frame at the body's squares; witness search over the rounding box")
            .with(
                "largest shift of the exact projection (units of 0.005)",
                body_wit.as_ref().map_or("-".into(), |w| sig(w.shift_ratio)),
            ),
    ));

    // Figures: the printed projections against exact views of the body inside the rounding
    // box; the roots over the rounding box.
    let frame_points = |x: &[f64], i: usize| -> Vec<[f64; 2]> {
        (0..3)
            .map(|j| [x[6 * i + 2 * j], x[6 * i + 2 * j + 1]])
            .collect()
    };
    let panels = (0..3)
        .map(|i| {
            let mut layers = vec![Layer::new(
                "printed",
                Shape::Polygon,
                Style::Printed,
                frame_points(&bx.center, i),
            )
            .labelled(&["P", "Q", "R"])];
            if let Some(w) = body_wit.as_ref().filter(|_| fits) {
                layers.push(Layer::new(
                    "exact view inside the rounding box",
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
        caption: "The printed figure coordinates (two decimals) and the nearest exact projections of the body (2, 3, 4) within their rounding.".into(),
        panels,
    });
    let root = |k: usize| -> Vec<[f64; 2]> {
        thin(
            &with_roots
                .iter()
                .map(|m| [m[k][0], m[k][2]])
                .collect::<Vec<_>>(),
            1500,
        )
    };
    let mut layers = vec![Layer::new(
        "root near the first printed solution",
        Shape::Points,
        Style::Computed,
        root(0),
    )];
    if targets.len() > 1 {
        layers.push(Layer::new(
            "root near the second",
            Shape::Points,
            Style::Other,
            root(1),
        ));
    }
    layers.push(Layer::new(
        "at the printed coordinates",
        Shape::Points,
        Style::Printed,
        at_printed.iter().map(|s| [s[0], s[2]]).collect(),
    ));
    layers.push(Layer::new(
        "the paper's solutions",
        Shape::Points,
        Style::Mark,
        targets.iter().map(|t| [t[0], t[2]]).collect(),
    ));
    b.figure(Figure {
        id: "fig-ex2-rounding".into(),
        claim: case.solutions.claim.claim.clone(),
        title: "§2: where the roots go within the rounding of the figure".into(),
        caption: format!(
            "(a², c²) of both real roots for {} seeded points of the ±0.005 box around the printed coordinates (seed {}), the roots at the printed coordinates, and the paper's two solutions.",
            case.rounding_trials, case.seed
        ),
        panels: vec![Plot {
            title: "roots over the rounding box".into(),
            x_label: "a²".into(),
            y_label: "c²".into(),
            equal_aspect: false,
            log_x: false,
            window: central_window(
                &layers.iter().take(2).flat_map(|l| l.points.iter().copied()).collect::<Vec<_>>(),
                0.02,
            ),
            layers,
        }],
    });

    // Feasibility of the printed solutions against the printed projections.
    let printed_checks: Vec<(String, Option<String>)> = targets
        .iter()
        .map(|t| (triple(t), violation(t, &proj)))
        .collect();
    let all_feasible = printed_checks.iter().all(|(_, v)| v.is_none());
    let recomputed: Vec<String> = at_printed
        .iter()
        .map(|s| {
            format!(
                "{}: {}",
                triple(s),
                violation(s, &proj).unwrap_or_else(|| "feasible".into())
            )
        })
        .collect();
    out.push(b.result(
        &case.feasibility,
        None,
        Verdict::holds(all_feasible),
        "both printed solutions are feasible".into(),
        printed_checks
            .iter()
            .map(|(t, v)| format!("{t}: {}", v.clone().unwrap_or_else(|| "feasible".into())))
            .collect::<Vec<_>>()
            .join("; "),
        Some(OldTolerance::exact("comparison with the printed projections")),
        Evidence::new("the rules of §2.2 (no negative square, no edge shorter than a projection) against the squared projections of the printed figure")
            .with("largest projections (PQ², QR², RP²)", sig_list(&[0, 1, 2].map(|e| proj.iter().map(|p| p[e]).fold(0.0, f64::max))))
            .with("roots recomputed at the printed coordinates", recomputed.join("; ")),
    ));
    Ok(out)
}

pub(super) fn check_census(
    b: &ResultBuilder,
    case: &crate::cases::CensusCase,
) -> Result<Vec<ClaimResult>> {
    use crate::derivations::solver::Degenerate;
    let c = crate::derivations::p3f3::census(case.trials, case.seed);
    let infinitely = matches!(c.collinear, Some(Degenerate::Collinear))
        && matches!(c.identical_frames, Some(Degenerate::IdenticalFrames { .. }));
    let ok = infinitely && c.truth_found == c.trials;
    let ev = Evidence::new("p3f3 on seeded random scenes (uniform rotations, points in the unit cube), plus a collinear body and two frames related by an in-plane rotation")
        .with("scenes (seed)", format!("{} ({})", c.trials, c.seed))
        .with("scenes with 0 / 1 / 2 feasible edge solutions", format!("{} / {} / {}", c.feasible_counts[0], c.feasible_counts[1], c.feasible_counts[2]))
        .with("true squares among the feasible ones", format!("{} of {}", c.truth_found, c.trials))
        .with("largest relative error of the true solution", below(c.max_truth_error))
        .with(
            "independent routes to c² (exact elimination over ℚ + Sturm, roots' closed form, companion matrix): largest relative disagreement with the solver",
            format!(
                "{} over {} scenes; same number of real roots in {}",
                below(c.max_route_disagreement),
                c.routes_checked.0,
                c.routes_checked.1
            ),
        )
        .with("collinear body", c.collinear.map_or("no degenerate outcome".into(), |d| d.to_string()))
        .with("frames identical up to an in-plane rotation", c.identical_frames.map_or("no degenerate outcome".into(), |d| d.to_string()))
        .with(
            "structure-and-motion solutions per edge solution (up to the global mirror reversal)",
            {
                // counted per edge solution up to the mirror; the mirror doubles, two edge
                // solutions double again
                let n = c.motions_per_edge_solution.iter().copied().max().unwrap_or(0);
                format!(
                    "{:?}: each later frame's depth pattern may flip (a planar triangle turns onto its mirror image), \
                     so {n} per edge solution up to the mirror, {} with it; with two edge solutions up to {}",
                    c.motions_per_edge_solution,
                    2 * n,
                    4 * n
                )
            },
        );
    Ok(case
        .claims
        .iter()
        .map(|claim| {
            b.result(
                claim,
                None,
                Verdict::holds(ok),
                "none, one or two solutions; infinitely many if collinear or two frames identical up to rotation".into(),
                format!(
                    "0/1/2 feasible edge solutions in {}/{}/{} scenes, never more; the degenerate scenes give infinitely many: {infinitely}",
                    c.feasible_counts[0], c.feasible_counts[1], c.feasible_counts[2]
                ),
                Some(OldTolerance::exact("counts of roots; degeneracy detected at rounding level")),
                ev.clone(),
            )
        })
        .collect())
}

pub(super) fn check_p3f4_census(
    b: &ResultBuilder,
    case: &crate::cases::CensusCase,
) -> Result<Vec<ClaimResult>> {
    let c = crate::derivations::p3f4::census(case.trials, case.frames, case.seed);
    let ok = c.unique == c.trials && c.truth_found == c.trials && c.viewing_axis_rank < 3;
    let ev = Evidence::new("p3f4 (frame differences, linear in a², b², c²) on seeded random scenes, plus rotations about the viewing axis and about one fixed generic axis")
        .with("scenes, frames (seed)", format!("{}, {} ({})", c.trials, c.frames, c.seed))
        .with("unique solutions (rank 3)", c.unique)
        .with("equal to the truth", c.truth_found)
        .with("largest relative error", below(c.max_truth_error))
        .with("median condition number", sig(c.median_condition))
        .with("rank, rotations about the viewing axis only", c.viewing_axis_rank)
        .with("rank, rotations about one fixed generic axis", c.fixed_axis_rank);
    Ok(case
        .claims
        .iter()
        .map(|claim| {
            b.result(
                claim,
                Some("four-frames").filter(|_| claim.claim == "abstract-linear"),
                Verdict::holds(ok),
                "linear in a², b², c² with a unique solution unless the motion is special".into(),
                format!(
                    "unique and exact in {} of {} generic scenes; rank {} for rotations about the viewing axis, {} about a fixed generic axis",
                    c.truth_found, c.trials, c.viewing_axis_rank, c.fixed_axis_rank
                ),
                Some(OldTolerance::exact("numerical rank with the rounding-noise floor of the entries")),
                ev.clone(),
            )
        })
        .collect())
}
