//! §4's printed coefficient matrix audited against its figure: which triangle and frame pair
//! each row is, a point of the figure's rounding box that reproduces every printed entry
//! within half a unit of its last digit, and the same search for single-entry mutants.

use super::rounding::{reproduce, RoundingBox, Witness};
use crate::derivations::p4f3::{identify_rows, row_enclosure, RowMatch};
use crate::derivations::twofold::FrameCoefficients;

/// What the audit needs.
#[derive(Clone, Debug)]
pub struct Input<'a> {
    /// The figure's coordinates (frame, point, x/y flattened) and their half-widths.
    pub bx: &'a RoundingBox,
    /// Points per frame.
    pub points: usize,
    /// The printed rows (x1 … x6, constant).
    pub rows: &'a [[f64; 7]],
    /// Half a unit of each printed entry; 0 for a structural zero (not a rounded number).
    pub half: &'a [[f64; 7]],
    /// Shift of each single-entry mutant, in half units of that entry.
    pub mutant_half_units: f64,
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
    /// Every nonzero entry moved by ± the mutant shift, and whether the search then failed.
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
    let pick = |f: usize| {
        let l = crate::model::squared_lengths(&frame(x, points, f - 1));
        FrameCoefficients::new(m.triangle.map(|e| l[e]))
    };
    let (c, k) = pick(m.first).difference(&pick(m.second));
    let mut row = [0.0; 7];
    for (e, v) in m.triangle.iter().zip(c) {
        row[*e] = m.factor * v;
    }
    row[6] = m.factor * k;
    row
}

/// Residuals of every nonzero printed entry, in units of its half unit.
fn scaled(x: &[f64], inp: &Input, rows: &[[f64; 7]], matches: &[RowMatch]) -> Vec<f64> {
    matches
        .iter()
        .zip(rows.iter().zip(inp.half))
        .flat_map(|(m, (p, h))| {
            let r = row_at(x, inp.points, m);
            (0..7)
                .filter(|j| h[*j] > 0.0)
                .map(move |j| (r[j] - p[j]) / h[j])
                .collect::<Vec<_>>()
        })
        .collect()
}

/// Run the audit.
pub fn run(inp: &Input) -> Audit {
    let frames: Vec<Vec<[f64; 2]>> = (0..inp.bx.center.len() / (2 * inp.points))
        .map(|f| frame(&inp.bx.center, inp.points, f))
        .collect();
    let matches = identify_rows(inp.rows, &frames);
    let coord_half = inp.bx.half.iter().fold(0.0, |a: f64, b| a.max(*b));
    let enclosure_half_units = matches
        .iter()
        .zip(inp.half)
        .map(|(m, h)| {
            let enc = row_enclosure(&frames, coord_half, m.triangle, m.first, m.second, m.factor);
            std::array::from_fn(|j| if h[j] > 0.0 { enc[j].width() / 2.0 / h[j] } else { 0.0 })
        })
        .collect();
    let at_printed = scaled(&inp.bx.center, inp, inp.rows, &matches)
        .iter()
        .fold(0.0, |a: f64, v| a.max(v.abs()));
    let search = |rows: &[[f64; 7]]| reproduce(inp.bx, &|x| Some(scaled(x, inp, rows, &matches)));
    let witness = search(inp.rows);
    let mut mutants = Vec::new();
    for (i, h) in inp.half.iter().enumerate() {
        for j in (0..7).filter(|j| h[*j] > 0.0) {
            for sign in [-1.0, 1.0] {
                let shift = sign * inp.mutant_half_units;
                let mut rows = inp.rows.to_vec();
                rows[i][j] += shift * h[j];
                mutants.push(Mutant {
                    row: i,
                    column: j,
                    shift,
                    rejected: search(&rows).is_none(),
                });
            }
        }
    }
    Audit {
        matches,
        enclosure_half_units,
        at_printed,
        witness,
        mutants,
    }
}
