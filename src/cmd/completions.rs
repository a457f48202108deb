//! `ndfplot completions <shell>` and `ndfplot man`: shell completion scripts and the manual page,
//! both generated from the clap definition in [`crate::cli`], so they always match the flags.

use crate::cli::Cli;
use crate::error::{Error, Result};
use crate::stdout;
use clap::CommandFactory;
use clap_complete::Shell;

/// Prints the completion script for `shell`.
pub fn completions(shell: Shell) -> Result<()> {
    let mut script = Vec::new();
    clap_complete::generate(shell, &mut Cli::command(), "ndfplot", &mut script);
    stdout::print(&String::from_utf8_lossy(&script))
}

/// Prints the manual page (roff).
pub fn man() -> Result<()> {
    let mut page = Vec::new();
    clap_mangen::Man::new(Cli::command())
        .render(&mut page)
        .map_err(|e| Error::io("manual page", e))?;
    stdout::print(&String::from_utf8_lossy(&page))
}
