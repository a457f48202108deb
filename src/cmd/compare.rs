//! `ndfplot compare`: the metrics of two curves of the same kind (docs/contracts.md) over the whole hemisphere
//! or a `--theta-range`, as a readable table, one JSON object, one CSV row or the one number `--metric`
//! names, and the `--max-error` bounds that turn them into a CI gate (exit 1 when exceeded). With
//! `--pairs`, the same for every pair of a JSON Lines input, compared in parallel and written in input
//! order, one row (JSON object, CSV row, number) per pair.
//!
//! Owns the formatting, the bound checks and the batch run only; the metrics are [`crate::model::metrics`]'s.

use crate::error::{Error, Result};
use crate::model::curve::Curve;
use crate::model::metrics::sampled::{Operand, compare_operands};
use crate::model::metrics::{Comparison, LOG_RATIO_FLOOR, Metric, MetricError, ThetaRange};
use crate::output::report::ReportFormat;
use crate::output::report::{Cell, Report};
use crate::problem::{Problem, Problems, join_key, suggestion};
use crate::spec::angle::AngleUnit;
use crate::spec::input::Record;

/// A `--max-error <metric>=<x>` bound.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bound {
    /// The bounded metric.
    pub metric: Metric,
    /// Largest accepted value (finite, ≥ 0).
    pub limit: f64,
}

/// Parses `<metric>=<x>` with x a finite number ≥ 0; problems are reported under `--max-error`.
pub fn parse_bound(text: &str) -> Result<Bound> {
    let names: Vec<&str> = Metric::ALL.iter().map(|m| m.name()).collect();
    let problem = |at: &str, message: String| {
        Error::input(Problems {
            source: "--max-error".into(),
            list: vec![Problem::new(at, message)],
        })
    };
    let Some((name, number)) = text.split_once('=') else {
        return Err(problem(
            "",
            format!("expected <metric>=<number> (got \"{text}\", expected e.g. max_rel=1e-3)"),
        ));
    };
    let Some(metric) = Metric::from_name(name) else {
        return Err(problem(
            name,
            format!(
                "unknown metric (got \"{name}\", expected one of: {}){}",
                names.join(", "),
                suggestion(name, names.iter().copied())
            ),
        ));
    };
    match number.trim().parse::<f64>() {
        Ok(limit) if limit.is_finite() && limit >= 0.0 => Ok(Bound { metric, limit }),
        _ => Err(problem(
            name,
            format!("not a number ≥ 0 (got \"{number}\", expected e.g. {name}=1e-3)"),
        )),
    }
}

/// Checks that two curves are of the same kind (two NDFs showing the same quantity, or two Fresnel
/// curves); the problem is at the model key of `b`, given under the key `b_key` (`""` for a whole
/// argument).
fn check_kinds(a: &Curve, b: &Curve, b_key: &str) -> std::result::Result<(), Problem> {
    let (ka, kb) = (a.kind(), b.kind());
    if ka == kb {
        return Ok(());
    }
    let (ma, mb) = (a.model(), b.model());
    let message = if ma.key() == mb.key() {
        format!(
            "compare needs two curves showing the same quantity (got {} against {})",
            kb.describe(),
            ka.describe()
        )
    } else {
        format!(
            "compare needs two curves of the same kind (got {} \"{}\" against {} \"{}\", expected two NDFs or two Fresnel curves)",
            mb.key(),
            mb.name(),
            ma.key(),
            ma.name()
        )
    };
    Err(Problem::new(join_key(b_key, mb.key()), message))
}

/// The metrics of `a` against `b` over `range` ([`compare_operands`]); the outer `Err` is two curves of
/// different kinds ([`check_kinds`], at `b_key`), the inner one numerics that failed.
fn compare_sides(
    a: &Operand,
    b: &Operand,
    b_key: &str,
    range: ThetaRange,
) -> std::result::Result<std::result::Result<Comparison, MetricError>, Problem> {
    if let (Operand::Curve(a), Operand::Curve(b)) = (a, b) {
        check_kinds(a, b, b_key)?;
    }
    Ok(compare_operands(a, b, range))
}

/// The metrics of `a` against `b` (two curves of one kind, or a sampled series against anything) over
/// `range`; curves of different kinds are a problem of `--b`, and a side that is not finite somewhere,
/// an integral that does not converge, a series with no sample in the range or two series with no θ
/// in common is an error (exit 2).
pub fn metrics(a: &Operand, b: &Operand, range: ThetaRange) -> Result<Comparison> {
    compare_sides(a, b, "", range)
        .map_err(|p| {
            Error::input(Problems {
                source: "--b".into(),
                list: vec![p],
            })
        })?
        .map_err(|e| Error::Numerics(format!("compare: {e}")))
}

/// Where the metrics are taken (`--theta-range`) and the unit θ is read and printed in (`--degrees`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Span {
    /// The θ range, in radians.
    pub range: ThetaRange,
    /// Its ends as given, in `unit` (0 and π/2, or 0 and 90, without `--theta-range`).
    pub given: [f64; 2],
    /// The unit of `--theta-range` and of every θ printed.
    pub unit: AngleUnit,
}

/// Parses `--theta-range A:B` in `unit` (radians may be multiples of π, as `--theta` reads them):
/// 0 ≤ A < B ≤ π/2 (or 90 degrees). `None` is the whole [0, π/2].
pub fn parse_span(text: Option<&str>, unit: AngleUnit) -> Result<Span> {
    let bad = |what: String| Error::Usage(format!("--theta-range: {what}"));
    let Some(text) = text else {
        return Ok(Span {
            range: ThetaRange::FULL,
            given: [0.0, unit.from_radians(ThetaRange::FULL.hi())],
            unit,
        });
    };
    let Some((a, b)) = text.split_once(':') else {
        return Err(bad(format!(
            "expected A:B (got \"{}\", expected e.g. 0:pi/4, or 0:50 with --degrees)",
            crate::problem::excerpt(text)
        )));
    };
    let end = |s: &str| -> Result<(f64, f64)> {
        let given = unit.parse(s).map_err(bad)?;
        Ok((given, unit.check(given).map_err(bad)?))
    };
    let ((from, lo), (to, hi)) = (end(a)?, end(b)?);
    let range = ThetaRange::new(lo, hi).ok_or_else(|| {
        bad(format!(
            "the range is empty (got {from:?}:{to:?}, expected A < B)"
        ))
    })?;
    Ok(Span {
        range,
        given: [from, to],
        unit,
    })
}

/// A number of the report, by name (`--metric`, the JSON members and CSV columns, in this order).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    /// The start of the θ range.
    ThetaFrom,
    /// The end of the θ range.
    ThetaTo,
    /// A metric's value.
    Value(Metric),
    /// The θ where a maximum metric is reached.
    Theta(Metric),
    /// The maximum of side a.
    APeak,
    /// θ of a's maximum.
    APeakTheta,
    /// The maximum of side b.
    BPeak,
    /// θ of b's maximum.
    BPeakTheta,
}

impl Field {
    /// Every field, in report order.
    pub const ALL: [Field; 14] = [
        Field::ThetaFrom,
        Field::ThetaTo,
        Field::Value(Metric::MaxAbs),
        Field::Theta(Metric::MaxAbs),
        Field::Value(Metric::MaxRel),
        Field::Theta(Metric::MaxRel),
        Field::Value(Metric::MaxLogRatio),
        Field::Theta(Metric::MaxLogRatio),
        Field::Value(Metric::L2Projected),
        Field::Value(Metric::L2Grid),
        Field::APeak,
        Field::APeakTheta,
        Field::BPeak,
        Field::BPeakTheta,
    ];

    /// The field's name with θ in `unit`: a metric's name, `<metric>_theta`, `a_peak`, `a_peak_theta`,
    /// `theta_from`, …; every angle's name ends in `_deg` in degrees.
    pub fn name(self, unit: AngleUnit) -> String {
        match self {
            Field::ThetaFrom => unit.name("theta_from"),
            Field::ThetaTo => unit.name("theta_to"),
            Field::Value(m) => m.name().to_string(),
            Field::Theta(m) => unit.name(&format!("{}_theta", m.name())),
            Field::APeak => "a_peak".into(),
            Field::APeakTheta => unit.name("a_peak_theta"),
            Field::BPeak => "b_peak".into(),
            Field::BPeakTheta => unit.name("b_peak_theta"),
        }
    }

    /// The field's value in `c` over `span`, angles in its unit (an end of the range as given);
    /// `None` for an undefined `max_log_ratio` and its θ.
    pub fn of(self, c: &Comparison, span: &Span) -> Option<f64> {
        let angle = |theta: f64| {
            Some(if theta == span.range.lo() {
                span.given[0]
            } else if theta == span.range.hi() {
                span.given[1]
            } else {
                span.unit.from_radians(theta)
            })
        };
        match self {
            Field::ThetaFrom => Some(span.given[0]),
            Field::ThetaTo => Some(span.given[1]),
            Field::Value(m) => m.of(c),
            Field::Theta(Metric::MaxAbs) => angle(c.max_abs_theta),
            Field::Theta(Metric::MaxRel) => angle(c.max_rel_theta),
            Field::Theta(Metric::MaxLogRatio) => c.max_log_ratio.and_then(|m| angle(m.theta)),
            Field::Theta(Metric::L2Projected | Metric::L2Grid) => None,
            Field::APeak => Some(c.a_peak.value),
            Field::APeakTheta => angle(c.a_peak.theta),
            Field::BPeak => Some(c.b_peak.value),
            Field::BPeakTheta => angle(c.b_peak.theta),
        }
    }

    /// The field named `name` in `unit`; an unknown name is a usage error under `--metric` listing
    /// every name.
    pub fn from_name(name: &str, unit: AngleUnit) -> Result<Field> {
        let names: Vec<String> = Field::ALL.iter().map(|f| f.name(unit)).collect();
        match Field::ALL.into_iter().find(|f| f.name(unit) == name) {
            Some(field) => Ok(field),
            None => Err(Error::Usage(format!(
                "--metric: unknown name (got \"{}\", expected one of: {}){}",
                crate::problem::excerpt(name),
                names.join(", "),
                suggestion(name, names.iter().map(String::as_str))
            ))),
        }
    }
}

/// Why `max_log_ratio` has no value, for messages and the table.
fn log_ratio_undefined(span: &Span) -> String {
    format!(
        "no theta in {:?}:{:?} where both sides exceed {LOG_RATIO_FLOOR:e}",
        span.given[0], span.given[1]
    )
}

/// `--metric NAME`: the field's number and a newline; `Err` says why the number is undefined (an
/// undefined `max_log_ratio` or its θ).
pub fn one_number(
    field: Field,
    c: &Comparison,
    span: &Span,
) -> std::result::Result<String, String> {
    field
        .of(c, span)
        .map(|v| format!("{v:?}\n"))
        .ok_or_else(|| {
            format!(
                "compare: {} is undefined: {}",
                field.name(span.unit),
                log_ratio_undefined(span)
            )
        })
}

/// What `compare` prints: the readable table, JSON, CSV, or the one number of `--metric`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Output {
    /// The readable table (the default).
    Table,
    /// One JSON object per line, one line per pair.
    Json,
    /// A header and one CSV row per pair.
    Csv,
    /// One number per line, one line per pair.
    Metric(Field),
}

impl Output {
    /// The output of `--format` or, when given, `--metric NAME` in `unit` ([`Field::from_name`]).
    pub fn of(format: ReportFormat, metric: Option<&str>, unit: AngleUnit) -> Result<Output> {
        Ok(match (metric, format) {
            (Some(name), _) => Output::Metric(Field::from_name(name, unit)?),
            (None, ReportFormat::Json) => Output::Json,
            (None, ReportFormat::Csv) => Output::Csv,
            (None, ReportFormat::Table) => Output::Table,
        })
    }
}

/// One compared pair: the name of its source (`stdin:3`, `pairs.jsonl:3`; empty for `--a`/`--b`),
/// each side's canonical JSON, and the metrics.
#[derive(Debug, Clone, PartialEq)]
pub struct Compared {
    /// Where the pair was read.
    pub source: String,
    /// The first side's canonical JSON.
    pub a: String,
    /// The second side's canonical JSON.
    pub b: String,
    /// The metrics of a against b.
    pub metrics: Comparison,
}

/// The readable report: the two sides (canonical JSON), the θ range when it is not the whole
/// hemisphere, then one row per metric with the θ where it is reached (`theta_deg` with `--degrees`);
/// an undefined `max_log_ratio` reads `undefined` and why.
pub fn table(pair: &Compared, span: &Span) -> String {
    let c = &pair.metrics;
    let mut out = format!("a  {}\nb  {}\n{}", pair.a, pair.b, range_line(span));
    out.push_str(&format!(
        "\n{:<14}{:<25}{}\n",
        "metric",
        "value",
        span.unit.name("theta")
    ));
    let rows = Metric::ALL
        .map(|m| (m.name(), Field::Value(m), Some(Field::Theta(m))))
        .into_iter()
        .chain([
            ("a_peak", Field::APeak, Some(Field::APeakTheta)),
            ("b_peak", Field::BPeak, Some(Field::BPeakTheta)),
        ]);
    for (name, value, theta) in rows {
        let theta = theta.and_then(|t| t.of(c, span));
        let (value, theta) = match value.of(c, span) {
            Some(v) => (
                format!("{v:?}"),
                theta.map_or_else(String::new, |t| format!("{t:?}")),
            ),
            None => (
                "undefined".into(),
                format!("({})", log_ratio_undefined(span)),
            ),
        };
        out.push_str(format!("{name:<14}{value:<25}{theta}").trim_end());
        out.push('\n');
    }
    out
}

/// The line under the readable table when a side is sampled, saying where each metric is taken
/// (docs/contracts.md): the maxima at the sampled θ, `l2_projected` by the trapezoidal rule over
/// them and `l2_grid` on the c-grid's nodes inside their span, reading samples linearly in between;
/// empty when both sides are curves.
pub fn sampled_note(a: &Operand, b: &Operand) -> String {
    let sides: Vec<&str> = [("a", a), ("b", b)]
        .into_iter()
        .filter(|(_, side)| matches!(side, Operand::Samples(_)))
        .map(|(name, _)| name)
        .collect();
    if sides.is_empty() {
        return String::new();
    }
    format!(
        "\n{} sampled: max_abs, max_rel and max_log_ratio are taken at the samples' theta; l2_projected\n\
         integrates by the trapezoidal rule over them and l2_grid sums the c-grid's nodes inside their span,\n\
         reading the samples as the straight lines drawn between them\n",
        match sides[..] {
            [one] => format!("{one} is"),
            _ => "a and b are".to_string(),
        }
    )
}

/// The θ range line of the tables (`theta  0.0:0.7853981633974483`), or nothing over the whole
/// hemisphere.
fn range_line(span: &Span) -> String {
    if span.range == ThetaRange::FULL {
        return String::new();
    }
    format!(
        "{}  {:?}:{:?}\n",
        span.unit.name("theta"),
        span.given[0],
        span.given[1]
    )
}

/// The readable report of `--pairs`: the θ range when it is not the whole hemisphere, then a header and
/// one row per pair: its source, the value of every metric (`undefined` for an undefined
/// `max_log_ratio`), and the two sides' canonical JSON; columns aligned, the θ of each maximum and the
/// peaks left to `--format json|csv`.
pub fn batch_table(pairs: &[&Compared], span: &Span) -> String {
    let header = std::iter::once("pair")
        .chain(Metric::ALL.iter().map(|m| m.name()))
        .chain(["a", "b"])
        .map(String::from)
        .collect();
    let rows: Vec<Vec<String>> = std::iter::once(header)
        .chain(pairs.iter().map(|pair| {
            std::iter::once(pair.source.clone())
                .chain(Metric::ALL.iter().map(|m| {
                    m.of(&pair.metrics)
                        .map_or_else(|| "undefined".into(), |v| format!("{v:?}"))
                }))
                .chain([pair.a.clone(), pair.b.clone()])
                .collect()
        }))
        .collect();
    let widths: Vec<usize> = (0..rows[0].len())
        .map(|i| rows.iter().map(|r| r[i].chars().count()).max().unwrap_or(0))
        .collect();
    let mut out = range_line(span);
    if !out.is_empty() {
        out.push('\n');
    }
    for row in &rows {
        let line: String = row
            .iter()
            .zip(&widths)
            .map(|(cell, &width)| format!("{cell:<width$}  "))
            .collect();
        out.push_str(line.trim_end());
        out.push('\n');
    }
    out
}

/// The report of `--format json` and `csv`: columns `a`, `b` (each side's canonical JSON), then every
/// [`Field`] by name; one row per pair. An undefined number is JSON `null` and an empty CSV field.
pub fn report(pairs: &[Compared], span: &Span) -> Report {
    let mut report = Report::new(
        ["a".to_string(), "b".to_string()]
            .into_iter()
            .chain(Field::ALL.iter().map(|f| f.name(span.unit))),
    );
    for pair in pairs {
        report.push(
            [Cell::Json(pair.a.clone()), Cell::Json(pair.b.clone())]
                .into_iter()
                .chain(Field::ALL.iter().map(|f| {
                    f.of(&pair.metrics, span)
                        .map_or(Cell::Missing, Cell::Number)
                }))
                .collect(),
        );
    }
    report
}

/// One line per bound of `bounds` that `c` does not meet: `<metric> = <x> exceeds --max-error …`, or
/// that a bound on an undefined `max_log_ratio` cannot be met.
pub fn exceeded(c: &Comparison, bounds: &[Bound], span: &Span) -> Vec<String> {
    bounds
        .iter()
        .filter_map(|b| {
            let name = b.metric.name();
            match b.metric.of(c) {
                Some(v) if v > b.limit => Some(format!(
                    "{name} = {v:?} exceeds --max-error {name}={:?}",
                    b.limit
                )),
                Some(_) => None,
                None => Some(format!(
                    "{name} is undefined ({}), so --max-error {name}={:?} is not met",
                    log_ratio_undefined(span),
                    b.limit
                )),
            }
        })
        .collect()
}

/// `Err(CheckFailed)` (exit 1) listing every exceeded bound, one `compare: …` line each
/// ([`exceeded`]).
pub fn check_bounds(c: &Comparison, bounds: &[Bound], span: &Span) -> Result<()> {
    let lines: Vec<String> = exceeded(c, bounds, span)
        .into_iter()
        .map(|line| format!("compare: {line}"))
        .collect();
    if lines.is_empty() {
        Ok(())
    } else {
        Err(Error::CheckFailed(lines.join("\n")))
    }
}

/// How a `--pairs` run reports: where the metrics are taken, what is printed, the bounds that gate it
/// and whether failed pairs still exit 0 (`--keep-going`).
#[derive(Debug, Clone)]
pub struct Batch {
    /// Where the metrics are taken and θ's unit.
    pub span: Span,
    /// What is printed per pair.
    pub output: Output,
    /// The `--max-error` bounds.
    pub bounds: Vec<Bound>,
    /// Exit 0 although some pairs failed (their rows say so).
    pub keep_going: bool,
}

/// One side of a pair, ready to compare: the key it was given under (`a`, `fit`, …), the operand and
/// its canonical JSON.
#[derive(Debug, Clone)]
pub struct ReadySide {
    /// The pair's key of the side.
    pub key: &'static str,
    /// The curve or series.
    pub operand: Operand,
    /// Its canonical JSON.
    pub json: String,
}

/// A pair as read: its source, its line and its two sides, or the problems that kept it from being
/// read.
pub type LoadedPair = Record<[ReadySide; 2]>;

/// What a `--pairs` run leaves after writing its output: the `compare: <source>: …` line of every
/// exceeded bound (the run exits 1 when there are any), and the problems of the pairs that could not
/// be compared (it exits 2 when there are any, unless `--keep-going`).
#[derive(Debug)]
pub struct BatchReport {
    /// The exceeded bounds, in input order.
    pub exceeded: Vec<String>,
    /// One entry per failed pair, in input order.
    pub problems: Vec<Problems>,
    /// How many pairs were compared.
    pub compared: usize,
}

/// One pair of a `--pairs` run: its line, its sides' canonical JSON when they could be read, and its
/// metrics or problems.
struct Outcome {
    line: usize,
    sides: Option<[String; 2]>,
    result: std::result::Result<Compared, Problems>,
}

/// Compares every readable pair of `pairs` over `span` as they are read (in parallel, a chunk at a
/// time, [`crate::pipeline::batch::in_order`]) and hands the output to `write` in input order: JSON,
/// CSV (its header first) and `--metric` lines as each chunk is done, the readable table (which
/// aligns every row) at the end. A pair whose sides are of different kinds, whose numerics fail or
/// whose `--metric` is undefined becomes a problem of its source, and the others are still written;
/// in JSON and CSV a failed pair is a row with status `error` ([`batch_row`]), with `--metric` an
/// empty line. An error reading `pairs` or writing ends the run after the pairs before it; `write`
/// returning `Ok(false)` (the reader went away) ends it quietly.
pub fn run_pairs(
    pairs: impl Iterator<Item = Result<LoadedPair>>,
    span: &Span,
    output: Output,
    bounds: &[Bound],
    mut write: impl FnMut(&str) -> Result<bool>,
) -> Result<BatchReport> {
    let columns = batch_columns(span);
    let mut report = BatchReport {
        exceeded: Vec::new(),
        problems: Vec::new(),
        compared: 0,
    };
    let mut table = Vec::new();
    if output == Output::Csv {
        write(&Report::new(columns.clone()).csv())?;
    }
    crate::pipeline::batch::in_order(
        pairs,
        |pair| outcome(pair, span, output),
        |outcome| {
            let row = || {
                let mut one = Report::new(columns.clone());
                one.push(batch_row(&outcome, span));
                one
            };
            let text = match output {
                Output::Table => String::new(),
                Output::Json => row().json_lines(),
                Output::Csv => row().csv_rows(),
                Output::Metric(field) => match &outcome.result {
                    Ok(pair) => one_number(field, &pair.metrics, span).unwrap_or_default(),
                    Err(_) => "\n".into(),
                },
            };
            match outcome.result {
                Ok(pair) => {
                    report.compared += 1;
                    report.exceeded.extend(
                        exceeded(&pair.metrics, bounds, span)
                            .into_iter()
                            .map(|line| format!("compare: {}: {line}", pair.source)),
                    );
                    if output == Output::Table {
                        table.push(pair);
                    }
                }
                Err(problems) => report.problems.push(problems),
            }
            write(&text)
        },
    )?;
    if output == Output::Table {
        write(&batch_table(&table.iter().collect::<Vec<_>>(), span))?;
    }
    Ok(report)
}

/// One pair compared: its sides read, its metrics taken (and its `--metric` checked for being
/// defined), or the problem that kept it from being compared, charged to its source.
fn outcome(pair: LoadedPair, span: &Span, output: Output) -> Outcome {
    let source = pair.source;
    let problem = |p: Problem| Problems {
        source: source.clone(),
        list: vec![p],
    };
    let [a, b] = match pair.value {
        Ok(sides) => sides,
        Err(p) => {
            return Outcome {
                line: pair.line,
                sides: None,
                result: Err(p),
            };
        }
    };
    let result = (|| {
        let metrics = compare_sides(&a.operand, &b.operand, b.key, span.range)
            .map_err(problem)?
            .map_err(|e| problem(Problem::new("", format!("compare: {e}"))))?;
        if let Output::Metric(field) = output {
            one_number(field, &metrics, span).map_err(|m| problem(Problem::new("", m)))?;
        }
        Ok(Compared {
            source: source.clone(),
            a: a.json.clone(),
            b: b.json.clone(),
            metrics,
        })
    })();
    Outcome {
        line: pair.line,
        sides: Some([a.json, b.json]),
        result,
    }
}

/// The columns of `--pairs --format json|csv`: `line` (the pair's line), the columns of [`report`],
/// then `status` (`ok` or `error`) and `error` (the problems on one line, empty when ok).
fn batch_columns(span: &Span) -> Vec<String> {
    ["line".to_string(), "a".to_string(), "b".to_string()]
        .into_iter()
        .chain(Field::ALL.iter().map(|f| f.name(span.unit)))
        .chain(["status".to_string(), "error".to_string()])
        .collect()
}

/// The row of one pair under [`batch_columns`]: a failed pair's numbers are empty, and its sides too
/// when they could not be read.
fn batch_row(outcome: &Outcome, span: &Span) -> Vec<Cell> {
    let sides = match &outcome.sides {
        Some([a, b]) => [Cell::Json(a.clone()), Cell::Json(b.clone())],
        None => [Cell::Missing, Cell::Missing],
    };
    let (numbers, status, error): (Vec<Cell>, _, _) = match &outcome.result {
        Ok(pair) => (
            Field::ALL
                .iter()
                .map(|f| {
                    f.of(&pair.metrics, span)
                        .map_or(Cell::Missing, Cell::Number)
                })
                .collect(),
            "ok",
            String::new(),
        ),
        Err(p) => (vec![Cell::Missing; Field::ALL.len()], "error", p.field()),
    };
    std::iter::once(Cell::Count(outcome.line))
        .chain(sides)
        .chain(numbers)
        .chain([Cell::Text(status.into()), Cell::Text(error)])
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_parse_and_reject_bad_input() {
        assert_eq!(
            parse_bound("max_rel=1e-3").unwrap(),
            Bound {
                metric: Metric::MaxRel,
                limit: 1e-3
            }
        );
        for (bad, needle) in [
            ("max_rel=", "max_rel: not a number"),
            ("max_rel=x", "not a number"),
            ("max_rel=-1", "not a number ≥ 0"),
            ("max_abs", "expected <metric>=<number>"),
            ("max_ab=1", "did you mean \"max_abs\""),
        ] {
            let message = parse_bound(bad).unwrap_err().to_string();
            assert!(
                message.starts_with("error: --max-error: ") && message.contains(needle),
                "{bad}: {message}"
            );
        }
    }
}
