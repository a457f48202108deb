//! The one place that writes output files: atomically, inside the output folder only.
//!
//! Each file is written as the hidden temporary `<dir>/.<name>.tmp` and renamed into place, so an
//! interrupted run never leaves a truncated file under a real name (CONTRACTS.md).

use crate::error::{Error, Result};
use std::fs;
use std::io::Write;
use std::path::Path;

/// The temporary name of `name` in `dir`.
fn temporary(dir: &Path, name: &str) -> std::path::PathBuf {
    dir.join(format!(".{name}.tmp"))
}

/// Writes `bytes` to `dir/name` atomically (temporary file, sync, rename). `name` must be a plain
/// file name (the caller validated the scene id it comes from).
pub fn write_atomic(dir: &Path, name: &str, bytes: &[u8]) -> Result<()> {
    debug_assert!(!name.contains(['/', '\\']) && !name.starts_with('.'));
    let target = dir.join(name);
    let tmp = temporary(dir, name);
    let shown = target.display().to_string();
    let result = (|| {
        let mut file = fs::File::create(&tmp)?;
        file.write_all(bytes)?;
        file.sync_all()?;
        fs::rename(&tmp, &target)
    })();
    result.map_err(|e| {
        let _ = fs::remove_file(&tmp);
        Error::io(shown, e)
    })
}

/// Removes stale temporaries that an interrupted run left for `name`.
pub fn remove_stale(dir: &Path, name: &str) -> Result<()> {
    let tmp = temporary(dir, name);
    match fs::remove_file(&tmp) {
        Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
            Err(Error::io(tmp.display().to_string(), e))
        }
        _ => Ok(()),
    }
}

/// Creates the output folder (and its parents) if needed.
pub fn ensure_dir(dir: &Path) -> Result<()> {
    fs::create_dir_all(dir).map_err(|e| Error::io(dir.display().to_string(), e))
}
