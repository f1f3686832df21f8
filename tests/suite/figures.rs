//! Every figure of the paper run, drawn as the report draws it, read back from the SVG: what
//! a reader would see is what the figure's data says.

use orthocheck::check::figure::{Figure, Layer, Shape, Style};
use orthocheck::report::svg::{css_colour, figure_svg};
use roxmltree::{Document, Node};

fn figures() -> &'static [Figure] {
    let r = crate::common::report().unwrap();
    assert!(r.figures.len() >= 14, "{} figures", r.figures.len());
    &r.figures
}

fn num(n: Node, a: &str) -> f64 {
    n.attribute(a)
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{a} of {:?}", n.tag_name().name()))
}

fn class<'a>(n: Node<'a, 'a>, c: &str) -> Vec<Node<'a, 'a>> {
    n.descendants()
        .filter(|d| d.attribute("class") == Some(c))
        .collect()
}

/// The pixels of a layer's data, in the order of its points: polyline and polygon vertices,
/// vertical lines (top and bottom), markers (`translate(x,y)`) of a points layer.
fn drawn(layer: Node, shape: Shape) -> Vec<(f64, f64)> {
    let pair = |t: &str| -> (f64, f64) {
        let (x, y) = t.split_once(',').expect("x,y");
        (x.parse().unwrap(), y.parse().unwrap())
    };
    let mut out = Vec::new();
    for n in layer.descendants().filter(|n| n.is_element()) {
        match (n.tag_name().name(), shape) {
            ("polyline" | "polygon", _) => {
                out.extend(n.attribute("points").unwrap().split(' ').map(pair))
            }
            ("line", Shape::Verticals) => {
                out.push((num(n, "x1"), num(n, "y1")));
                out.push((num(n, "x2"), num(n, "y2")));
            }
            ("path", Shape::Points) => {
                let t = n.attribute("transform").unwrap();
                out.push(pair(&t["translate(".len()..t.len() - 1]));
            }
            _ => {}
        }
    }
    out
}

/// Each figure drawn, with its panels and their layers side by side with the data.
fn each_panel(mut f: impl FnMut(&Figure, usize, Node, &[Node])) {
    for fig in figures() {
        let text = figure_svg(fig, true);
        let doc = Document::parse(&text).unwrap_or_else(|e| panic!("{}: {e}", fig.id));
        let panels = class(doc.root_element(), "panel");
        assert_eq!(panels.len(), fig.panels.len(), "{}", fig.id);
        for (i, p) in panels.iter().enumerate() {
            let layers = class(*p, "layer");
            assert_eq!(layers.len(), fig.panels[i].layers.len(), "{}", fig.id);
            f(fig, i, *p, &layers);
        }
    }
}

fn rect(n: Node) -> [f64; 4] {
    let (x, y) = (num(n, "x"), num(n, "y"));
    [x, y, x + num(n, "width"), y + num(n, "height")]
}

fn plot_area(panel: Node) -> [f64; 4] {
    let a = class(panel, "plot-area");
    assert_eq!(a.len(), 1);
    rect(a[0])
}

/// The points a layer can show: all of them, but those a logarithmic axis cannot place.
fn shown(l: &Layer, log_x: bool) -> Vec<[f64; 2]> {
    l.points
        .iter()
        .copied()
        .filter(|q| q[0].is_finite() && q[1].is_finite() && (!log_x || q[0] > 0.0))
        .collect()
}

#[test]
fn every_data_point_is_drawn_inside_its_plot_area() {
    // pixel coordinates are written to two decimals
    let slack = 0.01;
    each_panel(|fig, i, panel, layers| {
        let [x0, y0, x1, y1] = plot_area(panel);
        for (l, node) in fig.panels[i].layers.iter().zip(layers) {
            let px = drawn(*node, l.shape);
            let expected = match l.shape {
                Shape::Verticals => 2 * shown(l, fig.panels[i].log_x).len(),
                _ => shown(l, fig.panels[i].log_x).len(),
            };
            assert_eq!(
                px.len(),
                expected,
                "{} / {}: every point drawn",
                fig.id,
                l.name
            );
            for (x, y) in px {
                assert!(
                    x >= x0 - slack && x <= x1 + slack && y >= y0 - slack && y <= y1 + slack,
                    "{} / {} / {}: ({x}, {y}) outside [{x0}, {x1}] × [{y0}, {y1}]",
                    fig.id,
                    fig.panels[i].title,
                    l.name
                );
            }
        }
    });
}

#[test]
fn keys_lie_outside_every_plot_area() {
    for fig in figures() {
        let text = figure_svg(fig, true);
        let doc = Document::parse(&text).unwrap();
        let legend = class(doc.root_element(), "legend");
        let named = fig
            .panels
            .iter()
            .flat_map(|p| &p.layers)
            .any(|l| !l.name.is_empty());
        assert_eq!(legend.len(), usize::from(named), "{}: one key", fig.id);
        let Some(g) = legend.first() else { continue };
        let box_ = g
            .children()
            .find(|n| n.has_tag_name("rect"))
            .map(rect)
            .unwrap();
        for panel in class(doc.root_element(), "panel") {
            let a = plot_area(panel);
            let apart = box_[2] <= a[0] || a[2] <= box_[0] || box_[3] <= a[1] || a[3] <= box_[1];
            assert!(apart, "{}: key {box_:?} over plot area {a:?}", fig.id);
        }
    }
}

#[test]
fn each_series_of_a_figure_has_its_own_colour() {
    let colours: Vec<String> = Style::ALL.iter().map(|s| css_colour(*s)).collect();
    for (i, c) in colours.iter().enumerate() {
        assert!(!colours[..i].contains(c), "{c} twice in the palette");
    }
    for fig in figures() {
        let mut seen: Vec<(&str, Style)> = Vec::new();
        for l in fig.panels.iter().flat_map(|p| &p.layers) {
            match seen.iter().find(|(n, _)| *n == l.name) {
                Some((_, s)) => assert_eq!(*s, l.style, "{}: {} in two styles", fig.id, l.name),
                None => {
                    let other = seen.iter().find(|(_, s)| *s == l.style);
                    assert!(
                        other.is_none(),
                        "{}: {} and {:?} share a colour",
                        fig.id,
                        l.name,
                        other
                    );
                    seen.push((&l.name, l.style));
                }
            }
        }
    }
}

#[test]
fn equal_aspect_panels_have_one_scale() {
    let mut checked = 0;
    each_panel(|fig, i, panel, layers| {
        let plot = &fig.panels[i];
        assert_eq!(
            panel.attribute("data-equal-aspect"),
            Some(if plot.equal_aspect { "true" } else { "false" })
        );
        if !plot.equal_aspect {
            return;
        }
        // pairs of (data point, its pixel) over all the panel's layers
        let pairs: Vec<([f64; 2], (f64, f64))> = plot
            .layers
            .iter()
            .zip(layers)
            .filter(|(l, _)| l.shape != Shape::Verticals)
            .flat_map(|(l, n)| shown(l, false).into_iter().zip(drawn(*n, l.shape)))
            .collect();
        let scale = |k: usize| {
            let d = |q: &([f64; 2], (f64, f64))| (q.0[k], if k == 0 { q.1 .0 } else { q.1 .1 });
            let lo = pairs
                .iter()
                .map(d)
                .min_by(|a, b| a.0.total_cmp(&b.0))
                .unwrap();
            let hi = pairs
                .iter()
                .map(d)
                .max_by(|a, b| a.0.total_cmp(&b.0))
                .unwrap();
            ((hi.1 - lo.1) / (hi.0 - lo.0)).abs()
        };
        let (sx, sy) = (scale(0), scale(1));
        // two-decimal pixels over spans of tens of pixels
        assert!(
            (sx - sy).abs() <= 2e-3 * sx,
            "{} / {}: {sx} px per unit in x, {sy} in y",
            fig.id,
            plot.title
        );
        checked += 1;
    });
    assert!(checked >= 30, "{checked} equal-aspect panels");
}

#[test]
fn a_layer_under_an_equal_one_is_drawn_beneath_it() {
    for fig in figures() {
        for p in &fig.panels {
            for (i, a) in p.layers.iter().enumerate() {
                for b in &p.layers[i + 1..] {
                    let lines = |l: &Layer| matches!(l.shape, Shape::Line | Shape::Polygon);
                    let near = a.points.len() == b.points.len()
                        && a.points.iter().zip(&b.points).all(|(u, v)| {
                            let span = 1e-2 * (u[0].abs() + u[1].abs()).max(1.0);
                            (u[0] - v[0]).abs() < span && (u[1] - v[1]).abs() < span
                        });
                    if lines(a) && lines(b) && a.name != b.name && near {
                        assert!(
                            a.beneath,
                            "{} / {}: {} hidden under {}",
                            fig.id, p.title, a.name, b.name
                        );
                    }
                }
            }
        }
    }
}

#[test]
fn captions_and_labels_hold_no_latex() {
    for fig in figures() {
        let mut texts = vec![fig.title.as_str(), fig.caption.as_str()];
        for p in &fig.panels {
            texts.extend([p.title.as_str(), p.x_label.as_str(), p.y_label.as_str()]);
            texts.extend(p.layers.iter().map(|l| l.name.as_str()));
        }
        for t in texts {
            assert!(!t.contains('\\') && !t.contains('$'), "{}: {t}", fig.id);
        }
    }
}

#[test]
fn every_svg_is_titled_and_described() {
    for fig in figures() {
        for standalone in [true, false] {
            let text = figure_svg(fig, standalone);
            let doc = Document::parse(&text).unwrap();
            let root = doc.root_element();
            let child = |tag: &str| {
                root.children()
                    .find(|n| n.has_tag_name(tag))
                    .and_then(|n| n.text())
                    .map(str::to_string)
            };
            assert_eq!(
                child("title").as_deref(),
                Some(fig.title.as_str()),
                "{}",
                fig.id
            );
            assert_eq!(
                child("desc").as_deref(),
                Some(fig.caption.as_str()),
                "{}",
                fig.id
            );
            assert_eq!(root.attribute("role"), Some("img"));
        }
    }
}

#[test]
fn noise_curves_speak_in_percent() {
    let noise: Vec<&Figure> = figures()
        .iter()
        .filter(|f| f.id.contains("noise"))
        .collect();
    assert!(noise.len() >= 8, "{} noise figures", noise.len());
    for f in noise {
        assert!(f.caption.contains("Failed trials"), "{}", f.id);
        assert!(f.title.contains('%'), "{}", f.id);
        for p in &f.panels {
            assert!(
                p.x_label.contains('%') && p.log_x,
                "{}: {}",
                f.id,
                p.x_label
            );
            assert!(p.y_label.contains("≤ x"), "{}: {}", f.id, p.y_label);
        }
    }
}

#[test]
fn the_rounding_cloud_says_what_it_draws() {
    let f = figures()
        .iter()
        .find(|f| f.id == "fig-ex2-rounding")
        .unwrap();
    let cloud: usize = f.panels[0]
        .layers
        .iter()
        .filter(|l| l.points.len() > orthocheck::check::figure::CLOUD)
        .map(|l| l.points.len())
        .sum();
    assert!(
        f.caption.contains(&format!("{cloud} are drawn")),
        "{}",
        f.caption
    );
    // the paper's solutions are inside the window
    let marks = f.panels[0]
        .layers
        .iter()
        .find(|l| l.style == Style::Mark)
        .unwrap();
    let (x, y) = f.panels[0].window.unwrap();
    assert!(marks
        .points
        .iter()
        .all(|q| (x[0]..=x[1]).contains(&q[0]) && (y[0]..=y[1]).contains(&q[1])));
}

#[test]
fn the_dof_grid_shows_only_the_grid() {
    let f = figures().iter().find(|f| f.id == "fig-dof-grid").unwrap();
    let p = &f.panels[0];
    let (_, y) = p.window.unwrap();
    assert!(y[0] > 0.0, "the frame axis starts at k = 1: {y:?}");
    let identifiable = p.layers.iter().find(|l| l.name == "recoverable").unwrap();
    assert!(
        !identifiable.points.contains(&[1.0, 1.0]),
        "a single point in one frame has no shape to identify"
    );
}
