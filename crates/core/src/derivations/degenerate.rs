//! Degenerate inputs named before any solver runs, most specific first: duplicated points,
//! coincident points, collinear points, identical frames (the same lengths: an in-plane motion
//! or a mirror of another frame; [`refine_frames`] tells which from the coordinates). A planar
//! body is named by the §4 solvers, which see it in their singular systems.

use super::solver::{Degenerate, SquaredLengths};
use super::twofold::FrameCoefficients;
use crate::algebra::negligible;
use crate::model::Tracks;

/// The largest squared length of a frame: the scale its rounding is judged against.
fn frame_scale(f: &[f64]) -> f64 {
    f.iter().fold(0.0_f64, |m, v| m.max(*v))
}

/// Two points (1-based) with the same image in every frame: exactly (a point listed twice)
/// when `exact`, else up to rounding (within 64ε of the frame's largest squared length).
fn same_point(input: &SquaredLengths, exact: bool) -> Option<(usize, usize)> {
    let scales: Vec<f64> = input.frames.iter().map(|f| frame_scale(f)).collect();
    input.edges.iter().enumerate().find_map(|(e, &(i, j))| {
        let all = input.frames.iter().zip(&scales).all(|(f, s)| {
            if exact {
                f[e] == 0.0
            } else {
                negligible(f[e], *s)
            }
        });
        all.then_some((i.min(j) + 1, i.max(j) + 1))
    })
}

/// Whether every frame shows the points on one line: every triangle with the frame's
/// longest edge has a vanishing K = −16·area² (within rounding of its scale squared).
fn collinear(input: &SquaredLengths) -> bool {
    let p = input.names.len();
    if p < 3 {
        return false;
    }
    input.frames.iter().all(|f| {
        let Some((e, _)) = f.iter().enumerate().max_by(|a, b| a.1.total_cmp(b.1)) else {
            return true;
        };
        let (a, b) = input.edges[e];
        (0..p).filter(|&j| j != a && j != b).all(|j| {
            let tri = [
                f[super::p4f3::edge_index(a, b)],
                f[super::p4f3::edge_index(b, j)],
                f[super::p4f3::edge_index(j, a)],
            ];
            let c = FrameCoefficients::new(tri);
            negligible(c.k, c.scale * c.scale)
        })
    })
}

/// Two frames (1-based) whose squared lengths agree within rounding of the frames' scale.
pub fn identical_frames(input: &SquaredLengths) -> Vec<(usize, usize)> {
    let k = input.frames.len();
    let mut out = Vec::new();
    for i in 0..k {
        for j in i + 1..k {
            let (a, b) = (&input.frames[i], &input.frames[j]);
            let s = frame_scale(a) + frame_scale(b);
            if a.iter().zip(b).all(|(x, y)| negligible(x - y, s)) {
                out.push((i + 1, j + 1));
            }
        }
    }
    out
}

/// The most specific degenerate case of `input` for a solver that needs `min_frames` distinct
/// frames, or `None`. Identical frames count only when they leave fewer distinct frames than
/// the solver needs.
pub fn classify(input: &SquaredLengths, min_frames: usize) -> Option<Degenerate> {
    if let Some((first, second)) = same_point(input, true) {
        return Some(Degenerate::DuplicatedPoints { first, second });
    }
    if let Some((first, second)) = same_point(input, false) {
        return Some(Degenerate::CoincidentPoints { first, second });
    }
    if collinear(input) {
        return Some(Degenerate::Collinear);
    }
    let pairs = identical_frames(input);
    // frames equal to an earlier one add nothing
    let repeats = (1..=input.frames.len())
        .filter(|j| pairs.iter().any(|(_, s)| s == j))
        .count();
    if input.frames.len() - repeats < min_frames {
        let (first, second) = pairs[0];
        return Some(Degenerate::IdenticalFrames { first, second });
    }
    None
}

/// Frames with the same lengths are the same image or differ by an in-plane motion (or a
/// mirror): tell which from the coordinates, centred, within rounding of their extent.
pub fn refine_frames(d: Degenerate, tracks: &Tracks) -> Degenerate {
    let Degenerate::IdenticalFrames { first, second } = d else {
        return d;
    };
    let centred = |f: &[nalgebra::Vector2<f64>]| {
        let c = f.iter().sum::<nalgebra::Vector2<f64>>() / f.len().max(1) as f64;
        f.iter().map(|p| p - c).collect::<Vec<_>>()
    };
    let (a, b) = (
        centred(&tracks.frames[first - 1]),
        centred(&tracks.frames[second - 1]),
    );
    let size = a.iter().chain(&b).map(|p| p.norm()).fold(0.0, f64::max);
    if a.iter()
        .zip(&b)
        .all(|(p, q)| negligible((p - q).norm(), size))
    {
        d
    } else {
        Degenerate::InPlaneMotion { first, second }
    }
}
