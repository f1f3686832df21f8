//! `reconstruct` on a real turntable sequence that the project did not generate, judged
//! against the adjustment started from the sequence's own calibrated cameras.
//!
//! Usage: `cargo run --release -p orthocheck-benches --example real_turntable -- TRACKS
//! CAMERAS`. TRACKS: one track per line, `x1 y1 x2 y2 … xF yF` in pixels, `-1 -1` where the
//! point is not seen (the format of the Oxford dinosaur's `viff.xy`). CAMERAS: the F
//! projection matrices P = K [R | t] (3 × 4), three lines each, `#` lines skipped.
//!
//! Each point is triangulated from its images by the cameras (linear least squares), and
//! each camera split into K and R. The truth start is then the orthographic camera nearest
//! each real one: R's first two rows, the points scaled by the one factor and each frame
//! shifted by the translation that fit the images best (linear least squares). The sequence
//! is run twice, in pixels and calibrated (every image point mapped by K⁻¹, which removes
//! the pixels' aspect ratio and skew that no orthographic camera has). Each run prints
//! what `reconstruct` returns (its warnings, the final cost of each group) beside the cost
//! the adjustment started from the truth reaches on the same observations. `EXPORT=DIR`
//! writes each whole-sequence problem for `scripts/ceres_bench`'s solver (from the truth
//! and from the pipeline's fit).

use nalgebra::{DMatrix, Matrix3, Matrix3x4, Vector2, Vector3, Vector4};
use orthocheck::sfm::{
    bundle_adjust, reconstruct, BundleOptions, Frame, Observations, Options, Reconstruction,
};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let [tracks, cameras] = args.as_slice() else {
        eprintln!("usage: real_turntable TRACKS CAMERAS");
        std::process::exit(2);
    };
    let obs = read_tracks(tracks);
    let ps = read_cameras(cameras);
    assert_eq!(ps.len(), obs.frames.len(), "one camera per frame");
    let split: Vec<(Matrix3<f64>, Matrix3<f64>)> = ps
        .iter()
        .map(|p| rq(&p.fixed_columns::<3>(0).into_owned()))
        .collect();
    let points: Vec<Vector3<f64>> = (0..obs.names.len())
        .map(|j| triangulate(&obs, &ps, j))
        .collect();
    let seen = obs.count();
    println!(
        "{} tracks in {} frames, {} images ({:.1} % missing)",
        obs.names.len(),
        obs.frames.len(),
        seen,
        100.0 * (1.0 - seen as f64 / (obs.names.len() * obs.frames.len()) as f64)
    );
    let k = split[0].0;
    println!("K of frame 1: {k:.2}");
    let errors = reprojection(&obs, &ps, &points);
    println!(
        "the cameras' own reprojection error (px): median {:.3}, 99th percentile {:.3}, largest {:.3}",
        errors[errors.len() / 2],
        errors[errors.len() * 99 / 100],
        errors[errors.len() - 1]
    );
    let rotations: Vec<Matrix3<f64>> = split.iter().map(|s| s.1).collect();
    run("pixels", &obs, &rotations, &points);
    let calibrated = Observations {
        names: obs.names.clone(),
        frames: obs
            .frames
            .iter()
            .zip(&split)
            .map(|(f, (k, _))| {
                let inv = k.try_inverse().expect("an invertible K");
                f.iter()
                    .map(|y| y.map(|y| (inv * Vector3::new(y.x, y.y, 1.0)).xy()))
                    .collect()
            })
            .collect(),
    };
    run("calibrated (K⁻¹)", &calibrated, &rotations, &points);
}

/// The pipeline on `obs` beside the adjustment started from the truth.
fn run(label: &str, obs: &Observations, rotations: &[Matrix3<f64>], points: &[Vector3<f64>]) {
    println!("\n{label}:");
    let truth = truth_start(obs, rotations, points);
    let options = BundleOptions {
        standard_errors: false,
        ..BundleOptions::default()
    };
    let t0 = std::time::Instant::now();
    let best = bundle_adjust(obs, &truth, &options).expect("the truth-started adjustment");
    let best_cost = best.report.costs.last().copied().unwrap_or(f64::NAN);
    println!(
        "  truth-started adjustment: cost {:.10e} from {:.6e}, {} iterations{}, rms {:.4} ({:.2} s)",
        best_cost,
        best.report.costs[0],
        best.report.iterations,
        if best.report.converged { "" } else { " (limit)" },
        (2.0 * best_cost / obs.count() as f64).sqrt(),
        t0.elapsed().as_secs_f64()
    );
    let t0 = std::time::Instant::now();
    match reconstruct(obs, &Options::default()) {
        Ok(o) => {
            println!(
                "  reconstruct: {} group(s), {} dropped point(s), {} dropped frame(s) ({:.2} s)",
                o.components.len(),
                o.dropped_points.len(),
                o.dropped_frames.len(),
                t0.elapsed().as_secs_f64()
            );
            for (g, c) in o.components.iter().enumerate() {
                let cost = c.bundle.as_ref().and_then(|b| b.costs.last().copied());
                let whole = c.frames.len() == obs.frames.len()
                    && c.reconstruction.points.len() == obs.names.len();
                println!(
                    "  group {}: {} frames, {} points, cost {}{}",
                    g + 1,
                    c.frames.len(),
                    c.reconstruction.points.len(),
                    cost.map_or("none".into(), |c| format!("{c:.10e}")),
                    match (whole, cost) {
                        (true, Some(c)) => format!(
                            ", {:.6} × the truth-started cost: {}",
                            c / best_cost,
                            if c <= best_cost * (1.0 + 1e-6) {
                                "reached"
                            } else {
                                "missed"
                            }
                        ),
                        _ => String::new(),
                    }
                );
                if let (Some(dir), true) = (std::env::var_os("EXPORT"), whole) {
                    export(
                        std::path::Path::new(&dir),
                        label,
                        obs,
                        &best,
                        &truth,
                        &c.reconstruction,
                        cost,
                    );
                }
            }
            for w in o.warnings() {
                println!("  warning: {w}");
            }
        }
        Err(e) => println!("  reconstruct refused: {e}"),
    }
}

/// The whole sequence's problem for `scripts/ceres_bench`, from the truth and from the fit.
fn export(
    dir: &std::path::Path,
    label: &str,
    obs: &Observations,
    best: &orthocheck::sfm::Adjusted,
    truth: &Reconstruction,
    fit: &Reconstruction,
    cost: Option<f64>,
) {
    std::fs::create_dir_all(dir).expect("the export folder");
    let tag = label.split_whitespace().next().unwrap_or("run");
    let end = best.report.costs.last().copied().unwrap_or(f64::NAN);
    for (kind, start, start_cost) in [
        ("truth", truth, best.report.costs[0]),
        ("pipeline", fit, cost.unwrap_or(f64::NAN)),
    ] {
        let name = format!("real_{tag}_{kind}");
        let text = orthocheck_benches::problem_text(
            &name,
            obs,
            (start, &best.reconstruction),
            (best.report.iterations, end, start_cost),
            (0.0, 0.0),
        );
        std::fs::write(dir.join(format!("{name}.txt")), text).expect("the problem file");
    }
}

/// The orthographic cameras nearest the real ones: each rotation's first two rows, the
/// points scaled by the factor s and each frame shifted by the tᵢ that minimise
/// Σ ‖y − s Rᵢ X − tᵢ‖² (per frame centred, then s in closed form).
fn truth_start(
    obs: &Observations,
    rotations: &[Matrix3<f64>],
    points: &[Vector3<f64>],
) -> Reconstruction {
    let mut num = 0.0;
    let mut den = 0.0;
    let mut centres = Vec::new();
    for (f, r) in obs.frames.iter().zip(rotations) {
        let pairs: Vec<(Vector2<f64>, Vector2<f64>)> = f
            .iter()
            .zip(points)
            .filter_map(|(y, x)| y.map(|y| (y, (r * x).xy())))
            .collect();
        let n = pairs.len().max(1) as f64;
        let yc = pairs.iter().map(|p| p.0).sum::<Vector2<f64>>() / n;
        let pc = pairs.iter().map(|p| p.1).sum::<Vector2<f64>>() / n;
        for (y, p) in &pairs {
            num += (y - yc).dot(&(p - pc));
            den += (p - pc).norm_squared();
        }
        centres.push((yc, pc));
    }
    let s = num / den;
    Reconstruction {
        names: obs.names.clone(),
        points: points.iter().map(|x| x * s).collect(),
        frames: rotations
            .iter()
            .zip(&centres)
            .map(|(r, (yc, pc))| Frame {
                rotation: *r,
                translation: yc - pc * s,
            })
            .collect(),
        method: Vec::new(),
        conditioning: None,
        warnings: Vec::new(),
    }
}

/// M = K R, K upper triangular with a positive diagonal, R a proper rotation (P's sign
/// flipped where det M < 0, which names the same camera).
fn rq(m: &Matrix3<f64>) -> (Matrix3<f64>, Matrix3<f64>) {
    let m = if m.determinant() < 0.0 { -m } else { *m };
    let flip = Matrix3::new(0.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0);
    let qr = (flip * m).transpose().qr();
    let (q, r) = (qr.q(), qr.r());
    let mut k = flip * r.transpose() * flip;
    let mut rot = flip * q.transpose();
    let signs = Matrix3::from_diagonal(&k.diagonal().map(f64::signum));
    k *= signs;
    rot = signs * rot;
    (k / k[(2, 2)], rot)
}

/// The point of track `j` by linear least squares over its images (the null vector of the
/// stacked x P₃ − P₁, y P₃ − P₂).
fn triangulate(obs: &Observations, ps: &[Matrix3x4<f64>], j: usize) -> Vector3<f64> {
    let rows: Vec<_> = obs
        .frames
        .iter()
        .zip(ps)
        .filter_map(|(f, p)| f[j].map(|y| (y, p)))
        .flat_map(|(y, p)| [p.row(2) * y.x - p.row(0), p.row(2) * y.y - p.row(1)])
        .collect();
    let a = DMatrix::from_fn(rows.len(), 4, |i, c| rows[i][c]);
    let svd = (a.transpose() * &a).symmetric_eigen();
    let (i, _) = svd.eigenvalues.argmin();
    let h: Vector4<f64> = svd.eigenvectors.column(i).fixed_rows::<4>(0).into_owned();
    h.xyz() / h.w
}

/// Every image's distance from its point's projection by the real cameras, sorted.
fn reprojection(obs: &Observations, ps: &[Matrix3x4<f64>], points: &[Vector3<f64>]) -> Vec<f64> {
    let mut e: Vec<f64> = obs
        .frames
        .iter()
        .zip(ps)
        .flat_map(|(f, p)| {
            f.iter().zip(points).filter_map(move |(y, x)| {
                y.map(|y| {
                    let h = p * x.push(1.0);
                    (h.xy() / h.z - y).norm()
                })
            })
        })
        .collect();
    e.sort_by(f64::total_cmp);
    e
}

fn read_tracks(path: &str) -> Observations {
    let text = std::fs::read_to_string(path).expect("the tracks file");
    let rows: Vec<Vec<f64>> = text
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            l.split_whitespace()
                .map(|v| v.parse().expect("a number"))
                .collect()
        })
        .collect();
    let frames = rows[0].len() / 2;
    Observations {
        names: (1..=rows.len()).map(|j| format!("T{j}")).collect(),
        frames: (0..frames)
            .map(|f| {
                rows.iter()
                    .map(|r| {
                        let (x, y) = (r[2 * f], r[2 * f + 1]);
                        (x != -1.0 || y != -1.0).then(|| Vector2::new(x, y))
                    })
                    .collect()
            })
            .collect(),
    }
}

fn read_cameras(path: &str) -> Vec<Matrix3x4<f64>> {
    let text = std::fs::read_to_string(path).expect("the cameras file");
    let values: Vec<f64> = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .flat_map(|l| {
            l.split_whitespace()
                .map(|v| v.parse::<f64>().expect("a number"))
        })
        .collect();
    values
        .chunks_exact(12)
        .map(Matrix3x4::from_row_slice)
        .collect()
}
