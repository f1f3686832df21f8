//! §4's printed coefficient matrix audited against its figure: which triangle and frame pair
//! each row is, a point of the figure's rounding box that reproduces every printed entry
//! within half a unit of its last digit, and the same search for single-entry mutants.

use rayon::prelude::*;

use crate::algebra::Interval;
use crate::derivations::p4f3::{all_triangles, Triangle};
use crate::derivations::twofold::FrameCoefficients;
use crate::studies::rounding::{reproduce_grouped, GroupedResiduals, RoundingBox, Witness};

/// How a printed row of the paper's matrix arises from the figure: which triangle, which
/// pair of frames (`first` − `second`), and the factor applied.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RowMatch {
    /// The triangle (edge indices).
    pub triangle: Triangle,
    /// The frame whose equation comes first (1-based).
    pub first: usize,
    /// The frame subtracted (1-based).
    pub second: usize,
    /// The factor on F_first − F_second (±1, ±1/2 or ±2).
    pub factor: f64,
    /// Largest |printed − recomputed| over the row, at the printed coordinates.
    pub deviation: f64,
}

/// The row `factor · (F_first − F_second)` of `triangle` from image points
/// (`frames[f][point] = [x, y]`), as seven intervals (coefficients of x1 … x6 and the
/// constant) enclosing every value over the rounding box `[x ± half]`. The constant uses
/// K = −4 (2·area)², the squared cross product, which keeps the enclosure tight.
pub fn row_enclosure(
    frames: &[Vec<[f64; 2]>],
    half: f64,
    triangle: Triangle,
    first: usize,
    second: usize,
    factor: f64,
) -> [Interval; 7] {
    let p = frames[0].len();
    let all = edges_of(p);
    let points = |f: usize| -> Vec<[Interval; 2]> {
        frames[f]
            .iter()
            .map(|c| [Interval::around(c[0], half), Interval::around(c[1], half)])
            .collect()
    };
    // coefficients 2α, 2β, 2γ and K of one frame's equation for the triangle
    let frame_terms = |f: usize| -> ([Interval; 3], Interval) {
        let pts = points(f);
        let sq = |e: usize| {
            let (i, j) = all[e];
            (pts[i][0] - pts[j][0]).square() + (pts[i][1] - pts[j][1]).square()
        };
        let [u, v, w] = triangle.map(sq);
        let lin = [
            (v + w - u).scale(2.0),
            (u + w - v).scale(2.0),
            (u + v - w).scale(2.0),
        ];
        // the triangle's three points: the first edge's two, and the one it lacks
        let (a, b) = all[triangle[0]];
        let (c0, c1) = all[triangle[1]];
        let c = if c0 == a || c0 == b { c1 } else { c0 };
        let cross = (pts[b][0] - pts[a][0]) * (pts[c][1] - pts[a][1])
            - (pts[c][0] - pts[a][0]) * (pts[b][1] - pts[a][1]);
        (lin, cross.square().scale(-4.0))
    };
    let (l1, k1) = frame_terms(first - 1);
    let (l2, k2) = frame_terms(second - 1);
    let mut row = [Interval::point(0.0); 7];
    for (i, e) in triangle.iter().enumerate() {
        row[*e] = (l1[i] - l2[i]).scale(factor);
    }
    row[6] = (k1 - k2).scale(factor);
    row
}

/// The edges of `p` points (as in [`edges`](crate::model::edges)).
fn edges_of(p: usize) -> Vec<(usize, usize)> {
    crate::model::edges(p)
}

/// Identify each printed row (seven numbers: x1 … x6 and the constant) among every triangle,
/// ordered frame pair and factor ±1, ±1/2, ±2, by the smallest largest deviation at the
/// printed coordinates.
pub fn identify_rows(printed: &[[f64; 7]], frames: &[Vec<[f64; 2]>]) -> Vec<RowMatch> {
    let k = frames.len();
    let tris = all_triangles(frames[0].len());
    // every candidate row once, in the order of the search (they depend on the frames only)
    let mut candidates = Vec::new();
    // positive factors first: a tie between −(F₁ − F₂) and F₂ − F₁ names the latter
    for factor in [1.0, 0.5, 2.0, -1.0, -0.5, -2.0] {
        for &triangle in &tris {
            for first in 1..=k {
                for second in (1..=k).filter(|s| *s != first) {
                    let r = row_enclosure(frames, 0.0, triangle, first, second, factor);
                    candidates.push((triangle, first, second, factor, r.map(|iv| iv.mid())));
                }
            }
        }
    }
    printed
        .iter()
        .map(|row| {
            let mut best: Option<RowMatch> = None;
            for &(triangle, first, second, factor, mid) in &candidates {
                let deviation = mid
                    .iter()
                    .zip(row)
                    .map(|(m, x)| (m - x).abs())
                    .fold(0.0, f64::max);
                if best.is_none_or(|b| deviation < b.deviation) {
                    best = Some(RowMatch {
                        triangle,
                        first,
                        second,
                        factor,
                        deviation,
                    });
                }
            }
            best.unwrap_or(RowMatch {
                triangle: [0, 1, 2],
                first: 1,
                second: 1,
                factor: 0.0,
                deviation: f64::INFINITY,
            })
        })
        .collect()
}

/// What the audit needs.
#[derive(Clone, Debug)]
pub struct PrintedSystem<'a> {
    /// The figure's coordinates (frame, point, x/y flattened) and their half-widths.
    pub figure_box: &'a RoundingBox,
    /// Points per frame.
    pub points: usize,
    /// The printed rows (x1 … x6, constant).
    pub rows: &'a [[f64; 7]],
    /// Half a unit of each printed entry; 0 for a structural zero (not a rounded number).
    pub half: &'a [[f64; 7]],
    /// Shifts of the single-entry mutants, in half units of the entry.
    pub mutant_half_units: &'a [f64],
}

/// One single-entry mutant and what the search said.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Mutant {
    /// Row (0-based).
    pub row: usize,
    /// Column (0-based; 6 is the constant).
    pub column: usize,
    /// Signed shift in half units.
    pub shift: f64,
    /// Whether the search failed for it.
    pub rejected: bool,
}

/// The numbers of the audit.
#[derive(Clone, Debug)]
pub struct Audit {
    /// Per row: triangle, frame pair, factor, deviation at the printed coordinates.
    pub matches: Vec<RowMatch>,
    /// Per row, per column: the interval enclosure's width over the box, in half units of
    /// the printed entry (the old check's acceptance; 0 for structural zeros).
    pub enclosure_half_units: Vec<[f64; 7]>,
    /// Largest |recomputed − printed| / half unit at the printed coordinates.
    pub at_printed: f64,
    /// A point of the box whose rows reproduce every nonzero entry within its half unit.
    pub witness: Option<Witness>,
    /// Every nonzero entry moved by ± each mutant shift, and whether the search then failed.
    pub mutants: Vec<Mutant>,
}

/// Frame `f`'s points from flat coordinates.
fn frame(x: &[f64], points: usize, f: usize) -> Vec<[f64; 2]> {
    (0..points)
        .map(|j| [x[2 * (points * f + j)], x[2 * (points * f + j) + 1]])
        .collect()
}

/// The row `factor · (F_first − F_second)` of a triangle at flat coordinates `x`.
pub fn row_at(x: &[f64], points: usize, m: &RowMatch) -> [f64; 7] {
    // the triangle's three squared lengths only, as `model::squared_lengths` computes them
    // (this runs inside every fit's residual: no lists built)
    let pick = |f: usize| {
        FrameCoefficients::new(m.triangle.map(|e| {
            let (i, j) = crate::model::edge(e);
            let (a, b) = (2 * (points * (f - 1) + i), 2 * (points * (f - 1) + j));
            (x[a] - x[b]).powi(2) + (x[a + 1] - x[b + 1]).powi(2)
        }))
    };
    let (c, k) = pick(m.first).difference(&pick(m.second));
    let mut row = [0.0; 7];
    for (e, v) in m.triangle.iter().zip(c) {
        row[*e] = m.factor * v;
    }
    row[6] = m.factor * k;
    row
}

/// Residuals of every nonzero printed entry, in units of its half unit: one group per
/// printed row, moved by the coordinates of the two frames it compares.
struct Scaled<'a> {
    inp: &'a PrintedSystem<'a>,
    rows: &'a [[f64; 7]],
    matches: &'a [RowMatch],
}

impl GroupedResiduals for Scaled<'_> {
    fn groups(&self) -> usize {
        self.matches
            .len()
            .min(self.rows.len())
            .min(self.inp.half.len())
    }

    fn group(&self, g: usize, x: &[f64], out: &mut Vec<f64>) {
        let (m, p, h) = (&self.matches[g], &self.rows[g], &self.inp.half[g]);
        let r = row_at(x, self.inp.points, m);
        out.extend((0..7).filter(|j| h[*j] > 0.0).map(|j| (r[j] - p[j]) / h[j]));
    }

    fn moves(&self, i: usize, g: usize) -> bool {
        let f = i / (2 * self.inp.points) + 1;
        self.matches[g].first == f || self.matches[g].second == f
    }
}

/// Every residual of [`Scaled`] at `x`, in order.
fn scaled(x: &[f64], s: &Scaled) -> Vec<f64> {
    let mut out = Vec::new();
    for g in 0..s.groups() {
        s.group(g, x, &mut out);
    }
    out
}

/// Run the audit.
pub fn audit(inp: &PrintedSystem) -> Audit {
    let frames: Vec<Vec<[f64; 2]>> = (0..inp.figure_box.center.len() / (2 * inp.points))
        .map(|f| frame(&inp.figure_box.center, inp.points, f))
        .collect();
    let matches = identify_rows(inp.rows, &frames);
    let coord_half = inp.figure_box.half.iter().fold(0.0, |a: f64, b| a.max(*b));
    let enclosure_half_units = matches
        .iter()
        .zip(inp.half)
        .map(|(m, h)| {
            let enc = row_enclosure(&frames, coord_half, m.triangle, m.first, m.second, m.factor);
            std::array::from_fn(|j| {
                if h[j] > 0.0 {
                    enc[j].width() / 2.0 / h[j]
                } else {
                    0.0
                }
            })
        })
        .collect();
    let printed = Scaled {
        inp,
        rows: inp.rows,
        matches: &matches,
    };
    let at_printed = scaled(&inp.figure_box.center, &printed)
        .iter()
        .fold(0.0, |a: f64, v| a.max(v.abs()));
    let witness = reproduce_grouped(inp.figure_box, &printed);
    let mut moves = Vec::new();
    for (i, h) in inp.half.iter().enumerate() {
        for j in (0..7).filter(|j| h[*j] > 0.0) {
            for shift in inp.mutant_half_units.iter().flat_map(|m| [-m, *m]) {
                moves.push((i, j, shift));
            }
        }
    }
    // the searches are independent: in parallel, collected in order
    let mutants = moves
        .into_par_iter()
        .map(|(i, j, shift)| {
            let mut rows = inp.rows.to_vec();
            rows[i][j] += shift * inp.half[i][j];
            Mutant {
                row: i,
                column: j,
                shift,
                rejected: reproduce_grouped(
                    inp.figure_box,
                    &Scaled {
                        rows: &rows,
                        ..printed
                    },
                )
                .is_none(),
            }
        })
        .collect();
    Audit {
        matches,
        enclosure_half_units,
        at_printed,
        witness,
        mutants,
    }
}
