//! The `ndfplot` binary: parse the command line, start the worker threads, run the subcommand,
//! map the outcome to an exit code.

use clap::Parser;
use std::io::Write;
use std::process::ExitCode;

/// Most worker threads started, whatever `RAYON_NUM_THREADS` asks: more would only compete for the
/// cores, and thousands of thread stacks can exhaust a memory limit before any work starts.
const MAX_THREADS: usize = 64;

fn main() -> ExitCode {
    let cli = ndfplot::cli::Cli::parse();
    if let Err(message) = start_threads() {
        let _ = writeln!(std::io::stderr(), "error: {message}");
        return ExitCode::from(2);
    }
    match ndfplot::cmd::run(cli.command, cli.quiet) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            // A closed or full stderr must not turn an error into a panic.
            let _ = writeln!(std::io::stderr(), "{error}");
            ExitCode::from(error.exit_code())
        }
    }
}

/// Starts rayon's global pool with the threads `RAYON_NUM_THREADS` asks for (the core count when
/// unset, 0 or not a number), at most [`MAX_THREADS`] (saying so); a pool the system cannot start
/// is an error here rather than a panic at the first parallel loop.
fn start_threads() -> Result<(), String> {
    let cores = std::thread::available_parallelism().map_or(1, usize::from);
    let asked = std::env::var("RAYON_NUM_THREADS")
        .ok()
        .and_then(|v| v.trim().parse::<usize>().ok())
        .filter(|&n| n > 0)
        .unwrap_or(cores);
    if asked > MAX_THREADS {
        let _ = writeln!(
            std::io::stderr(),
            "warning: RAYON_NUM_THREADS={asked} is more than {MAX_THREADS}; using {MAX_THREADS}"
        );
    }
    rayon::ThreadPoolBuilder::new()
        .num_threads(asked.min(MAX_THREADS))
        .build_global()
        .map_err(|e| {
            format!(
                "could not start {} worker threads: {e}",
                asked.min(MAX_THREADS)
            )
        })
}
