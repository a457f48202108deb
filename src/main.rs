//! The `ndfplot` binary: parse the command line, start the worker threads, run the subcommand,
//! map the outcome to an exit code.

use clap::Parser;
use ndfplot::output::stderr;
use std::process::ExitCode;

/// Most worker threads started, whatever `RAYON_NUM_THREADS` asks: more would only compete for the
/// cores, and thousands of thread stacks can exhaust a memory limit before any work starts.
const MAX_THREADS: usize = 64;

fn main() -> ExitCode {
    let cli = ndfplot::cli::Cli::parse();
    stderr::configure(cli.color, cli.verbose);
    if let Err(message) = watch_interrupts().and_then(|()| start_threads()) {
        stderr::say(&format!("error: {message}"));
        return ExitCode::from(2);
    }
    match ndfplot::cmd::run(cli.command, cli.quiet) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            // A closed or full stderr must not turn an error into a panic (say ignores it).
            stderr::say(&error.to_string());
            ExitCode::from(error.exit_code())
        }
    }
}

/// Takes SIGINT, SIGTERM and SIGHUP on one watcher thread: they are blocked here, before any
/// other thread starts (threads inherit the mask), and the watcher waits for them; on one, the
/// temporaries being written are removed and the process exits with 128 + the signal's number,
/// as a shell reports a process the signal ended.
fn watch_interrupts() -> Result<(), String> {
    // SAFETY: `set` is initialized by sigemptyset before use; pthread_sigmask and sigwait only
    // read it; no handler runs in signal context (the signals are waited for, not caught).
    let set = unsafe {
        let mut set: libc::sigset_t = std::mem::zeroed();
        libc::sigemptyset(&mut set);
        for signal in [libc::SIGINT, libc::SIGTERM, libc::SIGHUP] {
            libc::sigaddset(&mut set, signal);
        }
        if libc::pthread_sigmask(libc::SIG_BLOCK, &set, std::ptr::null_mut()) != 0 {
            return Err("cannot block the interrupt signals".to_owned());
        }
        set
    };
    std::thread::Builder::new()
        .name("interrupts".to_owned())
        .spawn(move || {
            let mut signal: libc::c_int = 0;
            // SAFETY: `set` is a valid signal set and `signal` a valid place to write.
            if unsafe { libc::sigwait(&set, &mut signal) } == 0 {
                ndfplot::output::write::exit_removing_temporaries(128 + signal);
            }
        })
        .map(drop)
        .map_err(|e| format!("cannot start the interrupt watcher: {e}"))
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
        stderr::warning(&format!(
            "RAYON_NUM_THREADS={asked} is more than {MAX_THREADS}; using {MAX_THREADS}"
        ));
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
