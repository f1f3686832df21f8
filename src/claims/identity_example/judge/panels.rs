//! §5.2's figure panels judged against the printed debug blocks, and redrawn.

use super::blocks::Block;
use super::{
    num_f, printed_num, ClaimResult, Power, ResultBuilder, Tolerance, ToleranceSource, Value,
    Verdict,
};
use crate::cases::Printed;
use crate::check::figure::{clip_line, Figure, Layer, Plot, Shape, Style};
use crate::check::ClaimBuilder;
use crate::claims::identity_example::author_program::{Example, Num};
use crate::claims::identity_example::panels::{fit_panel, BlockLine, PanelFit};
use crate::claims::identity_example::IdentityExampleCase;

fn nums(p: &[Printed; 2]) -> [Num; 2] {
    [num_f(&p[0]), num_f(&p[1])]
}

fn fits(case: &IdentityExampleCase, ex: &Example, blocks: &[Block]) -> Vec<Option<PanelFit>> {
    let d = case.debug.significant_digits;
    let lines: Vec<BlockLine> = blocks
        .iter()
        .filter_map(|b| {
            Some(BlockLine {
                assignment: b.assignment()?,
                version: b.attempt.version,
                pa: [
                    printed_num(&b.attempt.pa[0], d),
                    printed_num(&b.attempt.pa[1], d),
                ],
                pb: [
                    printed_num(&b.attempt.pb[0], d),
                    printed_num(&b.attempt.pb[1], d),
                ],
            })
        })
        .collect();
    let box_half = case.panels.box_half.to_f64();
    case.panels
        .items
        .iter()
        .map(|p| {
            let pts: [[Num; 2]; 4] = std::array::from_fn(|k| nums(&p.points[k]));
            let seg: [[Num; 2]; 2] = std::array::from_fn(|k| nums(&p.segment[k]));
            fit_panel(ex, &pts, &seg, &lines, box_half)
        })
        .collect()
}

/// Segments on their lines: reproduced within rounding when every endpoint is within its
/// rounding bound of the line of a block with the panel's assignment. An endpoint off its
/// line is a drawing detail, not a contradiction of what the panels illustrate: a `note` when
/// every such endpoint is nearer the line than `distant`, the smallest distance the figure
/// itself shows as "distant from the line" (a wrong panel's tested point), so that at the
/// figure's own scale the panel shows the same; an `erratum` of the drawing otherwise. A panel
/// that is no assignment at all contradicts the claim that the panels are the attempts.
pub(super) fn judge_on_line(
    on: usize,
    endpoints: usize,
    unfit: usize,
    worst_off: f64,
    distant: f64,
) -> Verdict {
    if unfit > 0 {
        Verdict::Contradicted
    } else if on == endpoints {
        Verdict::ReproducedWithinRounding
    } else if worst_off < distant {
        Verdict::Note
    } else {
        Verdict::Erratum
    }
}

/// Correct panels put the tested point on the line (within its bound), wrong ones do not.
pub(super) fn judge_distance(correct: &[(f64, f64)], wrong: &[(f64, f64)]) -> Verdict {
    Verdict::holds(
        !correct.is_empty()
            && correct.iter().all(|(d, b)| d <= b)
            && wrong.iter().all(|(d, b)| d > b),
    )
}

pub(super) fn results(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    ex: &Example,
    truth: &[usize; 4],
    blocks: &[Block],
) -> Vec<ClaimResult> {
    let f = fits(case, ex, blocks);
    figure(b, case, &f, blocks, truth);
    let fitted: Vec<&PanelFit> = f.iter().flatten().collect();
    let unfit = f.len() - fitted.len();
    let on: usize = fitted
        .iter()
        .map(|p| {
            (0..2)
                .filter(|&k| p.endpoint_distance[k] <= p.endpoint_bound[k])
                .count()
        })
        .sum();
    let on_box: usize = fitted
        .iter()
        .map(|p| p.on_box.iter().filter(|x| **x).count())
        .sum();
    let k = case.debug.mutant_half_units;
    let half = case
        .panels
        .items
        .first()
        .map_or(0.0, |p| p.segment[0][0].half_unit());
    // the mutant: an endpoint on its line moved across it by k half units must fall off it
    let seg_rejected = fitted.iter().all(|p| {
        (0..2).all(|e| {
            p.endpoint_distance[e] > p.endpoint_bound[e]
                || p.endpoint_distance[e] + k * half > p.endpoint_bound[e]
        })
    });
    let off: Vec<f64> = fitted.iter().flat_map(|p| p.endpoint_distance).collect();
    let split = |c: bool| -> Vec<(f64, f64)> {
        fitted
            .iter()
            .filter(|p| (p.assignment == *truth) == c)
            .map(|p| (p.tested_distance, p.tested_bound))
            .collect()
    };
    let (good, bad) = (split(true), split(false));
    let distant = bad.iter().map(|x| x.0).fold(f64::INFINITY, f64::min);
    let first = b
        .claim(&case.panels.claim)
        .printed("panels", Value::count(case.panels.items.len()))
        .computed("segment endpoints on the line of a printed block with the panel's assignment", Value::count_of(on, 2 * fitted.len()))
        .computed("panels whose points are no assignment, or have no block", Value::count(unfit))
        .computed("endpoints on the box", Value::count_of(on_box, 2 * fitted.len()))
        .tolerance(Tolerance::bound(0.0, ToleranceSource::Propagated, "per endpoint: |1 − t|·√2·h(Pa) + |t|·√2·h(Pb) + √2·h(endpoint), h the half units (Pa, Pb to six significant digits, the panel to six decimals)"))
        .power(Power::mutant(seg_rejected, "every endpoint moved across its line by the mutant's half units is off it"))
        .method("each panel's four points matched to an assignment of frame 2 (re-centred at its R); its segment against the lines through the printed Pa, Pb of the blocks with that assignment")
        .detail("endpoint distances from the line", Value::reals(&off));
    let (first, worst_off) = off_endpoints(first, case, &f);
    let first = if on < 2 * fitted.len() {
        first
            .computed("smallest distance the figure shows as distant (a wrong panel's tested point)", Value::real(distant))
            .correction("draw those segments along the recomputed line T₂ₐT₂_b, as the other panels are drawn; what the panels show is unchanged")
    } else {
        first
    };
    let first = first.verdict(judge_on_line(
        on,
        2 * fitted.len(),
        unfit,
        worst_off,
        distant,
    ));
    let second = distance_result(b, case, &good, &bad, k * half);
    vec![first, second]
}

/// Whether the tested point is distant from the line exactly for the wrong assignments
/// (`good`, `bad`: distance and bound per panel); the mutant moves a correct one by `shift`.
fn distance_result(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    good: &[(f64, f64)],
    bad: &[(f64, f64)],
    shift: f64,
) -> ClaimResult {
    let moved_rejected = good.iter().all(|(d, bd)| d + shift > *bd);
    b
        .claim(&case.panels.claim)
        .suffix("distance")
        .printed("the tested point is distant from the line for the wrong assignments", Value::count(bad.len()))
        .computed_cell("correct panels", "tested point's distance from its line", Value::reals(&good.iter().map(|x| x.0).collect::<Vec<_>>()))
        .computed_cell("wrong panels", "tested point's distance from its line", Value::reals(&bad.iter().map(|x| x.0).collect::<Vec<_>>()))
        .tolerance(Tolerance::bound(good.iter().map(|x| x.1).fold(0.0, f64::max), ToleranceSource::Propagated, "the line's rounding at the tested point (as for the endpoints)"))
        .power(Power::mutant(moved_rejected, "a correct panel's tested point moved by the mutant's half units is called distant by the same test"))
        .method("distance of each panel's tested point (#1) from the line of its printed block")
        .verdict(judge_distance(good, bad))
}

/// Each endpoint off its line, named by its panel's line, and the largest such distance.
fn off_endpoints<'b>(
    mut r: ClaimBuilder<'b>,
    case: &IdentityExampleCase,
    fits: &[Option<PanelFit>],
) -> (ClaimBuilder<'b>, f64) {
    let mut worst: f64 = 0.0;
    for (item, fit) in case.panels.items.iter().zip(fits) {
        let Some(p) = fit else { continue };
        for e in 0..2 {
            if p.endpoint_distance[e] > p.endpoint_bound[e] {
                worst = worst.max(p.endpoint_distance[e]);
                r = r.computed_cell(
                    &format!("panel at line {}, endpoint {}", item.line, e + 1),
                    "distance off the line",
                    Value::real(p.endpoint_distance[e]),
                );
            }
        }
    }
    (r, worst)
}

fn figure(
    b: &ResultBuilder,
    case: &IdentityExampleCase,
    fits: &[Option<PanelFit>],
    blocks: &[Block],
    truth: &[usize; 4],
) {
    let box_half = case.panels.box_half.to_f64();
    let xy = |q: &[Printed; 2]| [q[0].to_f64(), q[1].to_f64()];
    let plots = case
        .panels
        .items
        .iter()
        .zip(fits)
        .enumerate()
        .map(|(i, (p, fit))| {
            let pts: Vec<[f64; 2]> = p.points.iter().map(xy).collect();
            let mut layers = vec![
                Layer::new(
                    "printed triangle",
                    Shape::Polygon,
                    Style::Printed,
                    vec![pts[3], pts[1], pts[2]],
                )
                .labelled(&["P", "Q", "R"]),
                Layer::new("printed point T", Shape::Points, Style::Third, vec![pts[0]])
                    .labelled(&["T"]),
                // wide beneath the recomputed line, which would otherwise hide it
                Layer::new(
                    "printed segment",
                    Shape::Line,
                    Style::Other,
                    p.segment.iter().map(xy).collect(),
                )
                .with_vertices()
                .beneath(),
            ];
            let title = match fit {
                Some(f) => format!(
                    "panel {}: {}",
                    i + 1,
                    fit_layers(p, f, blocks, box_half, truth, &mut layers)
                ),
                None => format!("panel {}: no assignment fits", i + 1),
            };
            Plot::image(&title, layers)
        })
        .collect();
    b.figure(Figure {
        id: "fig-ex5-panels".into(),
        claim: case.panels.claim.claim.clone(),
        title: "§5.2: the panels, redrawn".into(),
        caption: "Every panel of the §5.2 figure (a triangle with a line), numbered in the paper's order: frame 2 re-centred at the assigned R, the tested point, the segment the paper draws (wide, beneath), and T₂'s line (through the images of Tₐ and T_b) recomputed at the printed d0 (dashed, clipped to the panel's box); a ring marks a segment endpoint farther from the line of its printed block than the rounding allows. Each title says whether the panel's assignment of the points is the correct one, and the sign of b it was drawn with.".into(),
        panels: plots,
    });
}

/// The layers a fitted panel adds (the recomputed line, the endpoints off it) and its title.
fn fit_layers(
    p: &crate::claims::identity_example::Panel,
    f: &PanelFit,
    blocks: &[Block],
    box_half: f64,
    truth: &[usize; 4],
    layers: &mut Vec<Layer>,
) -> String {
    let xy = |q: &[Printed; 2]| [q[0].to_f64(), q[1].to_f64()];
    let line = blocks
        .iter()
        .filter(|bl| bl.assignment() == Some(f.assignment) && bl.attempt.version == f.version)
        .find_map(|bl| bl.recomputed.as_ref().map(|r| r.line));
    if let Some(c) = line.and_then(|l| clip_line(l[0], l[1], box_half)) {
        layers.push(Layer::new(
            LINE_NAME,
            Shape::Line,
            Style::Computed,
            c.to_vec(),
        ));
    }
    let off: Vec<[f64; 2]> = (0..2)
        .filter(|&e| f.endpoint_distance[e] > f.endpoint_bound[e])
        .filter_map(|e| p.segment.get(e).map(xy))
        .collect();
    if !off.is_empty() {
        layers.push(Layer::new(
            "endpoint off the line",
            Shape::Points,
            Style::Mark,
            off,
        ));
    }
    let sign = if f.version < 0 {
        "b negative"
    } else {
        "b positive"
    };
    let which = if f.assignment == *truth {
        "correct"
    } else {
        "wrong"
    };
    format!("{which} assignment, {sign}")
}

/// The key's name of the recomputed line: in words, not the paper's run-together symbols.
const LINE_NAME: &str = "T₂'s line (through Tₐ and T_b), recomputed";

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn panel_judges_both_sides() {
        assert_eq!(
            judge_on_line(48, 48, 0, 0.0, 0.25),
            Verdict::ReproducedWithinRounding
        );
        // endpoints off the line: nearer than what the figure calls distant, or not
        assert_eq!(judge_on_line(46, 48, 0, 0.03, 0.25), Verdict::Note);
        assert_eq!(judge_on_line(46, 48, 0, 0.3, 0.25), Verdict::Erratum);
        assert_eq!(judge_on_line(48, 48, 1, 0.0, 0.25), Verdict::Contradicted);
        assert_eq!(
            judge_distance(&[(1e-6, 5e-6)], &[(0.25, 5e-6)]),
            Verdict::Reproduced
        );
        assert_eq!(
            judge_distance(&[(1e-5, 5e-6)], &[(0.25, 5e-6)]),
            Verdict::Contradicted
        );
        assert_eq!(
            judge_distance(&[(1e-6, 5e-6)], &[(1e-6, 5e-6)]),
            Verdict::Contradicted
        );
    }
}
