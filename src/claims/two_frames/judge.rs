//! Claims of §5.1 and §5.4: the counterexample, the one-parameter family of two-view
//! solutions, the fourth point's single piece of information, and curves. The computation
//! is `derivations::two_frames` and `study`; here it is judged, with the
//! controls (a mutated counterexample, a body moved off rigidity) as the power.

use nalgebra::Vector3;

use crate::cases::Printed;
use crate::check::figure::{Figure, Layer, Plot, Shape, Style};
use crate::check::{ClaimResult, Power, ResultBuilder, Tolerance, ToleranceSource, Value, Verdict};
use crate::claims::two_frames::study::{
    curve_family, family_census, fit_counterexample, CounterexampleFit, FamilyCensus,
};
use crate::claims::two_frames::TwoFramesCase;
use crate::derivations::dof::identifiability;
use crate::derivations::two_frames::{align, trefoil, view, Counterexample};
use crate::error::Result;
use crate::model::{random_rotation, rng};

/// The counterexample holds when a construction rebuilds Q′, R′ within their printed
/// rounding, the triangles differ beyond the sides' rounding, and the images agree to
/// floating point.
pub(super) fn judge_counterexample(f: &CounterexampleFit) -> bool {
    f.construction.is_some()
        && f.rebuilt_ratio <= 1.0
        && f.difference_ratio > 1.0
        && f.mismatch_ratio <= 1.0
}

/// The family holds when every member reprojects within its bound, members differ beyond
/// it, and the true body is a member in every scene.
pub(super) fn judge_family(c: &FamilyCensus, trials: usize) -> bool {
    c.scenes == trials
        && c.worst_reprojection_ratio <= 1.0
        && c.smallest_difference_ratio > 1.0
        && c.truth_found == trials
}

fn printed_points(case: &TwoFramesCase) -> ([Vector3<f64>; 5], [Vector3<f64>; 5]) {
    let p = &case.counterexample.points;
    let v =
        |f: &dyn Fn(&Printed) -> f64, i: usize| Vector3::new(f(&p[i][0]), f(&p[i][1]), f(&p[i][2]));
    (
        std::array::from_fn(|i| v(&Printed::to_f64, i)),
        std::array::from_fn(|i| v(&Printed::half_unit, i)),
    )
}

/// A triangle laid in its own plane: P at the origin, Q on the positive x axis, R above it,
/// so that its drawing has its true side lengths.
fn in_plane(t: &[Vector3<f64>; 3]) -> Vec<[f64; 2]> {
    let (a, b) = (t[1] - t[0], t[2] - t[0]);
    let Some(e1) = a.try_normalize(0.0) else {
        return vec![[0.0, 0.0], [0.0, 0.0], [b.norm(), 0.0]];
    };
    let x = b.dot(&e1);
    vec![[0.0, 0.0], [a.norm(), 0.0], [x, (b - e1 * x).norm()]]
}

fn figure(b: &ResultBuilder, case: &TwoFramesCase, pts: &[Vector3<f64>; 5], c: &Counterexample) {
    let tri = |q: Vector3<f64>, r: Vector3<f64>| [pts[0], q, r];
    let first = tri(pts[1], pts[2]);
    let second = tri(pts[3], pts[4]);
    let v1 = (view(&first, &c.u1), view(&second, &c.u1));
    let v2 = view(&first, &c.u2);
    let v2p = align(&v2, &view(&second, &c.u2_prime));
    // PQR wide beneath, PQ′R′ drawn on it: where the images coincide both stay visible
    let layer = |name: &str, style: Style, pts: Vec<[f64; 2]>, primed: bool| {
        let l = Layer::new(name, Shape::Polygon, style, pts);
        if primed {
            l.labelled(&["P", "Q′", "R′"])
        } else {
            l.labelled(&["P", "Q", "R"]).beneath()
        }
    };
    let pair = |plain: Vec<[f64; 2]>, primed: Vec<[f64; 2]>| {
        vec![
            layer("PQR", Style::Computed, plain, false),
            layer("PQ′R′", Style::Other, primed, true),
        ]
    };
    let sides = |s: &[f64; 3]| {
        s.iter()
            .map(|x| crate::numfmt::sig_digits(*x, 3))
            .collect::<Vec<_>>()
            .join(", ")
    };
    b.figure(Figure {
        id: "fig-two-frames".into(),
        claim: case.counterexample.claim.claim.clone(),
        title: "§5.1: two triangles, the same two views".into(),
        caption: format!(
            "PQR and PQ′R′ (the printed coordinates) seen along u₁ (Q′ − Q), and PQR along u₂ with PQ′R′ along u₂′ (moved onto it by a rotation in the image plane): the images are congruent. The third panel lays each triangle in its own plane (P at the origin, PQ along the x axis): their true shapes differ, sides PQ, QR, RP {} against PQ′, Q′R′, R′P {}. PQR is drawn wide and pale beneath, PQ′R′ dashed on it; where they coincide, both names label the point.",
            sides(&c.sides),
            sides(&c.sides_prime)
        ),
        panels: vec![
            Plot::image("view 1 (along u₁)", pair(v1.0, v1.1)),
            Plot::image("view 2 (PQR along u₂, PQ′R′ along u₂′)", pair(v2, v2p)),
            Plot::image(
                "true shapes (each in its own plane)",
                pair(in_plane(&first), in_plane(&second)),
            ),
        ],
    });
}

fn counterexample_result(b: &ResultBuilder, case: &TwoFramesCase) -> ClaimResult {
    let (pts, half) = printed_points(case);
    let fit = fit_counterexample(pts, half);
    if let Some(c) = &fit.construction {
        figure(b, case, &pts, c);
    }
    // the mutant: Q′'s second coordinate moved by the mutant's half units
    let mut moved = pts;
    moved[3].y += case.mutant_half_units * half[3].y;
    let rejected = !judge_counterexample(&fit_counterexample(moved, half));
    let mut r = b
        .claim(&case.counterexample.claim)
        .printed("points", Value::label(case.counterexample.names.join(", ")))
        .computed("construction found", Value::flag(fit.construction.is_some()))
        .computed("rebuilt Q′, R′ off the printed ones (half units, largest)", Value::real(fit.rebuilt_ratio))
        .computed("smallest side difference over the sides' rounding", Value::real(fit.difference_ratio))
        .computed("image mismatch over 64ε", Value::real(fit.mismatch_ratio))
        .tolerance(Tolerance::bound(1.0, ToleranceSource::PrintedPrecision, "ratios to the printed half units (rebuilt points), to the triangle-inequality bound of the sides, and to 64ε (images)"))
        .power(Power::mutant(rejected, "Q′ with its second coordinate moved by the mutant's half units: the same construction and test reject it"))
        .method("u₁ along Q′ − Q; the axis n ⟂ u₁ through P, the view u₂ ⟂ n and the rotation about n solved (minimum-norm Newton from a fixed grid) so that Q′, R′ lie on the rotated lines; Q′, R′ rebuilt as q₁ ∩ q₂′ and r₁ ∩ r₂′, the projected triangles compared; two conditions for three unknowns, so any member of the construction reproduces the printed points");
    if let Some(c) = &fit.construction {
        r = r
            .detail("sides of PQR", Value::reals(&c.sides))
            .detail("sides of PQ′R′", Value::reals(&c.sides_prime))
            .detail("u₂", Value::reals(&[c.u2.x, c.u2.y, c.u2.z]))
            .detail(
                "u₂′",
                Value::reals(&[c.u2_prime.x, c.u2_prime.y, c.u2_prime.z]),
            )
            .detail("axis n", Value::reals(&[c.axis.x, c.axis.y, c.axis.z]))
            .detail("rotation (rad)", Value::real(c.angle));
    }
    let sides = [["PQ", "QR", "RP"], ["PQ′", "Q′R′", "R′P"]];
    for (names, ranges) in sides.iter().zip(&fit.side_ranges) {
        for (side, i) in names.iter().zip(ranges) {
            let range = Value::interval(i.lo, i.hi);
            r = r.cell(
                side,
                "range over the printed points' rounding (proven)",
                range,
            );
        }
    }
    r.verdict(Verdict::holds(judge_counterexample(&fit)))
}

pub(super) fn results(b: &ResultBuilder, case: &TwoFramesCase) -> Result<Vec<ClaimResult>> {
    let mut out = vec![counterexample_result(b, case)];
    let fam = family_census(
        case.points,
        case.trials,
        case.seed,
        &case.betas,
        case.control_shift,
    );
    let deficiencies: Vec<usize> = (3..=case.points.max(4))
        .map(|p| identifiability(p, 2, case.seed).map(|r| r.deficiency))
        .collect::<Result<_>>()?;
    let ok = judge_family(&fam, case.trials);
    out.push(
        fam_values(
            b.claim(&case.construction)
                .printed("points per scene", Value::count(case.points)),
            &fam,
            case,
        )
        .verdict(Verdict::holds(ok)),
    );
    out.push(
        fam_values(
            b.claim(&case.family)
                .suffix("family")
                .printed("points per scene", Value::count(case.points)),
            &fam,
            case,
        )
        .computed(
            "Jacobian deficiency at two frames, p = 3 …",
            Value::reals(&deficiencies.iter().map(|d| *d as f64).collect::<Vec<_>>()),
        )
        .verdict(Verdict::holds(ok && deficiencies.iter().all(|d| *d == 1))),
    );
    out.push(fourth_point_result(b, case)?);
    out.push(curves_result(b, case));
    out.extend(crate::claims::two_frames::member::result(b, case));
    Ok(out)
}

fn fam_values<'b>(
    c: crate::check::ClaimBuilder<'b>,
    fam: &FamilyCensus,
    case: &TwoFramesCase,
) -> crate::check::ClaimBuilder<'b> {
    c.computed("scenes", Value::count_of(fam.scenes, case.trials))
        .computed("largest reprojection error over its bound", Value::real(fam.worst_reprojection_ratio))
        .computed("smallest shape difference between members over its bound", Value::real(fam.smallest_difference_ratio))
        .computed("scenes whose true body is the member at the true angle", Value::count_of(fam.truth_found, case.trials))
        .tolerance(Tolerance::bound(1.0, ToleranceSource::ErrorBound, "ratios to the Davis–Kahan bound (1 + 2/sin β)·64ε·λ_max/(λ₂ − λ₁) of the epipolar vector"))
        .power(Power::mutant(fam.nonrigid_accepted == 0, "one point of frame 2 moved off the body by the control shift: no member reprojects within the bound"))
        .detail("largest reprojection error (relative)", Value::below(fam.worst_reprojection))
        .detail("smallest shape difference (relative)", Value::real(fam.smallest_difference))
        .detail("angles β", Value::reals(&case.betas))
        .detail("controls accepted", Value::count_of(fam.nonrigid_accepted, fam.scenes))
        .detail("seed", Value::exact(case.seed))
        .method("seeded random bodies in two frames: the affine epipolar constraint with equal scale gives rotated image coordinates with equal y′, and for each angle β the depths (x₂′ − cos β x₁′)/sin β; each member reprojected and compared with the others")
}

fn fourth_point_result(b: &ResultBuilder, case: &TwoFramesCase) -> Result<ClaimResult> {
    let r3 = identifiability(3, 2, case.seed)?;
    let r4 = identifiability(4, 2, case.seed)?;
    let gain = r4.exact_rank - r3.exact_rank;
    Ok(b.claim(&case.fourth_point)
        .printed("pieces of information of the fourth point in frame 2", Value::count(1))
        .computed("exact Jacobian rank, three points", Value::count(r3.exact_rank))
        .computed("exact Jacobian rank, four points", Value::count(r4.exact_rank))
        .computed("rank added by the fourth point's four coordinates", Value::count(gain))
        .computed("deficiency with four points", Value::count(r4.deficiency))
        .tolerance(Tolerance::exact("exact rank over ℚ at a rational scene"))
        .power(Power::exact_value("integer ranks: only a gain of 3 (one coordinate implied, its epipolar line) with deficiency 1 passes"))
        .method("exact Jacobian ranks (§2.1 parametrisation) at seeded rational scenes of three and four points")
        .detail("seed", Value::exact(case.seed))
        .verdict(Verdict::holds(gain == 3 && r4.deficiency == 1)))
}

fn curves_result(b: &ResultBuilder, case: &TwoFramesCase) -> ClaimResult {
    let second = random_rotation(&mut rng(case.seed));
    let Some(f) = curve_family(trefoil(case.curve_samples), second) else {
        return b
            .claim(&case.curves)
            .printed("samples", Value::count(case.curve_samples))
            .computed("equal-scale epipolar geometry", Value::flag(false))
            .power(Power::none("no family: nothing to control"))
            .verdict(Verdict::Contradicted);
    };
    let differ = f.differences.iter().all(|d| d.0 > f.difference_bound);
    let ok = f.worst_reprojection.0 <= f.worst_reprojection.1 && f.truth.0 <= f.truth.1 && differ;
    b.claim(&case.curves)
        .printed("samples of a trefoil", Value::count(case.curve_samples))
        .computed("largest reprojection error, and its bound", Value::reals(&[f.worst_reprojection.0, f.worst_reprojection.1]))
        .computed("member at the true angle vs the curve, and the bound", Value::reals(&[f.truth.0, f.truth.1]))
        .computed("other members vs the curve (largest distance change)", Value::reals(&f.differences.iter().map(|d| d.0).collect::<Vec<_>>()))
        .tolerance(Tolerance::bound(f.difference_bound, ToleranceSource::ErrorBound, "the Davis–Kahan bound of the family's members"))
        .power(Power::mutant(differ, "the other members, put through the same shape test against the curve, are rejected as the curve"))
        .method("the two-view family applied to a sampled smooth closed curve (all correspondences known)")
        .detail("true angle β", Value::real(f.beta))
        .detail("other angles", Value::reals(&f.others))
        .detail("RMS after the best rigid alignment", Value::reals(&f.differences.iter().map(|d| d.1).collect::<Vec<_>>()))
        .verdict(Verdict::holds(ok))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fit(rebuilt: f64, diff: f64, mismatch: f64, found: bool) -> CounterexampleFit {
        let p = [
            Vector3::zeros(),
            Vector3::x(),
            Vector3::y(),
            Vector3::z(),
            Vector3::x(),
        ];
        let c = crate::derivations::two_frames::counterexample(p);
        CounterexampleFit {
            construction: if found { c } else { None },
            rebuilt_ratio: rebuilt,
            difference_ratio: diff,
            mismatch_ratio: mismatch,
            side_ranges: crate::claims::two_frames::study::side_ranges(&p, &[Vector3::zeros(); 5]),
        }
    }

    #[test]
    fn counterexample_judge_both_sides() {
        let ok = fit(0.5, 3.0, 0.5, true);
        if ok.construction.is_some() {
            assert!(judge_counterexample(&ok));
            assert!(!judge_counterexample(&fit(1.5, 3.0, 0.5, true)));
            assert!(!judge_counterexample(&fit(0.5, 0.9, 0.5, true)));
            assert!(!judge_counterexample(&fit(0.5, 3.0, 2.0, true)));
        }
        assert!(!judge_counterexample(&fit(0.5, 3.0, 0.5, false)));
    }

    #[test]
    fn a_triangle_laid_flat_keeps_its_sides() {
        let t = [
            Vector3::new(1.0, 1.0, 1.0),
            Vector3::new(1.0, 3.0, 1.0),
            Vector3::new(1.0, 1.0, 4.0),
        ];
        let f = in_plane(&t);
        let d = |i: usize, j: usize| (f[i][0] - f[j][0]).hypot(f[i][1] - f[j][1]);
        assert_eq!(f[0], [0.0, 0.0]);
        assert_eq!(f[1], [2.0, 0.0]);
        // a few roundings of sides of length ≤ 4: 16 ε × the longest side bounds them
        let bound = 16.0 * f64::EPSILON * 4.0;
        assert!((d(1, 2) - 13f64.sqrt()).abs() <= bound);
        assert!((d(2, 0) - 3.0).abs() <= bound && f[2][1] > 0.0);
    }

    #[test]
    fn family_judge_both_sides() {
        let good = FamilyCensus {
            scenes: 3,
            worst_reprojection_ratio: 0.1,
            smallest_difference_ratio: 1e6,
            truth_found: 3,
            ..Default::default()
        };
        assert!(judge_family(&good, 3));
        assert!(!judge_family(
            &FamilyCensus {
                worst_reprojection_ratio: 2.0,
                ..good.clone()
            },
            3
        ));
        assert!(!judge_family(
            &FamilyCensus {
                smallest_difference_ratio: 0.5,
                ..good.clone()
            },
            3
        ));
        assert!(!judge_family(
            &FamilyCensus {
                truth_found: 2,
                ..good
            },
            3
        ));
    }
}
