//! Reading curve arguments (inline JSON, `@path` files and JSON Lines on standard input) and the
//! pairs of `compare --pairs` (JSON Lines from a file or standard input).
//!
//! Every problem of every argument is collected before failing, so one run reports them all.

use crate::error::{Error, Result};
use crate::problem::{Problem, Problems};
use crate::spec::curve::{self, CurveSpec};
use crate::spec::datafile::DataScope;
use crate::spec::json;
use crate::spec::scene::data::CsvFile;
use std::io::Read;

/// Largest spec file, `@FILE` argument or standard input read, in bytes (16 MiB): far more than
/// any scene within the curve caps needs, and small enough that parsing it stays well under 1 GiB.
pub const MAX_INPUT_BYTES: u64 = 16 << 20;

/// Reads a text file, naming it in the error; a leading byte order mark is skipped. Only regular
/// files of at most [`MAX_INPUT_BYTES`] are read ([`read_file_bytes`]).
pub fn read_file(path: &str) -> Result<String> {
    utf8(read_file_bytes(path)?).map_err(|(line, column)| {
        Error::Usage(format!(
            "{path}: {line}:{column}: not UTF-8 text (a byte sequence that is not UTF-8 starts here)"
        ))
    })
}

/// The bytes of a file, naming it in the error. Only regular files of at most
/// [`MAX_INPUT_BYTES`] are read: a FIFO or a device is refused before it is opened (opening a
/// FIFO would block).
pub fn read_file_bytes(path: &str) -> Result<Vec<u8>> {
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
    read_capped(file).map_err(|e| Error::io(path, e))
}

/// `bytes` as text without a leading byte order mark ([`without_bom`]), or the 1-based line and
/// column where a byte sequence that is not UTF-8 starts.
fn utf8(bytes: Vec<u8>) -> std::result::Result<String, (usize, usize)> {
    String::from_utf8(bytes)
        .map(without_bom)
        .map_err(|e| line_column(&e.as_bytes()[..e.utf8_error().valid_up_to()]))
}

/// Standard input as text (a leading byte order mark skipped), at most [`MAX_INPUT_BYTES`] of it;
/// more, or bytes that are not UTF-8, is an `InvalidData` error saying so.
pub fn read_stdin() -> std::io::Result<String> {
    utf8(read_capped(std::io::stdin().lock())?).map_err(|(line, column)| {
        std::io::Error::new(
            std::io::ErrorKind::InvalidData,
            format!(
                "{line}:{column}: not UTF-8 text (a byte sequence that is not UTF-8 starts here)"
            ),
        )
    })
}

/// `text` without a leading UTF-8 byte order mark, which some editors write at the start of a
/// file: an invisible character JSON does not allow, skipped as RFC 8259 permits. Every spec,
/// `@FILE`, `--pairs` file and standard input goes through here.
fn without_bom(text: String) -> String {
    match text.strip_prefix('\u{feff}') {
        Some(rest) => rest.to_string(),
        None => text,
    }
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

/// Parses one side of a comparison at JSON path `path`: a curve, or a `{"data": "csv", …}` series
/// whose file is to be read from `scope`.
fn parse_side(
    node: &json::Node,
    path: &str,
    scope: DataScope,
) -> std::result::Result<Side, Vec<Problem>> {
    if crate::spec::scene::data::is_data(node) {
        return crate::spec::scene::data::parse_csv_series(node, path, scope).map(Side::Csv);
    }
    curve::parse(node, path).map(Side::Curve)
}

/// The folder a data path given in `arg` resolves against: an `@path` file's folder, else the working
/// directory.
fn base_dir(arg: &str) -> &std::path::Path {
    let here = std::path::Path::new(".");
    match arg.strip_prefix('@') {
        Some(path) => std::path::Path::new(path).parent().unwrap_or(here),
        None => here,
    }
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
    let (text, source) = if arg == "-" {
        (
            stdin().map_err(|e| Error::io("stdin", e))?,
            "stdin".to_string(),
        )
    } else if let Some(path) = arg.strip_prefix('@') {
        (
            read_file(path).map_err(|e| e.for_option(flag))?,
            path.to_string(),
        )
    } else {
        (arg.to_string(), flag.to_string())
    };
    let scope = DataScope::new(base_dir(arg), std::sync::Arc::from(allow_read));
    let side = parse_json(&text, &source)
        .and_then(|node| {
            parse_side(&node, "", scope).map_err(|list| Problems {
                source: source.clone(),
                list,
            })
        })
        .map_err(Error::input)?;
    Ok((source, side))
}

/// The two sides of one pair of `compare --pairs`, validated but not read, with the keys they were
/// given under.
#[derive(Debug, Clone)]
pub struct Pair {
    /// The first side and its key (`a`, or `target` in a record of `fit --format jsonl`).
    pub a: (&'static str, Side),
    /// The second side and its key (`b`, or `fit`).
    pub b: (&'static str, Side),
}

/// The keys naming a pair's two sides: `{"a": …, "b": …}`, or `fit --format jsonl`'s
/// `{"target": …, "fit": …}`.
const PAIR_SIDES: [[&str; 2]; 2] = [["a", "b"], ["target", "fit"]];

/// The other keys of a `fit --format jsonl` record, accepted in a pair and not read (with every
/// family's parameter names).
const FIT_RECORD_KEYS: [&str; 6] = ["line", "family", "residual", "metric", "status", "error"];

/// Parses one line of `compare --pairs`: a JSON object holding `a` and `b`, or `target` and `fit`
/// (a record of `fit --format jsonl`, whose other fields are accepted and not read; a record with
/// status `error` is refused with its error); each side a curve or a CSV series read from `scope`.
/// Every problem of the line is reported.
fn parse_pair(line: &str, source: &str, scope: &DataScope) -> std::result::Result<Pair, Problems> {
    let problems = |list| Problems {
        source: source.to_string(),
        list,
    };
    let node = parse_json(line, source)?;
    let expected = "expected {\"a\": <curve>, \"b\": <curve>} or a record of fit --format jsonl";
    let json::Value::Object(members) = &node.value else {
        return Err(problems(vec![Problem::new(
            "",
            format!("a pair must be an object (got {node}, {expected})"),
        )]));
    };
    let parameters: Vec<&str> = crate::model::ndf::Family::ALL
        .into_iter()
        .flat_map(|f| f.param_names())
        .collect();
    let listed: Vec<&str> = PAIR_SIDES
        .iter()
        .flatten()
        .chain(&FIT_RECORD_KEYS)
        .copied()
        .collect();
    let accepted = crate::spec::keys::Accepted {
        object: Some("a pair"),
        listed: &listed,
        unlisted: &parameters,
    };
    let mut list = crate::spec::keys::validate(members, "", Some(&accepted));
    let get = |key: &str| members.iter().find(|(k, _)| k == key).map(|(_, v)| v);
    if let Some(json::Value::String(status)) = get("status").map(|v| &v.value)
        && status == "error"
    {
        let error = match get("error").map(|v| &v.value) {
            Some(json::Value::String(e)) => crate::problem::excerpt(e),
            _ => String::new(),
        };
        list.push(Problem::new(
            "status",
            format!("a record of a failed fit has no fit to compare (got error \"{error}\")"),
        ));
        return Err(problems(list));
    }
    let given: Vec<[&'static str; 2]> = PAIR_SIDES
        .into_iter()
        .filter(|keys| keys.iter().any(|k| get(k).is_some()))
        .collect();
    let [keys] = given[..] else {
        list.push(Problem::new(
            "",
            format!(
                "a pair needs its two sides under a and b, or target and fit (got {node}, {expected})"
            ),
        ));
        return Err(problems(list));
    };
    let mut sides = keys.map(|key| match get(key) {
        Some(side) => parse_side(side, key, scope.clone())
            .map_err(|p| list.extend(p))
            .ok(),
        None => {
            let other = keys.into_iter().find(|&k| k != key).unwrap_or_default();
            list.push(Problem::new(
                key,
                format!("missing side (got only {other}, {expected})"),
            ));
            None
        }
    });
    match (sides[0].take(), sides[1].take()) {
        (Some(a), Some(b)) if list.is_empty() => Ok(Pair {
            a: (keys[0], a),
            b: (keys[1], b),
        }),
        _ => Err(problems(list)),
    }
}

/// A batch input read as it arrives: its records in order, or the error that ended the reading (a
/// failed read, or more than [`MAX_INPUT_BYTES`] in all).
pub type Records<T> = Box<dyn Iterator<Item = Result<Record<T>>>>;

/// Reads the pairs of `compare --pairs`: `arg` a file path or `-` for standard input, holding one
/// pair per non-blank line (JSON Lines, [`parse_pair`]), each named `<file>:<line>` or
/// `stdin:<line>`. CSV paths resolve against the file's folder (the working directory for `-`) or
/// lie inside one of `allow_read`. Each line is validated on its own as it is read; only reading the
/// input, or finding no pair at all, fails the whole call. `stdin` is standard input (locked).
pub fn read_pairs(
    arg: &str,
    allow_read: &[std::path::PathBuf],
    stdin: impl std::io::BufRead + 'static,
) -> Result<Records<Pair>> {
    let folder = match arg {
        "-" => std::path::Path::new("."),
        path => std::path::Path::new(path)
            .parent()
            .unwrap_or(std::path::Path::new(".")),
    };
    let scope = DataScope::new(folder, std::sync::Arc::from(allow_read));
    let parse = move |line: &str, source: &str| parse_pair(line, source, &scope);
    let mut pairs = if arg == "-" {
        json_lines(stdin, "stdin", parse)
    } else {
        let bytes = read_file_bytes(arg)?;
        json_lines(std::io::Cursor::new(bytes), arg, parse)
    }
    .peekable();
    if pairs.peek().is_none() {
        let name = if arg == "-" { "stdin" } else { arg };
        return Err(Error::Usage(format!(
            "--pairs: no pair given (got no line in {name}, expected one JSON object per line)"
        )));
    }
    Ok(Box::new(pairs))
}

/// One record of a batch input: where it was read and what was read there.
#[derive(Debug, Clone)]
pub struct Record<T> {
    /// The name problems carry: `<name>:<line>` for JSON Lines, the argument (`--target[2]`) or the
    /// file otherwise.
    pub source: String,
    /// The 1-based line of a JSON Lines input, or the 1-based position of the argument among the
    /// records read from arguments: the `line` column of batch outputs.
    pub line: usize,
    /// The record, or the problems that kept it from being read.
    pub value: std::result::Result<T, Problems>,
}

/// The non-blank lines of the JSON Lines input `reader` (named `name`: `stdin` or a file path), in
/// order and as they are read, each with its source name `<name>:<line>` (1-based) and what `parse`
/// makes of it. The one reader of every batch input: lines are split on `\n` (a `\r` before it
/// dropped) and decoded one by one, so a line that is not UTF-8 is that line's problem, not the
/// batch's; a byte order mark before the first line is skipped; more than [`MAX_INPUT_BYTES`] in
/// all ends the input with an error once the records before are out.
fn json_lines<T: 'static>(
    reader: impl std::io::BufRead + 'static,
    name: &str,
    parse: impl Fn(&str, &str) -> std::result::Result<T, Problems> + 'static,
) -> Records<T> {
    let name = name.to_string();
    let mut reader = reader.take(MAX_INPUT_BYTES + 1);
    let (mut number, mut failed) = (0, false);
    let mut buffer = Vec::new();
    Box::new(std::iter::from_fn(move || {
        while !failed {
            buffer.clear();
            match std::io::BufRead::read_until(&mut reader, b'\n', &mut buffer) {
                Ok(0) => return None,
                Ok(_) if reader.limit() == 0 => {
                    failed = true;
                    let kind = std::io::ErrorKind::InvalidData;
                    let message = too_large(&format!("more than {MAX_INPUT_BYTES}"));
                    return Some(Err(Error::io(&name, std::io::Error::new(kind, message))));
                }
                Ok(_) => {}
                Err(e) => {
                    failed = true;
                    return Some(Err(Error::io(&name, e)));
                }
            }
            number += 1;
            let mut line = buffer.strip_suffix(b"\n").unwrap_or(&buffer);
            line = line.strip_suffix(b"\r").unwrap_or(line);
            if number == 1 {
                line = line.strip_prefix("\u{feff}".as_bytes()).unwrap_or(line);
            }
            if line.trim_ascii().is_empty() {
                continue;
            }
            let source = format!("{name}:{number}");
            let value = match std::str::from_utf8(line) {
                Ok(text) => parse(text, &source),
                Err(e) => Err(Problems {
                    source: source.clone(),
                    list: vec![Problem::new(
                        "",
                        format!(
                            "column {}: not UTF-8 text (a byte sequence that is not UTF-8 starts here)",
                            line_column(&line[..e.valid_up_to()]).1
                        ),
                    )],
                }),
            };
            return Some(Ok(Record {
                source,
                line: number,
                value,
            }));
        }
        None
    }))
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
/// (the path), `-` one curve per non-blank line of standard input (JSON Lines, `stdin:<line>`, read as
/// it arrives). Each curve is validated on its own, not resolved; only reading a file or standard
/// input, giving `-` twice, or finding no curve at all, fails the whole call. `stdin` is standard
/// input (locked).
pub fn read_curves(
    args: &[String],
    flag: &str,
    stdin: impl std::io::BufRead + 'static,
) -> Result<Records<CurveSpec>> {
    if args.iter().filter(|arg| *arg == "-").count() > 1 {
        return Err(Error::Usage(format!("{flag} - may be given only once")));
    }
    let mut stdin = Some(stdin);
    let single = args.len() == 1;
    let mut readers: Vec<Records<CurveSpec>> = Vec::new();
    for (i, arg) in args.iter().enumerate() {
        let record = if arg == "-" {
            if let Some(stdin) = stdin.take() {
                readers.push(json_lines(stdin, "stdin", parse_curve));
            }
            continue;
        } else if let Some(path) = arg.strip_prefix('@') {
            let text = read_file(path).map_err(|e| e.for_option(flag))?;
            Record {
                source: path.to_string(),
                line: i + 1,
                value: parse_curve(&text, path),
            }
        } else {
            let source = if single {
                flag.to_string()
            } else {
                format!("{flag}[{i}]")
            };
            Record {
                value: parse_curve(arg, &source),
                source,
                line: i + 1,
            }
        };
        readers.push(Box::new(std::iter::once(Ok(record))));
    }
    let mut curves = readers.into_iter().flatten().peekable();
    if curves.peek().is_none() {
        return Err(Error::Usage(format!("{flag}: no curve given")));
    }
    Ok(Box::new(curves))
}

/// Loads the curves named by `--curve` arguments ([`read_curves`]), in order, validated, not resolved;
/// every problem of every curve is reported together.
/// `flag` is the argument name used in messages (`--curve`).
pub fn load_curves(
    args: &[String],
    flag: &str,
    stdin: impl std::io::BufRead + 'static,
) -> Result<Vec<CurveSpec>> {
    let mut curves = Vec::new();
    let mut problems = Vec::new();
    for record in read_curves(args, flag, stdin)? {
        match record?.value {
            Ok(curve) => curves.push(curve),
            Err(p) => problems.push(p),
        }
    }
    if !problems.is_empty() {
        return Err(Error::Input(problems));
    }
    Ok(curves)
}
