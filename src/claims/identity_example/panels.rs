//! §5.2's figure panels: each `\DreieckMitGerade` draws frame 2 re-centred at an assigned R,
//! and a segment; the segment should lie on the line T₂ₐT₂_b of a printed debug block with
//! the same assignment, clipped to the panel's box.

use nalgebra::Vector2;

use crate::algebra::permutations4;
use crate::claims::identity_example::author_program::{Example, Num};
use crate::model::point_line_distance;

/// A printed block's line, as the panels are compared with it.
#[derive(Clone, Copy, Debug)]
pub struct BlockLine {
    /// The block's assignment.
    pub assignment: [usize; 4],
    /// Its version (sign of b).
    pub version: i8,
    /// The printed Pa (x, y).
    pub pa: [Num; 2],
    /// The printed Pb (x, y).
    pub pb: [Num; 2],
}

/// One panel against the blocks.
#[derive(Clone, Debug)]
pub struct PanelFit {
    /// The re-centred assignment of frame 2 the panel's four points are.
    pub assignment: [usize; 4],
    /// The version of the block whose line the segment is nearest.
    pub version: i8,
    /// Distances of the two segment endpoints from that line.
    pub endpoint_distance: [f64; 2],
    /// How far each endpoint may be from it by rounding alone.
    pub endpoint_bound: [f64; 2],
    /// Whether each endpoint lies on the box |x| = box or |y| = box (to the panel's rounding).
    pub on_box: [bool; 2],
    /// The distance of the tested point (#1) from the line.
    pub tested_distance: f64,
    /// How far the tested point may be from the line by rounding alone.
    pub tested_bound: f64,
}

fn v(p: &[Num; 2]) -> Vector2<f64> {
    Vector2::new(p[0].value, p[1].value)
}

/// How far a point x may be from the line through printed a, b by rounding alone: x = a +
/// t(b − a) + n; moving a by δa and b by δb moves the line at x by at most |1 − t||δa| +
/// |t||δb|, each |δ| ≤ √2 × its half unit; x itself moves by √2 × its own half unit.
fn line_bound(x: Vector2<f64>, x_half: f64, a: &[Num; 2], b: &[Num; 2]) -> f64 {
    let (va, vb) = (v(a), v(b));
    let d = vb - va;
    let t = if d.norm() == 0.0 {
        0.0
    } else {
        (x - va).dot(&d) / d.norm_squared()
    };
    let h = |p: &[Num; 2]| std::f64::consts::SQRT_2 * p[0].half.max(p[1].half);
    (1.0 - t).abs() * h(a) + t.abs() * h(b) + std::f64::consts::SQRT_2 * x_half
}

/// Fit one panel: which assignment its points are (each within two coordinate roundings of
/// frame 2 re-centred), and the nearest block line of that assignment. `None` when the
/// points are no assignment or no block has it.
pub fn fit_panel(
    ex: &Example,
    points: &[[Num; 2]; 4],
    segment: &[[Num; 2]; 2],
    blocks: &[BlockLine],
    box_half: f64,
) -> Option<PanelFit> {
    let tol = |p: &Num| p.half + 2.0 * ex.coord_half;
    let assignment = permutations4().into_iter().find(|asg| {
        let o = ex.frame2[asg[2]];
        (0..4).all(|k| {
            let q = ex.frame2[asg[k]] - o;
            (q.x - points[k][0].value).abs() <= tol(&points[k][0])
                && (q.y - points[k][1].value).abs() <= tol(&points[k][1])
        })
    })?;
    let seg = [v(&segment[0]), v(&segment[1])];
    let best = blocks
        .iter()
        .filter(|b| b.assignment == assignment)
        .min_by(|x, y| {
            let s = |b: &BlockLine| {
                seg.iter()
                    .map(|p| point_line_distance(*p, v(&b.pa), v(&b.pb)))
                    .sum::<f64>()
            };
            s(x).total_cmp(&s(y))
        })?;
    let (a, b) = (v(&best.pa), v(&best.pb));
    let half = |p: &[Num; 2]| p[0].half.max(p[1].half);
    let on_box = std::array::from_fn(|k| {
        let h = half(&segment[k]);
        (seg[k].x.abs() - box_half).abs() <= h || (seg[k].y.abs() - box_half).abs() <= h
    });
    let tested = v(&points[0]);
    Some(PanelFit {
        assignment,
        version: best.version,
        endpoint_distance: seg.map(|p| point_line_distance(p, a, b)),
        endpoint_bound: std::array::from_fn(|k| {
            line_bound(seg[k], half(&segment[k]), &best.pa, &best.pb)
        }),
        on_box,
        tested_distance: point_line_distance(tested, a, b),
        tested_bound: line_bound(tested, half(&points[0]), &best.pa, &best.pb),
    })
}
