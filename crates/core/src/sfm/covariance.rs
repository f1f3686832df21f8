//! The uncertainty of every point and frame after bundle adjustment: standard errors from
//! the normal equations at the optimum, up to the gauge, as Ceres' covariance estimation
//! gives them.
//!
//! The gauge (a common rotation, a common 3-D shift) is fixed by holding frame 1's rotation
//! and point 1 (its three coordinates), which leaves JᵀJ regular; the points are then
//! reported centred on their centroid, a function that no shift of the gauge moves, so its
//! covariance does not depend on how the gauge was fixed. With the camera system's Schur
//! complement S (frame 1's two translations and the other frames' five parameters) and a
//! point's block V_j, B_j = W_j V_j⁻¹:
//!
//! - Cov(x_i, x_j) = δ_ij V_j⁻¹ + B_iᵀ S⁻¹ B_j, Cov(c, x_j) = −S⁻¹ B_j;
//! - the centred point x_j − m, m the mean of all points (point 1 held constant), has
//!   Cov(x_j) − Cov(x_j, m) − Cov(m, x_j) + Cov(m), where Cov(x_j, m) = (V_j⁻¹ + B_jᵀ S⁻¹ B̄)/p
//!   and Cov(m) = (Σ V_i⁻¹ + B̄ᵀ S⁻¹ B̄)/p², B̄ = Σ B_i;
//! - a frame's rotation, relative to frame 1's (which the gauge holds), is its three
//!   parameters' block of S⁻¹; its translation, once the points are centred, is the image of
//!   the centroid y = C m + t (C the rotation's first two rows), gauge-free like the centred
//!   points, with Cov(y) = L S⁻¹ Lᵀ + L Cov(c, m) Cᵀ + C Cov(m, c) Lᵀ + C Cov(m) Cᵀ, L = ∂y/∂c
//!   (a residual's camera Jacobian at m);
//! - all times σ² = 2·cost / (2·observations − parameters), the residual variance.
//!
//! S⁻¹ is formed once ((5k)³ multiply-adds, the cost of one step); each point's terms cost
//! (5 nⱼ)² · 3 over the frames that see it, taken 64 points at a time in one matrix product
//! where their frames make that cheaper (long tracks), as the adjustment's own complement.

use std::ops::AddAssign as _;

use nalgebra::{DMatrix, Matrix2, Matrix2x3, Matrix3, Vector2, Vector3};

// chunks of points, and when one matrix product pays: as the adjustment's own Schur complement
use super::bundle::{camera_jacobian, Normal, State, CHUNK, DENSE_GAIN};
use crate::algebra::psd3_nonsingular;

/// The standard errors of one frame (the state's units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrameStd {
    /// Of its rotation relative to the first frame's, about the axes the points are given in
    /// (the first frame's camera axes when its rotation is the identity, as the pipeline
    /// makes it) x, y, z (radians, the update R·exp(\[δ\]×)); zero for the first frame,
    /// which fixes the frame of reference.
    pub rotation: Vector3<f64>,
    /// Of its image translation with the points centred (the centroid's image).
    pub translation: Vector2<f64>,
}

/// The standard errors of every point and frame.
pub(super) struct Errors {
    pub(super) points: Vec<Vector3<f64>>,
    pub(super) frames: Vec<FrameStd>,
}

/// Why no standard errors could be given.
const NO_FREEDOM: &str = "the data leave no residual degree of freedom to estimate the noise from";
/// Why no standard errors could be given.
const SINGULAR: &str =
    "the normal equations are singular at the optimum: some point or frame is not fixed by the data";

/// The rows of camera `f`'s parameters that are free: frame 1 (`f` = 0) keeps only its two
/// translations (its rotation is the gauge).
fn free_rows(f: usize) -> std::ops::Range<usize> {
    if f == 0 {
        3..5
    } else {
        0..5
    }
}

/// Each camera parameter's index in the reduced camera system (`None` for frame 1's
/// rotation), and the system's size.
fn camera_index(k: usize) -> (Vec<[Option<usize>; 5]>, usize) {
    let mut next = 0;
    let index = (0..k)
        .map(|f| {
            std::array::from_fn(|r| {
                free_rows(f).contains(&r).then(|| {
                    next += 1;
                    next - 1
                })
            })
        })
        .collect();
    (index, next)
}

/// The standard error of every centred point and every frame (in the state's units), or
/// why there are none: the normal equations are singular (a point or frame the data do not
/// fix), or the data leave no residual degree of freedom.
pub(super) fn standard_errors(
    n: &Normal,
    frames_of: &[Vec<usize>],
    state: &State,
    cost: f64,
) -> Result<Errors, &'static str> {
    let (p, k) = (state.pts.len(), state.rot.len());
    let observations: usize = frames_of.iter().map(Vec::len).sum();
    let (index, size) = camera_index(k);
    let parameters = size + 3 * p.saturating_sub(1);
    let dof = (2 * observations)
        .checked_sub(parameters)
        .filter(|d| *d > 0)
        .ok_or(NO_FREEDOM)?;
    let sigma2 = 2.0 * cost / dof as f64;
    // a point its views do not fix has a V_j singular up to rounding, not exactly: the same
    // test as the adjustment's re-solve (V sums 2 × 3 products of unit rows)
    let vinv: Vec<Matrix3<f64>> =
        n.v.iter()
            .map(|v| psd3_nonsingular(v, 3.0).then(|| v.try_inverse()).flatten())
            .collect::<Option<_>>()
            .ok_or(SINGULAR)?;
    let mut s = DMatrix::<f64>::zeros(size, size);
    for (f, u) in n.u.iter().enumerate() {
        for (a, ia) in index[f].iter().enumerate() {
            for (b, ib) in index[f].iter().enumerate() {
                if let (Some(ia), Some(ib)) = (ia, ib) {
                    s[(*ia, *ib)] += u[(a, b)];
                }
            }
        }
    }
    // B_j on the rows of the frames that see point j (point 1 is held: none)
    let blocks: Vec<Sparse> = (0..p)
        .map(|j| {
            if j == 0 {
                Sparse::empty()
            } else {
                Sparse::of(n, &index, frames_of, &vinv, j)
            }
        })
        .collect();
    // S = U − Σ W V⁻¹ Wᵀ = U − Σ B V Bᵀ
    subtract_points(&mut s, &blocks, &n.v);
    let mut b_bar = DMatrix::<f64>::zeros(size, 3);
    for b in &blocks {
        for (x, &rx) in b.rows.iter().enumerate() {
            b_bar.row_mut(rx).add_assign(&b.m.row(x));
        }
    }
    let sinv = crate::algebra::cholesky::cholesky_inverse(s).ok_or(SINGULAR)?;
    let sb_bar = &sinv * &b_bar;
    let pf = p as f64;
    let v_sum: Matrix3<f64> = vinv.iter().skip(1).sum();
    let cov_m = (v_sum + to3(&(b_bar.transpose() * &sb_bar))) / (pf * pf);
    let forms = quadratic_forms(&sinv, &blocks);
    let centroid = Centroid {
        sb_bar: &sb_bar,
        cov: &cov_m,
        at: state.pts.iter().sum::<Vector3<f64>>() / pf,
        p: pf,
    };
    let frames = (0..k)
        .map(|f| frame_std(&sinv, &index[f], &centroid, state, f, sigma2))
        .collect();
    let points = blocks
        .iter()
        .enumerate()
        .map(|(j, b)| {
            let (own, with_m) = if j == 0 {
                (Matrix3::zeros(), Matrix3::zeros())
            } else {
                let own = vinv[j] + forms[j];
                let cross = b.m.transpose() * sb_bar.select_rows(&b.rows);
                (own, (vinv[j] + to3(&cross)) / pf)
            };
            let c = own - with_m - with_m.transpose() + cov_m;
            Vector3::from_fn(|i, _| (c[(i, i)].max(0.0) * sigma2).sqrt())
        })
        .collect();
    Ok(Errors { points, frames })
}

/// What a frame's translation needs of the centroid m: S⁻¹ B̄ (so Cov(c, m) = −S⁻¹ B̄ / p),
/// Cov(m), m itself and the number of points p.
struct Centroid<'a> {
    sb_bar: &'a DMatrix<f64>,
    cov: &'a Matrix3<f64>,
    at: Vector3<f64>,
    p: f64,
}

/// Frame `f`'s standard errors (the module's formulas), its parameters at `index` in S⁻¹.
fn frame_std(
    sinv: &DMatrix<f64>,
    index: &[Option<usize>; 5],
    m: &Centroid,
    state: &State,
    f: usize,
    sigma2: f64,
) -> FrameStd {
    let free: Vec<(usize, usize)> = index
        .iter()
        .enumerate()
        .filter_map(|(r, i)| i.map(|i| (r, i)))
        .collect();
    // the first three parameters are the rotation's (none free for frame 1: the gauge)
    let rotation =
        Vector3::from_fn(|a, _| index[a].map_or(0.0, |i| (sinv[(i, i)].max(0.0) * sigma2).sqrt()));
    let c: Matrix2x3<f64> = state.rot[f].fixed_rows::<2>(0).into_owned();
    let l = camera_jacobian(&c, &m.at, f == 0);
    let mut cov = c * m.cov * c.transpose();
    for &(r, i) in &free {
        // L Cov(c, m) Cᵀ and its transpose, with Cov(c, m)'s row i = −(S⁻¹ B̄)ᵢ / p
        let g = Vector3::from_fn(|x, _| -m.sb_bar[(i, x)] / m.p);
        let cross: Matrix2<f64> = l.column(r) * (c * g).transpose();
        cov += cross + cross.transpose();
        for &(s, j) in &free {
            cov += l.column(r) * l.column(s).transpose() * sinv[(i, j)];
        }
    }
    FrameStd {
        rotation,
        translation: Vector2::from_fn(|a, _| (cov[(a, a)].max(0.0) * sigma2).sqrt()),
    }
}

/// The union of a chunk's rows, and each point's rows' positions in it.
fn union_rows(chunk: &[Sparse]) -> (Vec<usize>, Vec<Vec<usize>>) {
    let mut rows: Vec<usize> = chunk.iter().flat_map(|b| b.rows.iter().copied()).collect();
    rows.sort_unstable();
    rows.dedup();
    let pos = chunk
        .iter()
        .map(|b| {
            b.rows
                .iter()
                .map(|r| rows.binary_search(r).unwrap_or(0))
                .collect()
        })
        .collect();
    (rows, pos)
}

/// Whether one product over a chunk's `rows` costs less than point by point.
fn dense_pays(rows: usize, chunk: &[Sparse]) -> bool {
    let dense = rows * rows * 3 * chunk.len();
    let scattered: usize = chunk.iter().map(|b| 3 * b.rows.len() * b.rows.len()).sum();
    dense <= DENSE_GAIN * scattered
}

/// A chunk's blocks side by side on the union of its rows, each times `right[i]`.
fn side_by_side(
    chunk: &[Sparse],
    pos: &[Vec<usize>],
    rows: usize,
    right: &[Matrix3<f64>],
) -> DMatrix<f64> {
    let mut z = DMatrix::<f64>::zeros(rows, 3 * chunk.len());
    for (i, (b, p)) in chunk.iter().zip(pos).enumerate() {
        let m = &b.m * right[i];
        for (x, &px) in p.iter().enumerate() {
            for c in 0..3 {
                z[(px, 3 * i + c)] = m[(x, c)];
            }
        }
    }
    z
}

/// S −= Σ B_j V_j B_jᵀ over every point, chunk by chunk.
fn subtract_points(s: &mut DMatrix<f64>, blocks: &[Sparse], v: &[Matrix3<f64>]) {
    for (chunk, vs) in blocks.chunks(CHUNK).zip(v.chunks(CHUNK)) {
        let (rows, pos) = union_rows(chunk);
        // B V Bᵀ = (B L)(B L)ᵀ for V = L Lᵀ; a chunk with a V that has no Cholesky factor
        // (a point without images, or one barely determined) goes point by point
        let factors = dense_pays(rows.len(), chunk)
            .then(|| {
                vs.iter()
                    .map(|v| v.cholesky().map(|c| c.unpack()))
                    .collect::<Option<Vec<Matrix3<f64>>>>()
            })
            .flatten();
        if let Some(ls) = factors {
            let z = side_by_side(chunk, &pos, rows.len(), &ls);
            let zz = &z * z.transpose();
            for (a, &ra) in rows.iter().enumerate() {
                for (b, &rb) in rows.iter().enumerate() {
                    s[(ra, rb)] -= zz[(a, b)];
                }
            }
            continue;
        }
        for (b, v) in chunk.iter().zip(vs) {
            let bv = &b.m * v;
            for (x, &rx) in b.rows.iter().enumerate() {
                for (y, &ry) in b.rows.iter().enumerate() {
                    s[(rx, ry)] -= bv.row(x).dot(&b.m.row(y));
                }
            }
        }
    }
}

/// Each point's B_jᵀ S⁻¹ B_j, chunk by chunk, reading S⁻¹ in place where a chunk goes point
/// by point.
fn quadratic_forms(sinv: &DMatrix<f64>, blocks: &[Sparse]) -> Vec<Matrix3<f64>> {
    let mut out = Vec::with_capacity(blocks.len());
    for chunk in blocks.chunks(CHUNK) {
        let (rows, pos) = union_rows(chunk);
        if dense_pays(rows.len(), chunk) {
            let ones = vec![Matrix3::identity(); chunk.len()];
            let z = side_by_side(chunk, &pos, rows.len(), &ones);
            let y = sinv.select_rows(&rows).select_columns(&rows) * &z;
            for (i, (b, p)) in chunk.iter().zip(&pos).enumerate() {
                out.push(Matrix3::from_fn(|a, c| {
                    p.iter()
                        .enumerate()
                        .map(|(x, &px)| b.m[(x, a)] * y[(px, 3 * i + c)])
                        .sum()
                }));
            }
            continue;
        }
        for b in chunk {
            // S⁻¹ B on the point's own rows, then Bᵀ of it
            let sb = DMatrix::from_fn(b.rows.len(), 3, |x, c| {
                b.rows
                    .iter()
                    .enumerate()
                    .map(|(y, &ry)| sinv[(b.rows[x], ry)] * b.m[(y, c)])
                    .sum()
            });
            out.push(to3(&(b.m.transpose() * sb)));
        }
    }
    out
}

/// A point's B_j = W_j V_j⁻¹ on its rows of the camera system only.
struct Sparse {
    rows: Vec<usize>,
    m: DMatrix<f64>,
}

impl Sparse {
    fn empty() -> Sparse {
        Sparse {
            rows: Vec::new(),
            m: DMatrix::zeros(0, 3),
        }
    }

    fn of(
        n: &Normal,
        index: &[[Option<usize>; 5]],
        frames_of: &[Vec<usize>],
        vinv: &[Matrix3<f64>],
        j: usize,
    ) -> Sparse {
        let mut rows = Vec::new();
        let mut vals: Vec<[f64; 3]> = Vec::new();
        for (a, f) in frames_of[j].iter().enumerate() {
            let blk = n.w[j][a] * vinv[j];
            for (r, i) in index[*f].iter().enumerate() {
                if let Some(i) = i {
                    rows.push(*i);
                    vals.push([blk[(r, 0)], blk[(r, 1)], blk[(r, 2)]]);
                }
            }
        }
        let m = DMatrix::from_fn(rows.len(), 3, |r, c| vals[r][c]);
        Sparse { rows, m }
    }
}

fn to3(m: &DMatrix<f64>) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| m[(i, j)])
}
