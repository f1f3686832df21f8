//! The figure of one noise level: per noise model, the distribution of the largest relative
//! error over the edges, in percent as the paper speaks of it, with the printed run marked.

use crate::cases::NoiseLevel;
use crate::check::figure::{ecdf, percent_text, Figure, Layer, Plot, Shape, Style};
use crate::derivations::noise::LevelResult;
use crate::studies::noise::RunErrors;

/// Steps drawn per distribution.
const STEPS: usize = 200;

/// Relative errors are drawn in percent.
const PERCENT: f64 = 100.0;

/// The figure `fig-<id>` of a level: `res` the distributions (one per model or scene),
/// `run` the printed run's errors, `study` (trials, seed).
pub(super) fn figure(
    id: &str,
    lv: &NoiseLevel,
    res: &[LevelResult],
    run: Option<&RunErrors>,
    study: (usize, u64),
) -> Figure {
    let panel = |m: usize, what: &str| {
        let mut layers: Vec<Layer> = res
            .iter()
            .enumerate()
            .map(|(k, r)| {
                let steps = ecdf(&r.sorted[m], STEPS)
                    .into_iter()
                    .map(|[x, y]| [PERCENT * x, y])
                    .collect();
                Layer::new(&series_name(&r.model), Shape::Line, Style::series(k), steps)
            })
            .collect();
        if let Some(e) = run {
            layers.push(Layer::new(
                "the paper's test run",
                Shape::Verticals,
                Style::Mark,
                vec![[PERCENT * e.metrics[m], 0.5]],
            ));
        }
        Plot {
            title: format!("largest error in {what}"),
            x_label: format!("largest relative error in {what}, x (%, log scale)"),
            y_label: "fraction of trials with error ≤ x".into(),
            equal_aspect: false,
            log_x: true,
            log_y: false,
            layers,
            window: None,
        }
    };
    let failures: Vec<String> = res
        .iter()
        .map(|r| {
            format!(
                "{} of {} with {}",
                r.failures,
                r.trials,
                series_name(&r.model)
            )
        })
        .collect();
    let (trials, seed) = study;
    Figure {
        id: format!("fig-{}", id.replace('/', "-")),
        claim: id.to_string(),
        title: format!("Noise up to {} %: error distributions", percent_text(&lv.level)),
        caption: format!(
            "For each noise model, the fraction of its successful trials whose largest relative error over the edges is at most x, in squared lengths and in lengths, over {trials} seeded trials per model (seed {seed}); the vertical line is the paper's printed test run. Failed trials (no real solution with non-negative squares: {}) are not in the curves.",
            failures.join(", ")
        ),
        panels: vec![panel(0, "squares"), panel(2, "lengths")],
    }
}

/// A noise model's series name, short and in the paper's words ("errors of up to x %" of
/// the coordinates or of the lengths).
fn series_name(model: &str) -> String {
    model
        .replace("relative-coordinate", "errors in coordinates")
        .replace("relative-length", "errors in lengths")
        .replace(" at the paper's scene", ", paper's scene")
}
