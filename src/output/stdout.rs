//! The one place that writes command results to standard output.
//!
//! A reader that closes the pipe early (`ndfplot eval … | head -1`) is not an error: the write
//! stops quietly and the command still succeeds (docs/contracts.md, exit code 0).

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

/// Writes `bytes` to standard output (without flushing: end with [`flush`]) for a command that
/// writes as it computes: `Ok(false)` when the reader has closed the pipe, so the
/// command can stop computing and succeed.
pub fn stream(bytes: &[u8]) -> Result<bool> {
    match std::io::stdout().lock().write_all(bytes) {
        Ok(()) => Ok(true),
        Err(e) if e.kind() == ErrorKind::BrokenPipe => Ok(false),
        Err(e) => Err(Error::io("stdout", e)),
    }
}

/// Flushes standard output; a closed pipe counts as success.
pub fn flush() -> Result<()> {
    write_bytes(&[])
}
