//! A progress bar on standard error for long runs: shown only when stderr is a terminal, only
//! once a run has lasted [`SHOW_AFTER`], and never with `--quiet`. Standard output carries results
//! only, so the bar never touches it.

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::sync::{Arc, Mutex};
use std::time::Duration;

/// How long a run goes without a bar: shorter runs would only flicker.
pub const SHOW_AFTER: Duration = Duration::from_secs(1);

/// Redraw interval of a visible bar, so the elapsed time moves during long single steps.
const TICK: Duration = Duration::from_millis(100);

/// Progress over a known number of steps; every method is a no-op when the bar is disabled.
/// Steps may be counted from several threads.
#[derive(Debug)]
pub struct Progress {
    bar: Option<ProgressBar>,
    /// Set once the run is over; the delayed show checks it under the lock, so a bar never
    /// appears after `finish`.
    done: Arc<Mutex<bool>>,
}

impl Progress {
    /// A bar over `total` steps, drawn on stderr after [`SHOW_AFTER`] when `quiet` is false and
    /// stderr is a terminal.
    pub fn new(total: u64, quiet: bool) -> Progress {
        let done = Arc::new(Mutex::new(false));
        if quiet || !std::io::stderr().is_terminal() {
            return Progress { bar: None, done };
        }
        let bar = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::hidden());
        let style = ProgressStyle::with_template(
            "{spinner} {msg} [{bar:30}] {pos}/{len} {elapsed}, {eta} left",
        )
        .expect("the template is valid")
        .progress_chars("=> ");
        bar.set_style(style);
        let (delayed, finished) = (bar.clone(), Arc::clone(&done));
        std::thread::spawn(move || {
            std::thread::sleep(SHOW_AFTER);
            let finished = finished
                .lock()
                .unwrap_or_else(std::sync::PoisonError::into_inner);
            if !*finished {
                delayed.set_draw_target(ProgressDrawTarget::stderr());
                delayed.enable_steady_tick(TICK);
            }
        });
        Progress {
            bar: Some(bar),
            done,
        }
    }

    /// Names the current stage (`evaluating`, `encoding`).
    pub fn stage(&self, message: &'static str) {
        if let Some(bar) = &self.bar {
            bar.set_message(message);
        }
    }

    /// Counts `steps` more steps as done.
    pub fn advance(&self, steps: u64) {
        if let Some(bar) = &self.bar {
            bar.inc(steps);
        }
    }

    /// Removes the bar (it never appears if the run ends before [`SHOW_AFTER`]).
    pub fn finish(&self) {
        let mut done = self
            .done
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        *done = true;
        if let Some(bar) = &self.bar {
            bar.finish_and_clear();
        }
    }
}

impl Drop for Progress {
    /// A run that fails midway clears its bar too, so error lines start on a clean line.
    fn drop(&mut self) {
        self.finish();
    }
}
