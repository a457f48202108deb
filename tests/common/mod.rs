//! What the test binaries share: running the real `ndfplot` binary, scratch folders, reading the
//! reference CSVs of `tests/data`, parameter grids, and which tolerance each family is held to.
//! The tolerances themselves live in `ndfplot::model::math::tolerance`.

// Each binary uses its own part of these helpers.
#![allow(dead_code)]

use ndfplot::model::math::tolerance::{REL_TOL_NDF, REL_TOL_TROWBRIDGE_REITZ};
use ndfplot::model::ndf::Family;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// The package root, where `configs/`, `tests/data/` and `fuzz/` are.
pub fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// Runs the real binary with `args` and returns what it did.
pub fn ndfplot(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ndfplot"))
        .args(args)
        .output()
        .expect("the binary runs")
}

/// Runs the real binary with `args`, `stdin` written to its standard input.
pub fn ndfplot_stdin(args: &[&str], stdin: &str) -> Output {
    ndfplot_stdin_env(args, stdin, &[])
}

/// [`ndfplot_stdin`] with the environment variables `env` set.
pub fn ndfplot_stdin_env(args: &[&str], stdin: &str, env: &[(&str, &str)]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ndfplot"))
        .args(args)
        .envs(env.iter().copied())
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    child
        .stdin
        .take()
        .unwrap()
        .write_all(stdin.as_bytes())
        .unwrap();
    child.wait_with_output().unwrap()
}

/// Runs the real binary with `args`, writes `first` to its standard input and waits, standard input
/// still open, for the first line of its standard output (panicking after a minute without one: the
/// command waited for the end of its input); then writes `rest`, closes standard input, and returns
/// that first line and the whole output.
pub fn streamed(args: &[&str], first: &str, rest: &str) -> (String, Output) {
    use std::io::BufRead;
    let mut child = Command::new(env!("CARGO_BIN_EXE_ndfplot"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let mut stdin = child.stdin.take().unwrap();
    stdin.write_all(first.as_bytes()).unwrap();
    stdin.flush().unwrap();
    let (sender, receiver) = std::sync::mpsc::channel();
    let mut stdout = std::io::BufReader::new(child.stdout.take().unwrap());
    let reader = std::thread::spawn(move || {
        let mut line = String::new();
        stdout.read_line(&mut line).unwrap();
        sender.send(line.clone()).unwrap();
        std::io::Read::read_to_string(&mut stdout, &mut line).unwrap();
        line
    });
    let Ok(first_line) = receiver.recv_timeout(std::time::Duration::from_secs(60)) else {
        child.kill().unwrap();
        panic!("{args:?}: no output while the input was still open");
    };
    stdin.write_all(rest.as_bytes()).unwrap();
    drop(stdin);
    let mut output = child.wait_with_output().unwrap();
    output.stdout = reader.join().unwrap().into_bytes();
    (first_line, output)
}

/// `bytes` as UTF-8 text; the binary writes nothing else.
pub fn text(bytes: &[u8]) -> String {
    String::from_utf8(bytes.to_vec()).unwrap()
}

/// Runs `render SPECS… -o out --format formats` and asserts that it succeeds.
pub fn render_into(specs: &[&Path], out: &Path, formats: &str) {
    let mut args: Vec<&str> = vec!["render"];
    args.extend(specs.iter().map(|p| p.to_str().unwrap()));
    args.extend(["-o", out.to_str().unwrap(), "--format", formats]);
    let output = ndfplot(&args);
    assert_eq!(output.status.code(), Some(0), "{}", text(&output.stderr));
}

/// A fresh, empty folder `name` under the target directory; names are unique across a binary.
pub fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The sorted file names in `dir`; none when `dir` does not exist.
pub fn files_in(dir: &Path) -> Vec<String> {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Vec::new();
    };
    let mut names: Vec<String> = entries
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    names
}

/// The records of the CSV file at `path`, relative to the package root (lines starting with `#` are
/// comments, such as a provenance line above the header).
pub fn csv_records(path: &str) -> Vec<csv::StringRecord> {
    let path = root().join(path);
    let mut reader = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .from_path(&path)
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    reader.records().map(|r| r.expect("a CSV record")).collect()
}

/// Column `column` of `record` as a number.
pub fn number(record: &csv::StringRecord, column: usize) -> f64 {
    record[column]
        .parse()
        .unwrap_or_else(|e| panic!("{record:?}[{column}]: {e}"))
}

/// `n` values spaced evenly in log10 between `lo` and `hi`, both included.
pub fn log_grid(lo: f64, hi: f64, n: usize) -> Vec<f64> {
    let (l, h) = (lo.log10(), hi.log10());
    (0..n)
        .map(|i| {
            10f64
                .powf(l + (h - l) * i as f64 / (n - 1) as f64)
                .clamp(lo, hi)
        })
        .collect()
}

/// The relative accuracy `family`'s values are held to (`ndfplot::model::math::tolerance`).
pub fn ndf_tol(family: Family) -> f64 {
    match family {
        Family::TrowbridgeReitz => REL_TOL_TROWBRIDGE_REITZ,
        _ => REL_TOL_NDF,
    }
}
