//! Progress on standard error and a clean stop on Ctrl-C, for the long commands.
//!
//! The bar is drawn only when standard error is a terminal: piped or redirected output is
//! byte-identical with or without it. Ctrl-C stops the computation where it is: nothing has
//! been printed yet (output is written only once a command has its whole answer), files are
//! written to a temporary name and renamed, so the handler says "interrupted" and exits 130
//! (128 + SIGINT, the shell's convention) without leaving a half-written output.

use std::io::IsTerminal as _;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// The exit code of an interrupted command: 128 + SIGINT.
pub const INTERRUPTED: i32 = 130;

/// Install the Ctrl-C handler (once, at start-up). A failure to install it only means Ctrl-C
/// keeps its default meaning (the process ends), so it is not an error.
pub fn on_interrupt_stop() {
    let _ = ctrlc::set_handler(|| {
        eprintln!("\ninterrupted");
        std::process::exit(INTERRUPTED);
    });
}

/// A bar counting `total` units of work, drawn on standard error when it is a terminal,
/// hidden otherwise.
pub fn bar(total: u64, unit: &str) -> ProgressBar {
    if !std::io::stderr().is_terminal() {
        return ProgressBar::hidden();
    }
    let pb = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::stderr());
    let template = format!("{{bar:40}} {{pos}}/{{len}} {unit} ({{elapsed}}, about {{eta}} left)");
    if let Ok(style) = ProgressStyle::with_template(&template) {
        pb.set_style(style);
    }
    pb
}
