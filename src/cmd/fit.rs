//! `ndfplot fit` (docs/contracts.md): per target, without `--format`, the fitted curve on stdout (one line of
//! canonical curve JSON, ready for `eval`) and `residual=<x> (<metric>)` on stderr; with `--format jsonl`
//! or `csv`, one record per target holding its line, family, every parameter in its own column,
//! residual, metric, status, target, fit and error. A target that cannot be fitted becomes a problem of its
//! source (and, in the record formats, a row with status `error`); the others are still written.
//!
//! Owns the reading of `--family`, `--fix`, `--by` and `--format`, the mapping of fit errors to their
//! argument or target, and the text of the output; the fitting itself is [`crate::model::fit`]'s.

use crate::error::{Error, Result};
use crate::model::curve::Curve;
use crate::model::fit::{By, Fit, FitError, FitSpec, Subject};
use crate::model::ndf::Family;
use crate::output::report::{Cell, RecordFormat};
use crate::problem::{Problem, Problems, suggestion};
use crate::spec::input::Record;

fn usage(source: &str, at: &str, message: String) -> Error {
    Error::input(Problems {
        source: source.into(),
        list: vec![Problem::new(at, message)],
    })
}

/// Looks up an NDF family given as argument `flag` (`--family`, `--ndf`) by canonical name or
/// alias, suggesting the nearest name.
pub fn parse_family(flag: &str, name: &str) -> Result<Family> {
    Family::from_name(name).ok_or_else(|| {
        usage(
            flag,
            name,
            format!(
                "unknown ndf family (got \"{name}\", expected one of: {}){}",
                Family::NAMES.join(", "),
                suggestion(name, Family::NAMES)
            ),
        )
    })
}

/// Parses `--by`.
pub fn parse_by(name: &str) -> Result<By> {
    let names: Vec<&str> = By::ALL.iter().map(|b| b.name()).collect();
    By::from_name(name).ok_or_else(|| {
        usage(
            "--by",
            name,
            format!(
                "unknown fit method (got \"{name}\", expected one of: {}){}",
                names.join(", "),
                suggestion(name, names.iter().copied())
            ),
        )
    })
}

/// Parses every `--fix key=value` (value a finite number); all problems are reported together.
pub fn parse_fixed(args: &[String]) -> Result<Vec<(String, f64)>> {
    let mut fixed = Vec::new();
    let mut list = Vec::new();
    for text in args {
        match text.split_once('=') {
            Some((key, value)) => match value.trim().parse::<f64>() {
                Ok(v) if v.is_finite() => fixed.push((key.trim().to_string(), v)),
                _ => list.push(Problem::new(
                    key,
                    format!("not a number (got \"{value}\", expected {key}=<number>)"),
                )),
            },
            None => list.push(Problem::new(
                "",
                format!("expected key=value (got \"{text}\", expected e.g. alpha_abc2=1.75)"),
            )),
        }
    }
    if list.is_empty() {
        Ok(fixed)
    } else {
        Err(Error::input(Problems {
            source: "--fix".into(),
            list,
        }))
    }
}

/// Maps a fit error about `--fix` or the method to `error: --fix: <key>: <message>`, one about a
/// target to `error: <source>: <key>: <message>` with the target's source name (`--target`,
/// `--target[2]`, `stdin:7`).
fn fit_problems(e: FitError, target_source: &str) -> Problems {
    let source = match e.subject {
        Subject::Target => target_source,
        Subject::Fixed => "--fix",
    };
    Problems {
        source: source.into(),
        list: vec![Problem::new(e.key, e.message)],
    }
}

/// Maps a fit error to its argument: `error: --target|--fix: <key>: <message>`.
pub fn fit_error(e: FitError) -> Error {
    Error::input(fit_problems(e, "--target"))
}

/// How `ndfplot fit` writes its results.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Format {
    /// Per target, the fitted curve's line on stdout and its residual line on stderr.
    Curves,
    /// One JSON object per target, the fields of [`records`].
    Jsonl,
    /// CSV with the columns of [`records`].
    Csv,
}

impl Format {
    /// The format of `--format` (`None` for none given).
    pub fn of(format: Option<RecordFormat>) -> Format {
        match format {
            None => Format::Curves,
            Some(RecordFormat::Jsonl) => Format::Jsonl,
            Some(RecordFormat::Csv) => Format::Csv,
        }
    }
}

/// A target as read and resolved: its source, its line and its curve, or the problems that kept it
/// from being read.
pub type Target = Record<Curve>;

/// What a fit run leaves after writing its output: the problems of the targets that could not be
/// fitted (the run exits 2 when there are any, unless `--keep-going`) and the counts.
#[derive(Debug)]
pub struct Report {
    /// One entry per failed target, in input order.
    pub problems: Vec<Problems>,
    /// How many targets were fitted.
    pub fitted: usize,
}

/// One target's outcome: its line, its curve when it could be read, and its fit or problems.
struct Outcome {
    line: usize,
    target: Option<Curve>,
    fit: std::result::Result<Fit, Problems>,
}

/// Fits every readable target of `targets` as they are read (in parallel, a chunk at a time,
/// [`crate::pipeline::batch::in_order`]; each fit is [`FitSpec::fit`]'s) and hands the output to
/// `write` in input order as each chunk is done: in the record formats one row per target, failed
/// ones included (CSV's header first); without `--format` the fitted curve's line, with its residual
/// line handed to `note` (stderr). An error reading `targets` or writing ends the run after the
/// targets before it; `write` returning `Ok(false)` (the reader went away) ends it quietly.
pub fn run(
    spec: &FitSpec,
    targets: impl Iterator<Item = Result<Target>>,
    format: Format,
    mut write: impl FnMut(&str) -> Result<bool>,
    mut note: impl FnMut(&str),
) -> Result<Report> {
    let mut report = Report {
        problems: Vec::new(),
        fitted: 0,
    };
    let columns = record_columns(spec);
    if format == Format::Csv {
        write(&crate::output::report::Report::new(columns.iter().copied()).csv())?;
    }
    crate::pipeline::batch::in_order(
        targets,
        |t| match t.value {
            Ok(curve) => Outcome {
                line: t.line,
                fit: spec.fit(&curve).map_err(|e| fit_problems(e, &t.source)),
                target: Some(curve),
            },
            Err(p) => Outcome {
                line: t.line,
                target: None,
                fit: Err(p),
            },
        },
        |outcome| {
            let row = || {
                let mut one = crate::output::report::Report::new(columns.iter().copied());
                one.push(record(spec, &outcome));
                one
            };
            let text = match (format, &outcome.fit) {
                (Format::Curves, Ok(fit)) => format!("{}\n", fit.curve.canonical_json()),
                (Format::Curves, Err(_)) => String::new(),
                (Format::Jsonl, _) => row().json_lines(),
                (Format::Csv, _) => row().csv_rows(),
            };
            let more = write(&text)?;
            match outcome.fit {
                Ok(fit) => {
                    report.fitted += 1;
                    if format == Format::Curves {
                        note(&format!("{}\n", residual_line(&fit, spec.by())));
                    }
                }
                Err(problems) => report.problems.push(problems),
            }
            Ok(more)
        },
    )?;
    Ok(report)
}

/// `residual=<x> (<metric>)`.
fn residual_line(fit: &Fit, by: By) -> String {
    format!("residual={:?} ({})", fit.residual, by.residual_name())
}

/// The columns of the record formats: `line` (the target's line, or its position among `--target`
/// arguments), `family`, one column per parameter of the family by its registry name (fixed ones
/// included), `residual`, `metric`, `status` (`ok` or `error`), then the JSON text: `target` and
/// `fit` (canonical curve JSON) and `error` (the problems on one line, empty when ok). The plain
/// columns come first so that a field splitter reaches them before any quoted JSON.
fn record_columns(spec: &FitSpec) -> Vec<&'static str> {
    ["line", "family"]
        .into_iter()
        .chain(spec.family().param_names())
        .chain(["residual", "metric", "status", "target", "fit", "error"])
        .collect()
}

/// The record of one target under [`record_columns`]: a failed target's parameters, residual and fit
/// are empty, and its target too when it could not be read.
fn record(spec: &FitSpec, outcome: &Outcome) -> Vec<Cell> {
    let family = spec.family();
    let target = outcome
        .target
        .as_ref()
        .map_or(Cell::Missing, |c| Cell::Json(c.canonical_json()));
    let head = [Cell::Count(outcome.line), Cell::Text(family.name().into())];
    let metric = Cell::Text(spec.by().residual_name().into());
    match &outcome.fit {
        Ok(fit) => head
            .into_iter()
            .chain(fit.params().into_iter().map(|(_, v)| Cell::Number(v)))
            .chain([
                Cell::Number(fit.residual),
                metric,
                Cell::Text("ok".into()),
                target,
                Cell::Json(fit.curve.canonical_json()),
                Cell::Text(String::new()),
            ])
            .collect(),
        Err(problems) => head
            .into_iter()
            .chain(std::iter::repeat_n(
                Cell::Missing,
                family.param_names().len() + 1,
            ))
            .chain([
                metric,
                Cell::Text("error".into()),
                target,
                Cell::Missing,
                Cell::Text(problems.field()),
            ])
            .collect(),
    }
}
