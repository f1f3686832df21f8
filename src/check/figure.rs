//! Figures as data: what a check computed for the eye (points, lines, distributions), carried
//! in `report.json` and drawn by the HTML renderer without further computation.

use serde::Serialize;

/// How a layer is drawn.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Style {
    /// What the paper printed.
    Printed,
    /// What this tool computed.
    Computed,
    /// A second computed series.
    Other,
    /// A highlighted value (a paper's quoted value, a tested point).
    Mark,
}

/// What a layer is.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Shape {
    /// Separate points.
    Points,
    /// A connected polyline.
    Line,
    /// A closed polygon.
    Polygon,
    /// Vertical lines at the x of each point.
    Verticals,
}

/// One layer of a plot.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Layer {
    /// Legend name.
    pub name: String,
    /// Shape.
    pub shape: Shape,
    /// Style.
    pub style: Style,
    /// The points.
    pub points: Vec<[f64; 2]>,
    /// Labels of the points (empty, or one per point).
    pub labels: Vec<String>,
}

impl Layer {
    /// A layer without labels.
    pub fn new(name: &str, shape: Shape, style: Style, points: Vec<[f64; 2]>) -> Self {
        Layer {
            name: name.into(),
            shape,
            style,
            points,
            labels: Vec::new(),
        }
    }

    /// With one label per point.
    pub fn labelled(mut self, labels: &[&str]) -> Self {
        self.labels = labels.iter().map(|s| s.to_string()).collect();
        self
    }
}

/// One panel.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Plot {
    /// Panel title.
    pub title: String,
    /// Axis labels.
    pub x_label: String,
    /// Axis labels.
    pub y_label: String,
    /// Same scale on both axes (image coordinates).
    pub equal_aspect: bool,
    /// Logarithmic x axis.
    pub log_x: bool,
    /// Layers, drawn in order.
    pub layers: Vec<Layer>,
    /// The region shown, ([x₀, x₁], [y₀, y₁]); by default the layers' extent.
    pub window: Option<([f64; 2], [f64; 2])>,
}

impl Plot {
    /// An image-coordinate panel (equal aspect).
    pub fn image(title: &str, layers: Vec<Layer>) -> Self {
        Plot {
            title: title.into(),
            x_label: "x".into(),
            y_label: "y".into(),
            equal_aspect: true,
            log_x: false,
            layers,
            window: None,
        }
    }
}

/// A window around the middle of a cloud: the `q` and 1 − `q` quantiles of each coordinate,
/// widened by a tenth, so that a few far points do not shrink the rest to a dot.
pub fn central_window(points: &[[f64; 2]], q: f64) -> Option<([f64; 2], [f64; 2])> {
    let quant = |k: usize| -> Option<[f64; 2]> {
        let mut v: Vec<f64> = points
            .iter()
            .map(|p| p[k])
            .filter(|x| x.is_finite())
            .collect();
        v.sort_by(f64::total_cmp);
        let lo = crate::derivations::rounding::quantile(&v, q)?;
        let hi = crate::derivations::rounding::quantile(&v, 1.0 - q)?;
        let m = 0.1 * (hi - lo).max(f64::MIN_POSITIVE);
        Some([lo - m, hi + m])
    };
    Some((quant(0)?, quant(1)?))
}

/// A figure: one or more panels, tied to the claim it illustrates.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Figure {
    /// Unique id (also the HTML anchor).
    pub id: String,
    /// The result id it illustrates.
    pub claim: String,
    /// Title.
    pub title: String,
    /// What it shows.
    pub caption: String,
    /// Panels.
    pub panels: Vec<Plot>,
}

/// At most `n` evenly spaced elements of `v` (first and last kept): a cloud or a sorted
/// sample thinned for drawing, deterministically.
pub fn thin<T: Clone>(v: &[T], n: usize) -> Vec<T> {
    if v.len() <= n || n < 2 {
        return v.to_vec();
    }
    (0..n)
        .map(|i| v[i * (v.len() - 1) / (n - 1)].clone())
        .collect()
}

/// The empirical distribution function of sorted values, thinned to `n` steps:
/// points (value, fraction of values ≤ it).
pub fn ecdf(sorted: &[f64], n: usize) -> Vec<[f64; 2]> {
    let m = sorted.len().max(1) as f64;
    let all: Vec<[f64; 2]> = sorted
        .iter()
        .enumerate()
        .map(|(i, x)| [*x, (i + 1) as f64 / m])
        .collect();
    thin(&all, n)
}

/// The part of the line through `a` and `b` inside the square [−h, h]², as two points;
/// `None` when the line misses it.
pub fn clip_line(a: [f64; 2], b: [f64; 2], h: f64) -> Option<[[f64; 2]; 2]> {
    let d = [b[0] - a[0], b[1] - a[1]];
    // Liang–Barsky on the infinite line a + t d
    let (mut lo, mut hi) = (f64::NEG_INFINITY, f64::INFINITY);
    for k in 0..2 {
        if d[k] == 0.0 {
            if a[k].abs() > h {
                return None;
            }
            continue;
        }
        let (t1, t2) = ((-h - a[k]) / d[k], (h - a[k]) / d[k]);
        lo = lo.max(t1.min(t2));
        hi = hi.min(t1.max(t2));
    }
    (lo <= hi && lo.is_finite()).then(|| {
        [
            [a[0] + lo * d[0], a[1] + lo * d[1]],
            [a[0] + hi * d[0], a[1] + hi * d[1]],
        ]
    })
}
