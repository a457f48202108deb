//! `ndfplot fit` (docs/contracts.md): per target, without `--format`, the fitted curve on stdout (one line of
//! canonical curve JSON, ready for `eval`) and `residual=<x> (<metric>)` on stderr; with `--format jsonl`
//! or `csv`, one record per target holding target, fit, residual and metric. A target that cannot be
//! fitted becomes a problem of its source; the others are still written.
//!
//! Owns the reading of `--family`, `--fix`, `--by` and `--format`, the mapping of fit errors to their
//! argument or target, and the text of the output; the fitting itself is [`crate::model::fit`]'s.

use crate::error::{Error, Result};
use crate::model::curve::Curve;
use crate::model::fit::{By, Fit, FitError, FitSpec, Subject};
use crate::model::ndf::Family;
use crate::output::csv::Table;
use crate::output::report::RecordFormat;
use crate::problem::{Problem, Problems, suggestion};

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
    /// Per target, `{"target": <curve>, "fit": <curve>, "residual": <x>, "metric": "<name>"}`.
    Jsonl,
    /// CSV with columns `target,fit,residual,metric`, curves as canonical JSON.
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

/// A target as read: the name of its source and its curve, or the problems that kept it from being
/// read.
pub type Target = (String, std::result::Result<Curve, Problems>);

/// What a fit run writes: the text for stdout and for stderr, and the problems of the targets that
/// could not be fitted (the run exits 2 when there are any).
#[derive(Debug)]
pub struct Report {
    /// Standard output.
    pub stdout: String,
    /// Standard error before the problems: the residual lines of [`Format::Curves`].
    pub stderr: String,
    /// One entry per failed target, in input order.
    pub problems: Vec<Problems>,
}

/// Fits every readable target (in parallel, [`FitSpec::fit_all`]) and writes the results in input order
/// in `format`.
pub fn run(spec: &FitSpec, targets: Vec<Target>, format: Format) -> Report {
    let curves: Vec<Curve> = targets
        .iter()
        .filter_map(|(_, curve)| curve.as_ref().ok().cloned())
        .collect();
    let mut fits = spec.fit_all(&curves).into_iter();
    let mut fitted = Vec::with_capacity(targets.len());
    let mut problems = Vec::new();
    for (source, target) in targets {
        let result = target.and_then(|curve| {
            let fit = fits.next().expect("one fit per readable target");
            fit.map(|fit| (curve, fit))
                .map_err(|e| fit_problems(e, &source))
        });
        match result {
            Ok(pair) => fitted.push(pair),
            Err(p) => problems.push(p),
        }
    }
    let by = spec.by();
    let (stdout, stderr) = match format {
        Format::Curves => (
            fitted
                .iter()
                .map(|(_, fit)| format!("{}\n", fit.curve.canonical_json()))
                .collect(),
            fitted
                .iter()
                .map(|(_, fit)| format!("{}\n", residual_line(fit, by)))
                .collect(),
        ),
        Format::Jsonl => (jsonl(&fitted, by), String::new()),
        Format::Csv => (csv(&fitted, by), String::new()),
    };
    Report {
        stdout,
        stderr,
        problems,
    }
}

/// `residual=<x> (<metric>)`.
fn residual_line(fit: &Fit, by: By) -> String {
    format!("residual={:?} ({})", fit.residual, by.residual_name())
}

/// One line per fit: `{"target":<curve>,"fit":<curve>,"residual":<x>,"metric":"<name>"}`, curves as
/// canonical curve JSON objects, the residual in shortest round-trip form.
fn jsonl(fitted: &[(Curve, Fit)], by: By) -> String {
    fitted
        .iter()
        .map(|(target, fit)| {
            format!(
                "{{\"target\":{},\"fit\":{},\"residual\":{:?},\"metric\":\"{}\"}}\n",
                target.canonical_json(),
                fit.curve.canonical_json(),
                fit.residual,
                by.residual_name()
            )
        })
        .collect()
}

/// CSV `target,fit,residual,metric`, one row per fit, curves as canonical curve JSON (quoted).
fn csv(fitted: &[(Curve, Fit)], by: By) -> String {
    let mut table = Table::new(["target", "fit", "residual", "metric"], 160 * fitted.len());
    for (target, fit) in fitted {
        table.text(&target.canonical_json());
        table.text(&fit.curve.canonical_json());
        table.number(fit.residual);
        table.text(by.residual_name());
        table.end_row();
    }
    table.into_string()
}
