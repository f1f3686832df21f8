//! Tomasi–Kanade for complete tracks: centroid registration, the thin rank-3 factorisation,
//! the metric upgrade, orthonormal camera rows, the points refitted from them, frame 1 turned
//! to the identity.

use nalgebra::{DMatrix, Matrix2x3, Matrix3, Vector3};

use super::factor::{in_plane_pair, motion_block, rank3, registered};
use super::{Conditioning, Degenerate, Error, Frame, Observations, Reconstruction, Units};
use crate::algebra::{complete_rotation, orthonormal_rows};
use crate::model::Tracks;

/// Tomasi–Kanade factorisation with the linear metric upgrade (Poelman–Kanade's
/// constraints, Cholesky; eigenvalue clipping when L is not positive definite, said so in
/// `method`). Needs ≥ 4 points in ≥ 3 frames; a planar body, collinear points, or frames that
/// differ by in-plane motions only are named degenerate outcomes.
///
/// # Example
/// ```
/// use orthocheck_core::sfm::tomasi_kanade;
/// let scene = orthocheck_core::model::Scene::random(8, 5, 3);
/// let r = tomasi_kanade(&scene.tracks()).unwrap();
/// assert_eq!(r.points.len(), 8);
/// assert!(r.rms(&(&scene.tracks()).into()) < 1e-9);
/// ```
pub fn tomasi_kanade(tracks: &Tracks) -> Result<Reconstruction, Error> {
    let obs = Observations {
        names: tracks.names.clone(),
        frames: Vec::new(),
    };
    obs.check_counts_of(tracks.frames.len())?;
    let units = Units::of_tracks(tracks)?;
    let unit = Tracks {
        names: tracks.names.clone(),
        frames: tracks
            .frames
            .iter()
            .map(|f| f.iter().map(|y| (y - units.centre) / units.scale).collect())
            .collect(),
    };
    let mut rec = unit_tomasi_kanade(&unit)?;
    units.back(&mut rec);
    Ok(rec)
}

/// [`tomasi_kanade`] on tracks already at unit size.
pub(super) fn unit_tomasi_kanade(t: &Tracks) -> Result<Reconstruction, Error> {
    let (w, centroids) = registered(t);
    let factors = rank3(&w)?;
    let up = match super::metric::upgrade(&factors.motion) {
        Ok(u) => u,
        Err(Error::Degenerate(Degenerate::SpecialMotion { rank, unknowns })) => {
            return Err(Error::Degenerate(match in_plane_pair(&w) {
                Some((first, second)) => Degenerate::InPlaneMotion { first, second },
                None => Degenerate::SpecialMotion { rank, unknowns },
            }))
        }
        Err(e) => return Err(e),
    };
    let k = t.frames.len();
    let mq = &factors.motion * DMatrix::from_iterator(3, 3, up.q.iter().copied());
    let cams: Vec<Matrix2x3<f64>> = (0..k)
        .map(|f| orthonormal_rows(&motion_block(&mq, f)))
        .collect();
    let points = refit_points(&w, &cams)?;
    let frames = cams
        .iter()
        .zip(&centroids)
        .map(|(c, t)| Frame {
            rotation: complete_rotation(c),
            translation: *t,
        })
        .collect();
    let side = if 2 * k <= t.points() {
        "2k × 2k"
    } else {
        "p × p"
    };
    let mut method = vec![format!(
        "tomasi-kanade (rank 3 from the {side} Gram matrix)"
    )];
    method.push(if up.clipped {
        "metric upgrade: L not positive definite, nearest positive definite by eigenvalue clipping"
            .into()
    } else {
        "metric upgrade: cholesky".into()
    });
    let mut rec = Reconstruction {
        names: t.names.clone(),
        points,
        frames,
        method,
        conditioning: Some(Conditioning {
            factor: factors.singular[0] / factors.singular[2],
            metric: up.condition,
        }),
        warnings: up
            .clipped
            .then(|| super::metric::CLIPPED.to_string())
            .into_iter()
            .collect(),
    };
    rec.align_to_first();
    Ok(rec)
}

/// The points that best reproject through the cameras (linear least squares, one 3 × 3
/// system shared by every point: H = Σ CᵀC, X = H⁻¹ Σ Cᵀ w).
fn refit_points(w: &DMatrix<f64>, cams: &[Matrix2x3<f64>]) -> Result<Vec<Vector3<f64>>, Error> {
    let h: Matrix3<f64> = cams.iter().map(|c| c.transpose() * c).sum();
    let hinv = h
        .cholesky()
        .map(|c| c.inverse())
        .ok_or_else(|| Error::Numerical("the cameras see no common 3-D direction".into()))?;
    let mut big = DMatrix::zeros(3, w.nrows());
    for (f, c) in cams.iter().enumerate() {
        let hc = hinv * c.transpose();
        big.view_mut((0, 2 * f), (3, 2)).copy_from(&hc);
    }
    let x = big * w;
    Ok((0..w.ncols())
        .map(|j| Vector3::new(x[(0, j)], x[(1, j)], x[(2, j)]))
        .collect())
}
