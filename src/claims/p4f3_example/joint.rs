//! §4's figure against §4's table: the system solved from the figure's printed digits
//! (`ex4-figure-system`), and the edge table judged by one exact configuration fitted
//! jointly to the figure and to every printed coefficient (`ex4-body`). Computation lives
//! in `studies::ex4_joint`; here the verdicts.

use crate::cases::Printed;
use crate::check::{ClaimResult, Power, ResultBuilder, Tolerance, ToleranceSource, Value, Verdict};
use crate::claims::p4f3_example::study as ex4;
use crate::claims::p4f3_example::P4f3ExampleCase;
use crate::studies::joint_fit::{
    figure_system, joint_fit, joint_mutants, FigureSystem, JointFit, JointInput, JointMutant,
};
use crate::studies::rounding::RoundingBox;

/// Everything printed is reproduced when no scaled deviation exceeds one half unit.
fn within_rounding(worst: f64) -> bool {
    worst <= 1.0
}

/// The joint fit's verdict: every deviation within its rounding, or else the search found
/// no such configuration — which does not prove there is none.
fn joint_verdict(worst: Option<f64>) -> Verdict {
    match worst {
        Some(w) if within_rounding(w) => Verdict::ReproducedWithinRounding,
        _ => Verdict::Inconclusive,
    }
}

/// Whether every mutant at the largest shift pushes the fit beyond the rounding.
fn mutants_rejected(mutants: &[JointMutant], largest: f64) -> (usize, usize) {
    let at: Vec<_> = mutants
        .iter()
        .filter(|m| m.shift.abs() == largest)
        .collect();
    (
        at.iter().filter(|m| !within_rounding(m.worst)).count(),
        at.len(),
    )
}

/// Whether every |relative deviation| lies within its propagated bound.
fn within_bounds(relative: &[f64], bounds: &[f64]) -> bool {
    !relative.is_empty()
        && relative.len() == bounds.len()
        && relative.iter().zip(bounds).all(|(r, b)| r.abs() <= *b)
}

/// The inputs both results share.
pub(super) struct Shared<'a> {
    pub figure_box: &'a RoundingBox,
    pub rows: &'a [[f64; 7]],
    pub half: &'a [[f64; 7]],
}

/// The paper's system built from the figure's printed digits and solved, against the
/// printed x.
pub(super) fn figure_system_of(case: &P4f3ExampleCase, s: &Shared) -> FigureSystem {
    let x: Vec<f64> = case.solution.values[0]
        .iter()
        .map(Printed::to_f64)
        .collect();
    figure_system(s.figure_box, &x, s.rows, s.half)
}

pub(super) fn figure_system_result(
    b: &ResultBuilder,
    case: &P4f3ExampleCase,
    fs: &FigureSystem,
) -> Option<ClaimResult> {
    let claim = case.figure_system.as_ref()?;
    let xs = &case.solution.values[0];
    let x: Vec<f64> = xs.iter().map(Printed::to_f64).collect();
    let sdig = case.solution.significant_digits;
    let holds = within_bounds(&fs.relative, &fs.relative_bound);
    // the widest unknown: its acceptance interval against the printed x's half unit
    let k = (0..fs.relative_bound.len())
        .max_by(|a, c| fs.relative_bound[*a].total_cmp(&fs.relative_bound[*c]))
        .unwrap_or(0);
    let bound = fs.relative_bound.get(k).copied().unwrap_or(f64::MAX) * x[k].abs();
    let centre = fs.x.map_or(x[k], |v| v[k]);
    let worst_entry = fs
        .coefficient_half_units
        .iter()
        .flatten()
        .fold(0.0, |m: f64, v| m.max(v.abs()));
    let mut r = b.claim(claim);
    for p in xs {
        r = r.printed("x", p);
    }
    r = r
        .computed("solution of the system built from the figure's printed digits", Value::reals(&fs.x.map(|v| v.to_vec()).unwrap_or_default()))
        .computed("relative deviation from the printed x", Value::reals(&fs.relative))
        .computed("first-order bound of the relative change over the figure's rounding", Value::reals(&fs.relative_bound))
        .computed("largest coefficient deviation at the figure's printed digits (half units)", worst_entry)
        .tolerance(Tolerance::bound(bound, ToleranceSource::Propagated, "Σₖ |∂xᵢ/∂cₖ|·hₖ over the figure's rounding box (hₖ half a unit of each printed coordinate), the widest unknown"))
        .power(Power::interval(centre - bound, centre + bound, x[k], xs[k].half_unit_significant(sdig), &format!("printed x{} the figure's digits would accept: the propagated rounding of the figure around the figure's solution", k + 1)))
        .method("the paper's six equations (F₂ − F₁, F₃ − F₁ of triangles PQT, QRT, RPT) built from the figure's printed coordinates and solved; their rows against the printed rows, entry by entry in half units of the last printed digit; first-order propagation of the figure's rounding through the solve");
    for (i, row) in fs.coefficient_half_units.iter().enumerate() {
        r = r.cell(
            &format!("row {}", i + 1),
            "figure's coefficient − printed (half units)",
            Value::reals(row),
        );
    }
    Some(r.verdict(if holds {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Contradicted
    }))
}

/// Per squared edge, the interval of true values both its printed length and its printed
/// square allow.
fn edge_intervals(case: &P4f3ExampleCase) -> Vec<(f64, f64)> {
    let t = &case.body;
    let digits = t.significant_digits.unwrap_or(6);
    t.lengths
        .iter()
        .zip(&t.squares)
        .map(|(l, s)| {
            ex4::common_square(
                l.to_f64(),
                l.half_unit_significant(digits),
                s.to_f64(),
                s.half_unit_significant(digits),
            )
        })
        .collect()
}

pub(super) fn body_result(b: &ResultBuilder, case: &P4f3ExampleCase, s: &Shared) -> ClaimResult {
    let t = &case.body;
    let edges = edge_intervals(case);
    let consistent = edges.iter().all(|(lo, hi)| lo <= hi);
    let inp = JointInput {
        figure: s.figure_box,
        rows: s.rows,
        half: s.half,
        edges: &edges,
    };
    let fit = consistent.then(|| joint_fit(&inp, None)).flatten();
    let largest = case
        .matrix_mutant_half_units
        .iter()
        .fold(0.0, |m: f64, v| m.max(*v));
    let mutants = fit.as_ref().map_or_else(Vec::new, |(_, p)| {
        joint_mutants(&inp, p, &case.matrix_mutant_half_units)
    });
    let (rejected, of) = mutants_rejected(&mutants, largest);
    let mut r = b.claim(&t.claim);
    for ((l, sq), (lo, hi)) in t.lengths.iter().zip(&t.squares).zip(&edges) {
        r = r
            .printed("length", l)
            .printed("square", sq)
            .computed("common true square", Value::interval(*lo, *hi));
    }
    r = r
        .tolerance(Tolerance::bound(1.0, ToleranceSource::PrintedPrecision, "every figure coordinate within half a unit of its two decimals, every nonzero coefficient within half a unit of its last printed digit, every squared edge inside the interval its printed length and square allow"))
        .power(Power::mutant(of > 0 && rejected == of, &format!("every nonzero coefficient moved alone by ± {largest} of its half units: the same fit ends beyond the rounding ({rejected} of {of} mutants rejected)")))
        .method("one exact configuration — the tetrahedron of six squared edges and three orthographic cameras (rotation vector, image translation), 21 parameters — fitted to the 24 figure coordinates, the 24 nonzero printed coefficients and the six edge intervals, each residual in units of its own rounding: Levenberg–Marquardt on the Lᵖ norm, p = 2 … 64, from the affine cameras of the figure; the same fit, warm-started, for single-coefficient mutants");
    r = joint_details(r, fit.as_ref().map(|f| &f.0));
    r = body_measures(r, &t.squares);
    for shift in &case.matrix_mutant_half_units {
        let (n, of) = mutants_rejected(&mutants, *shift);
        r = r.detail(
            &format!("mutants rejected at ± {shift} half units"),
            Value::count_of(n, of),
        );
    }
    for m in mutants.iter().filter(|m| within_rounding(m.worst)) {
        r = r.detail(
            "mutant accepted (row, column, shift in half units)",
            Value::reals(&[m.row as f64 + 1.0, m.column as f64 + 1.0, m.shift]),
        );
    }
    r.verdict(joint_verdict(fit.map(|f| f.0.worst)))
}

/// What a reader computes from the printed squares: the Cayley–Menger determinant and the
/// volume of the tetrahedron, and the area of each face (exact over the printed digits).
fn body_measures<'b>(
    mut r: crate::check::ClaimBuilder<'b>,
    squares: &[crate::cases::Printed],
) -> crate::check::ClaimBuilder<'b> {
    use crate::derivations::p4f3::{cayley_menger, edge_index, heron16};
    use num_traits::{Signed as _, ToPrimitive as _};
    let Ok(s) = <[_; 6]>::try_from(squares.iter().map(|p| p.value.clone()).collect::<Vec<_>>())
    else {
        return r;
    };
    let cm = cayley_menger(&s);
    let cm_f = cm.to_f64().unwrap_or(f64::NAN);
    r = r.detail(
        "Cayley–Menger determinant of the printed squares (288 V²)",
        cm_f,
    );
    // a negative determinant (decided exactly): no tetrahedron has these distances, so no
    // volume to state; likewise a negative 16 A² for a face
    if !cm.is_negative() {
        r = r.detail("volume of the tetrahedron", (cm_f / 288.0).sqrt());
    }
    for (name, [i, j, k]) in [
        ("PQR", [0, 1, 2]),
        ("PQT", [0, 1, 3]),
        ("QRT", [1, 2, 3]),
        ("RPT", [2, 0, 3]),
    ] {
        let a16 = heron16(
            &s[edge_index(i, j)],
            &s[edge_index(j, k)],
            &s[edge_index(k, i)],
        );
        if !a16.is_negative() {
            let area = (a16.to_f64().unwrap_or(f64::NAN) / 16.0).sqrt();
            r = r.detail(&format!("area of face {name}"), area);
        }
    }
    r
}

fn joint_details<'b>(
    mut r: crate::check::ClaimBuilder<'b>,
    fit: Option<&JointFit>,
) -> crate::check::ClaimBuilder<'b> {
    let Some(f) = fit else {
        return r.computed("one exact configuration fits", Value::flag(false));
    };
    let worst_of = |v: &mut dyn Iterator<Item = &f64>| v.fold(0.0, |m: f64, x| m.max(x.abs()));
    r = r
        .computed("largest deviation of all (half units)", f.worst)
        .computed(
            "largest figure deviation (half units)",
            worst_of(&mut f.figure_half_units.iter()),
        )
        .computed(
            "largest coefficient deviation (half units)",
            worst_of(&mut f.coefficient_half_units.iter().flatten()),
        )
        .computed("fitted squared edges", Value::reals(&f.squares))
        .detail(
            "edge offsets from their interval's centre (half-widths)",
            Value::reals(&f.edge_half_units),
        );
    for (i, row) in f.coefficient_half_units.iter().enumerate() {
        r = r.cell(
            &format!("row {}", i + 1),
            "coefficient deviation (half units)",
            Value::reals(row),
        );
    }
    for (i, fr) in f.figure_half_units.chunks(8).enumerate() {
        r = r.cell(
            &format!("frame {}", i + 1),
            "figure deviation P, Q, R, T (half units)",
            Value::reals(fr),
        );
    }
    for (i, v) in f.views.iter().enumerate() {
        r = r.cell(
            &format!("camera {}", i + 1),
            "viewing direction",
            Value::reals(v),
        );
    }
    r
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_joint_judge_needs_every_deviation_within_one_half_unit() {
        assert_eq!(joint_verdict(Some(0.99)), Verdict::ReproducedWithinRounding);
        assert_eq!(joint_verdict(Some(1.01)), Verdict::Inconclusive);
        assert_eq!(joint_verdict(None), Verdict::Inconclusive);
    }

    #[test]
    fn mutants_count_at_their_shift() {
        let m = |shift: f64, worst: f64| JointMutant {
            row: 0,
            column: 0,
            shift,
            worst,
        };
        let ms = [m(10.0, 0.5), m(-10.0, 1.5), m(100.0, 9.0), m(-100.0, 1.01)];
        assert_eq!(mutants_rejected(&ms, 100.0), (2, 2));
        assert_eq!(mutants_rejected(&ms, 10.0), (1, 2));
    }

    #[test]
    fn bounds_decide_on_both_sides() {
        assert!(within_bounds(&[0.1, -0.2], &[0.2, 0.2]));
        assert!(!within_bounds(&[0.3], &[0.2]));
        assert!(!within_bounds(&[], &[]));
    }
}
