//! How often `reconstruct` reaches the truth-started optimum on turntable sequences whose
//! every track is the same few frames long (`sfm::turntable`), the hardest kind for its
//! starts (docs/limits.md, "Against the truth").
//!
//! Usage: `cargo run --release -p orthocheck-benches --example uniform_windows -- [SEEDS]
//! [WINDOW]` (defaults 25 seeds, window 3): 20 and 24 frames × 60 and 80 points, elevation
//! 30°, relative noise 0.5 %, seeds 1..=SEEDS. Each line: the sequence, its final cost over
//! the truth-started one, and the start kept; then the count within 10⁻⁶ of it (relative,
//! or lower).

use orthocheck::sfm::turntable::Turntable;
use orthocheck::sfm::{bundle_adjust, reconstruct, BundleOptions, Options, Reconstruction};

fn main() {
    let args: Vec<u64> = orthocheck_benches::numbers();
    let (seeds, window) = (
        args.first().copied().unwrap_or(25),
        args.get(1).copied().unwrap_or(3) as usize,
    );
    let (mut reached, mut runs) = (0usize, 0usize);
    for frames in [20usize, 24] {
        for points in [60usize, 80] {
            for seed in 1..=seeds {
                runs += 1;
                let t = Turntable {
                    points,
                    frames,
                    window,
                    elevation: 30f64.to_radians(),
                    noise: Some(0.005),
                    seed,
                };
                let (scene, obs) = t.generate();
                let label = format!("{frames} frames, {points} points, seed {seed}");
                let fit = reconstruct(&obs, &Options::default()).map(|o| o.into_single());
                let Ok(Some(c)) = fit else {
                    println!("{label}: refused or split into groups");
                    continue;
                };
                let Some(got) = c.bundle.and_then(|b| b.costs.last().copied()) else {
                    println!("{label}: no adjustment");
                    continue;
                };
                let truth = Reconstruction::of_scene(&scene);
                let best = bundle_adjust(&obs, &truth, &BundleOptions::default())
                    .ok()
                    .and_then(|a| a.report.costs.last().copied());
                let Some(best) = best else {
                    println!("{label}: the truth-started adjustment failed");
                    continue;
                };
                reached += usize::from(got <= best * (1.0 + 1e-6));
                let method = c.reconstruction.method.join("; ");
                let kept = method
                    .split("kept: ")
                    .nth(1)
                    .unwrap_or("the first start alone");
                println!(
                    "{label}: {:.6} × the truth-started cost; {kept}",
                    got / best
                );
            }
        }
    }
    println!("reached the truth-started optimum: {reached} of {runs}");
}
