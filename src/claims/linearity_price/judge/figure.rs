//! The figure of the price of linearity: per body, the median error of every method against
//! the noise level, both on logarithmic axes, in percent as the paper speaks of both.

use crate::check::figure::{Figure, Layer, Plot, Shape, Style};
use crate::claims::linearity_price::study::{Method, Results};
use crate::claims::linearity_price::LinearityPriceCase;

/// Errors and levels are drawn in percent.
const PERCENT: f64 = 100.0;

/// The series drawn, each with its own style (five: the palette's size); the unrefined
/// factorisation and the null control are in the tables only.
const SERIES: [(Method, Style); 5] = [
    (Method::P3f4Triangles, Style::Third),
    (Method::P4f3, Style::Computed),
    (Method::LeastSquares, Style::Other),
    (Method::TomasiKanadeBa, Style::Printed),
    (Method::TomasiKanadeBa3, Style::Mark),
];

/// `fig-linearity-price`: one panel per body.
pub(super) fn figure(res: &Results, case: &LinearityPriceCase) -> Figure {
    let panels = res
        .bodies
        .iter()
        .map(|(name, _, cells)| {
            let layers = SERIES
                .iter()
                .filter_map(|&(m, style)| {
                    let points: Vec<[f64; 2]> = cells
                        .iter()
                        .filter_map(|c| {
                            let med = c.of(m).summary()?.median.finite()?;
                            // a zero error has no place on a logarithmic axis
                            (med > 0.0).then_some([PERCENT * c.level, PERCENT * med])
                        })
                        .collect();
                    (!points.is_empty())
                        .then(|| Layer::new(m.name(), Shape::Line, style, points).with_vertices())
                })
                .collect();
            Plot {
                title: name.clone(),
                x_label: "noise level ε (%, log scale)".into(),
                y_label: "median largest edge-length error (%, log)".into(),
                equal_aspect: false,
                log_x: true,
                log_y: true,
                layers,
                window: None,
            }
        })
        .collect();
    Figure {
        id: "fig-linearity-price".into(),
        claim: case.claim.claim.clone(),
        title: "The price of linearity: the paper's solvers against the standard method".into(),
        caption: format!(
            "Per body, the median over {} seeded trials (seed {}) of the largest relative edge-length error, every method on the same noisy tracks (the paper's coordinate noise, up to ε of every image coordinate). A trial a method cannot solve counts as an error above every finite one; a median among those failures is not drawn. Methods the build or the body does not allow have no line.",
            res.trials, case.seed
        ),
        panels,
    }
}
