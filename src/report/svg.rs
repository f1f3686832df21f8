//! SVG drawing of figure data with plotters: no computation beyond placing what the checks
//! computed.

use plotters::prelude::*;

use crate::check::figure::{Layer, Plot, Shape, Style};

/// Panel size in pixels.
const W: u32 = 420;
const H: u32 = 320;

/// The colour of a style, as CSS (for the figure's key).
pub fn css_colour(s: Style) -> String {
    let RGBColor(r, g, b) = colour(s);
    format!("rgb({r}, {g}, {b})")
}

fn colour(s: Style) -> RGBColor {
    match s {
        Style::Printed => RGBColor(60, 60, 60),
        Style::Computed => RGBColor(31, 119, 180),
        Style::Other => RGBColor(214, 120, 20),
        Style::Mark => RGBColor(200, 30, 45),
    }
}

/// The drawing range of a plot: the layers' extent with a margin (equal scales when asked).
fn range(p: &Plot) -> ((f64, f64), (f64, f64)) {
    let pts: Vec<[f64; 2]> = p
        .layers
        .iter()
        .flat_map(|l| l.points.iter().copied())
        .filter(|q| q[0].is_finite() && q[1].is_finite() && (!p.log_x || q[0] > 0.0))
        .map(|q| if p.log_x { [q[0].log10(), q[1]] } else { q })
        .collect();
    let f = |k: usize| {
        pts.iter()
            .map(|q| q[k])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), v| {
                (l.min(v), h.max(v))
            })
    };
    let (mut x, mut y) = (f(0), f(1));
    for r in [&mut x, &mut y] {
        if !r.0.is_finite() {
            *r = (0.0, 1.0);
        }
        if r.1 - r.0 <= 0.0 {
            *r = (r.0 - 0.5, r.1 + 0.5);
        }
    }
    let m = 0.08 * (x.1 - x.0);
    x = (x.0 - m, x.1 + m);
    let m = 0.08 * (y.1 - y.0);
    y = (y.0 - m, y.1 + m);
    if p.equal_aspect {
        // widen the narrower axis so that one unit has the same length on both
        let (sx, sy) = ((x.1 - x.0) / W as f64, (y.1 - y.0) / H as f64);
        if sx > sy {
            let c = 0.5 * (y.0 + y.1);
            let h = 0.5 * sx * H as f64;
            y = (c - h, c + h);
        } else {
            let c = 0.5 * (x.0 + x.1);
            let w = 0.5 * sy * W as f64;
            x = (c - w, c + w);
        }
    }
    (x, y)
}

fn draw<DB: DrawingBackend>(
    p: &Plot,
    area: &DrawingArea<DB, plotters::coord::Shift>,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    area.fill(&WHITE)?;
    let ((x0, x1), (y0, y1)) = match p.window {
        Some((x, y)) => ((x[0], x[1]), (y[0], y[1])),
        None => range(p),
    };
    let mut chart = ChartBuilder::on(area)
        .caption(&p.title, ("sans-serif", 15))
        .margin(8)
        .x_label_area_size(32)
        .y_label_area_size(44)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(p.x_label.as_str())
        .y_desc(p.y_label.as_str())
        .light_line_style(WHITE.mix(0.0));
    if p.log_x {
        mesh.x_label_formatter(&|v| format!("{:.0e}", 10f64.powf(*v)));
    }
    mesh.draw()?;
    for layer in &p.layers {
        draw_layer(&mut chart, layer, p.log_x, (y0, y1))?;
    }
    // image panels carry no legend (it would cover the points): the caption's key says it
    if !p.equal_aspect && p.layers.iter().any(|l| !l.name.is_empty()) {
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::LowerRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK.mix(0.3))
            .label_font(("sans-serif", 11))
            .draw()?;
    }
    Ok(())
}

fn draw_layer<DB: DrawingBackend>(
    chart: &mut ChartContext<
        DB,
        Cartesian2d<plotters::coord::types::RangedCoordf64, plotters::coord::types::RangedCoordf64>,
    >,
    l: &Layer,
    log_x: bool,
    y: (f64, f64),
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let c = colour(l.style);
    // a logarithmic axis is drawn in log₁₀ of the values (its labels say 10^v)
    let pt = |q: &[f64; 2]| -> (f64, f64) { (if log_x { q[0].log10() } else { q[0] }, q[1]) };
    let pts: Vec<(f64, f64)> = l
        .points
        .iter()
        .filter(|q| !log_x || q[0] > 0.0)
        .map(pt)
        .collect();
    let stroke = if l.style == Style::Printed { 1 } else { 2 };
    let series = match l.shape {
        Shape::Points => {
            let size = if l.points.len() > 200 { 1 } else { 4 };
            chart.draw_series(pts.iter().map(|p| Circle::new(*p, size, c.filled())))?
        }
        Shape::Line => chart.draw_series(LineSeries::new(pts.clone(), c.stroke_width(stroke)))?,
        Shape::Polygon => {
            let mut closed = pts.clone();
            if let Some(f) = pts.first() {
                closed.push(*f);
            }
            chart.draw_series(LineSeries::new(closed, c.stroke_width(stroke)))?
        }
        Shape::Verticals => chart.draw_series(
            pts.iter()
                .map(|p| PathElement::new(vec![(p.0, y.0), (p.0, y.1)], c.stroke_width(2))),
        )?,
    };
    if !l.name.is_empty() {
        series
            .label(l.name.as_str())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 14, y)], c.stroke_width(2)));
    }
    for (q, label) in pts.iter().zip(&l.labels) {
        if !label.is_empty() {
            chart.draw_series(std::iter::once(Text::new(
                label.clone(),
                *q,
                ("sans-serif", 13).into_font().color(&c),
            )))?;
        }
    }
    Ok(())
}

/// One plot as an SVG document (without an XML namespace URL: it is inlined in HTML).
pub fn plot_svg(p: &Plot) -> String {
    let mut s = String::new();
    {
        let area = SVGBackend::with_string(&mut s, (W, H)).into_drawing_area();
        if let Err(e) = draw(p, &area) {
            return format!(
                "<p>figure not drawn: {}</p>",
                super::html::escape(&e.to_string())
            );
        }
        let _ = area.present();
    }
    s.replace(" xmlns=\"http://www.w3.org/2000/svg\"", "")
}
