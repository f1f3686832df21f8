//! §2's example under rounding restricted to exact views of the printed body
//! (`ex2-rounding-restricted`), and the discriminant of the paper's quadratic at the printed
//! data (`ex2-discriminant`). Computation in `studies::exact_views` (samples and the witness)
//! and `studies::view_bounds` (the proven separation of the two solutions).

use crate::algebra::Interval;
use crate::check::{
    ClaimBuilder, ClaimResult, Power, Quantity, ResultBuilder, Tolerance, ToleranceSource, Value,
    Verdict,
};
use crate::claims::p3f3_example::P3f3ExampleCase;
use crate::derivations::p3f3::route::{route, AFFINE_NAMES, D_NAMES};
use crate::studies::exact_views::{restricted, Restricted, RestrictedDesign};
use crate::studies::rounding::{inside, Acceptance, RoundingBox};
use crate::studies::view_bounds::{separation, Extreme, Views};

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
        let sep = Views::new(figure_box, body).map(|v| separation(&v));
        let route = route_cells(discriminant_result(b, c, &r, sep.as_ref()), figure_box);
        out.push(route);
    }
    out
}

/// The component whose accepted region is widest against its half unit (solution,
/// component).
fn widest_component(acc: &[[Acceptance; 3]]) -> (usize, usize) {
    let mut widest = (0, 0, 0.0);
    for (k, c) in acc.iter().enumerate() {
        for (e, a) in c.iter().enumerate() {
            if a.outer() > widest.2 {
                widest = (k, e, a.outer());
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
    let witness = r.witness.as_ref().is_some_and(inside);
    let (k, e) = widest_component(&r.acceptance);
    let (lo, hi) = r
        .acceptance
        .get(k)
        .map_or((f64::NEG_INFINITY, f64::INFINITY), |a| {
            a[e].interval(targets[k][e], half[k][e])
        });
    let out = b
        .claim(claim)
        .printed("solutions", Value::reals(&targets.concat()))
        .computed("exact views reproduce both printed solutions within their half units", Value::flag(witness))
        .tolerance(Tolerance::bound(1.0, ToleranceSource::Propagated, "exact views of the printed body whose coordinates round to the figure (half a unit of each printed digit); each printed component within half a unit of its sixth significant digit"))
        .power(Power::interval(lo, hi, targets[k][e], half[k][e], &format!("solution {} component {}: the same search for exact views, the target moved along the ladder of half units, fails first at this interval", k + 1, e + 1)))
        .method("per frame, views of the printed body (P at the origin) drawn with Q and R's first coordinate uniform in their rounding and R's second solved from rigidity, kept when inside its rounding; the paper's route at each; a minimum-norm search over the rotations of the body for exact views that round to the figure and reproduce every printed digit, started at the sample nearest them; the unrestricted box sampled beside it")
        .detail("samples of three exact views", r.samples)
        .detail("samples with two real roots", Value::count_of(r.two_real, r.samples));
    let out = super::judge::accepted_cells(out, &r.acceptance, targets, half);
    let out = sample_cells(out, r);
    let (out, excluded) = super::judge::with_alternative(out, &r.acceptance, targets, half);
    let v = if witness {
        Verdict::ReproducedWithinRounding
    } else {
        Verdict::Contradicted
    };
    out.verdict(crate::check::alternative_verdict(v, excluded))
}

/// The samples' part of the evidence: the draws per frame, the spread of the roots over the
/// exact views and over the unrestricted box, and the nearest views.
fn sample_cells<'b>(mut out: ClaimBuilder<'b>, r: &Restricted) -> ClaimBuilder<'b> {
    for (f, (a, n)) in r.accepted.iter().enumerate() {
        out = out.cell(
            &format!("frame {}", f + 1),
            "draws giving an exact view in the box",
            Value::count_of(*a, *n),
        );
    }
    for (k, (sp, un)) in r.spread.iter().zip(&r.unrestricted_spread).enumerate() {
        for e in 0..3 {
            let row = format!("solution {}, component {}", k + 1, e + 1);
            out = out
                .cell(
                    &row,
                    "5 / 50 / 95 % over the exact views",
                    Value::reals(&sp[e]),
                )
                .cell(
                    &row,
                    "5 / 50 / 95 % over the unrestricted box",
                    Value::reals(&un[e]),
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
    out
}

/// The paper's named quantities of §2.2 at the example, beside its discriminant: each at the
/// printed coordinates and enclosed over their rounding (naive interval arithmetic through the
/// paper's own route: an outer bound, never a sample's range).
fn route_cells(mut r: ClaimResult, figure_box: &RoundingBox) -> ClaimResult {
    let (Ok(at), Ok(over)) = (
        <[f64; 18]>::try_from(figure_box.center.as_slice()),
        <[f64; 18]>::try_from(figure_box.half.as_slice()),
    ) else {
        return r;
    };
    let boxed: [Interval; 18] = std::array::from_fn(|i| Interval::around(at[i], over[i]));
    let (Some(p), Some(e)) = (route(&at), route(&boxed)) else {
        return r;
    };
    let mut rows: Vec<(String, f64, Interval)> = Vec::new();
    for f in 0..3 {
        for (j, edge) in ["a", "b", "c"].iter().enumerate() {
            rows.push((
                format!("{edge}_{}²", f + 1),
                p.projections[f][j],
                e.projections[f][j],
            ));
        }
    }
    for k in 0..2 {
        for (j, name) in D_NAMES.iter().enumerate() {
            rows.push((format!("{name},{}", k + 1), p.d[k][j], e.d[k][j]));
        }
    }
    for (j, name) in AFFINE_NAMES.iter().enumerate() {
        rows.push(((*name).to_string(), p.affine[j], e.affine[j]));
    }
    const TABLE: &str = "the route's quantities at the example";
    for (name, v, i) in rows {
        let details = &mut r.evidence.details;
        details.push(Quantity::entry(
            TABLE,
            &name,
            "at the printed data",
            Value::real(v),
        ));
        details.push(Quantity::entry(
            TABLE,
            &name,
            "over the figure's rounding (outer bound)",
            Value::interval(i.lo, i.hi),
        ));
    }
    r
}

fn discriminant_result(
    b: &ResultBuilder,
    claim: &crate::cases::ClaimRef,
    r: &Restricted,
    sep: Option<&Extreme>,
) -> ClaimResult {
    let holds = sep.is_some_and(Extreme::proves_distinct);
    let (n, of) = r.unrestricted_no_real;
    let mut out = b
        .claim(claim)
        .printed("solutions", Value::label("two"))
        .computed("two distinct real solutions at every exact view rounding to the figure (proven)", Value::flag(holds))
        .tolerance(Tolerance::bound(0.0, ToleranceSource::Propagated, "the two solutions' separation in c² is not 0 at any exact view of the printed body whose coordinates round to the figure (half a unit of each printed digit): proven by branch-and-bound over every such view. On the paper's route Δ = α²·separation², and the separation is s·det (v₂ = v₁ + s·n, det the determinant of the route's Cramer step), so a separation away from 0 proves the route defined and Δ > 0 at every view"))
        .power(Power::mutant(n > 0, &format!("the same count over the unrestricted rounding box (projections no rigid body need produce) finds data with no real root: {n} of {of} samples")))
        .method("at every exact view the body's squares solve eq. p3f3sqr; the other solution is v₂ = v₁ − (∇F₃(v₁)·n / nᵀAn) n on the line of the two linear differences (n = d₁ × d₂). Its c² separation from the body is bracketed by branch-and-bound over the views' nine free coordinates (per frame Q and R's first coordinate, R's second from rigidity), cells contracted to the rounding of R's second coordinate and bounded by interval centred forms: the proven end bounds every view, the other end is attained at one. Beside it: β² − 4αγ of the paper's quadratic α c⁴ + β c² + γ at the printed data, its change and the roots' to first order over the figure's rounding (Σₖ |∂/∂cₖ|·hₖ), and its distribution over seeded exact views")
        .detail("smallest discriminant over the sampled exact views", r.discriminant_spread.0)
        .detail("discriminant over the sampled exact views: 5 / 50 / 95 %", Value::reals(&r.discriminant_spread.1));
    if let Some(e) = sep {
        out = out
            .computed(
                "separation in c² nearest 0 over every exact view: proven bound",
                e.proven,
            )
            .computed(
                "separation in c² nearest 0 over every exact view: attained at a view",
                e.attained
                    .map_or(Value::label("no view found"), Value::from),
            )
            .detail("cells bounded", e.cells);
        if let Some(at) = &e.at {
            // P is the origin of every frame: Q and R say where the view is
            let qr: Vec<f64> = at.chunks(6).flat_map(|f| f[2..].to_vec()).collect();
            out = out.detail(
                "the view attaining it: Q and R per frame",
                Value::reals(&qr),
            );
        }
    }
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
    // the body is a real solution at every exact view, so the other is real too: the claim
    // fails only at a double root, which a bracket reaching 0 cannot exclude
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
    fn the_widest_component_is_the_one_whose_search_fails_last() {
        let a = |r: f64| Acceptance {
            accepted: [1.0, 1.0],
            rejected: [Some(3.0), Some(r)],
        };
        let acc = [[a(3.0), a(10.0), a(3.0)], [a(3.0), a(3.0), a(30.0)]];
        assert_eq!(widest_component(&acc), (1, 2));
        assert_eq!(widest_component(&acc[..1]), (0, 1));
    }
}
