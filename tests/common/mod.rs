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
