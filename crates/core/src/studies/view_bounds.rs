//! A proven bound over every exact view of a three-point body that rounds to a three-frame
//! figure (§2's example): how far apart the two solutions of eq. p3f3sqr stay.
//! [`super::exact_views`] samples these views; this module encloses them, by
//! branch-and-bound over interval enclosures.
//!
//! With P at the origin, a frame's view is fixed by Q = (qx, qy) and R's first coordinate
//! rx: rigidity (Q·R = (a² + c² − b²)/2 with the depths √(a² − |q|²) and ±√(c² − |r|²))
//! leaves a quadratic in ry with the two roots
//! ry = (qy·m ± z_Q·√((a² − qx²)(c² − rx²) − m²)) / (a² − qx²), m = (a² + c² − b²)/2 − rx·qx.
//! So the views rounding to the figure are, per frame and sign, the (qx, qy, rx) in their
//! rounding box whose ry lands in its own: nine free coordinates for three frames.
//!
//! At every exact view the body's own squares v₁ = (a², b², c²) solve F₁ = F₂ = F₃ = 0 (eq.
//! p3f3sqr holds for true lengths). The other solution lies on the line of the two linear
//! differences, of direction n = d₁ × d₂ (dᵢ the coefficients of Fᵢ − F₃), and F₃ along it,
//! F₃(v₁ + s n) = s ∇F₃(v₁)·n + s² nᵀAn (A the matrix of F's quadratic part), gives
//! v₂ = v₁ − (∇F₃(v₁)·n / nᵀAn) n: no division by the determinant n_z of the paper's
//! Cramer step, which can vary by a large part of itself over a figure's rounding. The
//! separation of the two in c², s·n_z, is √Δ/|α| on the paper's route, so a bound away from
//! 0 proves at every view both that the route is defined and that Δ > 0.
//!
//! A cell of free coordinates is first contracted to the part whose ry can round to the
//! figure (or dropped), then bounded by the centred form ([`Grad`]) of the separation. A
//! cell's midpoint whose coordinates provably round to the figure is an exact view, so the
//! bound comes with a bracket: a proven end, and an end attained at a view. Where a cell
//! meets the edge of the views (a depth or ry's square root reaching 0) its slope has no
//! enclosure; such a cell is split until the budget ends, and the bracket stays open.

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use crate::algebra::{centre, Grad, Interval, Scalar};
use crate::derivations::twofold::{frame_difference, frame_slope, frame_terms};
use crate::studies::rounding::RoundingBox;

/// Free coordinates: (qx, qy, rx) per frame.
const VARS: usize = 9;

/// Cells bounded per search before it reports the bracket it has reached: 0.17–0.2 ms a
/// cell, about 4 s when both searches reach it (docs/limits.md); §2's figure needs 1,652.
pub const CELL_BUDGET: usize = 10_000;

/// The three frames' rounding boxes in the free coordinates, and the body.
#[derive(Clone, Debug)]
pub struct Views {
    /// Per frame: qx, qy, rx, ry as intervals (the figure's rounding, rounded outward).
    frames: [[Interval; 4]; 3],
    /// The same boxes rounded inward: a point inside rounds to the figure.
    inner: [[Interval; 4]; 3],
    /// a², b², c² (PQ², QR², RP²).
    body: [f64; 3],
}

/// A bracket of the separation's minimum (or maximum) over the exact views.
#[derive(Clone, Debug, PartialEq)]
pub struct Extreme {
    /// Whether this brackets the maximum (the other solution below the body).
    pub maximum: bool,
    /// The proven bound: no exact view goes below it (above it, for a maximum).
    pub proven: f64,
    /// The value's enclosure at the best exact view found, its far end (`None`: no cell's
    /// midpoint was provably such a view).
    pub attained: Option<f64>,
    /// The flat coordinates (P, Q, R per frame) of that view.
    pub at: Option<Vec<f64>>,
    /// Cells bounded.
    pub cells: usize,
}

impl Extreme {
    /// Whether the bracket proves the two solutions distinct at every view: its proven end
    /// strictly on the far side of 0 from the other end, and a view found.
    pub fn proves_distinct(&self) -> bool {
        self.attained.is_some()
            && if self.maximum {
                self.proven < 0.0
            } else {
                self.proven > 0.0
            }
    }
}

impl Views {
    /// The views of `body` (a², b², c²) rounding to `figure` (three frames of P, Q, R with
    /// P at the exact origin); `None` for another layout.
    pub fn new(figure: &RoundingBox, body: [f64; 3]) -> Option<Views> {
        let (c, h) = (&figure.center, &figure.half);
        let layout = c.len() == 18
            && h.len() == 18
            && (0..3).all(|f| (0..2).all(|k| c[6 * f + k] == 0.0 && h[6 * f + k] == 0.0));
        if !layout {
            return None;
        }
        let at = |f: usize, k: usize| (c[6 * f + 2 + k], h[6 * f + 2 + k]);
        // two steps inward cover the rounding of c ± h itself
        let inward = |(c, h): (f64, f64)| Interval {
            lo: (c - h).next_up().next_up(),
            hi: (c + h).next_down().next_down(),
        };
        Some(Views {
            frames: std::array::from_fn(|f| {
                std::array::from_fn(|k| Interval::around(at(f, k).0, at(f, k).1))
            }),
            inner: std::array::from_fn(|f| std::array::from_fn(|k| inward(at(f, k)))),
            body,
        })
    }

    /// The box of the free coordinates.
    fn root(&self) -> [Interval; VARS] {
        std::array::from_fn(|i| self.frames[i / 3][i % 3])
    }

    /// A frame's ry for its (qx, qy, rx) and branch; `None` where no view exists or the
    /// enclosure cannot be formed.
    fn ry<T: Scalar>(&self, [qx, qy, rx]: [T; 3], plus: bool) -> Option<T> {
        let [a2, b2, c2] = self.body.map(T::constant);
        let m = (a2 + c2 - b2) * T::constant(0.5) - rx * qx;
        let free = a2 - qx * qx;
        let zq = (free - qy * qy).sqrt()?;
        let root = (free * (c2 - rx * rx) - m * m).sqrt()?;
        let sign = T::constant(if plus { 1.0 } else { -1.0 });
        Some((qy * m + sign * zq * root) * free.recip()?)
    }

    /// Shrink frame `f`'s cell `x` (qx, qy, rx) to enclose every point whose ry on branch
    /// `plus` rounds to the figure; `None` when there is provably none. By the mean value
    /// theorem, ry(x) = ry(m) + Σᵢ ∂ᵢry(ξ)(xᵢ − mᵢ) with ξ in the cell, so ry(x) in its box
    /// bounds each xₖ − mₖ by (box − ry(m) − Σ_{i≠k} ∂ᵢry(X)(Xᵢ − mᵢ)) / ∂ₖry(X).
    fn contract(&self, x: &mut [Interval; 3], plus: bool, f: usize) -> Option<()> {
        let target = self.frames[f][3];
        let (mid, off) = centre(x);
        let Some(ry) = self.ry(Grad::variables(&mid, &off), plus) else {
            // no enclosure of the slope: drop the cell only when its ry provably misses the
            // box (an undefined enclosure proves nothing: keep it whole)
            return match self.ry(*x, plus) {
                Some(r) => r.intersect(target).map(|_| ()),
                None => Some(()),
            };
        };
        ry.value.intersect(target)?;
        for k in 0..3 {
            let Some(inv) = ry.grad[k].recip() else {
                continue;
            };
            let mut rest = ry.mid;
            for i in (0..3).filter(|&i| i != k) {
                rest = rest + ry.grad[i] * off[i];
            }
            let allowed = Interval::point(mid[k]) + (target - rest) * inv;
            x[k] = x[k].intersect(allowed)?;
        }
        Some(())
    }

    /// The other solution's c² minus the body's, s·n_z, at free coordinates `x` on the
    /// branches `plus`.
    fn separation_at<T: Scalar>(&self, x: &[T; VARS], plus: [bool; 3]) -> Option<T> {
        let mut t = [[T::constant(0.0); 4]; 3];
        for (f, tf) in t.iter_mut().enumerate() {
            let (qx, qy, rx) = (x[3 * f], x[3 * f + 1], x[3 * f + 2]);
            let ry = self.ry([qx, qy, rx], plus[f])?;
            *tf = frame_terms(squared_lengths([qx, qy], [rx, ry]));
        }
        let (d1, _) = frame_difference(&t[0], &t[2]);
        let (d2, _) = frame_difference(&t[1], &t[2]);
        let n = [
            d1[1] * d2[2] - d1[2] * d2[1],
            d1[2] * d2[0] - d1[0] * d2[2],
            d1[0] * d2[1] - d1[1] * d2[0],
        ];
        let g = frame_slope(&t[2], self.body.map(T::constant));
        let two = T::constant(2.0);
        let quadric = n[0] * n[0] + n[1] * n[1] + n[2] * n[2]
            - two * (n[0] * n[1] + n[0] * n[2] + n[1] * n[2]);
        let s = -(g[0] * n[0] + g[1] * n[1] + g[2] * n[2]) * quadric.recip()?;
        Some(s * n[2])
    }

    /// The flat coordinates (P, Q, R per frame) at free coordinates `m`, when every one of
    /// them provably rounds to the figure.
    fn view_at(&self, m: &[f64; VARS], plus: [bool; 3]) -> Option<Vec<f64>> {
        let mut out = Vec::with_capacity(18);
        for (f, inner) in self.inner.iter().enumerate() {
            let q = [m[3 * f], m[3 * f + 1], m[3 * f + 2]];
            let ry = self.ry(q.map(Interval::point), plus[f])?;
            let fits = (0..3).all(|k| inner[k].contains(q[k])) && ry.within(&inner[3]);
            if !fits {
                return None;
            }
            out.extend([0.0, 0.0, q[0], q[1], q[2], ry.mid()]);
        }
        Some(out)
    }
}

/// (PQ², QR², RP²) of a frame with P at the origin.
fn squared_lengths<T: Scalar>([qx, qy]: [T; 2], [rx, ry]: [T; 2]) -> [T; 3] {
    let (dx, dy) = (rx - qx, ry - qy);
    [qx * qx + qy * qy, dx * dx + dy * dy, rx * rx + ry * ry]
}

/// A cell of free coordinates on one choice of branches, with its proven lower bound.
#[derive(Clone, Debug)]
struct Cell {
    x: [Interval; VARS],
    plus: [bool; 3],
    lower: f64,
    /// Per coordinate: the width times the largest |∂f/∂xᵢ| (the split goes to the largest).
    weight: [f64; VARS],
}

impl PartialEq for Cell {
    fn eq(&self, o: &Self) -> bool {
        self.lower.total_cmp(&o.lower) == Ordering::Equal
    }
}
impl Eq for Cell {}
impl PartialOrd for Cell {
    fn partial_cmp(&self, o: &Self) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}
impl Ord for Cell {
    // the heap pops the smallest lower bound first
    fn cmp(&self, o: &Self) -> Ordering {
        o.lower.total_cmp(&self.lower)
    }
}

/// One minimisation of `sign` × the separation: its state between cells.
struct Search<'a> {
    views: &'a Views,
    sign: f64,
    best: f64,
    at: Option<Vec<f64>>,
    cells: usize,
}

impl Search<'_> {
    /// Bound `sign`·f over the cell (`None`: the cell holds no view rounding to the figure),
    /// and try its midpoint as a view.
    fn bound(&mut self, mut x: [Interval; VARS], plus: [bool; 3]) -> Option<Cell> {
        self.cells += 1;
        for f in 0..3 {
            let mut c = [x[3 * f], x[3 * f + 1], x[3 * f + 2]];
            self.views.contract(&mut c, plus[f], f)?;
            x[3 * f..3 * f + 3].copy_from_slice(&c);
        }
        let (mid, off) = centre(&x);
        let grad = self.views.separation_at(&Grad::variables(&mid, &off), plus);
        if let (Some(g), Some(p)) = (grad, self.views.view_at(&mid, plus)) {
            let far = if self.sign > 0.0 { g.mid.hi } else { -g.mid.lo };
            if far < self.best {
                (self.best, self.at) = (far, Some(p));
            }
        }
        let (lower, weight) = match grad {
            Some(g) => {
                let v = g.value;
                let w = std::array::from_fn(|i| {
                    x[i].width() * g.grad[i].lo.abs().max(g.grad[i].hi.abs())
                });
                (if self.sign > 0.0 { v.lo } else { -v.hi }, w)
            }
            // not enclosed: no bound, split by relative width
            None => {
                let root = self.views.root();
                (
                    f64::NEG_INFINITY,
                    std::array::from_fn(|i| x[i].width() / root[i].width()),
                )
            }
        };
        // a bound lost to overflow bounds nothing
        let lower = if lower.is_nan() {
            f64::NEG_INFINITY
        } else {
            lower
        };
        Some(Cell {
            x,
            plus,
            lower,
            weight,
        })
    }

    /// Split the cell at its heaviest coordinate.
    fn split(&mut self, c: &Cell) -> [Option<Cell>; 2] {
        let k = (0..VARS)
            .max_by(|&i, &j| c.weight[i].total_cmp(&c.weight[j]))
            .unwrap_or(0);
        let m = c.x[k].mid();
        let (mut lo, mut hi) = (c.x, c.x);
        lo[k].hi = m;
        hi[k].lo = m;
        [self.bound(lo, c.plus), self.bound(hi, c.plus)]
    }
}

/// The minimum (`sign` = 1) or maximum (`sign` = −1) of the separation over the exact views,
/// bracketed until the side of 0 is known (the proven end beyond 0, or a view on the near
/// side) or [`CELL_BUDGET`] runs out.
fn extreme(views: &Views, sign: f64) -> Extreme {
    let mut s = Search {
        views,
        sign,
        best: f64::INFINITY,
        at: None,
        cells: 0,
    };
    let mut heap = BinaryHeap::new();
    for b in 0..8 {
        let plus = [b & 1 != 0, b & 2 != 0, b & 4 != 0];
        heap.extend(s.bound(views.root(), plus));
    }
    // the heap's top holds the smallest lower bound of all
    while let Some(c) = heap.pop() {
        // a proven side needs a view too: an empty set would prove it vacuously
        if (c.lower > 0.0 && s.at.is_some()) || s.best <= 0.0 || s.cells + 2 > CELL_BUDGET {
            heap.push(c);
            break;
        }
        for half in s.split(&c).into_iter().flatten() {
            if half.lower <= s.best {
                heap.push(half);
            }
        }
    }
    // an empty heap: every cell dropped or beaten, the best view is the extreme
    let lower = heap.peek().map_or(s.best, |c| c.lower.min(s.best));
    Extreme {
        maximum: sign < 0.0,
        proven: sign * lower,
        attained: s.at.is_some().then_some(sign * s.best),
        at: s.at,
        cells: s.cells,
    }
}

/// The separation in c² of the other solution from the body nearest 0 over the exact
/// views: the minimum's bracket when the other solution is proven above the body, else the
/// maximum's (`cells` counts both searches).
pub fn separation(views: &Views) -> Extreme {
    let above = extreme(views, 1.0);
    if above.proves_distinct() {
        return above;
    }
    let mut below = extreme(views, -1.0);
    below.cells += above.cells;
    below
}
