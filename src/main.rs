//! The `orthocheck` command line: [`orthocheck::run_command_line`] parses the arguments,
//! dispatches to one subcommand and maps errors to exit codes. The command line lives in the
//! library, so that a release build compiles it, and the generic code it instantiates, once.
//!
//! Exit codes: 0 the command ran (whatever the verdicts); 1 a check could not be carried out
//! (a numerical failure, a write that failed), or a result was printed with warnings that it
//! may be wrong (`reconstruct`); 2 bad input or usage (clap exits with 2 on usage errors
//! itself); 130 interrupted by Ctrl-C.

#![forbid(unsafe_code)]

/// mimalloc serves the many small allocations of exact arithmetic and Monte Carlo trials
/// faster than the system allocator; results do not depend on the allocator.
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

fn main() -> std::process::ExitCode {
    orthocheck::run_command_line()
}
