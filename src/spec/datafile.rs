//! Reading the data files that specs and `compare` name (`{"data": "csv", "path": …}`): where a
//! file may be, what it may be, and how much of it may be read.
//!
//! A path resolves against the folder of the document that names it (a spec's folder; the working
//! directory for an inline `compare` side) and may not leave it — neither by an absolute path or
//! `..`, nor through a symbolic link — unless it lies inside a folder allowed with `--allow-read`.
//! Only regular files are read, up to [`MAX_DATA_FILE_BYTES`], by [`read_regular`]: the one reader
//! of untrusted files (also `render --check`'s of the stored outputs), which checks what a path
//! names before opening it and opens it without following a link or blocking. Messages never quote
//! a file's contents; [`crate::problem::excerpt`] bounds and sanitizes what they quote of its
//! header.

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
        match read_regular(&real, MAX_DATA_FILE_BYTES) {
            Ok(bytes) => Ok(bytes),
            Err(Refused::TooLarge(len)) => Err(too_large(len)),
            Err(Refused::Io(e)) => Err(io_message(&e)),
            Err(refused) => Err(refused.to_string()),
        }
    }
}

/// Why [`read_regular`] read nothing.
#[derive(Debug)]
pub enum Refused {
    /// The path names a symbolic link, which is not followed.
    Link,
    /// The path names something other than a regular file: what it is (`a FIFO`, `a folder`).
    NotRegular(&'static str),
    /// The file holds more bytes (at least this many) than the limit.
    TooLarge(u64),
    /// Opening or reading failed.
    Io(std::io::Error),
}

impl std::fmt::Display for Refused {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Refused::Link => f.write_str("a symbolic link, not followed (expected a regular file)"),
            Refused::NotRegular(what) => {
                write!(
                    f,
                    "not a regular file (got {what}, expected a regular file)"
                )
            }
            Refused::TooLarge(len) => write!(f, "too large (got {len} bytes)"),
            Refused::Io(e) => f.write_str(&io_message(e)),
        }
    }
}

/// What a file that is not regular is, for messages: `a folder`, `a FIFO`, …
pub fn file_kind(file_type: std::fs::FileType) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    if file_type.is_dir() {
        "a folder"
    } else if file_type.is_symlink() {
        "a symbolic link"
    } else if file_type.is_fifo() {
        "a FIFO"
    } else if file_type.is_socket() {
        "a socket"
    } else if file_type.is_char_device() {
        "a character device"
    } else if file_type.is_block_device() {
        "a block device"
    } else if file_type.is_file() {
        "a regular file"
    } else {
        "a special file"
    }
}

/// The bytes of the file at `path`, read as untrusted input: only when `path` itself (not a link
/// it names) is a regular file of at most `limit` bytes. What the path names is checked before
/// it is opened (opening a FIFO blocks, opening a device may act on it); the file is then opened
/// without following a link (`O_NOFOLLOW`) or blocking (`O_NONBLOCK`), and the opened file must be
/// the one checked (same device and inode, still regular), so a swap between the check and the
/// open is refused too. At most `limit + 1` bytes are ever read.
pub fn read_regular(path: &Path, limit: u64) -> Result<Vec<u8>, Refused> {
    use std::os::unix::fs::{MetadataExt, OpenOptionsExt};
    let checked = std::fs::symlink_metadata(path).map_err(Refused::Io)?;
    let regular = |meta: &std::fs::Metadata| {
        if meta.file_type().is_symlink() {
            Err(Refused::Link)
        } else if !meta.is_file() {
            Err(Refused::NotRegular(file_kind(meta.file_type())))
        } else if meta.len() > limit {
            Err(Refused::TooLarge(meta.len()))
        } else {
            Ok(())
        }
    };
    regular(&checked)?;
    let file = std::fs::File::options()
        .read(true)
        .custom_flags(libc::O_NOFOLLOW | libc::O_NONBLOCK)
        .open(path)
        .map_err(|e| match e.raw_os_error() {
            Some(libc::ELOOP) => Refused::Link,
            _ => Refused::Io(e),
        })?;
    let opened = file.metadata().map_err(Refused::Io)?;
    regular(&opened)?;
    if (opened.dev(), opened.ino()) != (checked.dev(), checked.ino()) {
        return Err(Refused::Io(std::io::Error::other(
            "replaced while being opened",
        )));
    }
    let mut bytes = Vec::new();
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(Refused::Io)?;
    if bytes.len() as u64 > limit {
        return Err(Refused::TooLarge(bytes.len() as u64));
    }
    Ok(bytes)
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
