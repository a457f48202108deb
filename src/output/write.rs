//! The one place that writes output files: atomically, inside the output folder only.
//!
//! Each file is written as a hidden temporary `<dir>/.<name>.<unique>.tmp`, created exclusively
//! (never through an existing file or symbolic link), and renamed into place with the rest of its
//! set once all are written ([`Staging`]), so an interrupted or failing run never leaves a
//! truncated file under a real name nor half a set renamed, and two runs into one folder never
//! touch each other's temporaries (the last rename wins per file; docs/contracts.md).
//!
//! A file that already holds exactly the bytes to write is left as it is ([`holds`]).
//!
//! A rename replaces whatever has the name, so each target is checked first: an existing regular
//! file or symbolic link (the link itself is replaced, never written through) is replaced; anything
//! else — a device node, a FIFO, a socket, a folder — is refused, naming the option and the path,
//! before any file of the call is written. `-` is never a file or folder name here: each command
//! maps it to standard output or refuses it ([`refuse_dash_folder`]) before calling.

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
/// Random characters between a temporary's prefix and its suffix: a file is taken as one of
/// ours only when exactly this many letters and digits stand there.
const UNIQUE_CHARS: usize = 6;

/// Whether `file_name` is a temporary of the output `name`: `.<name>.` then [`UNIQUE_CHARS`]
/// letters or digits, then [`SUFFIX`] — not merely a name that starts and ends alike (a user's
/// `.fig.csv.backup.tmp` is left alone).
fn is_temporary_of(file_name: &str, name: &str) -> bool {
    file_name
        .strip_prefix(&prefix(name))
        .and_then(|rest| rest.strip_suffix(SUFFIX))
        .is_some_and(|unique| {
            unique.len() == UNIQUE_CHARS && unique.chars().all(|c| c.is_ascii_alphanumeric())
        })
}

/// The temporaries being written now, removed by [`exit_removing_temporaries`] when the
/// process is interrupted.
static LIVE: std::sync::Mutex<Vec<std::path::PathBuf>> = std::sync::Mutex::new(Vec::new());

/// Ends the process with exit code `code` after removing every temporary it is writing: what an
/// interrupted run (SIGINT, SIGTERM, SIGHUP) does, so it leaves no half-written file behind.
/// Renamed files are complete and stay. The list stays locked until the exit, so no writer
/// registers a temporary after the clean-up.
pub fn exit_removing_temporaries(code: i32) -> ! {
    let live = LIVE
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    for path in live.iter() {
        let _ = fs::remove_file(path);
    }
    std::process::exit(code)
}

/// A temporary's entry in [`LIVE`] for as long as the guard lives.
struct Live(std::path::PathBuf);

impl Live {
    /// Creates a temporary with `create` and enters it in [`LIVE`], the list locked throughout:
    /// an interrupt's clean-up never runs between the two and misses the file.
    fn create(
        create: impl FnOnce() -> std::io::Result<tempfile::NamedTempFile>,
    ) -> std::io::Result<(tempfile::NamedTempFile, Live)> {
        let mut live = LIVE
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let file = create()?;
        live.push(file.path().to_path_buf());
        let entry = Live(file.path().to_path_buf());
        Ok((file, entry))
    }
}

impl Drop for Live {
    fn drop(&mut self) {
        let mut live = LIVE
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if let Some(i) = live.iter().position(|p| *p == self.0) {
            live.swap_remove(i);
        }
    }
}

/// Files written into one folder as a run produces them: each into a hidden temporary as soon as
/// its bytes are ready ([`Staging::stage`], in parallel), all renamed into place together at the
/// end ([`Staging::commit`]). A run that fails before the end changes no file of the set: its
/// temporaries are removed as their [`Staged`] files are dropped. The folder is created on first
/// use, not before: a run that fails earlier creates nothing.
pub struct Staging<'a> {
    /// The option the folder was given with, for messages.
    flag: &'a str,
    dir: &'a Path,
    /// Whether the folder has been made.
    made: std::sync::Mutex<bool>,
}

/// One file of a [`Staging`]: written to its temporary, closed (a run of thousands of files holds
/// no descriptor open per file), or left to a target that already [holds](holds) its bytes.
pub struct Staged {
    name: String,
    temporary: Option<(tempfile::TempPath, Live)>,
}

impl<'a> Staging<'a> {
    /// A set of files to write into `dir`, the folder given with the option `flag`.
    pub fn new(flag: &'a str, dir: &'a Path) -> Staging<'a> {
        Staging {
            flag,
            dir,
            made: std::sync::Mutex::new(false),
        }
    }

    /// Creates the folder if this set has not yet.
    fn ensure_dir(&self) -> Result<()> {
        let mut made = self
            .made
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        if !*made {
            ensure_dir(self.flag, self.dir)?;
            *made = true;
        }
        Ok(())
    }

    /// Writes `bytes`, the file `name` of the set, to a temporary created exclusively with a unique
    /// name, unless the file there already [holds](holds) exactly those bytes: then it will be left
    /// as it is, its modification time too (re-rendering an unchanged catalogue rewrites nothing).
    /// The target is [checked](check_target) first. `name` must be a plain file name (the caller
    /// validated the scene id it comes from). A file written gets the permissions a plain create
    /// would give (0666 less the umask).
    pub fn stage(&self, name: &str, bytes: &[u8]) -> Result<Staged> {
        debug_assert!(!name.contains(['/', '\\']) && !name.starts_with('.'));
        self.ensure_dir()?;
        let target = joined(self.dir, name);
        check_target(self.flag, &target)?;
        if holds(&target, bytes) {
            return Ok(Staged {
                name: name.to_owned(),
                temporary: None,
            });
        }
        let shown = target.display().to_string();
        let (mut file, live) = Live::create(|| {
            tempfile::Builder::new()
                .prefix(&prefix(name))
                .suffix(SUFFIX)
                .rand_bytes(UNIQUE_CHARS)
                .permissions(fs::Permissions::from_mode(0o666))
                .tempfile_in(self.dir)
        })
        .map_err(|e| Error::io(&shown, e).for_option(self.flag))?;
        file.write_all(bytes)
            .map_err(|e| Error::io(&shown, e).for_option(self.flag))?;
        Ok(Staged {
            name: name.to_owned(),
            temporary: Some((file.into_temp_path(), live)),
        })
    }

    /// Renames every file of `staged` into place, in order, first removing the
    /// [abandoned](ABANDONED_AFTER) temporaries of their names; returns their paths. Each target
    /// is [checked](check_target) again just before its rename: it may have changed since it was
    /// staged. On a failure the files not yet renamed are removed with their temporaries.
    pub fn commit(&self, staged: Vec<Staged>) -> Result<Vec<std::path::PathBuf>> {
        self.ensure_dir()?;
        let names: Vec<&str> = staged.iter().map(|s| s.name.as_str()).collect();
        remove_abandoned(self.dir, &names, ABANDONED_AFTER)?;
        let paths = names.iter().map(|name| self.dir.join(name)).collect();
        for Staged { name, temporary } in staged {
            let Some((path, _live)) = temporary else {
                continue;
            };
            let target = joined(self.dir, &name);
            check_target(self.flag, &target)?;
            path.persist(&target).map_err(|e| {
                Error::io(target.display().to_string(), e.error).for_option(self.flag)
            })?;
        }
        Ok(paths)
    }
}

/// Bytes read at a time by [`holds`].
const COMPARED_BLOCK: usize = 1 << 16;

/// Whether `target` is a regular file that holds exactly `bytes`. It is opened only if its name
/// is a regular file of `bytes.len()` bytes (not followed through a link), then without following a
/// link and without blocking, and read only if what was opened is that same file: block by block, stopping at the first difference, never past that length (a link, a
/// FIFO, a device, or a file of another length holds nothing). Any error reads as "no": the file is
/// then written as usual.
fn holds(target: &Path, bytes: &[u8]) -> bool {
    use std::io::Read;
    use std::os::unix::fs::{MetadataExt, OpenOptionsExt};
    let same_size_file = |meta: &fs::Metadata| meta.is_file() && meta.len() == bytes.len() as u64;
    let Ok(named) = fs::symlink_metadata(target) else {
        return false;
    };
    if !same_size_file(&named) {
        return false;
    }
    let Ok(mut file) = fs::OpenOptions::new()
        .read(true)
        .custom_flags(libc::O_NOFOLLOW | libc::O_NONBLOCK)
        .open(target)
    else {
        return false;
    };
    match file.metadata() {
        Ok(open)
            if same_size_file(&open) && (open.dev(), open.ino()) == (named.dev(), named.ino()) => {}
        _ => return false,
    }
    let mut block = vec![0; COMPARED_BLOCK.min(bytes.len()).max(1)];
    for expected in bytes.chunks(COMPARED_BLOCK) {
        let read = &mut block[..expected.len()];
        if file.read_exact(read).is_err() || read != expected {
            return false;
        }
    }
    // It may have grown since it was measured.
    matches!(file.read(&mut block[..1]), Ok(0))
}

/// `dir/name`, or `name` alone when `dir` is `.` (the folder of a bare `-o FILE`), as messages
/// show it.
fn joined(dir: &Path, name: &str) -> std::path::PathBuf {
    if dir == Path::new(".") {
        name.into()
    } else {
        dir.join(name)
    }
}

/// Refuses `target` when it exists and is neither a regular file nor a symbolic link: renaming
/// over it would replace a device node, a FIFO or a socket (or fail on a folder after the work).
/// The message names `flag`, the option the path came from, and what the path is.
pub fn check_target(flag: &str, target: &Path) -> Result<()> {
    match fs::symlink_metadata(target) {
        Ok(meta) if !meta.is_file() && !meta.file_type().is_symlink() => {
            Err(Error::Usage(format!(
                "{flag}: {}: not a regular file, left as it is (got {}, expected a regular file to \
             replace or a name not yet taken)",
                target.display(),
                crate::spec::datafile::file_kind(std::os::unix::fs::MetadataExt::mode(&meta))
            )))
        }
        _ => Ok(()),
    }
}

/// The one rule for `-` given to an option `flag` that names a folder (docs/contracts.md: `-` is
/// standard output or input where that makes sense, or is refused; never a file or folder named
/// `-`): refused, with `instead` saying what to do.
pub fn refuse_dash_folder(flag: &str, dir: &Path, instead: &str) -> Result<()> {
    if dir.as_os_str() == "-" {
        return Err(Error::Usage(format!(
            "{flag}: - is not a folder (got -, expected a folder; {instead})"
        )));
    }
    Ok(())
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
        let ours = names.iter().any(|n| is_temporary_of(file_name, n));
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

/// Writes every (file name, bytes) of `files` into `dir`, the folder given with the option `flag`,
/// as one [`Staging`]: every target is [checked](check_target) before any file is written, the
/// files are staged in parallel, then renamed into place; returns the paths written, in order.
/// When some fail, the error is the first failure in `files`' order, and no file is changed.
pub fn write_files<N: AsRef<str> + Sync, B: AsRef<[u8]> + Sync>(
    flag: &str,
    dir: &Path,
    files: &[(N, B)],
) -> Result<Vec<std::path::PathBuf>> {
    for (name, _) in files {
        check_target(flag, &joined(dir, name.as_ref()))?;
    }
    let staging = Staging::new(flag, dir);
    let staged: Vec<Result<Staged>> = files
        .par_iter()
        .map(|(name, bytes)| staging.stage(name.as_ref(), bytes.as_ref()))
        .collect();
    staging.commit(staged.into_iter().collect::<Result<_>>()?)
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

/// Creates `dir` (given with the option `flag`) if needed, checks that a file can be created in it
/// (a temporary, removed at once) and that none of the files `names` it is to hold is something a
/// rename must not replace ([`check_target`]), so a long run can fail before its work rather than
/// after it.
pub fn check_writable(flag: &str, dir: &Path, names: &[&str]) -> Result<()> {
    ensure_dir(flag, dir)?;
    for name in names {
        check_target(flag, &joined(dir, name))?;
    }
    tempfile::Builder::new()
        .prefix(".ndfplot-probe.")
        .suffix(SUFFIX)
        .tempfile_in(dir)
        .map(drop)
        .map_err(|e| Error::io(dir.display().to_string(), e).for_option(flag))
}

/// Creates the output folder `dir` of the option `flag` (and its parents) if needed. When it cannot,
/// because the path is taken by something other than a folder (a file, a link to nothing), the
/// message says so instead of the system's "File exists".
fn ensure_dir(flag: &str, dir: &Path) -> Result<()> {
    let error = match fs::create_dir_all(dir) {
        Ok(()) => return Ok(()),
        Err(error) => error,
    };
    let taken = |got: &str| {
        Err(Error::Usage(format!(
            "{flag}: {}: not a folder (got {got}, expected a folder or a name not yet taken)",
            dir.display()
        )))
    };
    match (fs::symlink_metadata(dir), fs::metadata(dir)) {
        (Ok(link), Err(_)) if link.file_type().is_symlink() => taken("a symbolic link to nothing"),
        (Ok(_), Ok(meta)) if !meta.is_dir() => taken(crate::spec::datafile::file_kind(
            std::os::unix::fs::MetadataExt::mode(&meta),
        )),
        _ => Err(Error::io(dir.display().to_string(), error).for_option(flag)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_our_temporary_names_are_taken_for_temporaries() {
        assert!(is_temporary_of(".fig.csv.a1B2c3.tmp", "fig.csv"));
        assert!(!is_temporary_of(".fig.csv.old-backup.tmp", "fig.csv"));
        assert!(!is_temporary_of(".fig.csv.bak.tmp", "fig.csv"));
        assert!(!is_temporary_of(".fig.csv.my-file.tmp", "fig.csv"));
        assert!(!is_temporary_of(".fig.csv.a1B2c3.tmp", "fig.svg"));
        assert!(!is_temporary_of(".fig.csv.a1B2c3", "fig.csv"));
    }

    #[test]
    fn a_file_that_holds_the_bytes_is_left_as_it_is_and_anything_else_replaced() {
        use std::os::unix::fs::MetadataExt;
        let dir = tempfile::tempdir().unwrap();
        let inode = |name: &str| fs::symlink_metadata(dir.path().join(name)).unwrap().ino();
        let files = [
            ("same.csv", b"1,2\n".to_vec()),
            ("other.csv", b"3,4\n".to_vec()),
        ];
        write_files("-o", dir.path(), &files).unwrap();
        let (same, other) = (inode("same.csv"), inode("other.csv"));
        // Identical bytes: the same file stays. Same length, other bytes: a new file.
        let again = [
            ("same.csv", b"1,2\n".to_vec()),
            ("other.csv", b"3,5\n".to_vec()),
        ];
        write_files("-o", dir.path(), &again).unwrap();
        assert_eq!(inode("same.csv"), same);
        assert_ne!(inode("other.csv"), other);
        assert_eq!(fs::read(dir.path().join("other.csv")).unwrap(), b"3,5\n");
        // A link to a file holding the bytes is replaced by a file, its target left alone.
        let outside = tempfile::tempdir().unwrap();
        let kept = outside.path().join("kept.csv");
        fs::write(&kept, b"1,2\n").unwrap();
        fs::remove_file(dir.path().join("same.csv")).unwrap();
        std::os::unix::fs::symlink(&kept, dir.path().join("same.csv")).unwrap();
        write_files("-o", dir.path(), &again).unwrap();
        assert!(
            fs::symlink_metadata(dir.path().join("same.csv"))
                .unwrap()
                .is_file()
        );
        assert_eq!(fs::read(&kept).unwrap(), b"1,2\n");
        // A longer or shorter file is not read, and is replaced.
        fs::write(dir.path().join("same.csv"), b"1,2\n\n").unwrap();
        assert!(!holds(&dir.path().join("same.csv"), b"1,2\n"));
        assert!(holds(&dir.path().join("other.csv"), b"3,5\n"));
        assert!(!holds(&dir.path().join("missing.csv"), b""));
    }

    #[test]
    fn a_staged_set_changes_nothing_until_it_is_committed_and_nothing_if_it_is_dropped() {
        let dir = tempfile::tempdir().unwrap();
        let folder = dir.path().join("out");
        let listing = || {
            let mut names: Vec<String> = fs::read_dir(&folder)
                .unwrap()
                .map(|e| e.unwrap().file_name().into_string().unwrap())
                .collect();
            names.sort();
            names
        };
        let staging = Staging::new("-o", &folder);
        // Nothing is made before the first file is staged.
        assert!(!folder.exists());
        let staged = vec![
            staging.stage("a.csv", b"1\n").unwrap(),
            staging.stage("b.csv", b"2\n").unwrap(),
        ];
        // Staged: hidden temporaries only.
        assert!(
            listing().iter().all(|n| n.starts_with('.')),
            "{:?}",
            listing()
        );
        assert_eq!(listing().len(), 2);
        let written = staging.commit(staged).unwrap();
        assert_eq!(written, [folder.join("a.csv"), folder.join("b.csv")]);
        assert_eq!(listing(), ["a.csv", "b.csv"]);
        // A run that fails before its commit drops what it staged: the folder is as it was.
        let staging = Staging::new("-o", &folder);
        let staged = [
            staging.stage("a.csv", b"3\n").unwrap(),
            staging.stage("c.csv", b"4\n").unwrap(),
        ];
        drop(staged);
        assert_eq!(listing(), ["a.csv", "b.csv"]);
        assert_eq!(fs::read(folder.join("a.csv")).unwrap(), b"1\n");
    }

    #[test]
    fn staged_files_hold_no_descriptor_open() {
        // A render stages every file before renaming any: thousands of outputs must not hold
        // thousands of descriptors (the usual limit is 1024).
        let dir = tempfile::tempdir().unwrap();
        let open = || {
            fs::read_dir("/proc/self/fd")
                .map(Iterator::count)
                .unwrap_or(0)
        };
        let staging = Staging::new("-o", dir.path());
        let before = open();
        let staged: Vec<Staged> = (0..200)
            .map(|k| staging.stage(&format!("f{k}.csv"), b"1\n").unwrap())
            .collect();
        // Other tests of this process open files meanwhile, a few at a time.
        assert!(open() < before + 50, "{before} → {} descriptors", open());
        assert_eq!(staging.commit(staged).unwrap().len(), 200);
    }
}
