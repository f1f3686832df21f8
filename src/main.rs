//! The `orthocheck` command line: parses arguments, calls the library, maps errors to exit codes.

use std::io::{IsTerminal, Write as _};
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::atomic::{AtomicUsize, Ordering};

use clap::{Parser, Subcommand, ValueEnum};
use orthocheck::derivations::identity;
use orthocheck::derivations::noise::LevelSummary;
use orthocheck::derivations::solver::{solve_tracks, Method};
use orthocheck::input::{load_tracks, tracks_to_csv, tracks_to_yaml, PointOrder};
use orthocheck::model::{rng, NoiseModel, Scene};
use orthocheck::{cases, check, derivations, report, Error};

#[derive(Parser)]
#[command(
    name = "orthocheck",
    version,
    about = "Machine-checked reproduction of Kłopotek's orthographic structure-from-motion paper"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Reproduce the paper: run every case and write report.md, report.json and report.html.
    Report {
        /// Output folder.
        #[arg(long, default_value = "target/orthocheck-report")]
        out: PathBuf,
        /// Folder of case files.
        #[arg(long, default_value = "paper_cases")]
        cases: PathBuf,
    },
    /// Count degrees of freedom (§2.1) and decide identifiability by Jacobian rank.
    Dof {
        /// Number of points p.
        #[arg(long, required_unless_present = "table")]
        points: Option<usize>,
        /// Number of frames k.
        #[arg(long, required_unless_present = "table")]
        frames: Option<usize>,
        /// The whole grid p = 1..max-points, k = 1..max-frames.
        #[arg(long, conflicts_with_all = ["points", "frames"])]
        table: bool,
        /// Largest p of the grid.
        #[arg(long, default_value_t = 8, requires = "table")]
        max_points: usize,
        /// Largest k of the grid.
        #[arg(long, default_value_t = 6, requires = "table")]
        max_frames: usize,
        /// Seed of the generic scene.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// JSON output.
        #[arg(long)]
        json: bool,
    },
    /// Machine-check the paper's printed formulas: one item, a claim's items, or all.
    Audit {
        /// An item id (p3f3sqr, appA-coefficients/f_cb, …) or a claim id (all its items);
        /// `twofold-squared` shows eq. p3f3sqr in full.
        #[arg(required_unless_present = "all")]
        id: Option<String>,
        /// Every item.
        #[arg(long, conflicts_with = "id")]
        all: bool,
        /// Folder of case files (the printed formulas are read from there).
        #[arg(long, default_value = "paper_cases")]
        cases: PathBuf,
        /// JSON output.
        #[arg(long)]
        json: bool,
        /// The errata list of the whole report as Markdown (what docs/errata.md holds).
        #[arg(long, conflicts_with_all = ["json", "id"])]
        markdown: bool,
    },
    /// Recover the squared edges (and the body) from a tracks file.
    Solve {
        /// Tracks: YAML (`frames:` lists of [x, y], optional `points:`) or CSV
        /// (`frame,point,x,y`).
        #[arg(long)]
        input: PathBuf,
        /// Solver; `auto` picks from the number of points and frames (p3f3, p3f4, p4f3, or
        /// lsq for p ≥ 4 points in k ≥ 3 frames).
        #[arg(long, value_enum, default_value = "auto")]
        method: MethodArg,
        /// JSON output.
        #[arg(long)]
        json: bool,
    },
    /// Run a noise study of a paper case with your own levels, trials and seed.
    Noise {
        /// The noise case's id (e.g. ex2-noise, ex3-noise).
        #[arg(long)]
        case: String,
        /// Relative error levels ε, comma-separated (default: the case's).
        #[arg(long, value_delimiter = ',')]
        levels: Vec<f64>,
        /// Trials per level and model (default: the case's).
        #[arg(long)]
        trials: Option<usize>,
        /// Seed (default: the case's).
        #[arg(long)]
        seed: Option<u64>,
        /// Noise model (default: both).
        #[arg(long, value_enum)]
        model: Option<ModelArg>,
        /// Folder of case files.
        #[arg(long, default_value = "paper_cases")]
        cases: PathBuf,
        /// JSON output.
        #[arg(long)]
        json: bool,
    },
    /// Find which frame-2 point is which frame-1 point (two frames; frame 2's order unknown).
    Identify {
        /// Tracks file with two frames (frame 2's points in any order).
        #[arg(long)]
        input: PathBuf,
        /// Test: the equal-scale epipolar residual of four points, the paper's four-point
        /// test, or the five-point line.
        #[arg(long, value_enum, default_value = "epipolar")]
        method: IdentifyMethod,
        /// Assignments listed.
        #[arg(long, default_value_t = 10)]
        top: usize,
        /// JSON output.
        #[arg(long)]
        json: bool,
    },
    /// Decide which points belong to one rigid body (two frames, correspondences known).
    Membership {
        /// Tracks file with two frames.
        #[arg(long)]
        input: PathBuf,
        /// Largest epipolar distance of a member, relative to the image size.
        #[arg(long, default_value_t = 1e-6)]
        tolerance: f64,
        /// JSON output.
        #[arg(long)]
        json: bool,
    },
    /// Print members of the one-parameter family of bodies two frames allow.
    Family {
        /// Tracks file with two frames.
        #[arg(long)]
        input: PathBuf,
        /// Members, at angles evenly spread in (0, π).
        #[arg(long, default_value_t = 5)]
        samples: usize,
        /// JSON output.
        #[arg(long)]
        json: bool,
    },
    /// Write a tracks file of a seeded random scene, to try the solvers on.
    Synth {
        /// Number of points.
        #[arg(long)]
        points: usize,
        /// Number of frames.
        #[arg(long)]
        frames: usize,
        /// Seed.
        #[arg(long)]
        seed: u64,
        /// Relative error up to ε on every image coordinate.
        #[arg(long)]
        noise: Option<f64>,
        /// Output format.
        #[arg(long, value_enum, default_value = "yaml")]
        format: FormatArg,
        /// Write to this file (refused if it exists); standard output otherwise.
        #[arg(long)]
        out: Option<PathBuf>,
    },
}

#[derive(Clone, Copy, ValueEnum)]
enum MethodArg {
    Auto,
    P3f3,
    P3f4,
    P4f3,
    Lsq,
}

#[derive(Clone, Copy, ValueEnum)]
enum IdentifyMethod {
    Epipolar,
    Four,
    Five,
}

#[derive(Clone, Copy, ValueEnum)]
enum ModelArg {
    RelativeCoordinate,
    RelativeLength,
}

#[derive(Clone, Copy, ValueEnum)]
enum FormatArg {
    Yaml,
    Csv,
}

fn exit_code(e: &Error) -> u8 {
    match e {
        Error::Numerical(_) => 1,
        _ => 2,
    }
}

fn run(cli: Cli) -> Result<(), Error> {
    match cli.command {
        Command::Report { out, cases } => {
            let all = cases::load_all(&cases)?;
            let started = std::time::Instant::now();
            let show = std::io::stderr().is_terminal();
            let progress = |i: usize, id: &str| {
                // only for a run that takes long enough to wonder about
                if show && started.elapsed().as_secs_f64() > 1.0 {
                    eprint!("\r{}/{} cases ({id})            ", i + 1, all.len());
                    let _ = std::io::stderr().flush();
                }
            };
            let provenance = report::Provenance {
                revision: git(&["rev-parse", "--short=12", "HEAD"]).map(|r| {
                    let dirty = git(&["status", "--porcelain", "--untracked-files=no"])
                        .is_some_and(|s| !s.is_empty());
                    if dirty {
                        format!("{r}+changes")
                    } else {
                        r
                    }
                }),
                date: std::env::var("SOURCE_DATE_EPOCH")
                    .ok()
                    .map(|e| format!("{e} (SOURCE_DATE_EPOCH)"))
                    .or_else(|| git(&["show", "-s", "--format=%cs", "HEAD"])),
                command: "cargo run --release -- report".into(),
                seeds: Vec::new(),
            };
            let r = report::Report::run(&all, provenance, &progress)?;
            if show && started.elapsed().as_secs_f64() > 1.0 {
                eprintln!();
            }
            r.write(&out)?;
            println!(
                "wrote {}, {} and {} ({} claims, {} figures)",
                out.join("report.md").display(),
                out.join("report.json").display(),
                out.join("report.html").display(),
                r.claims.len(),
                r.figures.len()
            );
            for (verdict, n) in &r.summary {
                if *n > 0 {
                    println!("  {verdict}: {n}");
                }
            }
        }
        Command::Dof {
            points,
            frames,
            table,
            max_points,
            max_frames,
            seed,
            json,
        } => {
            if table {
                let rows = derivations::dof::table(max_points, max_frames, seed)?;
                if json {
                    println!("{}", to_json(&rows));
                } else {
                    print!("{}", report::dof_table_text(&rows));
                }
            } else {
                let (p, k) = (points.unwrap_or(0), frames.unwrap_or(0));
                let r = derivations::dof::identifiability(p, k, seed)?;
                if json {
                    println!("{}", to_json(&r));
                } else {
                    print!("{}", report::dof_text(&r));
                }
            }
        }
        Command::Audit {
            id,
            all,
            cases,
            json,
            markdown,
        } => {
            let loaded = cases::load_all(&cases)?;
            if id.as_deref() == Some("twofold-squared") && !markdown {
                let case = loaded
                    .into_iter()
                    .find_map(|c| match c.check {
                        cases::CaseCheck::TwofoldSquared(t) => Some(t),
                        _ => None,
                    })
                    .ok_or_else(|| {
                        Error::InvalidInput(format!(
                            "no twofold_squared case in {}",
                            cases.display()
                        ))
                    })?;
                let a = check::audit_twofold(&case)?;
                if json {
                    println!("{}", to_json(&a));
                } else {
                    print!("{}", report::twofold_text(&a));
                }
                return Ok(());
            }
            if markdown {
                let r = report::Report::from_cases(&loaded)?;
                print!("{}", report::errata_markdown(&r.claims));
                return Ok(());
            }
            let mut items = check::audit_all(&loaded)?;
            if let Some(id) = &id {
                let id = if id == "twofold-squared" {
                    "p3f3sqr"
                } else {
                    id
                };
                items.retain(|it| it.id == id || it.claim == id);
                if items.is_empty() {
                    return Err(Error::InvalidInput(format!(
                        "no audit item or claim `{id}` (try `orthocheck audit --all`)"
                    )));
                }
            }
            if json {
                println!("{}", to_json(&items));
            } else {
                print!("{}", report::audit_text(&items, !all));
            }
        }
        Command::Solve {
            input,
            method,
            json,
        } => {
            let tracks = load_tracks(&input, PointOrder::ByName)?;
            let method = match method {
                MethodArg::Auto => Method::Auto,
                MethodArg::P3f3 => Method::P3f3,
                MethodArg::P3f4 => Method::P3f4,
                MethodArg::P4f3 => Method::P4f3,
                MethodArg::Lsq => Method::Lsq,
            };
            let solved = solve_tracks(&tracks, method).map_err(|e| in_file(&input, e))?;
            if json {
                println!("{}", to_json(&report::solve_json(&solved)));
            } else {
                print!("{}", report::solve_text(&solved));
            }
        }
        Command::Noise {
            case,
            levels,
            trials,
            seed,
            model,
            cases,
            json,
        } => {
            let summaries = noise(&case, &levels, trials, seed, model, &cases)?;
            if json {
                println!("{}", to_json(&summaries));
            } else {
                print!("{}", report::noise_text(&case, &summaries));
            }
        }
        Command::Identify {
            input,
            method,
            top,
            json,
        } => {
            let t = two_frames(&input, PointOrder::AsListed)?;
            let m = match method {
                IdentifyMethod::Epipolar => identity::IdentifyMethod::Epipolar,
                IdentifyMethod::Four => identity::IdentifyMethod::Four,
                IdentifyMethod::Five => identity::IdentifyMethod::Five,
            };
            let r = identity::identify(&t.frames[0], &t.frames[1], m, top)
                .map_err(|e| in_file(&input, e))?;
            if json {
                println!("{}", to_json(&r));
            } else {
                print!("{}", report::identify_text(&r));
            }
        }
        Command::Membership {
            input,
            tolerance,
            json,
        } => {
            if !(tolerance.is_finite() && tolerance >= 0.0) {
                return Err(Error::InvalidInput(format!(
                    "--tolerance {tolerance}: must be a finite number ≥ 0"
                )));
            }
            let t = two_frames(&input, PointOrder::ByName)?;
            if let Some(d) = identity::degeneracy(&t.frames[0], &t.frames[1]) {
                return Err(in_file(&input, Error::InvalidInput(d.to_string())));
            }
            let m = identity::membership(&t.frames[0], &t.frames[1], tolerance);
            let rows: Vec<report::MemberRow> = t
                .names
                .iter()
                .zip(&m)
                .map(|(n, (inside, d))| report::MemberRow {
                    point: n.clone(),
                    member: *inside,
                    distance: *d,
                })
                .collect();
            if json {
                println!("{}", to_json(&rows));
            } else {
                print!("{}", report::membership_text(&rows, tolerance));
            }
        }
        Command::Family {
            input,
            samples,
            json,
        } => {
            let t = two_frames(&input, PointOrder::ByName)?;
            if samples == 0 {
                return Err(Error::InvalidInput("--samples must be at least 1".into()));
            }
            if let Some(d) = identity::degeneracy(&t.frames[0], &t.frames[1]) {
                return Err(in_file(&input, Error::InvalidInput(d.to_string())));
            }
            let betas: Vec<f64> = (1..=samples)
                .map(|i| std::f64::consts::PI * i as f64 / (samples + 1) as f64)
                .collect();
            let members = derivations::two_frames::family(&t.frames[0], &t.frames[1], &betas)
                .ok_or_else(|| {
                    in_file(
                        &input,
                        Error::InvalidInput("the epipolar geometry is undetermined".into()),
                    )
                })?;
            let view = report::family_view(&t.names, &members);
            if json {
                println!("{}", to_json(&view));
            } else {
                print!("{}", report::family_text(&view));
            }
        }
        Command::Synth {
            points,
            frames,
            seed,
            noise,
            format,
            out,
        } => {
            if points == 0 || frames == 0 {
                return Err(Error::InvalidInput(
                    "--points and --frames must be at least 1".into(),
                ));
            }
            if let Some(e) = noise.filter(|e| !(e.is_finite() && *e >= 0.0)) {
                return Err(Error::InvalidInput(format!(
                    "--noise {e}: must be a finite ε ≥ 0"
                )));
            }
            let scene = Scene::random(points, frames, seed);
            let mut tracks = scene.tracks();
            if let Some(eps) = noise {
                // the noise stream is separate from the scene's, so --noise 0 gives the scene
                tracks = NoiseModel::RelativeCoordinate { eps }
                    .perturb_tracks(&tracks, &mut rng(seed.wrapping_add(1)));
            }
            let header = report::synth_header(&scene, seed, noise);
            let body = match format {
                FormatArg::Yaml => tracks_to_yaml(&tracks),
                FormatArg::Csv => tracks_to_csv(&tracks),
            };
            let text = format!("{header}{body}");
            match out {
                Some(path) => write_new(&path, &text)?,
                None => print!("{text}"),
            }
        }
    }
    Ok(())
}

/// Run the noise study of case `id` with the given overrides, one level and model at a time.
fn noise(
    id: &str,
    levels: &[f64],
    trials: Option<usize>,
    seed: Option<u64>,
    model: Option<ModelArg>,
    dir: &Path,
) -> Result<Vec<LevelSummary>, Error> {
    let all = cases::load_all(dir)?;
    let Some(case) = all.iter().find(|c| c.id == id) else {
        return Err(Error::InvalidInput(format!(
            "no case `{id}` in {}",
            dir.display()
        )));
    };
    let cases::CaseCheck::NoiseStudy(nc) = &case.check else {
        return Err(Error::InvalidInput(format!(
            "case `{id}` is not a noise study"
        )));
    };
    let mut study = check::study_of(nc)?;
    study.trials = trials.unwrap_or(study.trials);
    study.seed = seed.unwrap_or(study.seed);
    let levels: Vec<f64> = if levels.is_empty() {
        nc.levels.iter().map(|l| l.level.to_f64()).collect()
    } else {
        levels.to_vec()
    };
    if let Some(e) = levels.iter().find(|e| !(e.is_finite() && **e >= 0.0)) {
        return Err(Error::InvalidInput(format!(
            "--levels: {e} is not a finite ε ≥ 0"
        )));
    }
    let keep = |m: usize| match model {
        None => true,
        Some(ModelArg::RelativeCoordinate) => m == 0,
        Some(ModelArg::RelativeLength) => m == 1,
    };
    let runs = (0..2).filter(|m| keep(*m)).count() * levels.len();
    let total = runs * study.trials;
    let done = AtomicUsize::new(0);
    let show = std::io::stderr().is_terminal();
    let progress = |n: usize| {
        let d = done.fetch_add(n, Ordering::Relaxed) + n;
        if show {
            eprint!("\r{d}/{total} trials");
            let _ = std::io::stderr().flush();
        }
    };
    let out = derivations::noise::run_levels(&study, &levels, keep, &progress)
        .iter()
        .map(|r| r.summary())
        .collect();
    if show {
        eprintln!();
    }
    Ok(out)
}

/// A git query's trimmed output, when git answers (the source revision of the report).
fn git(args: &[&str]) -> Option<String> {
    let out = std::process::Command::new("git")
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .ok()?;
    out.status
        .success()
        .then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// A tracks file that must hold exactly two frames.
fn two_frames(path: &Path, order: PointOrder) -> Result<orthocheck::model::Tracks, Error> {
    let t = load_tracks(path, order)?;
    if t.frames.len() != 2 {
        return Err(in_file(
            path,
            Error::InvalidInput(format!(
                "{} frames: this command takes exactly two",
                t.frames.len()
            )),
        ));
    }
    Ok(t)
}

/// An input that parsed but cannot be used is still the user's file's fault: name it.
fn in_file(path: &Path, e: Error) -> Error {
    match e {
        Error::InvalidInput(message) => Error::Input {
            location: orthocheck::error::InputLocation {
                file: path.to_path_buf(),
                line: None,
                column: None,
                field: None,
            },
            message,
        },
        e => e,
    }
}

/// Write a file that must not exist yet: a user's file is never overwritten.
fn write_new(path: &Path, text: &str) -> Result<(), Error> {
    let io = |source| Error::Io {
        path: path.to_path_buf(),
        source,
    };
    let mut f = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)
        .map_err(io)?;
    f.write_all(text.as_bytes()).map_err(io)
}

fn to_json<T: serde::Serialize>(v: &T) -> String {
    serde_json::to_string_pretty(v).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(exit_code(&e))
        }
    }
}
