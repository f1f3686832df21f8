//! Progress on standard error and a clean stop on Ctrl-C, for the long commands.
//!
//! The bar is drawn only when standard error is a terminal: piped or redirected output is
//! byte-identical with or without it. Ctrl-C stops the computation where it is: nothing has
//! been printed yet (output is written only once a command has its whole answer), files are
//! written to a temporary name and renamed, so the handler removes the temporaries, says
//! "interrupted" and exits 130 (128 + SIGINT, the shell's convention) without leaving a
//! half-written output. SIGTERM and SIGHUP are handled the same way.

use std::io::{IsTerminal as _, Write as _};

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

/// The exit code of an interrupted command: 128 + SIGINT.
pub const INTERRUPTED: i32 = 130;

/// Install the handler of Ctrl-C, SIGTERM and SIGHUP (once, at start-up): it removes the
/// temporary files alive and exits 130. A failure to install it only means the signals keep
/// their default meaning (the process ends), so it is not an error.
///
/// SIGXFSZ (a file grown past the size limit) is caught too, so that the write fails with
/// EFBIG and its error names the file, instead of the signal ending the process silently.
pub fn on_interrupt_stop() {
    let _ = ctrlc::set_handler(|| {
        crate::files::remove_temporaries();
        // a closed standard error must not keep the command from stopping
        let _ = writeln!(std::io::stderr(), "\ninterrupted");
        std::process::exit(INTERRUPTED);
    });
    let _ = signal_hook::flag::register(
        signal_hook::consts::SIGXFSZ,
        std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false)),
    );
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
