//! §2's example under rounding restricted to exact views of the printed body
//! (`ex2-rounding-restricted`), and the discriminant of the paper's quadratic at the printed
//! data (`ex2-discriminant`). Computation lives in `studies::ex2_restricted`.

use crate::check::{ClaimResult, Power, ResultBuilder, Tolerance, ToleranceSource, Value, Verdict};
use crate::claims::p3f3_example::restricted_study::{restricted, Restricted, RestrictedDesign};
use crate::claims::p3f3_example::P3f3ExampleCase;
use crate::studies::rounding::{inside, RoundingBox};

/// Whether every printed component lies inside the range of its paired root.
fn inside_ranges(targets: &[[f64; 3]], ranges: &[[(f64, f64); 3]]) -> bool {
    !ranges.is_empty()
        && targets.len() == ranges.len()
        && targets
            .iter()
            .zip(ranges)
            .all(|(t, r)| (0..3).all(|e| r[e].0 <= t[e] && t[e] <= r[e].1))
}

/// Two real roots at every sample (and at least one sample).
fn always_two_real(r: &Restricted) -> bool {
    r.samples > 0 && r.two_real == r.samples && r.discriminant_range.0 > 0.0
}

pub(super) fn results(
    b: &ResultBuilder,
    case: &P3f3ExampleCase,
    figure_box: &RoundingBox,
    body: [f64; 3],
    targets: &[[f64; 3]],
    target_half: &[[f64; 3]],
) -> Vec<ClaimResult> {
    if case.restricted.is_none() && case.discriminant.is_none() {
        return Vec::new();
    }
    let r = restricted(&RestrictedDesign {
        figure_box,
        body,
        targets,
        target_half,
        trials: case.rounding_trials,
        seed: case.seed,
    });
    let mut out = Vec::new();
    if let Some(c) = &case.restricted {
        out.push(restricted_result(b, c, &r, targets, target_half));
    }
    if let Some(c) = &case.discriminant {
        out.push(discriminant_result(b, c, &r));
    }
    out
}

fn range_values(r: &[[(f64, f64); 3]], k: usize) -> Vec<Value> {
    r.get(k)
        .map(|c| c.iter().map(|(lo, hi)| Value::interval(*lo, *hi)).collect())
        .unwrap_or_default()
}

/// The weakest component: the widest restricted range against its half unit (solution,
/// component).
fn widest_component(range: &[[(f64, f64); 3]], half: &[[f64; 3]]) -> (usize, usize) {
    let mut widest = (0, 0, 0.0);
    for (k, c) in range.iter().enumerate() {
        for (e, (lo, hi)) in c.iter().enumerate() {
            let w = (hi - lo) / half[k][e];
            if w > widest.2 {
                widest = (k, e, w);
            }
        }
    }
    (widest.0, widest.1)
}

fn restricted_result(
    b: &ResultBuilder,
    claim: &crate::cases::ClaimRef,
    r: &Restricted,
    targets: &[[f64; 3]],
    half: &[[f64; 3]],
) -> ClaimResult {
    let within = inside_ranges(targets, &r.range);
    let witness = r.witness.as_ref().is_some_and(inside);
    let (k, e) = widest_component(&r.range, half);
    let (lo, hi) = r.range.get(k).map_or((0.0, 0.0), |c| c[e]);
    let mut out = b
        .claim(claim)
        .printed("solutions", Value::reals(&targets.concat()))
        .computed("printed solutions inside the restricted ranges", Value::flag(within))
        .computed("exact views reproduce both printed solutions within their half units", Value::flag(witness))
        .tolerance(Tolerance::bound(1.0, ToleranceSource::Propagated, "exact views of the printed body whose coordinates round to the figure (half a unit of each printed digit); each printed component within half a unit of its sixth significant digit"))
        .power(Power::interval(lo, hi, targets[k][e], half[k][e], &format!("solution {} component {}: the printed values any exact view rounding to the figure produces (the sampled range, an inner bound of what the search accepts)", k + 1, e + 1)))
        .method("per frame, views of the printed body (P at the origin) drawn with Q and R's first coordinate uniform in their rounding and R's second solved from rigidity, kept when inside its rounding; the paper's route at each; a minimum-norm search over the same views for one that reproduces every printed digit; the unrestricted box sampled beside it")
        .detail("samples of three exact views", r.samples)
        .detail("samples with two real roots", Value::count_of(r.two_real, r.samples));
    for (f, (a, n)) in r.accepted.iter().enumerate() {
        out = out.cell(
            &format!("frame {}", f + 1),
            "draws giving an exact view in the box",
            Value::count_of(*a, *n),
        );
    }
    for k in 0..targets.len() {
        for (e, v) in range_values(&r.range, k).into_iter().enumerate() {
            out = out.computed_cell(
                &format!("solution {}, component {}", k + 1, e + 1),
                "restricted range",
                v,
            );
        }
        for (e, v) in range_values(&r.unrestricted_range, k)
            .into_iter()
            .enumerate()
        {
            out = out.cell(
                &format!("solution {}, component {}", k + 1, e + 1),
                "unrestricted range",
                v,
            );
        }
    }
    let (n, of) = r.unrestricted_no_real;
    out = out.cell(
        "unrestricted box",
        "samples with no real root",
        Value::count_of(n, of),
    );
    if let Some(w) = &r.witness {
        out = out
            .cell(
                "nearest views",
                "largest shift of the coordinates (half units)",
                w.shift_ratio,
            )
            .cell(
                "nearest views",
                "largest component deviation (half units)",
                w.residual,
            );
    }
    out.verdict(if within && witness {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Contradicted
    })
}

fn discriminant_result(
    b: &ResultBuilder,
    claim: &crate::cases::ClaimRef,
    r: &Restricted,
) -> ClaimResult {
    let holds = always_two_real(r);
    let (n, of) = r.unrestricted_no_real;
    let mut out = b
        .claim(claim)
        .printed("solutions", Value::label("two"))
        .computed("two real roots at every exact view rounding to the figure", Value::flag(holds))
        .computed("discriminant range over the exact views", Value::interval(r.discriminant_range.0, r.discriminant_range.1))
        .tolerance(Tolerance::bound(0.0, ToleranceSource::Propagated, "Δ > 0 at every exact view of the printed body whose coordinates round to the figure"))
        .power(Power::mutant(n > 0, &format!("the same count over the unrestricted rounding box (projections no rigid body need produce) finds data with no real root: {n} of {of} samples")))
        .method("β² − 4αγ of the paper's quadratic α c⁴ + β c² + γ (F₃ with a², b² from Cramer's rule); its change and the roots' over the figure's rounding to first order (Σₖ |∂/∂cₖ|·hₖ); its range over the exact views of the printed body");
    if let Some(d) = &r.discriminant {
        out = out
            .computed("discriminant at the printed data", d.value)
            .computed("discriminant / β²", d.relative)
            .computed("separation of the roots in c² (√Δ/|α|)", d.separation)
            .computed(
                "linear worst-case change of Δ over the box, in units of Δ",
                d.worst_change,
            )
            .detail("quadratic [γ, β, α]", Value::reals(&d.quadratic))
            .cell(
                "root 1",
                "linear worst-case change over the box",
                Value::reals(&d.root_change[0]),
            )
            .cell(
                "root 2",
                "linear worst-case change over the box",
                Value::reals(&d.root_change[1]),
            );
    }
    out.verdict(if holds {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Inconclusive
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn targets_must_lie_inside_every_range() {
        let r = [[(1.0, 2.0), (3.0, 4.0), (5.0, 6.0)]];
        assert!(inside_ranges(&[[1.5, 3.5, 5.5]], &r));
        assert!(!inside_ranges(&[[2.5, 3.5, 5.5]], &r));
        assert!(!inside_ranges(&[], &[]));
    }

    #[test]
    fn two_real_needs_a_positive_discriminant_everywhere() {
        let mut r = Restricted {
            discriminant: None,
            accepted: [(1, 1); 3],
            samples: 2,
            two_real: 2,
            range: Vec::new(),
            discriminant_range: (0.5, 1.0),
            unrestricted_no_real: (0, 2),
            unrestricted_range: Vec::new(),
            witness: None,
        };
        assert!(always_two_real(&r));
        r.discriminant_range.0 = -0.1;
        assert!(!always_two_real(&r));
        r.discriminant_range.0 = 0.5;
        r.two_real = 1;
        assert!(!always_two_real(&r));
    }
}
