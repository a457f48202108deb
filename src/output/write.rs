//! The one place that writes output files: atomically, inside the output folder only.
//!
//! Each file is written as a hidden temporary `<dir>/.<name>.<unique>.tmp`, created exclusively
//! (never through an existing file or symbolic link), and renamed into place, so an interrupted
//! run never leaves a truncated file under a real name and two runs into one folder never touch
//! each other's temporaries (the last rename wins per file; docs/contracts.md).

use crate::error::{Error, Result};
use rayon::prelude::*;
use std::fs;
use std::io::Write;
use std::os::unix::fs::PermissionsExt;
use std::path::Path;
use std::time::{Duration, SystemTime};

/// Age beyond which a temporary is taken as left by a killed run, and may be removed.
pub const ABANDONED_AFTER: Duration = Duration::from_secs(3600);

/// The temporaries of `name` are `.<name>.<unique>.tmp`: this prefix, then [`SUFFIX`].
fn prefix(name: &str) -> String {
    format!(".{name}.")
}

/// The end of every temporary's name.
const SUFFIX: &str = ".tmp";

/// Writes `bytes` to `dir/name` atomically (exclusive temporary with a unique name, rename).
/// `name` must be a plain file name (the caller validated the scene id it comes from). The file
/// gets the permissions a plain create would give (0666 less the umask).
fn write_atomic(dir: &Path, name: &str, bytes: &[u8]) -> Result<()> {
    debug_assert!(!name.contains(['/', '\\']) && !name.starts_with('.'));
    let target = dir.join(name);
    let shown = target.display().to_string();
    let result = (|| {
        let mut file = tempfile::Builder::new()
            .prefix(&prefix(name))
            .suffix(SUFFIX)
            .permissions(fs::Permissions::from_mode(0o666))
            .tempfile_in(dir)?;
        file.write_all(bytes)?;
        file.persist(&target).map_err(|e| e.error)?;
        Ok(())
    })();
    // On failure the temporary was removed when dropped.
    result.map_err(|e| Error::io(shown, e))
}

/// Removes the temporaries of the files `names` in `dir` that are older than `age`: those a killed
/// run left. Younger ones may belong to a run still writing, and are left alone.
fn remove_abandoned(dir: &Path, names: &[&str], age: Duration) -> Result<()> {
    let shown = dir.display().to_string();
    let now = SystemTime::now();
    for entry in fs::read_dir(dir).map_err(|e| Error::io(&shown, e))? {
        let entry = entry.map_err(|e| Error::io(&shown, e))?;
        let file_name = entry.file_name();
        let Some(file_name) = file_name.to_str() else {
            continue;
        };
        let ours =
            file_name.ends_with(SUFFIX) && names.iter().any(|n| file_name.starts_with(&prefix(n)));
        let old = || {
            entry.metadata().is_ok_and(|m| {
                m.is_file()
                    && m.modified()
                        .is_ok_and(|t| now.duration_since(t).is_ok_and(|d| d > age))
            })
        };
        if ours && old() {
            match fs::remove_file(entry.path()) {
                Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                    return Err(Error::io(entry.path().display().to_string(), e));
                }
                _ => {}
            }
        }
    }
    Ok(())
}

/// Writes every (file name, bytes) of `files` into `dir` with [`write_atomic`], creating `dir` if
/// needed and first removing the [abandoned](ABANDONED_AFTER) temporaries of those names; returns
/// the paths written, in order. The files are written in parallel; when some fail, the error
/// is the first failure in `files`' order.
pub fn write_files<N: AsRef<str> + Sync, B: AsRef<[u8]> + Sync>(
    dir: &Path,
    files: &[(N, B)],
) -> Result<Vec<std::path::PathBuf>> {
    ensure_dir(dir)?;
    let names: Vec<&str> = files.iter().map(|(name, _)| name.as_ref()).collect();
    remove_abandoned(dir, &names, ABANDONED_AFTER)?;
    let results: Vec<Result<()>> = files
        .par_iter()
        .map(|(name, bytes)| write_atomic(dir, name.as_ref(), bytes.as_ref()))
        .collect();
    results.into_iter().collect::<Result<()>>()?;
    Ok(names.iter().map(|name| dir.join(name)).collect())
}

/// Splits an output file path given by the user as argument `flag` (`-o FILE`) into its folder (`.`
/// for a bare name) and its file name, refusing a path without a plain file name (`dir/`, `..`) or
/// with a hidden one (a leading `.` is kept for the temporaries).
pub fn split_file_path<'a>(flag: &str, path: &'a Path) -> Result<(&'a Path, &'a str)> {
    let shown = path.display().to_string();
    let name = path
        .file_name()
        .and_then(|n| n.to_str())
        .filter(|n| !n.starts_with('.') && !path.as_os_str().to_string_lossy().ends_with('/'))
        .ok_or_else(|| {
            Error::Usage(format!(
                "{flag}: not a file name to write (got \"{}\", expected a path ending in a plain, non-hidden UTF-8 file name)",
                crate::problem::excerpt(&shown)
            ))
        })?;
    let dir = match path.parent() {
        Some(dir) if !dir.as_os_str().is_empty() => dir,
        _ => Path::new("."),
    };
    Ok((dir, name))
}

/// Creates `dir` if needed and checks that a file can be created in it (a temporary, removed at
/// once), so a long run can fail before its work rather than after it.
pub fn check_writable(dir: &Path) -> Result<()> {
    ensure_dir(dir)?;
    tempfile::Builder::new()
        .prefix(".ndfplot-probe.")
        .suffix(SUFFIX)
        .tempfile_in(dir)
        .map(drop)
        .map_err(|e| Error::io(dir.display().to_string(), e))
}

/// Creates the output folder (and its parents) if needed.
fn ensure_dir(dir: &Path) -> Result<()> {
    fs::create_dir_all(dir).map_err(|e| Error::io(dir.display().to_string(), e))
}
