//! The one place that writes command results to standard output.
//!
//! A reader that closes the pipe early (`ndfplot eval … | head -1`) is not an error: the write
//! stops quietly and the command still succeeds (CONTRACTS.md, exit code 0).

use crate::error::{Error, Result};
use std::io::{ErrorKind, Write};

/// Writes `text` to standard output and flushes it; a closed pipe counts as success.
pub fn print(text: &str) -> Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() != ErrorKind::BrokenPipe => Err(Error::io("stdout", e)),
        _ => Ok(()),
    }
}
