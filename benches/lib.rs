//! What the benchmarks share: where the paper's cases are, the examples' command lines, the
//! turntable family's scenes.

use std::fmt::Write as _;
use std::path::PathBuf;

use nalgebra::{Rotation3, Vector2, Vector3};
use orthocheck::model::{rng, Body, Motion, NoiseModel, Scene};
use orthocheck::sfm::{Frame, Observations, Reconstruction, Units};
use rand::Rng;

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

/// A scene of the turntable family (`turntable_family`): its observations, the truth (the
/// body centred, in frame 1's camera coordinates, and the motions), the camera's elevation
/// (degrees) and the longest track.
pub struct FamilyScene {
    /// The observations, with gaps.
    pub obs: Observations,
    /// The true body and motions.
    pub truth: Reconstruction,
    /// The camera's elevation above the table, in degrees.
    pub elevation: f64,
    /// The longest track, L: each point is seen in 1..=L consecutive frames.
    pub longest: usize,
}

/// The seed of scene `s` of the family's run of seed `seed`.
pub fn family_seed(seed: u64, s: u64) -> u64 {
    seed.wrapping_mul(7_919).wrapping_add(s)
}

/// The family's scene of seed `seed`: 50–500 points uniform in [−1, 1]³ on a table turning
/// once over the frames, the camera's elevation 10°–70°, each point seen in consecutive
/// frames from a random first one (round the end), its track's length uniform in 1..=L (L
/// 2–8), the frame count k = round((L + 1) / (2 (1 − m))) for a missing share m drawn in
/// 80–92 %, clamped to 20–100 (so 20–56: tracks of at most 8 frames cannot leave 92 % or
/// less missing in more; L = 2 gives 20 frames, 92.5 % missing), relative noise 0.1 %–1 %.
pub fn family_scene(seed: u64) -> FamilyScene {
    let mut g = rng(seed);
    let p = g.random_range(50..=500usize);
    let longest = g.random_range(2..=8usize);
    let missing = g.random_range(0.80..0.92);
    let k = (((longest + 1) as f64 / (2.0 * (1.0 - missing))).round() as usize).clamp(20, 100);
    let elevation: f64 = g.random_range(10.0f64..70.0);
    let eps = g.random_range(0.001..0.01);
    let points: Vec<Vector3<f64>> = (0..p)
        .map(|_| Vector3::from_fn(|_, _| g.random_range(-1.0..1.0)))
        .collect();
    let tilt = Rotation3::from_axis_angle(&Vector3::x_axis(), elevation.to_radians());
    let motions: Vec<Motion> = (0..k)
        .map(|f| {
            let spin = Rotation3::from_axis_angle(
                &Vector3::y_axis(),
                std::f64::consts::TAU * f as f64 / k as f64,
            );
            Motion {
                rotation: tilt * spin * tilt.inverse(),
                translation: Vector2::zeros(),
            }
        })
        .collect();
    let names: Vec<String> = (1..=p).map(|j| format!("P{j}")).collect();
    let s = Scene {
        body: Body {
            names,
            points: points.clone(),
        },
        motions: motions.clone(),
    };
    let tracks = NoiseModel::RelativeCoordinate { eps }.perturb_tracks(&s.tracks(), &mut g);
    let spans: Vec<(usize, usize)> = (0..p)
        .map(|_| (g.random_range(0..k), g.random_range(1..=longest)))
        .collect();
    let obs = Observations::seen_where(&tracks, |f, j| (f + k - spans[j].0) % k < spans[j].1);
    let c = points.iter().sum::<Vector3<f64>>() / p as f64;
    let truth = Reconstruction {
        names: s.body.names.clone(),
        points: points.iter().map(|x| x - c).collect(),
        frames: motions
            .iter()
            .map(|m| {
                let r = *m.rotation.matrix();
                Frame {
                    rotation: r,
                    translation: (r * c).xy(),
                }
            })
            .collect(),
        method: Vec::new(),
        conditioning: None,
        warnings: Vec::new(),
    };
    FamilyScene {
        obs,
        truth,
        elevation,
        longest,
    }
}
