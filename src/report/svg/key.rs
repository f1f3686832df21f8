//! The text of a figure beside its data: point labels placed off the lines, and the key
//! below the panels.

use std::fmt::Write as _;

use super::{escape, label_colour, push_markers, stroke, Axes, CHAR_W, MARGIN};
use crate::check::figure::{Figure, Layer, Plot, Shape, Style};

/// The point labels of a panel, placed outward from the centre of the labelled points and
/// merged where several layers label the same pixel ("Q = Q′").
pub(super) fn draw_labels(s: &mut String, p: &Plot, a: &Axes) {
    let mut labels: Vec<((f64, f64), String, &'static str)> = Vec::new();
    for l in &p.layers {
        for (q, text) in l.points.iter().zip(&l.labels) {
            let Some(at) = a.px(*q).filter(|_| !text.is_empty()) else {
                continue;
            };
            match labels
                .iter_mut()
                .find(|(b, _, _)| (b.0 - at.0).hypot(b.1 - at.1) < 6.0)
            {
                Some((_, t, c)) => {
                    if !t.split(" = ").any(|x| x == text) {
                        *t = format!("{t} = {text}");
                        *c = label_colour(Style::Printed);
                    }
                }
                None => labels.push((at, text.clone(), label_colour(l.style))),
            }
        }
    }
    if labels.is_empty() {
        return;
    }
    let n = labels.len() as f64;
    let cx = labels.iter().map(|l| l.0 .0).sum::<f64>() / n;
    let cy = labels.iter().map(|l| l.0 .1).sum::<f64>() / n;
    s.push_str("<g class=\"labels\" font-size=\"12\" stroke=\"#fff\" stroke-width=\"3\" paint-order=\"stroke\">");
    for ((x, y), text, c) in &labels {
        let (dx, dy) = (x - cx, y - cy);
        let norm = dx.hypot(dy);
        let (mut ux, mut uy) = if norm > 1.0 {
            (dx / norm, dy / norm)
        } else {
            (0.0, -1.0)
        };
        // a label that would leave the plot area goes to the other side of its point
        let w = CHAR_W * 12.0 * text.chars().count() as f64;
        if (ux < -0.35 && x - 9.0 - w < a.left) || (ux > 0.35 && x + 9.0 + w > a.left + a.w) {
            ux = -ux;
        }
        if (uy < 0.0 && y - 9.0 - 12.0 < a.top) || (uy > 0.0 && y + 9.0 + 4.0 > a.top + a.h) {
            uy = -uy;
        }
        let anchor = if ux > 0.35 {
            "start"
        } else if ux < -0.35 {
            "end"
        } else {
            "middle"
        };
        let mut tx = x + 9.0 * ux;
        if anchor == "middle" && w < a.w {
            // a centred label (a vertical line's, at the top) stays inside the plot area
            tx = tx.clamp(a.left + 0.5 * w, a.left + a.w - 0.5 * w);
        }
        let _ = write!(
            s,
            "<text x=\"{tx:.2}\" y=\"{:.2}\" text-anchor=\"{anchor}\" fill=\"{c}\">{}</text>",
            y + 9.0 * uy + 4.0,
            escape(text)
        );
    }
    s.push_str("</g>");
}

/// The key: every series of the figure once, in its colour, dash and marker, in rows below
/// the panels. Returns its height.
pub(super) fn draw_legend(s: &mut String, f: &Figure, top: f64, width: f64) -> f64 {
    // every series once: the first layer of a name stands for it
    let mut key: Vec<&Layer> = Vec::new();
    for l in f.panels.iter().flat_map(|p| &p.layers) {
        if !l.name.is_empty() && !key.iter().any(|k| k.name == l.name) {
            key.push(l);
        }
    }
    if key.is_empty() {
        return 0.0;
    }
    let mut body = String::new();
    let (mut x, mut y, row) = (MARGIN, top + 4.0, 20.0);
    let mut right: f64 = 0.0;
    for l in key {
        let ew = 34.0 + CHAR_W * 12.0 * l.name.chars().count() as f64 + 14.0;
        if x > MARGIN && x + ew > width - MARGIN {
            x = MARGIN;
            y += row;
        }
        let mid = y + row / 2.0;
        match l.shape {
            Shape::Points => push_markers(&mut body, l.style, &[(x + 15.0, mid)], 4.0),
            Shape::Verticals => {
                let _ = write!(
                    body,
                    "<line x1=\"{0:.2}\" y1=\"{1:.2}\" x2=\"{0:.2}\" y2=\"{2:.2}\" {3}/>",
                    x + 15.0,
                    mid - 7.0,
                    mid + 7.0,
                    stroke(l)
                );
            }
            Shape::Line | Shape::Polygon => {
                let _ = write!(
                    body,
                    "<line x1=\"{:.2}\" y1=\"{mid:.2}\" x2=\"{:.2}\" y2=\"{mid:.2}\" {}/>",
                    x + 2.0,
                    x + 28.0,
                    stroke(l)
                );
                if l.vertices {
                    let r = if l.beneath { 4.5 } else { 3.0 };
                    push_markers(&mut body, l.style, &[(x + 15.0, mid)], r);
                }
            }
        }
        let _ = write!(
            body,
            "<text x=\"{:.2}\" y=\"{:.2}\" font-size=\"12\" fill=\"#000\">{}</text>",
            x + 34.0,
            mid + 4.0,
            escape(&l.name)
        );
        x += ew;
        right = right.max(x);
    }
    let h = y + row + 4.0 - top;
    let _ = write!(
        s,
        "<g class=\"legend\"><rect x=\"{:.2}\" y=\"{top:.2}\" width=\"{:.2}\" height=\"{h:.2}\" fill=\"#fff\" stroke=\"#ccc\"/>{body}</g>",
        MARGIN - 4.0,
        right - MARGIN + 4.0
    );
    h
}
