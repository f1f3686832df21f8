//! What the benchmarks share: where the paper's cases are, the examples' command lines.

use std::fmt::Write as _;
use std::path::PathBuf;

use orthocheck::sfm::{Observations, Reconstruction, Units};

/// The folder of the paper's cases, `paper_cases/` of the repository.
pub fn paper_cases() -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../paper_cases"))
}

/// The command line's arguments that parse as numbers, in order (the others left out).
pub fn numbers<T: std::str::FromStr>() -> Vec<T> {
    std::env::args()
        .skip(1)
        .filter_map(|a| a.parse().ok())
        .collect()
}

/// The command line of a calibration run: `[SCENES] [SEED] [absolute]`.
#[derive(Clone, Copy, Debug)]
pub struct Calibration {
    /// Scenes to run.
    pub scenes: u64,
    /// The run's seed (default 1).
    pub seed: u64,
    /// Noise of one scale across the image instead of relative noise.
    pub absolute: bool,
}

impl Calibration {
    /// The arguments, `scenes` scenes by default.
    pub fn from_args(scenes: u64) -> Calibration {
        let numbers: Vec<u64> = numbers();
        Calibration {
            scenes: numbers.first().copied().unwrap_or(scenes),
            seed: numbers.get(1).copied().unwrap_or(1),
            absolute: std::env::args().any(|a| a == "absolute"),
        }
    }

    /// The seed of scene `s` of a run of seed `seed`.
    pub fn scene_seed(seed: u64, s: u64) -> u64 {
        seed.wrapping_mul(1_000_003).wrapping_add(s)
    }
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
    /// Scenes with a bad item beyond 10 σ.
    pub far_scenes: usize,
    /// Of them, those where every such item was found.
    pub found_scenes: usize,
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

impl Tally {
    /// One scene's bad items beyond 10 σ: `far` of them, `found` of those found.
    pub fn far_in_scene(&mut self, far: usize, found: usize) {
        self.far += far;
        self.found += found;
        if far > 0 {
            self.far_scenes += 1;
            self.found_scenes += usize::from(found == far);
        }
    }
}

/// The bands and their sum as a Markdown table under `header` (its five column names; a
/// sixth is added: the scenes with a bad item beyond 10 σ where every such item was found).
pub fn print_bands(header: &str, bands: &[Tally; 3]) {
    println!("{header} scenes with one beyond 10 σ: every one found |");
    println!("|---|---:|---:|---:|---:|---:|");
    let mut all = Tally::default();
    for (name, b) in BANDS.iter().zip(bands) {
        print_row(name, b);
        all.scenes += b.scenes;
        all.good += b.good;
        all.lost += b.lost;
        all.far += b.far;
        all.found += b.found;
        all.far_scenes += b.far_scenes;
        all.found_scenes += b.found_scenes;
        all.refused += b.refused;
    }
    print_row("all", &all);
}

fn print_row(name: &str, b: &Tally) {
    let pct = |a: usize, n: usize| 100.0 * a as f64 / n.max(1) as f64;
    println!(
        "| {name} | {} | {} of {} ({:.2} %) | {} of {} ({:.2} %) | {} | {} of {} ({:.2} %) |",
        b.scenes,
        b.lost,
        b.good,
        pct(b.lost, b.good),
        b.found,
        b.far,
        pct(b.found, b.far),
        b.refused,
        b.found_scenes,
        b.far_scenes,
        pct(b.found_scenes, b.far_scenes)
    );
}

/// A reconstruction's frames and points as lines of a problem file, each tag prefixed by `tag`.
fn frames_and_points(text: &mut String, tag: &str, rec: &Reconstruction) {
    for (f, fr) in rec.frames.iter().enumerate() {
        let r = &fr.rotation;
        let _ = write!(text, "{tag}frame {f}");
        for i in 0..3 {
            for j in 0..3 {
                let _ = write!(text, " {:.16e}", r[(i, j)]);
            }
        }
        let _ = writeln!(text, " {:.16e} {:.16e}", fr.translation.x, fr.translation.y);
    }
    for (j, x) in rec.points.iter().enumerate() {
        let _ = writeln!(
            text,
            "{tag}point {j} {:.16e} {:.16e} {:.16e}",
            x.x, x.y, x.z
        );
    }
}

/// A bundle-adjustment problem file (`scripts/ceres_bench/`, format in `ceres_export`): units, sizes, orthocheck's figures, the start, the observations and
/// orthocheck's result, in the units `sfm::Units` works in.
pub fn problem_text(
    name: &str,
    obs: &Observations,
    (start, result): (&Reconstruction, &Reconstruction),
    (iterations, final_cost, start_cost): (usize, f64, f64),
    (secs, overhead): (f64, f64),
) -> String {
    let units = Units::of(obs).expect("finite coordinates");
    let mut unit_start = start.clone();
    units.forward(&mut unit_start);
    let mut unit_result = result.clone();
    units.forward(&mut unit_result);
    let unit_obs = units.to_unit(obs);
    let mut text = String::new();
    let _ = writeln!(text, "name {name}");
    let _ = writeln!(
        text,
        "units {:.16e} {:.16e} {:.16e}",
        units.centre.x, units.centre.y, units.scale
    );
    let _ = writeln!(
        text,
        "sizes {} {} {}",
        obs.frames.len(),
        obs.names.len(),
        obs.count()
    );
    let _ = writeln!(
        text,
        "rust {} {final_cost:.16e} {start_cost:.16e} {secs:.6e} {overhead:.6e}",
        iterations
    );
    frames_and_points(&mut text, "", &unit_start);
    for (f, j, y) in unit_obs.seen() {
        let _ = writeln!(text, "obs {f} {j} {:.16e} {:.16e}", y.x, y.y);
    }
    frames_and_points(&mut text, "rust_", &unit_result);
    text
}
