//! The one place that writes command results to standard output.
//!
//! A reader that closes the pipe early (`ndfplot eval … | head -1`) is not an error: the write
//! stops quietly and the command still succeeds (CONTRACTS.md, exit code 0).

use crate::error::{Error, Result};
use std::io::{ErrorKind, Write};

/// Writes `text` to standard output and flushes it; a closed pipe counts as success.
pub fn print(text: &str) -> Result<()> {
    write_bytes(text.as_bytes())
}

/// Writes `bytes` (a figure's SVG, PNG, PDF, CSV or HTML for `render -o -`) to standard output and
/// flushes it; a closed pipe counts as success.
pub fn write_bytes(bytes: &[u8]) -> Result<()> {
    let mut out = std::io::stdout().lock();
    match out.write_all(bytes).and_then(|()| out.flush()) {
        Err(e) if e.kind() != ErrorKind::BrokenPipe => Err(Error::io("stdout", e)),
        _ => Ok(()),
    }
}
