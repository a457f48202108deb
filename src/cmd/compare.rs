//! `ndfplot compare`: the metrics of two curves of the same kind (CONTRACTS.md) over the whole hemisphere
//! or a `--theta-range`, as a readable table, one JSON object, one CSV row or the one number `--metric`
//! names, and the `--max-error` bounds that turn them into a CI gate (exit 1 when exceeded).
//!
//! Owns the formatting and the bound checks only; the metrics are [`crate::metrics`]'s.

use crate::angle::AngleUnit;
use crate::curve::Curve;
use crate::error::{Error, Result};
use crate::metrics::sampled::{Operand, compare_operands};
use crate::metrics::{Comparison, LOG_RATIO_FLOOR, Metric, ThetaRange};
use crate::output::report::{Cell, Report};
use crate::problem::{Problem, Problems, suggestion};

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

/// Checks that two curves are of the same kind (both NDFs or both Fresnel); the problem is reported
/// under `--b`.
pub fn check_kinds(a: &Curve, b: &Curve) -> Result<()> {
    let (ma, mb) = (a.model(), b.model());
    if ma.key() == mb.key() {
        return Ok(());
    }
    Err(Error::input(Problems {
        source: "--b".into(),
        list: vec![Problem::new(
            mb.key(),
            format!(
                "compare needs two curves of the same kind (got {} \"{}\" against {} \"{}\", expected two NDFs or two Fresnel curves)",
                mb.key(),
                mb.name(),
                ma.key(),
                ma.name()
            ),
        )],
    }))
}

/// The metrics of `a` against `b` (two curves of one kind, or a sampled series against anything) over
/// `range`; a side that is not finite somewhere, an integral that does not converge, a series with no
/// sample in the range or two series with no θ in common is an error (exit 2).
pub fn metrics(a: &Operand, b: &Operand, range: ThetaRange) -> Result<Comparison> {
    if let (Operand::Curve(a), Operand::Curve(b)) = (a, b) {
        check_kinds(a, b)?;
    }
    compare_operands(a, b, range).map_err(|e| Error::Numerics(format!("compare: {e}")))
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

/// `--metric NAME`: the field's number and a newline; an undefined `max_log_ratio` is an error
/// (exit 2) saying why.
pub fn one_number(field: Field, c: &Comparison, span: &Span) -> Result<String> {
    field
        .of(c, span)
        .map(|v| format!("{v:?}\n"))
        .ok_or_else(|| {
            Error::Numerics(format!(
                "compare: {} is undefined: {}",
                field.name(span.unit),
                log_ratio_undefined(span)
            ))
        })
}

/// The readable report: the two sides (canonical JSON), the θ range when it is not the whole
/// hemisphere, then one row per metric with the θ where it is reached (`theta_deg` with `--degrees`);
/// an undefined `max_log_ratio` reads `undefined` and why.
pub fn table(a: &str, b: &str, c: &Comparison, span: &Span) -> String {
    let mut out = format!("a  {a}\nb  {b}\n");
    if span.range != ThetaRange::FULL {
        out.push_str(&format!(
            "{}  {:?}:{:?}\n",
            span.unit.name("theta"),
            span.given[0],
            span.given[1]
        ));
    }
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

/// The report of `--format json` and `csv`: columns `a`, `b` (each side's canonical JSON), then every
/// [`Field`] by name; one row. An undefined number is JSON `null` and an empty CSV field.
pub fn report(a: &str, b: &str, c: &Comparison, span: &Span) -> Report {
    let mut report = Report::new(
        ["a".to_string(), "b".to_string()]
            .into_iter()
            .chain(Field::ALL.iter().map(|f| f.name(span.unit))),
    );
    report.push(
        [Cell::Json(a.into()), Cell::Json(b.into())]
            .into_iter()
            .chain(
                Field::ALL
                    .iter()
                    .map(|f| f.of(c, span).map_or(Cell::Missing, Cell::Number)),
            )
            .collect(),
    );
    report
}

/// `Err(CheckFailed)` (exit 1) listing every exceeded bound, one line each; a bound on an undefined
/// `max_log_ratio` cannot be met and fails too.
pub fn check_bounds(c: &Comparison, bounds: &[Bound], span: &Span) -> Result<()> {
    let exceeded: Vec<String> = bounds
        .iter()
        .filter_map(|b| {
            let name = b.metric.name();
            match b.metric.of(c) {
                Some(v) if v > b.limit => Some(format!(
                    "compare: {name} = {v:?} exceeds --max-error {name}={:?}",
                    b.limit
                )),
                Some(_) => None,
                None => Some(format!(
                    "compare: {name} is undefined ({}), so --max-error {name}={:?} is not met",
                    log_ratio_undefined(span),
                    b.limit
                )),
            }
        })
        .collect();
    if exceeded.is_empty() {
        Ok(())
    } else {
        Err(Error::CheckFailed(exceeded.join("\n")))
    }
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
