//! The solvers benchmarked the PoseLib way: over N seeded generated instances, the mean number
//! of real solutions returned, the share of them that are valid (feasible, residual within the
//! rounding bound below), the share of instances whose ground truth is among them (within the
//! solver's own first-order error bound), and the median time per instance. Prints a Markdown
//! table: `cargo bench -p orthocheck-benches --bench solver_table` (the criterion benches in `benches/solvers.rs`
//! time the same hot paths with confidence intervals).
//!
//! A new row is one line in `main`: `measure(name, n, instance, outcome, hot)`.

use std::hint::black_box;
use std::time::Instant;

use orthocheck::derivations::solver::{SolverOutput, SquaredLengths};
use orthocheck::derivations::{p3f3, p3f4, p4f3};
use orthocheck::model::{edges, Scene};

/// Instances per solver.
const N: usize = 10_000;
/// Timing repetitions over all instances; the median of the per-instance means is reported.
const REPS: usize = 21;
/// Equation residuals (relative to the squared scale) at most this count as valid: 64 units of
/// rounding per term, at most 16 terms per equation (the p3f3 quadric has 10, the linear rows 4).
const RESIDUAL_BOUND: f64 = 64.0 * 16.0 * f64::EPSILON;

/// What the full solver returned for one instance.
struct Outcome {
    solutions: usize,
    valid: usize,
    truth_found: bool,
}

/// One row of the table.
struct Row {
    name: String,
    instances: usize,
    mean_solutions: f64,
    valid_share: f64,
    truth_share: f64,
    median_ns: f64,
}

/// A generated instance: the solver's input and the true squared edges.
struct Instance {
    input: SquaredLengths,
    truth: Vec<f64>,
}

fn scene(points: usize, frames: usize, seed: u64) -> Instance {
    let s = Scene::random(points, frames, seed);
    Instance {
        input: SquaredLengths::from_tracks(&s.tracks()),
        truth: edges(points)
            .iter()
            .map(|&(i, j)| s.body.squared_distance(i, j))
            .collect(),
    }
}

/// The table's columns from a solver output in the shared calling convention.
fn outcome(out: Option<SolverOutput>, truth: &[f64]) -> Outcome {
    let Some(out) = out else {
        return Outcome {
            solutions: 0,
            valid: 0,
            truth_found: false,
        };
    };
    let real: Vec<_> = out
        .solutions
        .iter()
        .filter(|s| s.imaginary.iter().all(|v| *v == 0.0))
        .collect();
    let valid = real
        .iter()
        .filter(|s| s.feasibility.is_feasible() && s.residual <= RESIDUAL_BOUND)
        .count();
    let truth_found = real.iter().any(|s| {
        let err = s
            .squared_edges
            .iter()
            .zip(truth)
            .map(|(a, b)| (a - b).abs())
            .fold(0.0, f64::max);
        s.error_bound.is_some_and(|b| err <= b)
    });
    Outcome {
        solutions: real.len(),
        valid,
        truth_found,
    }
}

/// Measure one solver: `full` gives the outcome of an instance, `hot` is the timed path.
fn measure<I, R>(
    name: &str,
    n: usize,
    instance: impl Fn(u64) -> I,
    full: impl Fn(&I) -> Outcome,
    hot: impl Fn(&I) -> R,
) -> Row {
    let inst: Vec<I> = (0..n as u64).map(instance).collect();
    let outs: Vec<Outcome> = inst.iter().map(&full).collect();
    let sols: usize = outs.iter().map(|o| o.solutions).sum();
    let valid: usize = outs.iter().map(|o| o.valid).sum();
    let found = outs.iter().filter(|o| o.truth_found).count();
    let mut per_instance: Vec<f64> = (0..REPS)
        .map(|_| {
            let t = Instant::now();
            for i in &inst {
                black_box(hot(black_box(i)));
            }
            t.elapsed().as_secs_f64() * 1e9 / n as f64
        })
        .collect();
    per_instance.sort_by(f64::total_cmp);
    Row {
        name: name.into(),
        instances: n,
        mean_solutions: sols as f64 / n as f64,
        valid_share: if sols == 0 {
            0.0
        } else {
            valid as f64 / sols as f64
        },
        truth_share: found as f64 / n as f64,
        median_ns: per_instance[REPS / 2],
    }
}

/// An instance with the fixed-size input of a solver's core, built before the timing.
fn with<A>(i: Instance, core_input: fn(&Instance) -> A) -> (Instance, A) {
    let a = core_input(&i);
    (i, a)
}

fn l3(i: &Instance) -> [[f64; 3]; 3] {
    std::array::from_fn(|f| std::array::from_fn(|e| i.input.frames[f][e]))
}

fn l34(i: &Instance) -> [[f64; 3]; 4] {
    std::array::from_fn(|f| std::array::from_fn(|e| i.input.frames[f][e]))
}

fn l6(i: &Instance) -> [[f64; 6]; 3] {
    std::array::from_fn(|f| std::array::from_fn(|e| i.input.frames[f][e]))
}

fn time(ns: f64) -> String {
    if ns < 1e3 {
        format!("{ns:.0} ns")
    } else if ns < 1e6 {
        format!("{:.2} µs", ns / 1e3)
    } else {
        format!("{:.2} ms", ns / 1e6)
    }
}

fn print(rows: &[Row]) {
    println!("| solver | instances | solutions / instance | valid | ground truth found | median time / instance |");
    println!("|---|---:|---:|---:|---:|---:|");
    for r in rows {
        println!(
            "| {} | {} | {:.3} | {:.2} % | {:.2} % | {} |",
            r.name,
            r.instances,
            r.mean_solutions,
            100.0 * r.valid_share,
            100.0 * r.truth_share,
            time(r.median_ns)
        );
    }
}

fn main() {
    // `cargo bench` passes `--bench`; `cargo test --benches` runs it too: keep that quick
    let n = if std::env::args().any(|a| a == "--bench") {
        N
    } else {
        100
    };
    let rows = vec![
        measure(
            "p3f3 (§2.2, core)",
            n,
            |s| with(scene(3, 3, s), l3),
            |i| outcome(p3f3::solve(&i.0.input).ok(), &i.0.truth),
            |i| p3f3::solve_core(&i.1),
        ),
        measure(
            "p3f3 (§2.2, full solve)",
            n,
            |s| scene(3, 3, s),
            |i| outcome(p3f3::solve(&i.input).ok(), &i.truth),
            |i| p3f3::solve(&i.input).map(|o| o.solutions.len()),
        ),
        measure(
            "p3f4 (§3, core)",
            n,
            |s| with(scene(3, 4, s), l34),
            |i| outcome(p3f4::solve(&i.0.input).ok(), &i.0.truth),
            |i| p3f4::solve_core(&i.1),
        ),
        measure(
            "p4f3 (§4, core)",
            n,
            |s| with(scene(4, 3, s), l6),
            |i| outcome(p4f3::solve(&i.0.input).ok(), &i.0.truth),
            |i| p4f3::solve_core(&i.1),
        ),
        measure(
            "least squares (§4, 6 points × 4 frames)",
            n / 10,
            |s| scene(6, 4, s),
            |i| outcome(p4f3::solve_least_squares(&i.input).ok(), &i.truth),
            |i| p4f3::solve_least_squares(&i.input).map(|o| o.solutions.len()),
        ),
        // rows for Tomasi–Kanade and bundle adjustment go here, one line each
    ];
    print(&rows);
}
