//! §5.1: the member of the two-frame family the figures draw, against the member the printed
//! points are (`two-frames-drawn-member`). Computation lives in `drawn_member`.

use nalgebra::Vector3;

use crate::cases::Printed;
use crate::check::{
    alternative_verdict, ClaimBuilder, ClaimResult, Power, ResultBuilder, Tolerance,
    ToleranceSource, Value, Verdict,
};
use crate::claims::two_frames::drawn_member::{
    member, read, rebuild, theta_bound, DrawnReading, Picture,
};
use crate::claims::two_frames::{DrawnMember, TwoFramesCase};

/// The drawn angle agrees with the printed points' when their difference, folded into
/// (−π/2, π/2] (turns are directions, defined modulo π: −π/2 + ε and π/2 − ε are 2ε
/// apart), lies within the two propagated roundings.
fn same_member(drawn: f64, printed: f64, bound: f64) -> bool {
    fold(drawn - printed).abs() <= bound
}

/// The alternatives the drawings must tell from the printed member's turn `printed`: the
/// member equation's other root, θ = 0 (the body left as it was), and the same turn in the
/// opposite sense; and whether the drawn turn excludes both.
fn alternatives(drawn: f64, printed: f64, bound: f64) -> ([f64; 2], bool) {
    let alternatives = [0.0, fold(-printed)];
    let excluded = alternatives.iter().all(|a| !same_member(drawn, *a, bound));
    (alternatives, excluded)
}

/// An angle difference folded into (−π/2, π/2] (directions are defined modulo π).
fn fold(a: f64) -> f64 {
    let pi = std::f64::consts::PI;
    let r = a.rem_euclid(pi);
    if r > pi / 2.0 {
        r - pi
    } else {
        r
    }
}

fn flat(d: &crate::claims::two_frames::Drawing) -> Vec<f64> {
    let p = |x: &[Printed; 2]| [x[0].to_f64(), x[1].to_f64()];
    let mut v: Vec<f64> = p(&d.corner).to_vec();
    d.edges.iter().for_each(|e| v.extend(p(e)));
    d.labels.iter().for_each(|e| v.extend(p(e)));
    [&d.n, &d.frame1_ray]
        .into_iter()
        .chain(&d.frame2_rays)
        .for_each(|s| s.iter().for_each(|e| v.extend(p(e))));
    v
}

/// The mean φ and mean bound of the readings showing body `k`.
fn group(readings: &[DrawnReading], k: usize) -> Option<(f64, f64)> {
    let g: Vec<&DrawnReading> = readings.iter().filter(|r| r.body == k).collect();
    let first = g.first()?.phi;
    let n = g.len() as f64;
    let phi = first + g.iter().map(|r| fold(r.phi - first)).sum::<f64>() / n;
    Some((phi, g.iter().map(|r| r.phi_bound).sum::<f64>() / n))
}

/// Per picture: its labels, the body it shows, the misfits, φ and n.
fn picture_details<'b>(
    mut r: crate::check::ClaimBuilder<'b>,
    dm: &DrawnMember,
    readings: &[DrawnReading],
) -> crate::check::ClaimBuilder<'b> {
    let deg = f64::to_degrees;
    for (d, rd) in dm.drawings.iter().zip(readings) {
        r = r
            .cell(
                &format!("picture {}", d.lines),
                "labels",
                Value::label(d.label_names.join(", ")),
            )
            .cell(
                &format!("picture {}", d.lines),
                "shows the rotated body",
                Value::flag(rd.body == 1),
            )
            .cell(
                &format!("picture {}", d.lines),
                "label misfit against the original, the rotated body",
                Value::reals(&rd.misfit),
            )
            .cell(
                &format!("picture {}", d.lines),
                "φ of the frame-2 rays and its bound (degrees)",
                Value::reals(&[deg(rd.phi), deg(rd.phi_bound)]),
            )
            .cell(
                &format!("picture {}", d.lines),
                "angle of n from the z edge (degrees)",
                deg(rd.n_tilt),
            );
    }
    r
}

pub(super) fn result(b: &ResultBuilder, case: &TwoFramesCase) -> Option<ClaimResult> {
    let dm: &DrawnMember = case.drawn_member.as_ref()?;
    let pts: Vec<Vector3<f64>> = case
        .counterexample
        .points
        .iter()
        .map(|p| Vector3::new(p[0].to_f64(), p[1].to_f64(), p[2].to_f64()))
        .collect();
    let half: Vec<[f64; 2]> = case
        .counterexample
        .points
        .iter()
        .map(|p| [p[0].half_unit(), p[1].half_unit()])
        .collect();
    // P at the origin; [Q, R, Q′, R′]
    let qr = [pts[1], pts[2], pts[3], pts[4]];
    let m = member(&qr);
    let tb = theta_bound(&qr, &[half[1], half[2], half[3], half[4]]);
    let bodies = [[pts[0], pts[1], pts[2]], [pts[0], pts[3], pts[4]]];
    let readings: Vec<DrawnReading> = dm
        .drawings
        .iter()
        .filter_map(|d| {
            let h = d.corner[0].half_unit();
            read(&Picture { flat: flat(d) }, &bodies, h)
        })
        .collect();
    let (g0, g1) = (group(&readings, 0), group(&readings, 1));
    let deg = f64::to_degrees;
    let mut r = b
        .claim(&dm.claim)
        .printed("Q′ₓ", &case.counterexample.points[3][0])
        .printed("R′ₓ", &case.counterexample.points[4][0]);
    let (Some(m), Some(tb), Some((phi, b0)), Some((phi2, b1))) = (m, tb, g0, g1) else {
        return Some(
            r.computed("member identified", Value::flag(false))
                .power(Power::none("no member or no reading of both bodies"))
                .verdict(Verdict::Inconclusive),
        );
    };
    let theta = fold(phi2 - phi);
    let bound = b0 + b1 + tb;
    let holds = same_member(theta, m.theta, bound);
    let [qx, rx] = rebuild(&pts[1], &pts[2], phi, theta);
    let qh = case.counterexample.points[3][0].half_unit();
    let rh = case.counterexample.points[4][0].half_unit();
    r = r
        .computed("θ of the printed points (degrees)", deg(m.theta))
        .computed("φ, φ′ of the printed points (degrees)", Value::reals(&[deg(m.phi), deg(m.phi_turned)]))
        .computed("frame-2 abscissae of Q, R, Q′, R′", Value::reals(&m.abscissae))
        .computed("θ drawn (degrees)", deg(theta))
        .computed("φ, φ′ drawn (degrees)", Value::reals(&[deg(phi), deg(phi2)]))
        .computed("Q′ₓ, R′ₓ rebuilt from the drawn member", Value::reals(&[qx, rx]))
        .computed("rebuilt − printed Q′ₓ, R′ₓ (half units)", Value::reals(&[(qx - pts[3].x) / qh, (rx - pts[4].x) / rh]))
        .tolerance(Tolerance::bound(deg(bound), ToleranceSource::Propagated, "degrees: Σ|∂φ/∂c|·h of the drawings' three-decimal coordinates (mean over the pictures of each body, both bodies) plus Σ|∂θ/∂c|·h of the printed points"))
        .power(Power::interval(deg(theta - bound), deg(theta + bound), deg(theta), deg(bound), "θ (degrees) of the printed points the drawings would accept: exactly what the drawings' three decimals and the printed points' digits allow"))
        .method("per picture: the cube's thin edges as the scene's axes (x along the frame-1 ray, z along n), their signs and the scale fitted to the labels of P and the two points of either body; the frame-2 rays' direction in the scene; the turn θ = φ′ − φ between the pictures of the two bodies, against the non-trivial root of (R(−θ)Q′ − Q) × (R(−θ)R′ − R) = 0 of the printed points; Q′ and R′ rebuilt from Q and R by the drawn member");
    r = picture_details(r, dm, &readings);
    Some(alternatives_result(r, holds, (theta, m.theta, bound)))
}

/// The verdict, with the alternatives the drawn turn must exclude: `(drawn, printed, bound)`.
fn alternatives_result(
    r: ClaimBuilder,
    holds: bool,
    (drawn, printed, bound): (f64, f64, f64),
) -> ClaimResult {
    let (alternatives, excluded) = alternatives(drawn, printed, bound);
    let mut r = r
        .computed(
            "alternatives: the other root θ = 0 and the opposite turn −θ (degrees)",
            Value::reals(&alternatives.map(f64::to_degrees)),
        )
        .computed(
            "an alternative within the tolerance of θ drawn",
            Value::flag(!excluded),
        );
    if holds && !excluded {
        r = r.undecided("θ drawn lies within the tolerance of an alternative as well: the drawings cannot tell which member they show");
    }
    let v = if holds {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Inconclusive
    };
    r.verdict(alternative_verdict(v, excluded))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_member_judge_decides_on_both_sides() {
        assert!(same_member(0.30, 0.31, 0.02));
        assert!(!same_member(0.30, 0.33, 0.02));
        let pi = std::f64::consts::PI;
        // π − 0.1 and the subtraction of π each round once: a few units of π's last place
        assert!((fold(pi - 0.1) + 0.1).abs() <= 4.0 * f64::EPSILON * pi);
        assert_eq!(fold(0.2), 0.2);
    }

    #[test]
    fn alternatives_are_excluded_only_when_far_from_the_drawn_turn() {
        // a large turn, drawn within its bound: both alternatives lie far outside
        assert_eq!(alternatives(-0.75, -0.75, 0.01), ([0.0, 0.75], true));
        // a small turn: θ = 0 lies within the bound of the drawn turn
        assert!(!alternatives(0.005, 0.005, 0.01).1);
        // a turn near a quarter circle: its opposite sense folds onto itself
        let q = std::f64::consts::FRAC_PI_2 - 0.001;
        assert!(!alternatives(q, q, 0.01).1);
    }
}
