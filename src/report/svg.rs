//! SVG drawing of figure data: one document per figure, its panels in a grid and its key
//! below them, outside every plot area. Nothing is computed here beyond placing what the
//! checks computed: ranges, ticks, pixel positions, label offsets.
//!
//! The document is written so that a reader (or a test) can follow it: each panel's plot
//! area is a `rect class="plot-area"`, each layer a `g class="layer"` holding its data
//! (polylines, polygons, lines and markers placed by `translate(x,y)`), the key a
//! `g class="legend"` whose `rect` bounds it.
//!
//! A figure wider than one panel carries a CSS `min-width` ([`min_width`]): shown in a box
//! that scrolls sideways, its text stays legible on a narrow screen instead of shrinking.

use std::fmt::Write as _;

mod key;

use crate::check::figure::{Figure, Layer, Plot, Shape, Style, CLOUD};
use crate::mathtext::escape;
use crate::numfmt::sig;
use key::{draw_labels, draw_legend};

/// Plot-area height of a panel, and of a panel of a figure with many panels.
const PLOT_H: f64 = 220.0;
const SMALL_H: f64 = 150.0;
/// Plot-area width of a panel without equal scales.
const PLOT_W: f64 = 330.0;
/// Room around a plot area: tick labels and axis label (left, bottom), title (top).
const LEFT: f64 = 60.0;
const RIGHT: f64 = 16.0;
const TOP: f64 = 26.0;
const BOTTOM: f64 = 42.0;
/// Outer margin of the document, and the widest a row of panels may grow.
const MARGIN: f64 = 8.0;
const MAX_ROW: f64 = 1200.0;
/// Average advance of a character of the sans-serif font, per pixel of font size.
const CHAR_W: f64 = 0.6;
/// The narrowest document: room for one panel and its key.
const NARROWEST: f64 = 420.0;
/// The smallest text of a figure, in px: its tick labels.
const TICK_FONT: f64 = 11.0;
/// The size in px the smallest text keeps when a figure is shown narrower than it is drawn.
const READABLE_TEXT: f64 = 9.0;
/// The widest figure left free to shrink, in px: one panel without equal scales (422 px). On a
/// 400-px-wide screen, whose column is about 338 px beside the page's and a claim's padding,
/// its ticks keep at least 11 × 338 / 430 ≈ 8.7 px; a wider figure gets a minimum width
/// instead ([`min_width`]).
const FREE_TO_SHRINK: f64 = 430.0;

/// The colour of a style, as CSS: the Okabe–Ito colour-blind-safe palette, restricted to its
/// colours with at least 3:1 contrast against white (enough for lines and markers; text
/// labels take a darker shade where needed, `label_colour`).
pub fn css_colour(s: Style) -> String {
    colour(s).to_string()
}

fn colour(s: Style) -> &'static str {
    match s {
        Style::Printed => "#000000",
        Style::Computed => "#0072B2",
        Style::Other => "#D55E00",
        Style::Third => "#009E73",
        Style::Mark => "#CC79A7",
    }
}

/// The colour of a style's text labels: its series colour where that reaches the 4.5:1 of
/// text against white, else a darker shade of the same hue that does.
pub(crate) fn label_colour(s: Style) -> &'static str {
    match s {
        Style::Other => "#B34D00",
        Style::Third => "#007A5A",
        Style::Mark => "#A36186",
        s => colour(s),
    }
}

/// Dash pattern of a style's lines: a second cue beside the colour.
fn dash(s: Style) -> Option<&'static str> {
    match s {
        Style::Printed | Style::Mark => None,
        Style::Computed => Some("7 3"),
        Style::Other => Some("9 3 2 3"),
        Style::Third => Some("2 2.5"),
    }
}

/// A marker's outline around the origin, of radius about `r`, and whether it is filled.
fn marker(s: Style, r: f64) -> (String, bool) {
    match s {
        Style::Printed => (format!("M{0},{0}h{1}v{1}h-{1}z", -r, 2.0 * r), true),
        Style::Computed => (
            format!(
                "M{},0a{r},{r} 0 1,0 {},0a{r},{r} 0 1,0 {},0z",
                -r,
                2.0 * r,
                -2.0 * r
            ),
            true,
        ),
        Style::Other => (
            format!(
                "M0,{:.2}L{:.2},{:.2}L{:.2},{:.2}z",
                -1.25 * r,
                1.1 * r,
                0.7 * r,
                -1.1 * r,
                0.7 * r
            ),
            true,
        ),
        Style::Third => (
            format!("M0,{0:.2}L{1},0L0,{2:.2}L{3},0z", -1.3 * r, r, 1.3 * r, -r),
            true,
        ),
        Style::Mark => {
            let q = 1.6 * r;
            (
                format!(
                    "M{:.2},0a{q:.2},{q:.2} 0 1,0 {:.2},0a{q:.2},{q:.2} 0 1,0 {:.2},0z",
                    -q,
                    2.0 * q,
                    -2.0 * q
                ),
                false,
            )
        }
    }
}

/// A panel placed on the page: its data window (in log₁₀ on a logarithmic axis) and the
/// pixel rectangle of its plot area.
struct Axes {
    x: [f64; 2],
    y: [f64; 2],
    left: f64,
    top: f64,
    w: f64,
    h: f64,
    log_x: bool,
    log_y: bool,
}

impl Axes {
    /// The pixel of a data point; `None` for a point the axes cannot show (non-positive on a
    /// logarithmic axis, non-finite, or beyond a range that overflows).
    fn px(&self, q: [f64; 2]) -> Option<(f64, f64)> {
        let xv = if self.log_x {
            (q[0] > 0.0).then(|| q[0].log10())?
        } else {
            q[0]
        };
        let yv = if self.log_y {
            (q[1] > 0.0).then(|| q[1].log10())?
        } else {
            q[1]
        };
        let px = self.left + (xv - self.x[0]) / (self.x[1] - self.x[0]) * self.w;
        let py = self.top + self.h - (yv - self.y[0]) / (self.y[1] - self.y[0]) * self.h;
        // a range that overflows (values near f64::MAX) has no pixel either
        (px.is_finite() && py.is_finite()).then_some((px, py))
    }
}

/// The data range of a panel in drawing coordinates, padded: its window, or its layers'
/// extent.
fn extent(p: &Plot) -> ([f64; 2], [f64; 2]) {
    let tx = |v: f64| if p.log_x { v.log10() } else { v };
    let ty = |v: f64| if p.log_y { v.log10() } else { v };
    let (x, y) = match p.window {
        Some((x, y)) => ([tx(x[0]), tx(x[1])], [ty(y[0]), ty(y[1])]),
        None => {
            let mut x = [f64::INFINITY, f64::NEG_INFINITY];
            let mut y = x;
            for l in &p.layers {
                for q in &l.points {
                    let (xv, yv) = (tx(q[0]), ty(q[1]));
                    if xv.is_finite() && yv.is_finite() {
                        x = [x[0].min(xv), x[1].max(xv)];
                        if l.shape != Shape::Verticals {
                            y = [y[0].min(yv), y[1].max(yv)];
                        }
                    }
                }
            }
            (x, y)
        }
    };
    let labelled = p.layers.iter().any(|l| !l.labels.is_empty());
    let pad = |r: [f64; 2]| {
        let r = if !(r[0].is_finite() && r[1].is_finite()) {
            [0.0, 1.0]
        } else if r[1] - r[0] <= 0.0 {
            let m = 0.5f64.max(0.1 * r[0].abs());
            [r[0] - m, r[1] + m]
        } else {
            r
        };
        // room for the markers, and for the point labels placed outward
        let m = if labelled { 0.12 } else { 0.04 } * (r[1] - r[0]);
        [r[0] - m, r[1] + m]
    };
    (pad(x), pad(y))
}

/// Widen a range about its centre to `len`.
fn widen(r: [f64; 2], len: f64) -> [f64; 2] {
    let c = 0.5 * (r[0] + r[1]);
    [c - 0.5 * len, c + 0.5 * len]
}

/// Each panel's window and plot-area size: equal scales where claimed, one common size for
/// the equal-scale panels of a figure (the widest data aspect, within limits).
fn layout(f: &Figure) -> Vec<([f64; 2], [f64; 2], f64, f64)> {
    let h = if f.panels.len() > 6 { SMALL_H } else { PLOT_H };
    let ext: Vec<_> = f.panels.iter().map(extent).collect();
    let aspect = f
        .panels
        .iter()
        .zip(&ext)
        .filter(|(p, _)| p.equal_aspect)
        .map(|(_, (x, y))| (x[1] - x[0]) / (y[1] - y[0]))
        .fold(0.0, f64::max);
    let w_eq = (h * aspect).clamp(0.6 * h, 2.0 * h);
    f.panels
        .iter()
        .zip(ext)
        .map(|(p, (x, y))| {
            if p.equal_aspect {
                // one data unit is the same number of pixels on both axes
                let s = ((x[1] - x[0]) / w_eq).max((y[1] - y[0]) / h);
                (widen(x, s * w_eq), widen(y, s * h), w_eq, h)
            } else {
                (x, y, PLOT_W, h)
            }
        })
        .collect()
}

/// Round ticks (1, 2 or 5 × 10ⁿ apart) inside [lo, hi], about `n` of them.
fn ticks(lo: f64, hi: f64, n: f64) -> Vec<f64> {
    let span = hi - lo;
    if !(span > 0.0 && span.is_finite()) {
        return Vec::new();
    }
    let raw = span / n.max(1.0);
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag);
    let (a, b) = ((lo / step).ceil() as i64, (hi / step).floor() as i64);
    (a..=b).map(|k| k as f64 * step).collect()
}

/// Ticks of a logarithmic axis (in log₁₀): the decades, with 2 and 5 between them when
/// fewer than two decades are shown.
fn log_ticks(lo: f64, hi: f64) -> Vec<f64> {
    let (a, b) = (lo.ceil() as i64, hi.floor() as i64);
    let subs: &[f64] = if b - a < 2 { &[1.0, 2.0, 5.0] } else { &[1.0] };
    ((a - 1)..=b)
        .flat_map(|k| subs.iter().map(move |m| (m * 10f64.powi(k as i32)).log10()))
        .filter(|v| (lo..=hi).contains(v))
        .collect()
}

fn tick_text(v: f64, step: f64) -> String {
    if v.abs() < 1e-6 * step.abs() {
        "0".into()
    } else {
        sig(v)
    }
}

/// The axes of one panel: frame, grid, ticks, labels, title.
fn draw_axes(s: &mut String, p: &Plot, a: &Axes) {
    let (l, t, w, h) = (a.left, a.top, a.w, a.h);
    let _ = write!(
        s,
        "<g class=\"axes\" font-size=\"{TICK_FONT}\" fill=\"#333\">"
    );
    let xt = if a.log_x {
        log_ticks(a.x[0], a.x[1])
    } else {
        ticks(a.x[0], a.x[1], (w / 55.0).max(3.0))
    };
    let step = xt.get(1).zip(xt.first()).map_or(1.0, |(b, a)| b - a);
    for v in &xt {
        let px = l + (v - a.x[0]) / (a.x[1] - a.x[0]) * w;
        let text = if a.log_x {
            sig(10f64.powf(*v))
        } else {
            tick_text(*v, step)
        };
        let _ = write!(
            s,
            "<line x1=\"{px:.2}\" y1=\"{t:.2}\" x2=\"{px:.2}\" y2=\"{:.2}\" stroke=\"#e6e6e6\"/><line x1=\"{px:.2}\" y1=\"{0:.2}\" x2=\"{px:.2}\" y2=\"{:.2}\" stroke=\"#666\"/><text x=\"{px:.2}\" y=\"{:.2}\" text-anchor=\"middle\">{}</text>",
            t + h,
            t + h + 4.0,
            t + h + 15.0,
            escape(&text)
        );
    }
    let yt = if a.log_y {
        log_ticks(a.y[0], a.y[1])
    } else {
        ticks(a.y[0], a.y[1], (h / 45.0).max(3.0))
    };
    let step = yt.get(1).zip(yt.first()).map_or(1.0, |(b, a)| b - a);
    for v in &yt {
        let py = t + h - (v - a.y[0]) / (a.y[1] - a.y[0]) * h;
        let _ = write!(
            s,
            "<line x1=\"{l:.2}\" y1=\"{py:.2}\" x2=\"{:.2}\" y2=\"{py:.2}\" stroke=\"#e6e6e6\"/><line x1=\"{:.2}\" y1=\"{py:.2}\" x2=\"{l:.2}\" y2=\"{py:.2}\" stroke=\"#666\"/><text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"end\">{}</text>",
            l + w,
            l - 4.0,
            l - 6.0,
            py + 4.0,
            escape(&if a.log_y {
                sig(10f64.powf(*v))
            } else {
                tick_text(*v, step)
            })
        );
    }
    let _ = write!(
        s,
        "<rect class=\"plot-area\" x=\"{l:.2}\" y=\"{t:.2}\" width=\"{w:.2}\" height=\"{h:.2}\" fill=\"none\" stroke=\"#999\"/>\
         <text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"middle\" font-size=\"12\">{}</text>\
         <text transform=\"translate({:.2},{:.2}) rotate(-90)\" text-anchor=\"middle\" font-size=\"12\">{}</text>\
         <text x=\"{:.2}\" y=\"{:.2}\" text-anchor=\"middle\" font-size=\"13\" fill=\"#000\">{}</text></g>",
        l + 0.5 * w,
        t + h + 32.0,
        escape(&p.x_label),
        l - 46.0,
        t + 0.5 * h,
        escape(&p.y_label),
        l + 0.5 * w,
        t - 9.0,
        escape(&p.title)
    );
}

fn points_attr(pts: &[(f64, f64)]) -> String {
    pts.iter()
        .map(|(x, y)| format!("{x:.2},{y:.2}"))
        .collect::<Vec<_>>()
        .join(" ")
}

/// The stroke attributes of a line layer.
fn stroke(l: &Layer) -> String {
    let c = colour(l.style);
    if l.beneath {
        // wide and pale: the layers drawn on it stay visible, and so does it
        return format!(
            "stroke=\"{c}\" stroke-width=\"6\" stroke-opacity=\"0.4\" stroke-linejoin=\"round\""
        );
    }
    let width = if l.style == Style::Printed { 2.0 } else { 1.8 };
    let mut s = format!("stroke=\"{c}\" stroke-width=\"{width}\" stroke-linejoin=\"round\"");
    if let Some(d) = dash(l.style) {
        let _ = write!(s, " stroke-dasharray=\"{d}\"");
    }
    s
}

fn push_markers(s: &mut String, style: Style, pts: &[(f64, f64)], r: f64) {
    let (d, filled) = marker(style, r);
    let c = colour(style);
    let paint = if filled {
        format!("fill=\"{c}\" stroke=\"none\"")
    } else {
        format!("fill=\"none\" stroke=\"{c}\" stroke-width=\"2\"")
    };
    let _ = write!(s, "<g class=\"markers\" {paint}>");
    for (x, y) in pts {
        let _ = write!(
            s,
            "<path transform=\"translate({x:.2},{y:.2})\" d=\"{d}\"/>"
        );
    }
    s.push_str("</g>");
}

/// One layer's data.
fn draw_layer(s: &mut String, l: &Layer, a: &Axes) {
    let pts: Vec<(f64, f64)> = l.points.iter().filter_map(|q| a.px(*q)).collect();
    let _ = write!(
        s,
        "<g class=\"layer\" data-name=\"{}\" data-style=\"{}\">",
        escape(&l.name),
        style_name(l.style)
    );
    match l.shape {
        Shape::Points if l.points.len() > CLOUD => push_markers(s, l.style, &pts, 1.3),
        Shape::Points => push_markers(s, l.style, &pts, 4.0),
        Shape::Line | Shape::Polygon => {
            let tag = if l.shape == Shape::Line {
                "polyline"
            } else {
                "polygon"
            };
            let _ = write!(
                s,
                "<{tag} points=\"{}\" fill=\"none\" {}/>",
                points_attr(&pts),
                stroke(l)
            );
            if l.vertices {
                // beneath, larger: the markers drawn on them leave a rim
                push_markers(s, l.style, &pts, if l.beneath { 4.5 } else { 3.0 });
            }
        }
        Shape::Verticals => {
            for (x, _) in &pts {
                let _ = write!(
                    s,
                    "<line x1=\"{x:.2}\" y1=\"{:.2}\" x2=\"{x:.2}\" y2=\"{:.2}\" {}/>",
                    a.top,
                    a.top + a.h,
                    stroke(l)
                );
            }
        }
    }
    s.push_str("</g>");
}

fn style_name(s: Style) -> &'static str {
    match s {
        Style::Printed => "printed",
        Style::Computed => "computed",
        Style::Other => "other",
        Style::Third => "third",
        Style::Mark => "mark",
    }
}

/// Break a caption into lines of at most `n` characters, at spaces.
fn wrap(text: &str, n: usize) -> Vec<String> {
    let mut lines = vec![String::new()];
    for word in text.split_whitespace() {
        let last = lines.last_mut().map_or(0, |l| l.chars().count());
        if last > 0 && last + 1 + word.chars().count() > n {
            lines.push(String::new());
        }
        if let Some(l) = lines.last_mut() {
            if !l.is_empty() {
                l.push(' ');
            }
            l.push_str(word);
        }
    }
    lines
}

/// Where a figure's panels go: each panel's window and plot-area size ([`layout`]), the cells
/// of the grid they fill row by row, and the document's width.
struct Grid {
    sizes: Vec<([f64; 2], [f64; 2], f64, f64)>,
    cell_w: f64,
    cell_h: f64,
    cols: usize,
    rows: usize,
    width: f64,
}

fn grid(f: &Figure) -> Grid {
    let sizes = layout(f);
    let cell_w = sizes.iter().map(|z| z.2).fold(0.0, f64::max) + LEFT + RIGHT;
    let cell_h = sizes.iter().map(|z| z.3).fold(0.0, f64::max) + TOP + BOTTOM;
    let cols = ((MAX_ROW / cell_w).floor() as usize).clamp(1, f.panels.len().max(1));
    let rows = f.panels.len().div_ceil(cols);
    let width = (cols as f64 * cell_w + 2.0 * MARGIN).max(NARROWEST);
    Grid {
        sizes,
        cell_w,
        cell_h,
        cols,
        rows,
        width,
    }
}

/// The minimum width of a document `width` px wide: the width at which its smallest text is
/// [`READABLE_TEXT`] px (of its width rounded up, as its attribute may be); `None` when it is
/// free to shrink.
fn shrink_limit(width: f64) -> Option<f64> {
    (width > FREE_TO_SHRINK).then(|| (width.ceil() * READABLE_TEXT / TICK_FONT).ceil())
}

/// The narrowest a figure is shown, in CSS px (its SVG's `min-width`): the width at which its
/// smallest text is still `READABLE_TEXT` px, so that on a narrow screen a figure of several
/// panels keeps its text legible and scrolls sideways (in a container with `overflow-x: auto`)
/// instead of shrinking. `None` for a figure no wider than one panel, which may shrink.
pub fn min_width(f: &Figure) -> Option<f64> {
    shrink_limit(grid(f).width)
}

/// One figure as one SVG document with a `<title>` (the figure's title) and a `<desc>` (its
/// caption). `standalone` writes a file of its own (XML declaration, namespace, the title and
/// caption also as visible text); otherwise it is inlined in HTML beside its caption.
pub fn figure_svg(f: &Figure, standalone: bool) -> String {
    let g = grid(f);
    let width = g.width;
    let head = if standalone { 28.0 } else { 0.0 };
    let mut body = String::new();
    for (i, (p, (x, y, w, h))) in f.panels.iter().zip(g.sizes).enumerate() {
        let a = Axes {
            x,
            y,
            left: MARGIN + (i % g.cols) as f64 * g.cell_w + LEFT,
            top: head + (i / g.cols) as f64 * g.cell_h + TOP,
            w,
            h,
            log_x: p.log_x,
            log_y: p.log_y,
        };
        let _ = write!(
            body,
            "<g class=\"panel\" data-equal-aspect=\"{}\">",
            p.equal_aspect
        );
        draw_axes(&mut body, p, &a);
        for l in &p.layers {
            draw_layer(&mut body, l, &a);
        }
        draw_labels(&mut body, p, &a);
        body.push_str("</g>");
    }
    let grid_bottom = head + g.rows as f64 * g.cell_h;
    let legend_h = draw_legend(&mut body, f, grid_bottom + 4.0, width);
    let mut height = grid_bottom + legend_h + 12.0;
    if standalone {
        let chars = ((width - 2.0 * MARGIN) / (CHAR_W * 12.0)) as usize;
        for line in wrap(&f.caption, chars.max(20)) {
            height += 16.0;
            let _ = write!(
                body,
                "<text x=\"{MARGIN}\" y=\"{height:.2}\" font-size=\"12\" fill=\"#333\">{}</text>",
                escape(&line)
            );
        }
        let _ = write!(
            body,
            "<text x=\"{MARGIN}\" y=\"20\" font-size=\"15\" font-weight=\"bold\">{}</text>",
            escape(&f.title)
        );
        height += 8.0;
    }
    document(f, standalone, (width, height), &body)
}

/// The `<svg>` element around a figure's drawn `body`, `size` (width, height) px.
fn document(f: &Figure, standalone: bool, size: (f64, f64), body: &str) -> String {
    let (width, height) = size;
    let id = escape(&f.id);
    let min = shrink_limit(width).map_or(String::new(), |m| format!("min-width: {m:.0}px; "));
    let mut s = String::new();
    if standalone {
        s.push_str("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    }
    let _ = write!(
        s,
        "<svg {}width=\"{width:.0}\" height=\"{height:.0}\" viewBox=\"0 0 {width:.0} {height:.0}\" role=\"img\" aria-labelledby=\"{id}-title {id}-desc\" font-family=\"sans-serif\" style=\"{min}max-width: 100%; height: auto\">\
         <title id=\"{id}-title\">{}</title><desc id=\"{id}-desc\">{}</desc>\
         <rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>{body}</svg>",
        if standalone {
            "xmlns=\"http://www.w3.org/2000/svg\" "
        } else {
            ""
        },
        escape(&f.title),
        escape(&f.caption)
    );
    if standalone {
        s.push('\n');
    }
    s
}

/// One plot as an inline SVG document: a figure of one panel, titled by the panel.
pub fn plot_svg(p: &Plot) -> String {
    figure_svg(
        &Figure {
            id: "plot".into(),
            claim: String::new(),
            title: p.title.clone(),
            caption: p.title.clone(),
            panels: vec![p.clone()],
        },
        false,
    )
}

/// The file name of a figure's SVG beside the report: its id, when the id is a plain name
/// (letters, digits, `-`, `_`, `.`, not starting with a dot), so that writing it can never
/// reach outside the report's folder.
pub fn file_name(f: &Figure) -> Option<String> {
    let plain = !f.id.is_empty()
        && !f.id.starts_with('.')
        && f.id
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || matches!(c, '-' | '_' | '.'));
    plain.then(|| format!("{}.svg", f.id))
}

/// Every figure as a standalone SVG document named `<figure id>.svg`; an id that is not a
/// plain file name is an error rather than a path outside the report's folder.
pub fn figure_files(figures: &[Figure]) -> crate::error::Result<Vec<(String, String)>> {
    figures
        .iter()
        .map(|f| {
            file_name(f)
                .map(|n| (n, figure_svg(f, true)))
                .ok_or_else(|| {
                    crate::error::Error::InvalidInput(format!(
                        "figure id {:?} is not a plain file name",
                        f.id
                    ))
                })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_round_and_inside() {
        let t = ticks(-0.3, 2.2, 5.0);
        assert_eq!(t.first().copied(), Some(0.0));
        assert!(t.iter().all(|v| (-0.3..=2.2).contains(v)));
        assert!(ticks(1.0, 1.0, 5.0).is_empty());
        let l = log_ticks(-3.2, -1.9);
        assert!(l.iter().all(|v| (-3.2..=-1.9).contains(v)) && l.len() >= 3);
    }

    #[test]
    fn file_names_stay_in_the_folder() {
        let f = |id: &str| Figure {
            id: id.into(),
            claim: String::new(),
            title: String::new(),
            caption: String::new(),
            panels: Vec::new(),
        };
        assert_eq!(
            file_name(&f("fig-ex2-0.1")).as_deref(),
            Some("fig-ex2-0.1.svg")
        );
        assert_eq!(file_name(&f("../x")), None);
        assert_eq!(file_name(&f(".hidden")), None);
        assert_eq!(file_name(&f("a/b")), None);
        assert_eq!(file_name(&f("")), None);
    }

    #[test]
    fn wide_figures_keep_a_minimum_width() {
        assert_eq!(shrink_limit(420.0), None);
        // 828 × 9 / 11 = 677.45…
        assert_eq!(shrink_limit(828.0), Some(678.0));
        let m = shrink_limit(1143.6).unwrap_or(0.0);
        assert!(m * TICK_FONT / 1144.0 >= READABLE_TEXT && m <= 1144.0);
    }

    #[test]
    fn wrap_breaks_at_spaces() {
        assert_eq!(wrap("aa bb cc", 5), vec!["aa bb", "cc"]);
    }
}
