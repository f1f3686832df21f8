//! Every figure of the paper run, drawn as the report draws it, read back from the SVG: what
//! a reader would see is what the figure's data says.

use orthocheck::check::figure::{Figure, Layer, Plot, Shape, Style};
use orthocheck::check::{ClaimResult, Value};
use orthocheck::numfmt::{sampled_digits, sig_digits};
use orthocheck::report::svg::{css_colour, figure_svg, min_width};
use orthocheck::report::values::trials_of;
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

/// The claim result a figure illustrates.
fn result_of(f: &Figure) -> &'static ClaimResult {
    let r = crate::common::report().unwrap();
    r.claims
        .iter()
        .find(|c| c.id == f.claim)
        .unwrap_or_else(|| panic!("{}: no result {}", f.id, f.claim))
}

fn noise_figures() -> Vec<&'static Figure> {
    figures()
        .iter()
        .filter(|f| f.id.contains("noise"))
        .collect()
}

fn quantity<'a>(qs: &'a [orthocheck::check::Quantity], name: &str) -> Option<&'a Value> {
    qs.iter().find(|q| q.name == name).map(|q| &q.value)
}

fn real(v: &Value) -> f64 {
    match v {
        Value::Real { value } => value.0,
        v => panic!("not a real: {v:?}"),
    }
}

/// A panel's vertical lines in the style of what the paper printed: the paper's bound.
fn lines(p: &Plot) -> Vec<&Layer> {
    p.layers
        .iter()
        .filter(|l| l.shape == Shape::Verticals && l.style == Style::Printed)
        .collect()
}

#[test]
fn noise_figures_draw_the_papers_bound_apart_from_its_run() {
    let mut bounded = 0;
    for f in noise_figures() {
        let c = result_of(f);
        let bound = ["error below", "error above"]
            .iter()
            .find_map(|n| quantity(&c.printed, n).map(|v| (*n, v)));
        let Some((direction, Value::Printed { text, .. })) = bound else {
            // no number in the paper's words: no bound to draw, and the caption says so
            assert!(f.panels.iter().all(|p| lines(p).is_empty()), "{}", f.id);
            assert!(f.caption.contains("gives no number"), "{}", f.caption);
            continue;
        };
        bounded += 1;
        let percent = 100.0 * text.parse::<f64>().unwrap();
        let words = direction.trim_start_matches("error ");
        for p in &f.panels {
            let l = lines(p);
            assert_eq!(l.len(), 1, "{} / {}: one bound line", f.id, p.title);
            let at = l[0].points[0][0];
            assert!(
                (at - percent).abs() <= 1e-9 * percent,
                "{} / {}: bound drawn at {at} %, the paper says {percent} %",
                f.id,
                p.title
            );
            assert!(l[0].name.contains("paper's bound") && l[0].name.contains(words));
            assert_eq!(l[0].labels.len(), 1, "{}: the bound line is labelled", f.id);
            assert!(l[0].labels[0].starts_with("paper: "), "{}", l[0].labels[0]);
            if let Some(run) = p.layers.iter().find(|x| x.name == "the paper's test run") {
                assert_ne!(run.style, l[0].style, "{}: bound and run look alike", f.id);
            }
        }
        assert!(f.caption.contains("The paper says"), "{}", f.caption);
    }
    assert!(bounded >= 6, "{bounded} noise figures with a bound");
}

#[test]
fn noise_captions_say_why_in_the_judges_numbers() {
    for f in noise_figures() {
        let c = result_of(f);
        let Some(Value::Label { text: decision }) = quantity(&c.evidence.details, "decision")
        else {
            panic!("{}: no decision", f.id)
        };
        let words = if decision == "too close to call" {
            format!("the claim is {decision}")
        } else {
            format!("the claim {decision}")
        };
        assert!(
            f.caption.to_lowercase().contains(&words),
            "{}: {words}? {}",
            f.id,
            f.caption
        );
        let digits = sampled_digits(trials_of(c).unwrap_or(1));
        let pc = |x: f64| format!("{} %", sig_digits(100.0 * x, digits));
        let median = c
            .computed
            .iter()
            .any(|q| q.name.ends_with(": median trial's error"));
        // the numbers the result reports, as the caption shows them
        let mut shown = Vec::new();
        for q in &c.computed {
            if (median && q.name.ends_with(": median trial's error"))
                || (!median && q.name == "printed run: error")
            {
                shown.push(pc(real(&q.value)));
            }
            let rank = if median {
                ": percentile rank of the bound"
            } else {
                ": percentile of the printed run"
            };
            if q.name.ends_with(rank) {
                shown.push(sig_digits(real(&q.value), digits));
            }
        }
        assert!(shown.len() >= 3, "{}: {shown:?}", f.id);
        for t in shown {
            assert!(f.caption.contains(&t), "{}: {t} not in {}", f.id, f.caption);
        }
        // in the panel judged, one marker per model where the judge reads its curve
        let judged: Vec<&Plot> = f
            .panels
            .iter()
            .filter(|p| p.title.ends_with("(judged)"))
            .collect();
        assert_eq!(judged.len(), 1, "{}: one judged panel", f.id);
        let count = |s: Shape| judged[0].layers.iter().filter(|l| l.shape == s).count();
        assert_eq!(count(Shape::Points), count(Shape::Line), "{}", f.id);
        let reading = quantity(&c.computed, "reading");
        let Some(Value::Label { text: reading }) = reading else {
            panic!("{}: no reading", f.id)
        };
        let how = if reading.starts_with("mean") {
            "mean"
        } else {
            "largest"
        };
        let what = if reading.ends_with("squares") {
            "squares"
        } else {
            "lengths"
        };
        assert_eq!(
            judged[0].title,
            format!("{how} error in {what} (judged)"),
            "{}: the panel judged is the reading of the result",
            f.id
        );
    }
}

#[test]
fn noise_figures_are_titled_by_section_and_setting() {
    let noise = noise_figures();
    let mut titles: Vec<&str> = noise.iter().map(|f| f.title.as_str()).collect();
    for f in &noise {
        let c = result_of(f);
        assert!(
            f.title.starts_with(&format!("§{} (", c.section)),
            "{}: {} is not §{}",
            f.id,
            f.title,
            c.section
        );
        assert!(
            f.title.contains(" points, ") && f.title.contains(" frames): noise up to "),
            "{}",
            f.title
        );
    }
    let n = titles.len();
    titles.sort_unstable();
    titles.dedup();
    assert_eq!(titles.len(), n, "noise figures share a title: {titles:?}");
}

fn side_lengths(l: &Layer) -> Vec<f64> {
    let n = l.points.len();
    (0..n)
        .map(|i| {
            let (a, b) = (l.points[i], l.points[(i + 1) % n]);
            (a[0] - b[0]).hypot(a[1] - b[1])
        })
        .collect()
}

#[test]
fn the_two_frames_figure_shows_the_true_shapes() {
    let f = figures().iter().find(|f| f.id == "fig-two-frames").unwrap();
    let c = result_of(f);
    let reals = |name: &str| -> Vec<f64> {
        match quantity(&c.evidence.details, name) {
            Some(Value::Reals { values }) => values.iter().map(|r| r.0).collect(),
            v => panic!("{name}: {v:?}"),
        }
    };
    let layer = |p: &'static Plot, name: &str| -> &'static Layer {
        p.layers
            .iter()
            .find(|l| l.name == name && l.shape == Shape::Polygon)
            .unwrap_or_else(|| panic!("{}: no {name}", p.title))
    };
    let (shapes, views): (Vec<&Plot>, Vec<&Plot>) = f
        .panels
        .iter()
        .partition(|p| p.title.contains("true shape"));
    assert_eq!(shapes.len(), 1, "one panel of the true shapes");
    assert!(views.len() >= 2 && shapes[0].equal_aspect);
    let (a, b) = (layer(shapes[0], "PQR"), layer(shapes[0], "PQ′R′"));
    let (sa, sb) = (side_lengths(a), side_lengths(b));
    // the check's own sides, each triangle laid in its plane: P at the origin, PQ along x
    for (drawn, computed) in [(&sa, reals("sides of PQR")), (&sb, reals("sides of PQ′R′"))] {
        for (x, y) in drawn.iter().zip(&computed) {
            assert!((x - y).abs() <= 1e-9 * y, "side {x} drawn, {y} computed");
        }
    }
    for l in [a, b] {
        assert_eq!(l.points[0], [0.0, 0.0], "{}: P at the origin", l.name);
        assert_eq!(l.points[1][1], 0.0, "{}: PQ along x", l.name);
    }
    let differ = sa
        .iter()
        .zip(&sb)
        .any(|(x, y)| (x - y).abs() > 0.05 * x.max(*y));
    assert!(differ, "the true shapes look alike: {sa:?}, {sb:?}");
    // while the views show congruent images
    for p in views {
        let (u, v) = (
            side_lengths(layer(p, "PQR")),
            side_lengths(layer(p, "PQ′R′")),
        );
        for (x, y) in u.iter().zip(&v) {
            assert!(
                (x - y).abs() <= 1e-6 * x.max(*y),
                "{}: {u:?} vs {v:?}",
                p.title
            );
        }
    }
}

/// Whether a text cites a source line ("line 1404", "lines 1385-…").
fn cites_a_line(t: &str) -> bool {
    t.match_indices("line").any(|(i, _)| {
        let rest = &t[i + "line".len()..];
        let rest = rest.strip_prefix('s').unwrap_or(rest);
        rest.strip_prefix(' ')
            .is_some_and(|r| r.starts_with(|c: char| c.is_ascii_digit()))
    })
}

const SUBSCRIPTS: &str = "₀₁₂₃₄₅₆₇₈₉ₐₑₒₓₔₕₖₗₘₙₚₛₜ";

/// Whether a text runs symbols together, a subscript directly followed by a letter ("T₂ₐT₂_b").
fn runs_together(t: &str) -> bool {
    let c: Vec<char> = t.chars().collect();
    c.windows(2)
        .any(|w| SUBSCRIPTS.contains(w[0]) && w[1].is_alphabetic() && !SUBSCRIPTS.contains(w[1]))
}

#[test]
fn panel_titles_and_keys_are_words() {
    assert!(cites_a_line("line 1404: b −") && cites_a_line("lines 1385-2158"));
    assert!(!cites_a_line("largest error in lengths") && !cites_a_line("T₂'s line (through)"));
    assert!(
        runs_together("recomputed T₂ₐT₂_b") && !runs_together("T₂'s line (through Tₐ and T_b)")
    );
    for fig in figures() {
        for p in &fig.panels {
            assert!(!cites_a_line(&p.title), "{}: {}", fig.id, p.title);
            assert!(!runs_together(&p.title), "{}: {}", fig.id, p.title);
            for l in &p.layers {
                assert!(!runs_together(&l.name), "{}: key {}", fig.id, l.name);
            }
        }
    }
    let ex5 = figures().iter().find(|f| f.id == "fig-ex5-panels").unwrap();
    for (i, p) in ex5.panels.iter().enumerate() {
        assert!(
            p.title.starts_with(&format!("panel {}: ", i + 1)),
            "{}",
            p.title
        );
    }
}

/// The column a figure in a claim's box gets on a 400-px-wide screen: less the page's padding
/// (0.8 rem), the box's padding and border (1 rem + 1 px) and the figure's border (1 px), each
/// side.
const PHONE_COLUMN: f64 = 400.0 - 2.0 * (12.8 + 17.0 + 1.0);

#[test]
fn figures_keep_their_text_legible_at_400_px() {
    for fig in figures() {
        for standalone in [true, false] {
            let text = figure_svg(fig, standalone);
            let doc = Document::parse(&text).unwrap();
            let root = doc.root_element();
            let width = num(root, "width");
            let min = root.attribute("style").and_then(|s| {
                s.split(';')
                    .find_map(|d| d.trim().strip_prefix("min-width:"))
                    .map(|v| v.trim().trim_end_matches("px").parse::<f64>().unwrap())
            });
            assert_eq!(min, min_width(fig), "{}", fig.id);
            let shown = width.min(PHONE_COLUMN).max(min.unwrap_or(0.0));
            let smallest = doc
                .descendants()
                .filter_map(|n| n.attribute("font-size"))
                .map(|v| v.parse::<f64>().unwrap())
                .fold(f64::INFINITY, f64::min);
            let px = smallest * shown / width;
            match min {
                Some(m) => {
                    assert!(m <= width, "{}: never drawn wider than it is", fig.id);
                    assert!(px >= 9.0 - 1e-9, "{}: {px:.2} px at {shown} px", fig.id);
                }
                None => {
                    assert!(width <= 430.0, "{}: {width} px shrinks freely", fig.id);
                    assert!(px >= 8.5, "{}: {px:.2} px at {shown} px", fig.id);
                }
            }
        }
    }
    // every figure of several panels in a row scrolls rather than shrinks
    for id in ["fig-ex5-panels", "fig-two-frames", "fig-ex2-noise-1"] {
        let f = figures().iter().find(|f| f.id == id).unwrap();
        assert!(min_width(f).is_some(), "{id}");
    }
}
