//! The rank-3 factorisation of the registered measurement matrix, the thin way: the
//! eigen-decomposition of the smaller Gram matrix (2k × 2k or p × p), so 10⁴ points in 100
//! frames cost one 200 × 200 eigenproblem and two matrix products.

use nalgebra::{DMatrix, Matrix2, Matrix2x3, SymmetricEigen, Vector2};

use super::ITERATION_LIMIT as SVD_MAX_ITERATIONS;
use super::{Degenerate, Error};
use crate::algebra::negligible;
use crate::model::Tracks;

/// The registered measurement matrix: rows 2f, 2f+1 hold frame f's x and y coordinates minus
/// the frame's centroid; one column per point.
pub fn registered(t: &Tracks) -> (DMatrix<f64>, Vec<Vector2<f64>>) {
    let (k, p) = (t.frames.len(), t.points());
    let mut w = DMatrix::zeros(2 * k, p);
    let mut centroids = Vec::with_capacity(k);
    for (f, frame) in t.frames.iter().enumerate() {
        let c = frame.iter().sum::<Vector2<f64>>() / p.max(1) as f64;
        for (j, y) in frame.iter().enumerate() {
            w[(2 * f, j)] = y.x - c.x;
            w[(2 * f + 1, j)] = y.y - c.y;
        }
        centroids.push(c);
    }
    (w, centroids)
}

/// W ≈ M S with M (2k × 3) and S (3 × p).
#[derive(Clone, Debug, PartialEq)]
pub struct Factors {
    /// The affine motion, two rows per frame.
    pub motion: DMatrix<f64>,
    /// The affine shape, one column per point.
    pub shape: DMatrix<f64>,
    /// The four largest singular values of W (zero beyond its size).
    pub singular: [f64; 4],
}

/// The eigenpairs of a symmetric matrix, largest first, by a bounded iteration.
fn eigen_desc(g: DMatrix<f64>) -> Result<(Vec<f64>, DMatrix<f64>), Error> {
    if !g.iter().all(|v| v.is_finite()) {
        return Err(Error::Numerical("a non-finite Gram matrix".into()));
    }
    let e = SymmetricEigen::try_new(g, f64::EPSILON, SVD_MAX_ITERATIONS)
        .ok_or_else(|| Error::Numerical("the Gram eigen-decomposition did not converge".into()))?;
    let mut order: Vec<usize> = (0..e.eigenvalues.len()).collect();
    order.sort_by(|&a, &b| e.eigenvalues[b].total_cmp(&e.eigenvalues[a]));
    let values = order.iter().map(|&i| e.eigenvalues[i]).collect();
    let vectors = DMatrix::from_fn(e.eigenvectors.nrows(), order.len(), |r, c| {
        e.eigenvectors[(r, order[c])]
    });
    Ok((values, vectors))
}

/// W Wᵀ from the blocks on and above the diagonal only (the rest by symmetry): about 60 %
/// of the full product's work for 200 rows.
fn gram_rows(w: &DMatrix<f64>) -> DMatrix<f64> {
    const B: usize = 40;
    let n = w.nrows();
    let mut g = DMatrix::zeros(n, n);
    for a in (0..n).step_by(B) {
        let ra = B.min(n - a);
        let wa = w.rows(a, ra);
        for c in (a..n).step_by(B) {
            let rc = B.min(n - c);
            let blk = wa * w.rows(c, rc).transpose();
            g.view_mut((a, c), (ra, rc)).copy_from(&blk);
            g.view_mut((c, a), (rc, ra)).copy_from(&blk.transpose());
        }
    }
    g
}

/// The rank-3 factorisation of `w`; a degenerate configuration when its rank is below 3
/// within rounding. An eigenvalue λᵢ = σᵢ² of the Gram matrix counts as zero when
/// λᵢ ≤ 64ε · n · λ₁, n the inner dimension of the Gram product: each entry sums n products,
/// so its rounding is at most about nε times λ₁.
pub fn rank3(w: &DMatrix<f64>) -> Result<Factors, Error> {
    let (rows, cols) = w.shape();
    let by_rows = rows <= cols;
    let (g, inner) = if by_rows {
        (gram_rows(w), cols)
    } else {
        (gram_rows(&w.transpose()), rows)
    };
    let (lam, vec) = eigen_desc(g)?;
    let l = |i: usize| lam.get(i).copied().unwrap_or(0.0).max(0.0);
    let top = l(0);
    let zero = |v: f64| negligible(v, inner as f64 * top);
    if top == 0.0 || zero(l(1)) {
        return Err(Error::Degenerate(Degenerate::Collinear));
    }
    if zero(l(2)) {
        return Err(Error::Degenerate(planar_or_in_plane(w)));
    }
    let singular = [l(0).sqrt(), l(1).sqrt(), l(2).sqrt(), l(3).sqrt()];
    let v3 = vec.columns(0, 3).into_owned();
    let (motion, shape) = if by_rows {
        // W = U Σ Vᵀ: M = U Σ^½, S = Σ^½ Vᵀ = Σ^-½ Uᵀ W
        let mut m = v3.clone();
        let mut s = v3.transpose() * w;
        for (i, sv) in singular.iter().take(3).enumerate() {
            m.column_mut(i).scale_mut(sv.sqrt());
            s.row_mut(i).scale_mut(1.0 / sv.sqrt());
        }
        (m, s)
    } else {
        // M = W V Σ^-½, S = Σ^½ Vᵀ
        let mut m = w * &v3;
        let mut s = v3.transpose();
        for (i, sv) in singular.iter().take(3).enumerate() {
            m.column_mut(i).scale_mut(1.0 / sv.sqrt());
            s.row_mut(i).scale_mut(sv.sqrt());
        }
        (m, s)
    };
    Ok(Factors {
        motion,
        shape,
        singular,
    })
}

/// The 2 × p block of frame `f`.
fn block(w: &DMatrix<f64>, f: usize) -> DMatrix<f64> {
    w.rows(2 * f, 2).into_owned()
}

/// Whether frames `a` and `b` of `w` differ by an orthogonal map of the image plane only (an
/// in-plane motion, or a mirror): Wᵦ = O Wₐ, O the polar factor of Wᵦ Wₐᵀ. The residual
/// ‖Wᵦ − O Wₐ‖ counts as zero within 64ε of (1 + κ)(‖Wₐ‖ + ‖Wᵦ‖), κ the condition of Wₐ
/// (O's rounding is amplified by it).
pub fn in_plane(w: &DMatrix<f64>, a: usize, b: usize) -> bool {
    let (wa, wb) = (block(w, a), block(w, b));
    let c: Matrix2<f64> = Matrix2::from_iterator((&wb * wa.transpose()).iter().copied());
    let gram: Matrix2<f64> = Matrix2::from_iterator((&wa * wa.transpose()).iter().copied());
    let Some(svd) = nalgebra::SVD::try_new(c, true, true, f64::EPSILON, SVD_MAX_ITERATIONS) else {
        return false;
    };
    let (Some(u), Some(vt)) = (svd.u, svd.v_t) else {
        return false;
    };
    let o = u * vt;
    let ev = gram.symmetric_eigenvalues();
    let (lo, hi) = (ev.min().max(0.0).sqrt(), ev.max().max(0.0).sqrt());
    if hi == 0.0 {
        return false;
    }
    let kappa = if lo > 0.0 { hi / lo } else { f64::INFINITY };
    let resid = (&wb - DMatrix::from_iterator(2, 2, o.iter().copied()) * &wa).norm();
    kappa.is_finite() && negligible(resid, (1.0 + kappa) * (wa.norm() + wb.norm()))
}

/// The first pair of frames (1-based) that differ by an in-plane motion only.
pub fn in_plane_pair(w: &DMatrix<f64>) -> Option<(usize, usize)> {
    let k = w.nrows() / 2;
    (0..k).find_map(|a| {
        (a + 1..k)
            .find(|&b| in_plane(w, a, b))
            .map(|b| (a + 1, b + 1))
    })
}

/// A rank-2 registered matrix: every frame an in-plane motion of frame 1 (the same view), or
/// else a planar body.
fn planar_or_in_plane(w: &DMatrix<f64>) -> Degenerate {
    let k = w.nrows() / 2;
    if k >= 2 && (1..k).all(|f| in_plane(w, 0, f)) {
        Degenerate::InPlaneMotion {
            first: 1,
            second: 2,
        }
    } else {
        Degenerate::Coplanar
    }
}

/// The 2 × 3 block of frame `f` of a motion matrix.
pub fn motion_block(m: &DMatrix<f64>, f: usize) -> Matrix2x3<f64> {
    Matrix2x3::from_fn(|r, c| m[(2 * f + r, c)])
}

/// One point's images in two frames.
type ImagePair = (Vector2<f64>, Vector2<f64>);

/// Frames that are one view up to in-plane motions, judged on what is observed: for every pair
/// of frames that follow each other in at least three tracks, the images of those tracks
/// differ by an orthogonal map of the image plane (`factor::in_plane`, at rounding level), so
/// no depth is seen (in-plane motions compose, so the pairs that chain the tracks decide for
/// all). The first such pair (1-based), as the complete-tracks path names it; `None` when
/// some pair sees depth or no pair shares three points.
pub(crate) fn same_view(views: &[super::judge::Images]) -> Option<(usize, usize)> {
    // each point's images in the frames adjacent in its track: one entry per observation at
    // most, so time and memory stay within what the tracks hold
    let mut pairs: std::collections::BTreeMap<(usize, usize), Vec<ImagePair>> =
        std::collections::BTreeMap::new();
    for v in views {
        for w in v.windows(2) {
            let ((a, ya), (b, yb)) = (w[0], w[1]);
            let (key, pair) = if a < b {
                ((a, b), (ya, yb))
            } else {
                ((b, a), (yb, ya))
            };
            pairs.entry(key).or_default().push(pair);
        }
    }
    let mut first = None;
    for ((a, b), shared) in pairs.iter().filter(|(_, s)| s.len() >= 3) {
        let n = shared.len() as f64;
        let ca = shared.iter().map(|s| s.0).sum::<Vector2<f64>>() / n;
        let cb = shared.iter().map(|s| s.1).sum::<Vector2<f64>>() / n;
        let w = DMatrix::from_fn(4, shared.len(), |r, c| {
            let (ya, yb) = shared[c];
            match r {
                0 | 1 => ya[r] - ca[r],
                _ => yb[r - 2] - cb[r - 2],
            }
        });
        if !in_plane(&w, 0, 1) {
            return None;
        }
        first.get_or_insert((a + 1, b + 1));
    }
    first
}
