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
    /// A third computed series.
    Third,
    /// A highlighted value (a paper's quoted value, a tested point, a disagreement).
    Mark,
}

impl Style {
    /// Every style: within one figure each series has its own (distinct colours).
    pub const ALL: [Style; 5] = [
        Style::Printed,
        Style::Computed,
        Style::Other,
        Style::Third,
        Style::Mark,
    ];

    /// The style of the `k`-th of several computed series (models, roots), in order.
    pub fn series(k: usize) -> Style {
        [Style::Computed, Style::Other, Style::Third][k % 3]
    }
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
    /// Drawn wide beneath the layers after it, so that a layer that coincides with it
    /// (an exact view on its printed one) leaves both visible.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub beneath: bool,
    /// Markers at the points of a line or polygon: its vertices are data (a polygon's
    /// corners, a printed segment's ends), not where a line was cut.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub vertices: bool,
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
            beneath: false,
            vertices: shape == Shape::Polygon,
        }
    }

    /// With markers at its points.
    pub fn with_vertices(mut self) -> Self {
        self.vertices = true;
        self
    }

    /// Drawn wide beneath the later layers.
    pub fn beneath(mut self) -> Self {
        self.beneath = true;
        self
    }

    /// With one label per point.
    pub fn labelled(mut self, labels: &[&str]) -> Self {
        self.labels = labels.iter().map(|s| s.to_string()).collect();
        self.vertices = true;
        self
    }
}

/// One panel. Axis labels carry their unit as the paper's text speaks it (e.g. percent).
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
    /// Logarithmic y axis.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub log_y: bool,
    /// Layers, drawn in order.
    pub layers: Vec<Layer>,
    /// The region shown, ([x₀, x₁], [y₀, y₁]); by default the layers' extent. Every point
    /// of every layer lies inside it (see [`Plot::keep_inside`]).
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
            log_y: false,
            layers,
            window: None,
        }
    }

    /// Widen the window to hold every layer but the clouds whole, drop the points of the
    /// clouds (`Points` layers of more than [`CLOUD`] points) that still lie outside it (their
    /// far tails), and return how many were dropped, for the caption to say.
    pub fn keep_inside(&mut self) -> usize {
        let Some((mut x, mut y)) = self.window else {
            return 0;
        };
        let cloud = |l: &Layer| l.shape == Shape::Points && l.points.len() > CLOUD;
        for q in self
            .layers
            .iter()
            .filter(|l| !cloud(l))
            .flat_map(|l| l.points.iter())
        {
            x = [x[0].min(q[0]), x[1].max(q[0])];
            y = [y[0].min(q[1]), y[1].max(q[1])];
        }
        self.window = Some((x, y));
        let inside = |q: &[f64; 2]| (x[0]..=x[1]).contains(&q[0]) && (y[0]..=y[1]).contains(&q[1]);
        let mut dropped = 0;
        for l in self.layers.iter_mut().filter(|l| cloud(l)) {
            let before = l.points.len();
            l.points.retain(|q| inside(q));
            dropped += before - l.points.len();
        }
        dropped
    }
}

/// A `Points` layer of more points than this is a cloud: drawn as small dots.
pub const CLOUD: usize = 200;

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

/// A printed fraction in percent, digit for digit (`"0.001"` is `"0.1"`): the unit the
/// paper's text speaks in, with no digit added or lost.
pub fn percent_text(p: &crate::cases::Printed) -> String {
    use num_bigint::BigInt;
    use num_rational::BigRational;
    use num_traits::Signed;
    let d = (p.decimals - 2).max(0) as usize;
    let scale = BigInt::from(10).pow(d as u32 + 2);
    let n = (&p.value * BigRational::from_integer(scale))
        .round()
        .to_integer();
    let digits = format!("{:0>width$}", n.abs().to_string(), width = d + 1);
    let (int, frac) = digits.split_at(digits.len() - d);
    let sign = if n.is_negative() { "-" } else { "" };
    if d == 0 {
        format!("{sign}{int}")
    } else {
        format!("{sign}{int}.{frac}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cases::Printed;

    #[test]
    fn percent_shifts_the_digits() {
        let p = |t: &str| percent_text(&Printed::parse(t).unwrap());
        assert_eq!(p("0.001"), "0.1");
        assert_eq!(p("0.01"), "1");
        assert_eq!(p("0.1"), "10");
        assert_eq!(p("0.125"), "12.5");
        assert_eq!(p("2"), "200");
    }

    #[test]
    fn keep_inside_drops_only_the_cloud_tail() {
        let cloud: Vec<[f64; 2]> = (0..=CLOUD).map(|i| [i as f64, 0.0]).collect();
        let mark = Layer::new("m", Shape::Points, Style::Mark, vec![[-5.0, 1.0]]);
        let mut p = Plot::image(
            "t",
            vec![Layer::new("c", Shape::Points, Style::Computed, cloud), mark],
        );
        p.window = Some(([0.0, 10.0], [0.0, 0.5]));
        let dropped = p.keep_inside();
        assert_eq!(dropped, CLOUD - 10);
        assert_eq!(p.window, Some(([-5.0, 10.0], [0.0, 1.0])));
        assert_eq!(p.layers[1].points.len(), 1);
    }
}
