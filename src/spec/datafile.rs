//! Reading the data files that specs and `compare` name (`{"data": "csv", "path": …}`): where a
//! file may be, what it may be, and how much of it may be read.
//!
//! A path resolves against the folder of the document that names it (a spec's folder; the working
//! directory for an inline `compare` side) and may not leave it — neither by an absolute path or
//! `..`, nor through a symbolic link — unless it lies inside a folder allowed with `--allow-read`.
//! Only regular files are read, up to [`MAX_DATA_FILE_BYTES`]. Messages never quote a file's
//! contents; [`crate::problem::excerpt`] bounds and sanitizes what they quote of its header.

use std::io::Read;
use std::path::{Component, Path, PathBuf};
use std::sync::Arc;

/// Largest data file read, in bytes (64 MiB): far more than [`crate::spec::scene::data::MAX_DATA_POINTS`]
/// rows need.
pub const MAX_DATA_FILE_BYTES: u64 = 64 << 20;

/// Where the data files of one document may be read from.
#[derive(Debug, Clone, PartialEq)]
pub struct DataScope {
    /// The folder relative paths resolve against, always readable.
    pub base: PathBuf,
    /// Further folders allowed with `--allow-read` (as given; made absolute when checked).
    pub allowed: Arc<[PathBuf]>,
}

impl DataScope {
    /// The scope of a document in `base`, with the extra readable folders `allowed`.
    pub fn new(base: impl Into<PathBuf>, allowed: Arc<[PathBuf]>) -> DataScope {
        DataScope {
            base: base.into(),
            allowed,
        }
    }

    /// The bytes of the data file `path` (as a document names it), or why it may not or cannot be
    /// read: a path leaving the readable folders (by itself or through a symbolic link), a missing
    /// file, a file that is not regular, or one larger than [`MAX_DATA_FILE_BYTES`]. The message
    /// does not repeat `path`.
    pub fn read(&self, path: &str) -> Result<Vec<u8>, String> {
        let leaves = |how: &str| {
            format!(
                "leaves the spec's folder{how} (expected a relative path inside it, or inside a \
                 folder given with --allow-read)"
            )
        };
        let roots: Vec<PathBuf> = std::iter::once(&self.base)
            .chain(self.allowed.iter())
            .filter_map(|root| absolute(root).ok())
            .collect();
        let written = absolute(&self.base.join(path)).map_err(|e| e.to_string())?;
        if !roots.iter().any(|root| written.starts_with(root)) {
            return Err(leaves(""));
        }
        let real = std::fs::canonicalize(&written).map_err(|e| io_message(&e))?;
        let inside = roots
            .iter()
            .filter_map(|root| std::fs::canonicalize(root).ok())
            .any(|root| real.starts_with(root));
        if !inside {
            return Err(leaves(" through a symbolic link"));
        }
        let regular = |meta: &std::fs::Metadata| {
            if !meta.is_file() {
                Err("not a regular file".to_string())
            } else if meta.len() > MAX_DATA_FILE_BYTES {
                Err(too_large(meta.len()))
            } else {
                Ok(())
            }
        };
        // Checked before opening, as opening a FIFO would block.
        regular(&std::fs::metadata(&real).map_err(|e| io_message(&e))?)?;
        let file = std::fs::File::open(&real).map_err(|e| io_message(&e))?;
        regular(&file.metadata().map_err(|e| io_message(&e))?)?;
        let mut bytes = Vec::new();
        file.take(MAX_DATA_FILE_BYTES + 1)
            .read_to_end(&mut bytes)
            .map_err(|e| io_message(&e))?;
        if bytes.len() as u64 > MAX_DATA_FILE_BYTES {
            return Err(too_large(bytes.len() as u64));
        }
        Ok(bytes)
    }
}

fn too_large(bytes: u64) -> String {
    format!(
        "file too large (got {bytes} bytes, expected at most {} MiB)",
        MAX_DATA_FILE_BYTES >> 20
    )
}

/// An I/O error's description without the OS error number.
fn io_message(error: &std::io::Error) -> String {
    let text = error.to_string();
    match text.find(" (os error") {
        Some(end) => text[..end].to_string(),
        None => text,
    }
}

/// `path` made absolute against the working directory, `.` and `..` resolved lexically (without
/// following symbolic links).
fn absolute(path: &Path) -> std::io::Result<PathBuf> {
    let path = if path.as_os_str().is_empty() {
        Path::new(".")
    } else {
        path
    };
    let mut out = PathBuf::new();
    for component in std::path::absolute(path)?.components() {
        match component {
            Component::ParentDir => {
                out.pop();
            }
            Component::CurDir => {}
            other => out.push(other),
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_resolve_lexically_before_any_link_is_followed() {
        let cwd = std::env::current_dir().unwrap();
        assert_eq!(absolute(Path::new("a/./b/../c")).unwrap(), cwd.join("a/c"));
        let scope = DataScope::new("tests/data/malformed", Arc::from([]));
        for outside in [
            "/proc/self/environ",
            "../../Cargo.toml",
            "x/../../overlay.csv",
        ] {
            let message = scope.read(outside).unwrap_err();
            assert!(
                message.starts_with("leaves the spec's folder"),
                "{outside}: {message}"
            );
        }
        assert!(scope.read("overlay.csv").is_ok());
        let widened = DataScope::new("tests/data/malformed", Arc::from([PathBuf::from(".")]));
        assert!(widened.read("../../../Cargo.toml").is_ok());
    }
}
