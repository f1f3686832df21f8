//! Tracks with gaps: Tomasi–Kanade on the largest complete block (frames and points chosen
//! greedily: drop the frame or point with the largest share of missing entries until none is
//! missing), then grown by intersection (a point from the reconstructed frames that see it:
//! linear least squares) and resection (a frame from the reconstructed points it sees: the
//! linear 2 × 3 affine fit, then its nearest orthonormal rows), until every point and frame
//! is reached; bundle adjustment follows in the pipeline.

use nalgebra::{Matrix2x3, Matrix3, Vector2, Vector3};

use super::{Error, Frame, Observations, Reconstruction, Units, MIN_FRAMES, MIN_POINTS};
use crate::algebra::{complete_rotation, orthonormal_rows, psd3_nonsingular};

/// The frames and points (indices, ascending) of a complete block, chosen greedily.
pub fn largest_complete_block(obs: &Observations) -> (Vec<usize>, Vec<usize>) {
    let (k, p) = (obs.frames.len(), obs.names.len());
    let mut frame_on = vec![true; k];
    let mut point_on = vec![true; p];
    let mut frame_missing: Vec<usize> = obs
        .frames
        .iter()
        .map(|f| f.iter().filter(|y| y.is_none()).count())
        .collect();
    let mut point_missing = vec![0usize; p];
    for f in &obs.frames {
        for (j, y) in f.iter().enumerate() {
            point_missing[j] += usize::from(y.is_none());
        }
    }
    let (mut nf, mut np) = (k, p);
    loop {
        // the worst row and column by their share of missing entries
        let worst_f = (0..k)
            .filter(|&f| frame_on[f])
            .max_by_key(|&f| frame_missing[f] * np.max(1));
        let worst_p = (0..p)
            .filter(|&j| point_on[j])
            .max_by_key(|&j| point_missing[j] * nf.max(1));
        let share_f = worst_f.map_or(0.0, |f| frame_missing[f] as f64 / np.max(1) as f64);
        let share_p = worst_p.map_or(0.0, |j| point_missing[j] as f64 / nf.max(1) as f64);
        if share_f == 0.0 && share_p == 0.0 {
            break;
        }
        if share_f >= share_p {
            let Some(f) = worst_f else { break };
            frame_on[f] = false;
            nf -= 1;
            for (j, y) in obs.frames[f].iter().enumerate() {
                if y.is_none() && point_on[j] {
                    point_missing[j] -= 1;
                }
            }
        } else {
            let Some(j) = worst_p else { break };
            point_on[j] = false;
            np -= 1;
            for (f, row) in obs.frames.iter().enumerate() {
                if row[j].is_none() && frame_on[f] {
                    frame_missing[f] -= 1;
                }
            }
        }
    }
    (
        (0..k).filter(|&f| frame_on[f]).collect(),
        (0..p).filter(|&j| point_on[j]).collect(),
    )
}

/// The point that best reprojects through the known frames that see it; `None` when they do
/// not fix it (fewer than two views, or views whose rows span less than 3-D within rounding).
pub fn intersect(frames: &[Option<Frame>], seen: &[(usize, Vector2<f64>)]) -> Option<Vector3<f64>> {
    let mut h = Matrix3::zeros();
    let mut g = Vector3::zeros();
    for (f, y) in seen {
        if let Some(fr) = &frames[*f] {
            let c = fr.rows();
            h += c.transpose() * c;
            g += c.transpose() * (y - fr.translation);
        }
    }
    // h sums 2 × 3 products of unit rows: its entries round to about ε · (views)
    if !psd3_nonsingular(&h, 3.0) {
        return None;
    }
    h.cholesky().map(|c| c.solve(&g))
}

/// The camera that best maps the known points to their images: the affine fit
/// y − ȳ = A (X − X̄), A's nearest orthonormal rows, t = ȳ − C X̄; `None` with fewer than four
/// known points or points that span less than 3-D within rounding.
pub fn resect(points: &[Option<Vector3<f64>>], seen: &[(usize, Vector2<f64>)]) -> Option<Frame> {
    let known: Vec<(Vector3<f64>, Vector2<f64>)> = seen
        .iter()
        .filter_map(|(j, y)| points[*j].map(|x| (x, *y)))
        .collect();
    if known.len() < MIN_POINTS {
        return None;
    }
    let n = known.len() as f64;
    let xm = known.iter().map(|k| k.0).sum::<Vector3<f64>>() / n;
    let ym = known.iter().map(|k| k.1).sum::<Vector2<f64>>() / n;
    let mut xx = Matrix3::zeros();
    let mut yx = Matrix2x3::zeros();
    for (x, y) in &known {
        xx += (x - xm) * (x - xm).transpose();
        yx += (y - ym) * (x - xm).transpose();
    }
    if !psd3_nonsingular(&xx, n) {
        return None;
    }
    let a = yx * xx.try_inverse()?;
    let c = orthonormal_rows(&a);
    Some(Frame {
        rotation: complete_rotation(&c),
        translation: ym - c * xm,
    })
}

/// What the growth did not reach, by kind, each kind named only when some were missed:
/// frames by number, points by name.
fn unreached(frames: &[usize], points: &[&str]) -> String {
    let list = |v: Vec<String>| v.join(", ");
    let mut parts = Vec::new();
    if !frames.is_empty() {
        parts.push(format!(
            "{} frame(s) ({}; each needs 4 reconstructed points, not coplanar)",
            frames.len(),
            list(frames.iter().map(usize::to_string).collect())
        ));
    }
    if !points.is_empty() {
        parts.push(format!(
            "{} point(s) ({}; each needs 2 reconstructed frames)",
            points.len(),
            list(points.iter().map(|n| n.to_string()).collect())
        ));
    }
    format!(
        "not reachable from the largest complete block: {}",
        parts.join(" and ")
    )
}

/// The block's reconstruction, grown to every frame and point (unit observations; `numbers`
/// the input's number of each frame, for the message).
fn grow(
    obs: &Observations,
    block: &Reconstruction,
    (frames_in, points_in): (&[usize], &[usize]),
    numbers: &[usize],
) -> Result<(Vec<Frame>, Vec<Vector3<f64>>), Error> {
    let (k, p) = (obs.frames.len(), obs.names.len());
    let mut frames: Vec<Option<Frame>> = vec![None; k];
    let mut points: Vec<Option<Vector3<f64>>> = vec![None; p];
    for (a, &f) in frames_in.iter().enumerate() {
        frames[f] = Some(block.frames[a]);
    }
    for (b, &j) in points_in.iter().enumerate() {
        points[j] = Some(block.points[b]);
    }
    let by_point = obs.by_point();
    let by_frame: Vec<Vec<(usize, Vector2<f64>)>> = (0..k)
        .map(|f| {
            (0..p)
                .filter_map(|j| obs.frames[f][j].map(|y| (j, y)))
                .collect()
        })
        .collect();
    loop {
        let mut progress = false;
        for (j, seen) in by_point.iter().enumerate() {
            if points[j].is_none() {
                points[j] = intersect(&frames, seen);
                progress |= points[j].is_some();
            }
        }
        for (f, seen) in by_frame.iter().enumerate() {
            if frames[f].is_none() {
                frames[f] = resect(&points, seen);
                progress |= frames[f].is_some();
            }
        }
        if !progress {
            break;
        }
    }
    let lost_f: Vec<usize> = (0..k)
        .filter(|&f| frames[f].is_none())
        .map(|f| numbers[f])
        .collect();
    let lost_p: Vec<&str> = (0..p)
        .filter(|&j| points[j].is_none())
        .map(|j| obs.names[j].as_str())
        .collect();
    if !lost_f.is_empty() || !lost_p.is_empty() {
        return Err(Error::Unreachable(unreached(&lost_f, &lost_p)));
    }
    Ok((
        frames.into_iter().flatten().collect(),
        points.into_iter().flatten().collect(),
    ))
}

/// The starting reconstruction of tracks with gaps (before bundle adjustment).
pub fn initial(obs: &Observations) -> Result<Reconstruction, Error> {
    let numbers: Vec<usize> = (1..=obs.frames.len()).collect();
    initial_numbered(obs, &numbers)
}

/// [`initial`] of a part of the input: `numbers` gives each frame's number in the input, for
/// the messages.
pub(crate) fn initial_numbered(
    obs: &Observations,
    numbers: &[usize],
) -> Result<Reconstruction, Error> {
    obs.check_counts()?;
    let units = Units::of(obs)?;
    let unit = units.to_unit(obs);
    let (fs, ps) = largest_complete_block(&unit);
    if fs.len() < MIN_FRAMES || ps.len() < MIN_POINTS {
        return Err(Error::Unreachable(format!(
            "the largest complete block found has {} points in {} frames: at least {MIN_POINTS} in {MIN_FRAMES} are needed",
            ps.len(),
            fs.len()
        )));
    }
    let block_obs = Observations {
        names: ps.iter().map(|&j| unit.names[j].clone()).collect(),
        frames: fs
            .iter()
            .map(|&f| ps.iter().map(|&j| unit.frames[f][j]).collect())
            .collect(),
    };
    let tracks = block_obs
        .complete()
        .ok_or_else(|| Error::Numerical("the complete block has a gap".into()))?;
    let block_numbers: Vec<usize> = fs.iter().map(|&f| numbers[f]).collect();
    let block = super::tk::unit_tomasi_kanade(&tracks)
        .map_err(|e| super::pipeline::renumber(e, &block_numbers))?;
    let (frames, points) = grow(&unit, &block, (&fs, &ps), numbers)?;
    let mut method = block.method.clone();
    method[0] = format!(
        "{} on the largest complete block ({} points in {} frames)",
        method[0],
        ps.len(),
        fs.len()
    );
    method.push(format!(
        "gaps: {} points by intersection, {} frames by resection",
        obs.names.len() - ps.len(),
        obs.frames.len() - fs.len()
    ));
    let mut rec = Reconstruction {
        names: obs.names.clone(),
        points,
        frames,
        method,
        conditioning: block.conditioning,
        warnings: block.warnings.clone(),
    };
    rec.align_to_first();
    rec.centre();
    units.back(&mut rec);
    Ok(rec)
}
