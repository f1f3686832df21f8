//! Fateman's benchmark: p · (p + 1) for p = (1 + x + y + z + t)^N.
//!
//! `cargo run --release --example fateman -- N [--heap] [--repeat R] [--threads T]` prints
//! the term counts and, on the last line, the median seconds of R products (3 unless given;
//! the power is not timed), as `scripts/fateman.py` measures python-flint. `--heap` forces
//! the heap method instead of letting the shape choose (the dense array, for this product);
//! `--threads` sets the threads a large array product shares (1 unless given, as FLINT's
//! default).

use std::time::Instant;

use orthocheck::algebra::mpoly::{mul_with, Coef, MPoly, MulMethod, Ring};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let value = |flag: &str| {
        let i = args.iter().position(|a| a == flag)?;
        args.get(i + 1)?.parse::<u32>().ok()
    };
    let repeat = value("--repeat").unwrap_or(3).max(1);
    let threads = value("--threads").unwrap_or(1).max(1) as usize;
    let n: u32 = args
        .iter()
        .enumerate()
        .filter(|(i, _)| *i == 0 || !["--repeat", "--threads"].contains(&args[i - 1].as_str()))
        .find_map(|(_, a)| a.parse().ok())
        .unwrap_or(20);
    let method = if args.iter().any(|a| a == "--heap") {
        MulMethod::Heap
    } else {
        MulMethod::Auto
    };
    let r = Ring::new(&["x", "y", "z", "t"]);
    let one = MPoly::constant(r.nvars(), Coef::Small(1));
    let s = r
        .names()
        .iter()
        .filter_map(|v| r.var(v))
        .fold(one.clone(), |acc, v| &acc + &v);
    let p = s.pow(n);
    let q = &p + &one;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool");
    let mut times = Vec::new();
    let mut terms = 0;
    for _ in 0..repeat {
        let start = Instant::now();
        let prod = pool.install(|| mul_with(&p, &q, method));
        times.push(start.elapsed().as_secs_f64());
        terms = prod.len();
    }
    times.sort_by(f64::total_cmp);
    println!(
        "N = {n}: {} × {} terms -> {terms} terms ({method:?}, {threads} thread(s), median of {repeat})",
        p.len(),
        q.len(),
    );
    println!("{:.3}", times[times.len() / 2]);
}
