//! The first screen (HTML): the paper's main results, one line each with its standing and
//! what carries it, then the argument map that draws what each rests on.

use std::fmt::Write as _;

use super::page::Page;
use crate::check::standing::Standing;
use crate::mathtext::escape;
use crate::report::argument::{self, carries, Colour, Map, NODE_H, NODE_W};
use crate::report::layout::{anchor, section_anchor};
use crate::report::style::{badge_background, standing_background, BADGE_TEXT};

/// A standing's badge.
pub(crate) fn standing_badge(s: Standing) -> String {
    format!("<span class=\"badge s-{0}\">{0}</span>", s.name())
}

/// The main results and the map; nothing when the report names none.
pub(crate) fn push_main_results(s: &mut String, page: &Page) {
    let r = page.report;
    if r.main_results.is_empty() {
        return;
    }
    s.push_str(
        "<section id=\"main-results\" aria-labelledby=\"main-results-h\"><h2 id=\"main-results-h\">Do the main results stand?</h2>\
         <p class=\"meta\">The abstract's and the conclusions' claims, each with its standing: what the verdicts of \
         everything it rests on, transitively, make of it (the rule: <code>docs/verdicts.md</code>).</p><ol class=\"main\">",
    );
    for m in &r.main_results {
        let c = carries(m);
        let ids: Vec<String> = c
            .ids
            .iter()
            .map(|id| {
                format!(
                    "<a href=\"#{}\"><code>{}</code></a>",
                    anchor(id),
                    escape(id)
                )
            })
            .collect();
        let target = r
            .claims
            .iter()
            .find(|x| x.id == m.id || x.claim == m.id)
            .map_or_else(|| m.id.clone(), |x| x.id.clone());
        let _ = write!(
            s,
            "<li>{} <q>{}</q> <a href=\"#{}\"><code>{}</code></a> (<a href=\"#{}\">§{}</a>)<br><span class=\"carries\">{}{}{}</span></li>",
            standing_badge(m.standing),
            page.quote(&m.quote),
            anchor(&target),
            escape(&m.id),
            section_anchor(&m.section),
            escape(&m.section),
            escape(&c.lead),
            ids.join(", "),
            escape(&c.tail)
        );
    }
    s.push_str("</ol>");
    let map = argument::map(r);
    let _ = write!(
        s,
        "<figure class=\"map\"><div class=\"scroll\" tabindex=\"0\" role=\"region\" aria-label=\"argument map (scrolls sideways)\">{}</div>\
         <figcaption>The argument map: the main results on top (coloured by standing), below them every claim they rest \
         on, one column per section of the paper, each under the claims that use it (coloured by its decisive verdict, \
         as the badges). A line runs from a result to a claim it rests on; every box links to its card. The whole graph \
         is each claim's <code>rests_on</code> in <code>report.json</code>.</figcaption></figure></section>",
        map_svg(&map)
    );
}

/// The map as inline SVG (`id="argument-map"`).
fn map_svg(map: &Map) -> String {
    let mut s = format!(
        "<svg id=\"argument-map\" viewBox=\"0 0 {w:.0} {h:.0}\" width=\"{w:.0}\" height=\"{h:.0}\" \
         role=\"group\" aria-label=\"argument map: {} main results and {} claims they rest on\" font-family=\"system-ui, sans-serif\" font-size=\"10\">",
        map.nodes.iter().filter(|n| matches!(n.colour, Colour::Standing(_))).count(),
        map.nodes.iter().filter(|n| matches!(n.colour, Colour::Verdict(_))).count(),
        w = map.width,
        h = map.height,
    );
    // pointing at (or focusing) a main result dims what it does not rest on
    s.push_str("<style>");
    for i in 0..map.reach.len() {
        let _ = write!(
            s,
            "#argument-map:has(.n{i}:hover,.n{i}:focus) .e:not(.r{i}),#argument-map:has(.n{i}:hover,.n{i}:focus) a:not(.r{i}){{opacity:.18}}"
        );
    }
    s.push_str("</style>");
    push_columns(&mut s, map);
    push_edges(&mut s, map);
    push_nodes(&mut s, map);
    s.push_str("</svg>");
    s
}

/// Each section's column: a box and its number.
fn push_columns(s: &mut String, map: &Map) {
    let bottom = map.height - 4.0;
    for (sec, left) in &map.columns {
        let _ = write!(
            s,
            "<rect x=\"{:.1}\" y=\"104\" width=\"{:.1}\" height=\"{:.1}\" rx=\"6\" fill=\"#f4f4f4\" stroke=\"#8a8a8a\"/>\
             <text x=\"{:.1}\" y=\"120\" fill=\"#333\" font-weight=\"bold\">§{}</text>",
            left - 6.0,
            NODE_W + 12.0,
            bottom - 104.0,
            left,
            escape(sec)
        );
    }
}

/// Every edge, from the user to its support: darker from a main result.
fn push_edges(s: &mut String, map: &Map) {
    for &(from, to) in &map.edges {
        let (a, b) = (&map.nodes[from], &map.nodes[to]);
        let main = matches!(a.colour, Colour::Standing(_));
        let (y1, y2) = (a.y + NODE_H, b.y);
        let bend = ((y2 - y1).abs() / 2.0).max(12.0);
        // an edge belongs to a main result's reach when both its ends do
        let classes: String = map
            .reach
            .iter()
            .enumerate()
            .filter(|(_, set)| set.contains(&from) && set.contains(&to))
            .map(|(i, _)| format!(" r{i}"))
            .collect();
        let _ = write!(
            s,
            "<path class=\"e{classes}\" d=\"M{:.1} {:.1}C{:.1} {:.1} {:.1} {:.1} {:.1} {:.1}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{}\"/>",
            a.x,
            y1,
            a.x,
            y1 + bend,
            b.x,
            y2 - bend,
            b.x,
            y2,
            if main { "#5f5f5f" } else { "#949494" },
            if main { "1.2" } else { "0.8" }
        );
    }
}

/// Every box, linked to its card; each names the main results whose reach holds it.
fn push_nodes(s: &mut String, map: &Map) {
    let reach_of = |node: usize| -> String {
        map.reach
            .iter()
            .enumerate()
            .filter(|(_, set)| set.contains(&node))
            .map(|(i, _)| format!(" r{i}"))
            .collect()
    };
    for (k, n) in map.nodes.iter().enumerate() {
        let main = if k < map.reach.len() {
            format!(" n{k}")
        } else {
            String::new()
        };
        let (fill, word) = match n.colour {
            Colour::Standing(st) => (standing_background(st), st.name()),
            Colour::Verdict(v) => (badge_background(v), v.name()),
        };
        let shown: String = if n.id.chars().count() > 24 {
            n.id.chars().take(23).chain(['…']).collect()
        } else {
            n.id.clone()
        };
        let _ = write!(
            s,
            "<a class=\"{}{main}\" href=\"#{}\" aria-label=\"{}: {}\"><rect x=\"{:.1}\" y=\"{:.1}\" width=\"{NODE_W:.0}\" height=\"{NODE_H:.0}\" rx=\"4\" fill=\"{fill}\"/>\
             <text x=\"{:.1}\" y=\"{:.1}\" fill=\"{BADGE_TEXT}\" text-anchor=\"middle\">{}</text></a>",
            reach_of(k).trim_start(),
            anchor(&n.target),
            escape(&n.id),
            word,
            n.x - NODE_W / 2.0,
            n.y,
            n.x,
            n.y + NODE_H / 2.0 + 3.8,
            escape(&shown)
        );
    }
}
