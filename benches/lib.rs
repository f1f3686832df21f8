//! What the benchmarks share: where the paper's cases are.

use std::path::PathBuf;

/// The folder of the paper's cases, `paper_cases/` of the repository.
pub fn paper_cases() -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../paper_cases"))
}

/// One band's counts in a calibration run (`membership_calibration`, `robust_calibration`):
/// the scenes, the good items judged and those set apart, the far bad items and those found,
/// the scenes refused.
#[derive(Clone, Copy, Debug, Default)]
pub struct Tally {
    /// Scenes.
    pub scenes: usize,
    /// Good items judged (true members, good observations).
    pub good: usize,
    /// Of them, those set apart.
    pub lost: usize,
    /// Bad items beyond 10 σ.
    pub far: usize,
    /// Of them, those found.
    pub found: usize,
    /// Scenes refused.
    pub refused: usize,
}

/// The calibration runs' bands of scene sizes: 6–9, 10–19, 20–50 members or points.
pub const BANDS: [&str; 3] = ["6–9", "10–19", "20–50"];

/// The band (index into [`BANDS`]) of a scene of `n` members or points.
pub fn band(n: usize) -> usize {
    match n {
        ..10 => 0,
        10..20 => 1,
        _ => 2,
    }
}

/// The bands and their sum as a Markdown table under `header` (its five column names).
pub fn print_bands(header: &str, bands: &[Tally; 3]) {
    println!("{header}");
    println!("|---|---:|---:|---:|---:|");
    let mut all = Tally::default();
    for (name, b) in BANDS.iter().zip(bands) {
        print_row(name, b);
        all.scenes += b.scenes;
        all.good += b.good;
        all.lost += b.lost;
        all.far += b.far;
        all.found += b.found;
        all.refused += b.refused;
    }
    print_row("all", &all);
}

fn print_row(name: &str, b: &Tally) {
    let pct = |a: usize, n: usize| 100.0 * a as f64 / n.max(1) as f64;
    println!(
        "| {name} | {} | {} of {} ({:.2} %) | {} of {} ({:.2} %) | {} |",
        b.scenes,
        b.lost,
        b.good,
        pct(b.lost, b.good),
        b.found,
        b.far,
        pct(b.found, b.far),
        b.refused
    );
}
