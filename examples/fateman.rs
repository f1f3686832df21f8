//! Fateman's benchmark: p · (p + 1) for p = (1 + x + y + z + t)^N.
//!
//! `cargo run --release --example fateman -- N [--heap]` prints the term counts and, on the
//! last line, the seconds the product took (the power is not timed). `--heap` forces the
//! heap method instead of letting the shape choose (the dense array, for this product).

use std::time::Instant;

use orthocheck::algebra::mpoly::{mul_with, Coef, MPoly, MulMethod, Ring};

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let n: u32 = args.iter().find_map(|a| a.parse().ok()).unwrap_or(20);
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
    let start = Instant::now();
    let prod = mul_with(&p, &q, method);
    let secs = start.elapsed().as_secs_f64();
    println!(
        "N = {n}: {} × {} terms -> {} terms ({method:?})",
        p.len(),
        q.len(),
        prod.len()
    );
    println!("{secs:.3}");
}
