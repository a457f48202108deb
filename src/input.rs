//! Reading curve arguments: inline JSON, `@path` files and JSON Lines on standard input.
//!
//! Every problem of every argument is collected before failing, so one run reports them all.

use crate::curve::{self, CurveSpec};
use crate::datafile::DataScope;
use crate::error::{Error, Result};
use crate::json;
use crate::problem::{Problem, Problems};
use crate::scene::data::CsvFile;
use std::io::Read;

/// Largest spec file, `@FILE` argument or standard input read, in bytes (16 MiB): far more than
/// any scene within the curve caps needs, and small enough that parsing it stays well under 1 GiB.
pub const MAX_INPUT_BYTES: u64 = 16 << 20;

/// Reads a text file, naming it in the error. Only regular files of at most [`MAX_INPUT_BYTES`]
/// are read: a FIFO or a device is refused before it is opened (opening a FIFO would block).
pub fn read_file(path: &str) -> Result<String> {
    let meta = std::fs::metadata(path).map_err(|e| Error::io(path, e))?;
    let refuse = |what: String| {
        let kind = std::io::ErrorKind::InvalidInput;
        Err(Error::io(path, std::io::Error::new(kind, what)))
    };
    if !meta.is_file() {
        return refuse("not a regular file".to_owned());
    }
    if meta.len() > MAX_INPUT_BYTES {
        return refuse(too_large(&meta.len().to_string()));
    }
    let file = std::fs::File::open(path).map_err(|e| Error::io(path, e))?;
    let bytes = read_capped(file).map_err(|e| Error::io(path, e))?;
    String::from_utf8(bytes).map_err(|e| {
        let (line, column) = line_column(&e.as_bytes()[..e.utf8_error().valid_up_to()]);
        Error::Usage(format!(
            "{path}: {line}:{column}: not UTF-8 text (a byte sequence that is not UTF-8 starts here)"
        ))
    })
}

/// Standard input as text, at most [`MAX_INPUT_BYTES`] of it; more, or bytes that are not UTF-8,
/// is an `InvalidData` error saying so.
pub fn read_stdin() -> std::io::Result<String> {
    let bytes = read_capped(std::io::stdin().lock())?;
    String::from_utf8(bytes).map_err(|e| {
        let (line, column) = line_column(&e.as_bytes()[..e.utf8_error().valid_up_to()]);
        std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!(
                "{line}:{column}: not UTF-8 text (a byte sequence that is not UTF-8 starts here)"
            ),
        )
    })
}

/// Everything `reader` gives, up to [`MAX_INPUT_BYTES`]; a longer input is an `InvalidData`
/// error, found after reading one byte past the cap.
fn read_capped(reader: impl Read) -> std::io::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    reader.take(MAX_INPUT_BYTES + 1).read_to_end(&mut bytes)?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            too_large(&format!("more than {MAX_INPUT_BYTES}")),
        ));
    }
    Ok(bytes)
}

/// The message for an input of `size` (a number of bytes, or a bound on it) beyond
/// [`MAX_INPUT_BYTES`].
fn too_large(size: &str) -> String {
    format!(
        "input too large (got {size} bytes, expected at most {} MiB)",
        MAX_INPUT_BYTES >> 20
    )
}

/// The 1-based line and column (in characters) just after `text`, valid UTF-8.
fn line_column(text: &[u8]) -> (usize, usize) {
    let text = std::str::from_utf8(text).unwrap_or_default();
    let line = text.matches('\n').count() + 1;
    let column = text.rsplit('\n').next().unwrap_or_default().chars().count() + 1;
    (line, column)
}

/// Parses JSON text from `source` (a file name or argument name) into a node, reporting a syntax
/// error at its `line:column`.
pub fn parse_json(text: &str, source: &str) -> std::result::Result<json::Node, Problems> {
    json::parse(text).map_err(|e| Problems {
        source: source.to_string(),
        list: vec![Problem::new(
            format!("{}:{}", e.line, e.col),
            format!("invalid JSON: {}", e.message),
        )],
    })
}

/// One side of `compare` as given, validated but not read: a curve, or a CSV series.
#[derive(Debug, Clone)]
pub enum Side {
    /// A curve.
    Curve(CurveSpec),
    /// A `{"data": "csv", …}` series.
    Csv(CsvFile),
}

/// Parses one side of a comparison: a curve, or a `{"data": "csv", …}` series whose file is read
/// from `scope`.
fn parse_side(text: &str, source: &str, scope: DataScope) -> std::result::Result<Side, Problems> {
    let node = parse_json(text, source)?;
    let problems = |list| Problems {
        source: source.to_string(),
        list,
    };
    if crate::scene::data::is_data(&node) {
        let file = crate::scene::data::parse_csv_series(&node, scope).map_err(problems)?;
        return Ok(Side::Csv(file));
    }
    curve::parse(&node, "").map(Side::Curve).map_err(problems)
}

/// Loads one side of `compare` from `arg`: inline JSON, `@path` or `-` (one line on `stdin`), holding a
/// curve or a `{"data": "csv", "path": …}` series. The CSV path resolves against the folder of an
/// `@path` file, else against the working directory, and may be read from there or from the
/// folders `allow_read`; the file is not read. Returns the source's name (as problems name it) and
/// the side.
pub fn load_operand(
    arg: &str,
    flag: &str,
    allow_read: &[std::path::PathBuf],
    stdin: impl FnOnce() -> std::io::Result<String>,
) -> Result<(String, Side)> {
    let here = std::path::Path::new(".");
    let (text, source, base_dir) = if arg == "-" {
        let text = stdin().map_err(|e| Error::io("stdin", e))?;
        (text, "stdin".to_string(), here)
    } else if let Some(path) = arg.strip_prefix('@') {
        let folder = std::path::Path::new(path).parent().unwrap_or(here);
        (read_file(path)?, path.to_string(), folder)
    } else {
        (arg.to_string(), flag.to_string(), here)
    };
    let scope = DataScope::new(base_dir, std::sync::Arc::from(allow_read));
    let side = parse_side(&text, &source, scope).map_err(|p| Error::Input(vec![p]))?;
    Ok((source, side))
}

fn parse_curve(text: &str, source: &str) -> std::result::Result<CurveSpec, Problems> {
    let node = parse_json(text, source)?;
    curve::parse(&node, "").map_err(|list| Problems {
        source: source.to_string(),
        list,
    })
}

/// Reads the curves named by curve arguments, in order, each with the source name its problems carry:
/// `{…}` inline JSON (`flag`, or `flag[i]` among several arguments), `@path` a file holding one curve
/// (the path), `-` one curve per non-blank line of `stdin` (JSON Lines, `stdin:<line>`). Each curve is
/// validated on its own, not resolved; only reading a file or stdin, or finding no curve at all, fails
/// the whole call.
pub fn read_curves(
    args: &[String],
    flag: &str,
    stdin: impl FnOnce() -> std::io::Result<String>,
) -> Result<Vec<(String, std::result::Result<CurveSpec, Problems>)>> {
    let mut curves = Vec::new();
    let mut stdin = Some(stdin);
    for (i, arg) in args.iter().enumerate() {
        if arg == "-" {
            let read = stdin
                .take()
                .ok_or_else(|| Error::Usage(format!("{flag} - may be given only once")))?;
            let text = read().map_err(|e| Error::io("stdin", e))?;
            for (line_no, line) in text.lines().enumerate() {
                if !line.trim().is_empty() {
                    let source = format!("stdin:{}", line_no + 1);
                    curves.push((source.clone(), parse_curve(line, &source)));
                }
            }
        } else if let Some(path) = arg.strip_prefix('@') {
            curves.push((path.to_string(), parse_curve(&read_file(path)?, path)));
        } else {
            let source = if args.len() == 1 {
                flag.to_string()
            } else {
                format!("{flag}[{i}]")
            };
            curves.push((source.clone(), parse_curve(arg, &source)));
        }
    }
    if curves.is_empty() {
        return Err(Error::Usage(format!("{flag}: no curve given")));
    }
    Ok(curves)
}

/// Loads the curves named by `--curve` arguments ([`read_curves`]), in order, validated, not resolved;
/// every problem of every curve is reported together.
/// `flag` is the argument name used in messages (`--curve`).
pub fn load_curves(
    args: &[String],
    flag: &str,
    stdin: impl FnOnce() -> std::io::Result<String>,
) -> Result<Vec<CurveSpec>> {
    let mut curves = Vec::new();
    let mut problems = Vec::new();
    for (_, result) in read_curves(args, flag, stdin)? {
        match result {
            Ok(curve) => curves.push(curve),
            Err(p) => problems.push(p),
        }
    }
    if !problems.is_empty() {
        return Err(Error::Input(problems));
    }
    Ok(curves)
}
