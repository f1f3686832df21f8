//! How often `reconstruct` reaches the optimum that a bundle adjustment started from the
//! truth reaches, over a broad seeded family of turntable sequences, and whether it warns
//! where it does not.
//!
//! Usage: `cargo run --release -p orthocheck-benches --example turntable_family -- [SCENES]
//! [SEED]` (defaults 400 scenes, seed 1). Each scene: 50–500 points uniform in [−1, 1]³ on
//! a table turning once over the frames, the camera's elevation 10°–70°; each point seen in
//! consecutive frames from a random first one, its track's length uniform in 1..=L (L, the
//! longest track, 2–8), the frame count chosen so that 80–92 % of the entries are missing
//! (20–100 frames), relative noise 0.1 %–1 %. The pipeline reaches the optimum when every
//! group it returns has a final cost within 10⁻⁶ of the truth-started adjustment of the
//! same observations (the group's frames and points), relative (distinct optima differ by
//! far more); lower counts as reached too. One group over every frame is the whole scene;
//! scenes split into groups, or with frames dropped, are counted apart as well. The table:
//! elevation band × L. `SHOW_ERRORS=1` prints each miss's warnings or error, and each of
//! its groups' cost against the truth-started one; `ONLY=N` (or `N,M,…`) runs those scenes alone; `EXPORT=DIR`
//! writes each group's problem for `scripts/ceres_bench` (from the truth and from the
//! pipeline's fit). `NECKER=1` prints, for each missed group, whether each pair of
//! consecutive frames has the optimum's relative rotation (S), its depth-reflected twin's
//! (T) or neither (?), within 1°; `CUTS=1` with it tries reflecting the fit after each frame
//! (docs/limits.md).

use nalgebra::Vector3;
use orthocheck::sfm::turntable::{family_scene, family_seed, FamilyScene};
use orthocheck::sfm::{
    bundle_adjust, reconstruct, BundleOptions, Component, Observations, Options, Reconstruction,
};

/// The adjustment alone: the peers compute no standard errors.
fn loop_only() -> BundleOptions {
    BundleOptions {
        standard_errors: false,
        ..BundleOptions::default()
    }
}

fn main() {
    let args: Vec<u64> = orthocheck_benches::numbers();
    let (scenes, seed) = (
        args.first().copied().unwrap_or(400),
        args.get(1).copied().unwrap_or(1),
    );
    // [elevation band][longest − 2]: (scenes, reached, missed but warned, errors, split)
    let mut table: [[Cell; 7]; 3] = [[(0, 0, 0, 0, 0); 7]; 3];
    // scenes that reached the optimum and still warned
    let mut alarms = 0usize;
    // scenes reached as one group over every frame (the whole scene's optimum)
    let mut whole = 0usize;
    // ONLY=N or ONLY=N,M,…: those scenes alone
    let only: Option<Vec<u64>> = std::env::var("ONLY")
        .ok()
        .map(|v| v.split(',').filter_map(|n| n.trim().parse().ok()).collect());
    for s in 0..scenes {
        if only.as_ref().is_some_and(|o| !o.contains(&s)) {
            continue;
        }
        let m = family_scene(family_seed(seed, s));
        let band = ((m.elevation - 10.0) / 20.0).floor().clamp(0.0, 2.0) as usize;
        let cell = &mut table[band][m.longest - 2];
        cell.0 += 1;
        match reconstruct(&m.obs, &Options::default()) {
            Ok(o) => {
                // every group against the optimum of its own observations started from the
                // truth (one group over every frame: the whole scene's)
                let costs: Vec<(Option<f64>, Option<f64>)> = o
                    .components
                    .iter()
                    .enumerate()
                    .map(|(g, c)| costs(&m, c, (s, g)))
                    .collect();
                let reached = costs
                    .iter()
                    .all(|c| matches!(c, (Some(a), Some(b)) if *a <= b * (1.0 + 1e-6)));
                cell.4 += usize::from(o.components.len() > 1 || !o.dropped_frames.is_empty());
                let warned = !o.warnings().is_empty();
                if reached {
                    cell.1 += 1;
                    alarms += usize::from(warned);
                    whole += usize::from(o.components.len() == 1 && o.dropped_frames.is_empty());
                    if std::env::var_os("SHOW_ERRORS").is_some() && warned {
                        eprintln!("scene {s}: reached, warned: {}", o.warnings().join(" | "));
                    }
                } else if warned {
                    cell.2 += 1;
                    if std::env::var_os("SHOW_ERRORS").is_some() {
                        eprintln!("scene {s}: missed, warned: {}", o.warnings().join(" | "));
                        for (c, (got, best)) in o.components.iter().zip(&costs) {
                            eprintln!(
                                "  group of frames {:?} ({} points): cost {got:?} against the truth-started {best:?}",
                                c.frames,
                                c.reconstruction.points.len()
                            );
                        }
                    }
                } else if std::env::var_os("SHOW_ERRORS").is_some() {
                    for (c, (got, best)) in o.components.iter().zip(&costs) {
                        eprintln!(
                            "scene {s}: silent miss, frames {:?}, cost {got:?} against the truth-started {best:?}; {}",
                            c.frames,
                            c.reconstruction.method.join("; ")
                        );
                    }
                }
            }
            Err(e) => {
                if std::env::var_os("SHOW_ERRORS").is_some() {
                    eprintln!("scene {s}: {e}");
                }
                cell.3 += 1;
            }
        }
    }
    print_table(&table);
    println!("warned although the optimum was reached: {alarms}");
    println!("reached as one group over every frame (the whole scene's optimum): {whole}");
}

/// A group's final cost, and the cost the adjustment of the same observations started from
/// the truth reaches.
/// With `EXPORT=DIR`, each group's problem is written for `scripts/ceres_bench`'s solver
/// (`orthocheck_benches::problem_text`): `DIR/family_S_G_truth.txt` from the truth, with the
/// truth-started adjustment as orthocheck's result, and `DIR/family_S_G_pipeline.txt` from
/// the pipeline's fit (S the scene, G the group).
fn costs(m: &FamilyScene, c: &Component, (s, g): (u64, usize)) -> (Option<f64>, Option<f64>) {
    let index: std::collections::HashMap<&str, usize> = m
        .obs
        .names
        .iter()
        .enumerate()
        .map(|(j, n)| (n.as_str(), j))
        .collect();
    let cols: Vec<usize> = c
        .reconstruction
        .names
        .iter()
        .map(|n| index[n.as_str()])
        .collect();
    let obs = Observations {
        names: c.reconstruction.names.clone(),
        frames: c
            .frames
            .iter()
            .map(|&f| cols.iter().map(|&j| m.obs.frames[f - 1][j]).collect())
            .collect(),
    };
    let truth = Reconstruction {
        names: obs.names.clone(),
        points: cols.iter().map(|&j| m.truth.points[j]).collect(),
        frames: c.frames.iter().map(|&f| m.truth.frames[f - 1]).collect(),
        ..m.truth.clone()
    };
    let adjusted = bundle_adjust(&obs, &truth, &loop_only()).ok();
    let best = adjusted
        .as_ref()
        .and_then(|a| a.report.costs.last().copied());
    let got = c.bundle.as_ref().and_then(|b| b.costs.last().copied());
    if let (Some(_), Some(a), Some(gc), Some(bc)) =
        (std::env::var_os("NECKER"), &adjusted, got, best)
        && gc > bc * (1.0 + 1e-6)
    {
        necker(
            &obs,
            (&c.reconstruction, gc),
            (&a.reconstruction, bc),
            (s, g),
        );
    }
    if let (Some(dir), Some(a)) = (std::env::var_os("EXPORT"), &adjusted) {
        let starts = [
            ("truth", &truth, a.report.costs[0]),
            ("pipeline", &c.reconstruction, got.unwrap_or(f64::NAN)),
        ];
        export(std::path::Path::new(&dir), (s, g), &obs, a, &starts);
    }
    (got, best)
}

/// Writes one problem file per start for the Ceres solver: `DIR/family_S_G_KIND.txt`, each
/// with the truth-started adjustment `a` as orthocheck's result.
fn export(
    dir: &std::path::Path,
    (s, g): (u64, usize),
    obs: &Observations,
    a: &orthocheck::sfm::Adjusted,
    starts: &[(&str, &Reconstruction, f64)],
) {
    std::fs::create_dir_all(dir).expect("the export folder");
    let end = a.report.costs.last().copied().unwrap_or(f64::NAN);
    for (kind, start, start_cost) in starts {
        let name = format!("family_{s}_{g}_{kind}");
        let text = orthocheck_benches::problem_text(
            &name,
            obs,
            (start, &a.reconstruction),
            (a.report.iterations, end, *start_cost),
            (0.0, 0.0),
        );
        std::fs::write(dir.join(format!("{name}.txt")), text).expect("the problem file");
    }
}

/// Per cell: scenes, reached, misses warned, refused, split into groups or with frames
/// dropped (each group judged on its own).
type Cell = (usize, usize, usize, usize, usize);

fn print_table(table: &[[Cell; 7]; 3]) {
    println!("reached the truth-started optimum (of scenes; misses warned; refused; scenes split into groups or with frames dropped, each group judged on its own), by elevation and longest track:\n");
    println!("| elevation | L = 2 | 3 | 4 | 5 | 6 | 7 | 8 | all |");
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut total = (0, 0, 0, 0, 0);
    for (b, row) in table.iter().enumerate() {
        let mut line = format!("| {}°–{}° |", 10 + 20 * b, 30 + 20 * b);
        let mut sum = (0, 0, 0, 0, 0);
        for c in row {
            line += &format!(" {} of {} ({}; {}; {}) |", c.1, c.0, c.2, c.3, c.4);
            sum = (
                sum.0 + c.0,
                sum.1 + c.1,
                sum.2 + c.2,
                sum.3 + c.3,
                sum.4 + c.4,
            );
        }
        line += &format!(
            " {} of {} ({}; {}; {}) |",
            sum.1, sum.0, sum.2, sum.3, sum.4
        );
        println!("{line}");
        total = (
            total.0 + sum.0,
            total.1 + sum.1,
            total.2 + sum.2,
            total.3 + sum.3,
            total.4 + sum.4,
        );
    }
    let silent = total.0 - total.1 - total.2 - total.3;
    println!(
        "\nall: {} of {} reached ({:.1} %); of the misses {} warned, {} refused, {} silent; {} scenes split into groups or with frames dropped",
        total.1,
        total.0,
        100.0 * total.1 as f64 / total.0.max(1) as f64,
        total.2,
        total.3,
        silent,
        total.4
    );
}

/// A missed group's relative rotations against the truth-started optimum's, and with `CUTS`
/// set, how far hops that reflect the fit after one frame (each cut adjusted in full, the
/// best kept, up to 8 rounds while the cost falls) take it.
fn necker(
    obs: &Observations,
    (fit, fit_cost): (&Reconstruction, f64),
    (optimum, optimum_cost): (&Reconstruction, f64),
    (s, g): (u64, usize),
) {
    eprintln!(
        "  scene {s} group {g}: relative rotations {}",
        pattern(fit, optimum)
    );
    if std::env::var_os("CUTS").is_none() {
        return;
    }
    let mut current = (fit_cost, fit.clone());
    let mut hops = Vec::new();
    for _ in 0..8 {
        let best = (1..current.1.frames.len())
            .filter_map(|k| {
                let a = bundle_adjust(obs, &twin_after(obs, &current.1, k), &loop_only()).ok()?;
                Some((*a.report.costs.last()?, k, a.reconstruction))
            })
            .min_by(|x, y| x.0.total_cmp(&y.0));
        match best {
            Some((v, k, r)) if v < current.0 * (1.0 - 1e-6) => {
                hops.push((k, v));
                current = (v, r);
            }
            _ => break,
        }
    }
    eprintln!(
        "    fit {fit_cost:.4e}, truth-started {optimum_cost:.4e}, best cut ({:e}, {hops:?})",
        current.0
    );
}

/// Per pair of consecutive frames, whether the fit's relative rotation is the reference's
/// (S), its depth-reflected twin's (T), or neither (?).
fn pattern(fit: &Reconstruction, reference: &Reconstruction) -> String {
    let d = nalgebra::Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
    let angle = |m: nalgebra::Matrix3<f64>| {
        ((m.trace() - 1.0) / 2.0)
            .clamp(-1.0, 1.0)
            .acos()
            .to_degrees()
    };
    (1..fit.frames.len())
        .map(|k| {
            let rel =
                |r: &Reconstruction| r.frames[k].rotation * r.frames[k - 1].rotation.transpose();
            let (f, t) = (rel(fit), rel(reference));
            let same = angle(f * t.transpose());
            let twin = angle(f * (d * t * d).transpose());
            if same < 1.0 && same < twin {
                'S'
            } else if twin < 1.0 {
                'T'
            } else {
                '?'
            }
        })
        .collect()
}

/// The fit with every frame from `k` on replaced by its depth-reflected twin (R ↦ DRD), and
/// every point seen mostly from `k` on reflected (X ↦ DX).
fn twin_after(obs: &Observations, fit: &Reconstruction, k: usize) -> Reconstruction {
    let d = nalgebra::Matrix3::from_diagonal(&Vector3::new(1.0, 1.0, -1.0));
    let mut out = fit.clone();
    for f in &mut out.frames[k..] {
        f.rotation = d * f.rotation * d;
    }
    for (j, x) in out.points.iter_mut().enumerate() {
        let (before, after) = obs
            .frames
            .iter()
            .enumerate()
            .filter(|(_, f)| f[j].is_some())
            .fold(
                (0, 0),
                |(b, a), (i, _)| if i < k { (b + 1, a) } else { (b, a + 1) },
            );
        if after > before {
            *x = d * *x;
        }
    }
    out
}
