//! How often variable projection reaches the best optimum of a turntable sequence from
//! random starts, beside alternating least squares from the same starts, and from the
//! chained pairs (the start `reconstruct` uses).
//!
//! Usage: `cargo run --release -p orthocheck-benches --example turntable_starts -- [POINTS]
//! [WINDOW] [STARTS]` (defaults 117 points, window 4, 20 starts; 36 frames, 30° elevation,
//! 0.1 % noise, seed 1: the case of `tests/suite/sfm_tracks.rs`). A run reaches the optimum when its
//! cost is within 10⁻⁶ of the best cost found, relative (distinct local optima differ by
//! orders of magnitude more: the distinct costs are printed).

use orthocheck::sfm::turntable::Turntable;
use orthocheck::sfm::{judge, missing, Units};

fn main() {
    let args: Vec<usize> = orthocheck_benches::numbers();
    let (points, window, starts) = (
        args.first().copied().unwrap_or(117),
        args.get(1).copied().unwrap_or(4),
        args.get(2).copied().unwrap_or(20),
    );
    let t = Turntable {
        points,
        frames: 36,
        window,
        elevation: 30f64.to_radians(),
        noise: Some(0.001),
        seed: 1,
    };
    let (_, obs) = t.generate();
    let units = Units::of(&obs).expect("finite");
    let views = judge::views(&units.to_unit(&obs));
    let missing_share = 1.0 - obs.count() as f64 / (points * 36) as f64;
    println!(
        "{points} points, 36 frames, window {window}: {:.1} % missing",
        100.0 * missing_share
    );
    let chain = missing::chained_start(&views, 36)
        .and_then(|s| missing::varpro(&views, s, missing::MAX_ITERATIONS));
    let mut costs: Vec<(&str, f64)> = Vec::new();
    if let Some(c) = &chain {
        println!(
            "chained pairs: variable projection cost {:.6e}, {} iterations",
            c.cost, c.iterations
        );
        costs.push(("chain", c.cost));
    }
    for s in 0..starts as u64 {
        let vp = missing::varpro(
            &views,
            missing::random_start(36, s),
            missing::MAX_ITERATIONS,
        );
        let als = missing::als(
            &views,
            missing::random_start(36, s),
            10 * missing::MAX_ITERATIONS,
        );
        costs.push(("varpro", vp.map_or(f64::INFINITY, |f| f.cost)));
        costs.push(("als", als.map_or(f64::INFINITY, |f| f.cost)));
    }
    let best = costs.iter().map(|c| c.1).fold(f64::INFINITY, f64::min);
    for method in ["varpro", "als"] {
        let mine: Vec<f64> = costs
            .iter()
            .filter(|c| c.0 == method)
            .map(|c| c.1)
            .collect();
        let hit = mine.iter().filter(|&&c| c <= best * (1.0 + 1e-6)).count();
        let mut sorted = mine.clone();
        sorted.sort_by(f64::total_cmp);
        println!(
            "{method}: {hit} of {starts} random starts reach the best cost {best:.6e}; median final cost {:.3e}",
            sorted[sorted.len() / 2]
        );
    }
}
