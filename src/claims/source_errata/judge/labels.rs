//! The labels of a drawing judged: the printed naming against the corrected one, each fitted
//! to the drawn cube by `figure_labels`.

use super::{ClaimBuilder, Decided};
use crate::cases::Printed;
use crate::check::Value;
use crate::claims::source_errata::figure_labels::{fit, LabelFit, Labelled, Picture};
use crate::claims::source_errata::{LabelPicture, NamedPoint};

/// The point `name`, relative to the origin, with the half unit of its printed digits.
fn point(points: &[NamedPoint], origin: &str, name: &str) -> Option<([f64; 3], f64)> {
    let find = |n: &str| points.iter().find(|p| p.name == n);
    let (p, o) = (find(name)?, find(origin)?);
    let mut at = [0.0; 3];
    let mut h: f64 = 0.0;
    for (k, a) in at.iter_mut().enumerate() {
        *a = p.at.get(k)?.to_f64() - o.at.get(k)?.to_f64();
        h = h.max(p.at[k].half_unit() + o.at[k].half_unit());
    }
    Some((at, h))
}

fn xy(v: &[Printed]) -> Option<[f64; 2]> {
    Some([v.first()?.to_f64(), v.get(1)?.to_f64()])
}

fn picture(p: &LabelPicture, origin: &str) -> Option<Picture> {
    let all = p
        .corner
        .iter()
        .chain(p.ends.iter().flatten())
        .chain(p.labels.iter().flat_map(|l| &l.at));
    Some(Picture {
        corner: xy(&p.corner)?,
        ends: [
            xy(p.ends.first()?)?,
            xy(p.ends.get(1)?)?,
            xy(p.ends.get(2)?)?,
        ],
        half_unit: all.map(Printed::half_unit).fold(0.0, f64::max),
        origin_label: xy(&p.labels.iter().find(|l| l.name == origin)?.at)?,
    })
}

/// The fit of the picture's labels when label `n` shows the point `shows(n)`.
fn naming(
    p: &LabelPicture,
    points: &[NamedPoint],
    origin: &str,
    half_side: f64,
    shows: &dyn Fn(&str) -> String,
) -> Option<LabelFit> {
    let pic = picture(p, origin)?;
    let labelled = p
        .labels
        .iter()
        .filter(|l| l.name != origin)
        .map(|l| {
            let (at3, h3) = point(points, origin, &shows(&l.name))?;
            Some(Labelled {
                at: xy(&l.at)?,
                point: at3,
                point_half_unit: h3,
            })
        })
        .collect::<Option<Vec<_>>>()?;
    fit(&pic, half_side, &labelled)
}

/// The corrected naming decides the erratum when every picture fits it, and some picture does
/// not fit the printed naming.
pub(super) fn labels_confirm(printed: &[bool], corrected: &[bool]) -> bool {
    !corrected.is_empty() && corrected.iter().all(|f| *f) && printed.iter().any(|f| !f)
}

/// The decision, with the per-picture misfits as evidence. The mutant swaps, in the corrected
/// naming, the points of the first two labels after the origin's: it must not fit.
pub(super) fn labels_decision<'b>(
    mut r: ClaimBuilder<'b>,
    half_side: &Printed,
    origin: &str,
    points: &[NamedPoint],
    pictures: &[LabelPicture],
) -> (ClaimBuilder<'b>, Decided) {
    let s = half_side.to_f64();
    let (mut printed, mut corrected, mut mutant) = (Vec::new(), Vec::new(), Vec::new());
    for p in pictures {
        let fixed = |n: &str| p.rename.get(n).cloned().unwrap_or_else(|| n.to_string());
        let others: Vec<String> = p
            .labels
            .iter()
            .filter(|l| l.name != origin)
            .map(|l| l.name.clone())
            .collect();
        let swapped = |n: &str| match others.as_slice() {
            [a, b, ..] if n == a => fixed(b),
            [a, b, ..] if n == b => fixed(a),
            _ => fixed(n),
        };
        let fits = [
            naming(p, points, origin, s, &|n| n.to_string()),
            naming(p, points, origin, s, &fixed),
            naming(p, points, origin, s, &swapped),
        ];
        for (name, f) in ["as printed", "as corrected"].iter().zip(&fits) {
            if let Some(f) = f {
                r = r.computed_cell(
                    &format!("lines {}", p.lines),
                    &format!("label misfit {name}"),
                    Value::real(f.misfit),
                );
            }
        }
        if let Some(f) = &fits[1] {
            r = r.cell(
                &format!("lines {}", p.lines),
                "misfit the rounding allows",
                Value::real(f.bound),
            );
        }
        let ok = |f: &Option<LabelFit>| f.as_ref().is_some_and(LabelFit::fits);
        printed.push(ok(&fits[0]));
        corrected.push(ok(&fits[1]));
        mutant.push(ok(&fits[2]));
    }
    let ok = labels_confirm(&printed, &corrected);
    let d = Decided {
        ok,
        mutant_rejected: !labels_confirm(&printed, &mutant),
        method: "; the labels fitted to the drawn cube's projection (best of its 48 symmetries), printed naming against corrected",
        mutant: "; the corrected naming with two labels' points swapped must not fit",
    };
    (
        r.computed("the drawings decide the correction", Value::flag(ok)),
        d,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_label_judge_on_both_sides() {
        assert!(labels_confirm(&[true, false], &[true, true]));
        assert!(!labels_confirm(&[true, true], &[true, true]));
        assert!(!labels_confirm(&[false, false], &[true, false]));
        assert!(!labels_confirm(&[], &[]));
    }
}
