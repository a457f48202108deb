//! Reading the data files that specs and `compare` name (`{"data": "csv", "path": …}`): where a
//! file may be, what it may be, and how much of it may be read.
//!
//! A path resolves against the folder of the document that names it (a spec's folder; the working
//! directory for an inline `compare` side) and may not leave it — neither by an absolute path or
//! `..`, nor through a symbolic link — unless it lies inside a folder allowed with `--allow-read`.
//! Only regular files are read, up to [`MAX_DATA_FILE_BYTES`], by [`read_beneath`] (and
//! [`read_regular`] for a path the user named): the one reader of untrusted files (also `render
//! --check`'s of the stored outputs and `albedo --against`'s), which walks from the readable folder to
//! the file without following a link, checks what it names before opening it and opens it without
//! following a link or blocking. Messages never quote
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
        let beneath = roots
            .iter()
            .filter_map(|root| std::fs::canonicalize(root).ok())
            .find_map(|root| {
                let relative = real.strip_prefix(&root).ok()?.to_path_buf();
                Some((root, relative))
            });
        let Some((root, relative)) = beneath else {
            return Err(leaves(" through a symbolic link"));
        };
        match read_beneath(&root, &relative, MAX_DATA_FILE_BYTES) {
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

/// What a file of mode `mode` (its `st_mode`, or `MetadataExt::mode`) is, for messages: `a folder`,
/// `a FIFO`, …
pub fn file_kind(mode: u32) -> &'static str {
    match mode & libc::S_IFMT {
        libc::S_IFDIR => "a folder",
        libc::S_IFLNK => "a symbolic link",
        libc::S_IFIFO => "a FIFO",
        libc::S_IFSOCK => "a socket",
        libc::S_IFCHR => "a character device",
        libc::S_IFBLK => "a block device",
        libc::S_IFREG => "a regular file",
        _ => "a special file",
    }
}

/// The bytes of the file at `path`, read as untrusted input: only when `path` itself (not a link
/// it names) is a regular file of at most `limit` bytes. The folder holding it is the one the path
/// names (links on the way followed: it is the folder the user named); the file is then read by
/// [`read_beneath`] from that folder.
pub fn read_regular(path: &Path, limit: u64) -> Result<Vec<u8>, Refused> {
    let name = path.file_name().ok_or(Refused::NotRegular("a folder"))?;
    let folder = match path.parent() {
        Some(parent) if !parent.as_os_str().is_empty() => parent,
        _ => Path::new("."),
    };
    read_beneath(folder, Path::new(name), limit)
}

/// The bytes of the regular file `relative` (a plain relative path: names only, no `..`) below the
/// folder `root`, read as untrusted input. Every folder on the way is opened from the one before it
/// (`openat`) without following a link, so the file read is one reached from `root` through real
/// folders at the moment it is opened — a folder swapped for a link after any earlier check is
/// refused, not followed. What the last name is is looked at before it is opened (opening a FIFO
/// blocks, opening a device may act on it); it is then opened without following a link
/// (`O_NOFOLLOW`) or blocking (`O_NONBLOCK`), and the opened file must be the one looked at (same
/// device and inode, still regular), so a swap between the two is refused too. At most `limit + 1`
/// bytes are ever read.
pub fn read_beneath(root: &Path, relative: &Path, limit: u64) -> Result<Vec<u8>, Refused> {
    use std::os::unix::fs::{MetadataExt, OpenOptionsExt};
    let names: Vec<&std::ffi::OsStr> = relative
        .components()
        .map(|component| match component {
            Component::Normal(name) => Ok(name),
            _ => Err(Refused::Io(std::io::Error::other(
                "not a plain relative path",
            ))),
        })
        .collect::<Result<_, _>>()?;
    let (last, folders) = names.split_last().ok_or(Refused::NotRegular("a folder"))?;
    let mut folder: std::os::fd::OwnedFd = std::fs::File::options()
        .read(true)
        .custom_flags(libc::O_DIRECTORY)
        .open(root)
        .map_err(Refused::Io)?
        .into();
    for name in folders {
        let (kind, ..) = stat_at(&folder, name)?;
        if kind != libc::S_IFDIR {
            return Err(Refused::NotRegular(file_kind(kind)));
        }
        folder = open_at(&folder, name, libc::O_DIRECTORY)?;
    }
    let (kind, size, identity) = stat_at(&folder, last)?;
    if kind != libc::S_IFREG {
        return Err(Refused::NotRegular(file_kind(kind)));
    }
    if size > limit {
        return Err(Refused::TooLarge(size));
    }
    let file = std::fs::File::from(open_at(&folder, last, libc::O_NONBLOCK)?);
    let opened = file.metadata().map_err(Refused::Io)?;
    if !opened.is_file() || (opened.dev(), opened.ino()) != identity {
        return Err(Refused::Io(std::io::Error::other(
            "replaced while being opened",
        )));
    }
    if opened.len() > limit {
        return Err(Refused::TooLarge(opened.len()));
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

/// What `name` inside `folder` is, without following a link: its file type bits (`S_IFMT` of its
/// mode), its size and its (device, inode). A link is [`Refused::Link`].
fn stat_at(
    folder: &std::os::fd::OwnedFd,
    name: &std::ffi::OsStr,
) -> Result<(libc::mode_t, u64, (u64, u64)), Refused> {
    use std::os::fd::AsRawFd;
    let name = c_name(name)?;
    let mut stat = std::mem::MaybeUninit::<libc::stat>::uninit();
    // SAFETY: `folder` is an open descriptor, `name` a NUL-terminated string, and `stat` points to
    // writable memory of the size fstatat fills; it is read only when the call succeeds.
    let status = unsafe {
        libc::fstatat(
            folder.as_raw_fd(),
            name.as_ptr(),
            stat.as_mut_ptr(),
            libc::AT_SYMLINK_NOFOLLOW,
        )
    };
    if status != 0 {
        return Err(Refused::Io(std::io::Error::last_os_error()));
    }
    // SAFETY: fstatat succeeded, so it filled `stat`.
    let stat = unsafe { stat.assume_init() };
    match stat.st_mode & libc::S_IFMT {
        libc::S_IFLNK => Err(Refused::Link),
        kind => Ok((kind, stat.st_size as u64, (stat.st_dev, stat.st_ino))),
    }
}

/// `name` inside `folder` opened read-only with `flags`, never through a link (`O_NOFOLLOW`; a link
/// swapped in since it was looked at is [`Refused::Link`]).
fn open_at(
    folder: &std::os::fd::OwnedFd,
    name: &std::ffi::OsStr,
    flags: libc::c_int,
) -> Result<std::os::fd::OwnedFd, Refused> {
    use std::os::fd::{AsRawFd, FromRawFd};
    let name = c_name(name)?;
    // SAFETY: `folder` is an open descriptor and `name` a NUL-terminated string.
    let fd = unsafe {
        libc::openat(
            folder.as_raw_fd(),
            name.as_ptr(),
            libc::O_RDONLY | libc::O_NOFOLLOW | libc::O_CLOEXEC | flags,
        )
    };
    if fd < 0 {
        let error = std::io::Error::last_os_error();
        return Err(match error.raw_os_error() {
            Some(libc::ELOOP) => Refused::Link,
            _ => Refused::Io(error),
        });
    }
    // SAFETY: openat returned a new descriptor that nothing else owns.
    Ok(unsafe { std::os::fd::OwnedFd::from_raw_fd(fd) })
}

/// A file name as the C string the system calls take (a name holding NUL names no file).
fn c_name(name: &std::ffi::OsStr) -> Result<std::ffi::CString, Refused> {
    use std::os::unix::ffi::OsStrExt;
    std::ffi::CString::new(name.as_bytes())
        .map_err(|_| Refused::Io(std::io::Error::other("a name holding a NUL byte")))
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

    /// What a scope checked is read through real folders only: a folder on the way swapped for a link
    /// after the check (here: before the read) is refused, not followed, as is a link or a FIFO at the
    /// end; the file itself is read when nothing was swapped.
    #[test]
    fn the_walk_to_a_data_file_follows_no_link_met_on_the_way() {
        let root = tempfile::tempdir().unwrap();
        let outside = tempfile::tempdir().unwrap();
        std::fs::create_dir(root.path().join("sub")).unwrap();
        std::fs::write(root.path().join("sub/data.csv"), "theta,y\n0,1\n").unwrap();
        std::fs::write(outside.path().join("data.csv"), "secret\n").unwrap();
        let relative = Path::new("sub/data.csv");
        assert_eq!(
            read_beneath(root.path(), relative, 1 << 20).unwrap(),
            b"theta,y\n0,1\n"
        );
        std::fs::rename(root.path().join("sub"), root.path().join("old")).unwrap();
        std::os::unix::fs::symlink(outside.path(), root.path().join("sub")).unwrap();
        assert!(matches!(
            read_beneath(root.path(), relative, 1 << 20),
            Err(Refused::Link)
        ));
        std::os::unix::fs::symlink(
            outside.path().join("data.csv"),
            root.path().join("last.csv"),
        )
        .unwrap();
        assert!(matches!(
            read_beneath(root.path(), Path::new("last.csv"), 1 << 20),
            Err(Refused::Link)
        ));
        let fifo = std::ffi::CString::new(
            root.path()
                .join("fifo")
                .into_os_string()
                .into_encoded_bytes(),
        )
        .unwrap();
        // SAFETY: a NUL-terminated path.
        assert_eq!(unsafe { libc::mkfifo(fifo.as_ptr(), 0o600) }, 0);
        assert!(matches!(
            read_beneath(root.path(), Path::new("fifo"), 1 << 20),
            Err(Refused::NotRegular("a FIFO"))
        ));
        assert!(matches!(
            read_beneath(root.path(), Path::new("old/data.csv"), 4),
            Err(Refused::TooLarge(12))
        ));
    }
}
