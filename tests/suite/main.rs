//! Integration tests in one binary; the paper runs once for all of them (`common::report`).

/// The committed adversarial corpus: no panic, no hang, no NaN, the documented exit class.
mod adversarial;
/// report.html in headless Chromium: it loads, its links resolve, it is not blank.
mod browser;
/// Every paper case (its snapshot) and every malformed case (its error): one test per file.
mod cases;
/// The command line: exit codes, JSON shapes, determinism.
mod cli;
/// The paper's cases and their report, computed once for the binary.
#[path = "../common/mod.rs"]
mod common;
/// docs/errata.md is what `orthocheck audit --all --markdown` prints.
mod errata;
/// Every figure of the paper run, drawn: data inside the axes, keys outside, one colour per
/// series, equal scales where claimed, captions without LaTeX.
mod figures;
/// The floors of docs/architecture.md on the sources: no import runs up a floor, no kind
/// names another.
mod floors;
/// Structured fuzzing of the tracks and case parsers (proptest; long run in docs/limits.md).
mod fuzz;
mod hardening;
/// The paper cases cover the claims this tool must decide.
mod inventory;
/// The Markdown and HTML renderers on fixed claims.
mod renderers;
/// Orthographic structure from motion: `reconstruct` and the `sfm` library.
mod sfm;
/// `reconstruct` on tracks that cannot all take part: dropped, grouped, warned of.
mod sfm_groups;
mod sfm_tracks;
/// One verdict set with or without the paper's source; every quote at its tightest lines.
mod transcription;
/// Every formula of the paper's cases, typeset: no script swallows a symbol, every symbol
/// reaches the reader in its order; eq. p3f3sqr reads 2a²b².
mod typesetting;
