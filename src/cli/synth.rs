//! `orthocheck synth`: a tracks file of a seeded random scene, to try the solvers on.

use std::fmt::Write as _;
use std::path::PathBuf;

use crate::input::{tracks_to_csv, tracks_to_yaml};
use crate::model::Tracks;
use crate::numfmt::round_trip;
use crate::seeds::synthetic;
use crate::Error;
use clap::ValueEnum;
use rand::seq::SliceRandom as _;

use super::{out, write_new};

/// Arguments of `synth`.
#[derive(clap::Args)]
pub struct Args {
    /// Number of points.
    #[arg(long, allow_negative_numbers = true)]
    points: usize,
    /// Number of frames.
    #[arg(long, allow_negative_numbers = true)]
    frames: usize,
    /// Seed.
    #[arg(long, allow_negative_numbers = true, value_parser = super::SeedParser)]
    seed: u64,
    /// Relative error up to ε on every image coordinate.
    #[arg(long, allow_negative_numbers = true)]
    noise: Option<f64>,
    /// Output format.
    #[arg(long, value_enum, default_value = "yaml")]
    format: FormatArg,
    /// Write to this file (refused if it exists); standard output otherwise.
    #[arg(long)]
    out: Option<PathBuf>,
    /// Shuffle the order of the points in every frame after the first (seeded by --seed),
    /// for `identify`, which finds which point is which between two frames listed in
    /// different orders (so use it with --frames 2). The header names the order each frame
    /// lists the points in, to check identify's answer against; CSV rows of a shuffled frame
    /// are labelled X1, X2, … so that their names do not give the answer away. A shuffled
    /// file is not for `solve`, which needs the points in the same order in every frame.
    #[arg(long)]
    shuffle: bool,
    /// A turntable sequence instead of random motions: the body turns by 360°/frames per
    /// frame about an axis tilted by --elevation, and each point is seen in --window
    /// consecutive frames from a random first one (the rest are gaps: no CSV row, `null` in
    /// YAML), the missing data of real sequences (e.g. `--points 117 --frames 36 --window 4`:
    /// about 90 % missing, 13 points a frame). For `reconstruct`, not `solve`.
    #[arg(long, conflicts_with = "shuffle")]
    turntable: bool,
    /// Frames each point is seen in, with --turntable (2 ..= --frames).
    #[arg(
        long,
        allow_negative_numbers = true,
        default_value_t = 4,
        requires = "turntable"
    )]
    window: usize,
    /// The camera's elevation above the table, in degrees, with --turntable (−89 ..= 89).
    #[arg(
        long,
        allow_negative_numbers = true,
        default_value_t = 30.0,
        requires = "turntable"
    )]
    elevation: f64,
}

/// The tracks file formats.
#[derive(Clone, Copy, ValueEnum)]
enum FormatArg {
    Yaml,
    Csv,
}

/// Make the scene, write its tracks with a header naming the truth.
pub fn run(a: Args) -> Result<(), Error> {
    check_limits(&a).map_err(Error::InvalidInput)?;
    if a.turntable {
        return turntable(&a);
    }
    let s = synthetic(a.points, a.frames, a.seed, a.noise);
    let header = synth_header(&s.scene, a.seed, a.noise);
    let text = if a.shuffle {
        let orders = shuffled_orders(a.points, a.frames, a.seed);
        let tracks = reorder(&s.tracks, &orders)?;
        let body = match a.format {
            FormatArg::Yaml => tracks_to_yaml(&tracks),
            FormatArg::Csv => shuffled_csv(&tracks),
        };
        let csv = matches!(a.format, FormatArg::Csv);
        format!(
            "{}{body}",
            shuffled_header(&header, &s.tracks.names, &orders, a.seed, csv)
        )
    } else {
        let body = match a.format {
            FormatArg::Yaml => tracks_to_yaml(&s.tracks),
            FormatArg::Csv => tracks_to_csv(&s.tracks),
        };
        format!("{header}{body}")
    };
    match a.out {
        Some(path) => write_new(&path, &text),
        None => {
            out(&text)?;
            Ok(())
        }
    }
}

/// `synth --turntable`: the sequence's observations, with a header naming the truth.
fn turntable(a: &Args) -> Result<(), Error> {
    let t = crate::sfm::turntable::Turntable {
        points: a.points,
        frames: a.frames,
        window: a.window,
        elevation: a.elevation.to_radians(),
        noise: a.noise,
        seed: a.seed,
    };
    let (scene, obs) = t.generate();
    let header = synth_header(&scene, a.seed, a.noise).replacen(
        "\n",
        &format!(
            " --turntable --window {} --elevation {}\n",
            a.window, a.elevation
        ),
        1,
    );
    let body = match a.format {
        FormatArg::Yaml => crate::input::observations_to_yaml(&obs),
        FormatArg::Csv => crate::input::observations_to_csv(&obs),
    };
    let text = format!("{header}{body}");
    match &a.out {
        Some(path) => write_new(path, &text),
        None => {
            out(&text)?;
            Ok(())
        }
    }
}

/// The random stream of `--shuffle`: apart from the scene's (`seed`) and its noise's
/// (`seed + 1`, [`crate::seeds::noise_seed`]), so that shuffling moves no point.
fn shuffle_seed(seed: u64) -> u64 {
    seed.wrapping_add(2)
}

/// For every frame after the first, the order it lists the points in: `orders[f][k]` is the
/// point (index into frame 1's) listed `k`-th in frame `f + 2`.
fn shuffled_orders(points: usize, frames: usize, seed: u64) -> Vec<Vec<usize>> {
    let mut g = crate::model::rng(shuffle_seed(seed));
    (1..frames)
        .map(|_| {
            let mut order: Vec<usize> = (0..points).collect();
            order.shuffle(&mut g);
            order
        })
        .collect()
}

/// The tracks with every frame after the first listed in its order; frame 1 and the names
/// (frame 1's) as they were.
fn reorder(t: &Tracks, orders: &[Vec<usize>]) -> Result<Tracks, Error> {
    let frames = t
        .frames
        .iter()
        .enumerate()
        .map(
            |(i, f)| match i.checked_sub(1).and_then(|k| orders.get(k)) {
                Some(order) => order.iter().map(|&j| f[j]).collect(),
                None => f.clone(),
            },
        )
        .collect();
    Tracks::new(t.names.clone(), frames)
}

/// Shuffled tracks as CSV: frame 1's rows named, every later frame's rows labelled X1, X2, …
/// in the order listed (a name there would tell which point is which).
fn shuffled_csv(t: &Tracks) -> String {
    let mut s = String::from("frame,point,x,y\n");
    for (i, f) in t.frames.iter().enumerate() {
        for (k, p) in f.iter().enumerate() {
            let name = if i == 0 {
                t.names[k].clone()
            } else {
                format!("X{}", k + 1)
            };
            let (x, y) = (round_trip(p.x), round_trip(p.y));
            let _ = writeln!(s, "{},{name},{x},{y}", i + 1);
        }
    }
    s
}

/// The header of a shuffled file: the command with `--shuffle`, the truth, and the order
/// every later frame lists the points in.
fn shuffled_header(
    header: &str,
    names: &[String],
    orders: &[Vec<usize>],
    seed: u64,
    csv: bool,
) -> String {
    // the header's first line is the command that makes the file again
    let mut s = match header.split_once('\n') {
        Some((command, rest)) => format!("{command} --shuffle\n{rest}"),
        None => format!("{header} --shuffle\n"),
    };
    let labels = if csv {
        " (rows X1, X2, … in this order)"
    } else {
        ""
    };
    let _ = writeln!(
        s,
        "# shuffled (seed {seed}): every frame after the first lists the points in another order, for `orthocheck identify`{labels}"
    );
    for (f, order) in orders.iter().enumerate() {
        let listed: Vec<&str> = order.iter().map(|&j| names[j].as_str()).collect();
        let _ = writeln!(s, "# frame {} lists: {}", f + 2, listed.join(" "));
    }
    s
}

/// The sizes within `docs/limits.md`, and ε in range, before the scene is made.
fn check_limits(a: &Args) -> Result<(), String> {
    use crate::limits::{count, SYNTH_FRAMES, SYNTH_POINTS, SYNTH_POINTS_TIMES_FRAMES};
    count("--points", a.points, SYNTH_POINTS)?;
    count("--frames", a.frames, SYNTH_FRAMES)?;
    count(
        "--points × --frames",
        a.points.saturating_mul(a.frames),
        SYNTH_POINTS_TIMES_FRAMES,
    )?;
    if a.shuffle && a.frames < 2 {
        return Err(format!(
            "--shuffle reorders the frames after the first, and --frames {} has none (identify takes --frames 2)",
            a.frames
        ));
    }
    if a.turntable {
        if a.window < 2 || a.window > a.frames {
            return Err(format!(
                "--window {}: each point must be seen in 2 ..= --frames ({}) frames",
                a.window, a.frames
            ));
        }
        if !(a.elevation.is_finite() && a.elevation.abs() <= 89.0) {
            return Err(format!(
                "--elevation {}: the camera's elevation is −89 ..= 89 degrees",
                a.elevation
            ));
        }
    }
    a.noise
        .map_or(Ok(()), |e| crate::limits::noise_level("--noise", e))
}

/// The comment block `orthocheck synth` writes above the tracks: how to make them again, and
/// the truth to compare a solve with.
fn synth_header(scene: &crate::model::Scene, seed: u64, noise: Option<f64>) -> String {
    // The edges among the first points only: a header listing all p(p−1)/2 edges of a large
    // scene would outgrow the tracks themselves (10,000 points: 49,995,000 edges, ~1 GB).
    const LISTED_POINTS: usize = 10;
    let b = &scene.body;
    let p = b.points.len();
    let shown = p.min(LISTED_POINTS);
    let truth: Vec<String> = crate::derivations::solver::edges(shown)
        .iter()
        .map(|&(i, j)| {
            format!(
                "{}={}",
                crate::derivations::solver::edge_name(&b.names[i], &b.names[j]),
                crate::numfmt::sig(b.squared_distance(i, j))
            )
        })
        .collect();
    let label = if shown == p {
        "true squared edges".to_string()
    } else {
        format!(
            "true squared edges among the first {shown} points ({} of {}; the same seed gives the rest)",
            truth.len(),
            p * (p - 1) / 2
        )
    };
    format!(
        "# orthocheck synth --points {p} --frames {} --seed {seed}{}\n# {label}: {}\n",
        scene.motions.len(),
        noise.map_or(String::new(), |e| format!(" --noise {e}")),
        truth.join(" ")
    )
}
