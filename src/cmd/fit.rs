//! `ndfplot fit`: the fitted curve on stdout (one line of canonical curve JSON, ready for `eval`) and
//! `residual=<x> (<metric>)` on stderr (CONTRACTS.md).
//!
//! Owns the reading of `--family`, `--fix` and `--by` and the mapping of fit errors to their argument;
//! the fitting itself is [`crate::fit`]'s.

use crate::curve::Curve;
use crate::error::{Error, Result};
use crate::fit::{By, Fit, FitError, Subject, fit};
use crate::ndf::Family;
use crate::problem::{Problem, Problems, suggestion};

fn usage(source: &str, at: &str, message: String) -> Error {
    Error::input(Problems {
        source: source.into(),
        list: vec![Problem::new(at, message)],
    })
}

/// Looks up `--family` (canonical names and aliases), suggesting the nearest name.
pub fn parse_family(name: &str) -> Result<Family> {
    Family::from_name(name).ok_or_else(|| {
        usage(
            "--family",
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

/// Maps a fit error to `error: --target|--fix: <key>: <message>`.
pub fn fit_error(e: FitError) -> Error {
    let source = match e.subject {
        Subject::Target => "--target",
        Subject::Fixed => "--fix",
    };
    usage(source, &e.key, e.message)
}

/// Runs the fit.
pub fn run(target: &Curve, family: Family, fixed: &[(String, f64)], by: By) -> Result<Fit> {
    fit(target, family, fixed, by).map_err(fit_error)
}

/// The stdout line: the fitted curve's canonical JSON, newline-terminated.
pub fn stdout_line(fit: &Fit) -> String {
    format!("{}\n", fit.curve.canonical_json())
}

/// The stderr line: `residual=<x> (<metric>)`.
pub fn residual_line(fit: &Fit, by: By) -> String {
    format!("residual={:?} ({})", fit.residual, by.residual_name())
}
