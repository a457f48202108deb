//! What ndfplot says on standard error besides its results: `error:` and `warning:` lines, the
//! closing line of a run, and the per-figure detail of `-v`; their labels are coloured when
//! `--color` allows it.
//!
//! Informative only: a closed or full stderr never fails a command, so every write here ignores
//! its error. Set once per process by [`configure`]; until then, nothing is coloured and `-v`
//! detail is off (the library's callers and tests see plain text).

use crate::model::names::named;
use std::io::Write;
use std::sync::OnceLock;

named! {
    /// When ndfplot colours the labels of its own messages (`--color`).
    pub enum ColorChoice {
        /// When stderr is a terminal and the `NO_COLOR` environment variable is unset or empty.
        Auto = "auto",
        /// Always, even into a pipe or a file.
        Always = "always",
        /// Never.
        Never = "never",
    }
}

/// How this process writes its messages.
#[derive(Debug, Clone, Copy)]
struct Settings {
    colour: bool,
    verbose: bool,
}

static SETTINGS: OnceLock<Settings> = OnceLock::new();

fn settings() -> Settings {
    SETTINGS.get().copied().unwrap_or(Settings {
        colour: false,
        verbose: false,
    })
}

/// Whether labels are coloured under `choice`, for a stderr that `is_terminal` and a `NO_COLOR`
/// variable `no_color` (<https://no-color.org>: set and non-empty turns automatic colour off).
pub fn colours(choice: ColorChoice, is_terminal: bool, no_color: Option<&str>) -> bool {
    match choice {
        ColorChoice::Always => true,
        ColorChoice::Never => false,
        ColorChoice::Auto => is_terminal && no_color.is_none_or(str::is_empty),
    }
}

/// Sets, once per process, whether labels are coloured ([`colours`] of this process's stderr and
/// environment) and whether `-v` detail is written.
pub fn configure(choice: ColorChoice, verbose: bool) {
    use std::io::IsTerminal;
    let no_color = std::env::var("NO_COLOR").ok();
    let colour = colours(choice, std::io::stderr().is_terminal(), no_color.as_deref());
    let _ = SETTINGS.set(Settings { colour, verbose });
}

/// `text` with the label that starts each of its lines (`error:`, `warning:`) in bold red or bold
/// yellow when `colour` is set (SGR escape sequences); unchanged otherwise.
pub fn painted(text: &str, colour: bool) -> String {
    if !colour {
        return text.to_string();
    }
    text.split_inclusive('\n')
        .map(|line| {
            for (label, sgr) in [("error:", "1;31"), ("warning:", "1;33")] {
                if let Some(rest) = line.strip_prefix(label) {
                    return format!("\x1b[{sgr}m{label}\x1b[0m{rest}");
                }
            }
            line.to_string()
        })
        .collect()
}

/// Writes `text` and a newline, its labels coloured as configured.
pub fn say(text: &str) {
    let _ = writeln!(std::io::stderr(), "{}", painted(text, settings().colour));
}

/// Writes `warning: <text>`.
pub fn warning(text: &str) {
    say(&format!("warning: {text}"));
}

/// The closing line of a run, `<what> in <seconds> s` (two decimals), unless `quiet`.
pub fn summary(quiet: bool, what: &str, started: std::time::Instant) {
    if !quiet {
        say(&format!(
            "{what} in {:.2} s",
            started.elapsed().as_secs_f64()
        ));
    }
}

/// Whether `-v` asked for detail.
pub fn verbose() -> bool {
    settings().verbose
}

/// Writes a line of `-v` detail, only when `-v` was given.
pub fn detail(text: &str) {
    if verbose() {
        say(text);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn automatic_colour_needs_a_terminal_and_no_no_color() {
        assert!(colours(ColorChoice::Auto, true, None));
        assert!(colours(ColorChoice::Auto, true, Some("")));
        assert!(!colours(ColorChoice::Auto, true, Some("1")));
        assert!(!colours(ColorChoice::Auto, false, None));
        assert!(colours(ColorChoice::Always, false, Some("1")));
        assert!(!colours(ColorChoice::Never, true, None));
    }

    #[test]
    fn only_the_leading_labels_are_painted() {
        let text = "error: a.json: x: bad\nwarning: b.json: legend\nnote error: kept\n";
        assert_eq!(painted(text, false), text);
        assert_eq!(
            painted(text, true),
            "\x1b[1;31merror:\x1b[0m a.json: x: bad\n\x1b[1;33mwarning:\x1b[0m b.json: legend\nnote error: kept\n"
        );
    }
}
