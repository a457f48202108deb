//! `ndfplot compare`: the metrics of two curves of the same kind (CONTRACTS.md), as a readable table or
//! one JSON object, and the `--max-error` bounds that turn them into a CI gate (exit 1 when exceeded).
//!
//! Owns the formatting and the bound checks only; the metrics are [`crate::metrics`]'s.

use crate::curve::Curve;
use crate::error::{Error, Result};
use crate::metrics::sampled::{Operand, compare_operands};
use crate::metrics::{Comparison, Metric};
use crate::problem::{Problem, Problems, suggestion};
use serde::Serialize;
use serde_json::value::RawValue;

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

/// The metrics of `a` against `b` (two curves of one kind, or a sampled series against anything); a
/// side that is not finite somewhere, an integral that does not converge or two series with no θ in
/// common is an error (exit 2).
pub fn metrics(a: &Operand, b: &Operand) -> Result<Comparison> {
    if let (Operand::Curve(a), Operand::Curve(b)) = (a, b) {
        check_kinds(a, b)?;
    }
    compare_operands(a, b).map_err(|e| Error::Numerics(format!("compare: {e}")))
}

/// The readable report: the two sides (canonical JSON), then one row per metric with the θ where it
/// is reached.
pub fn table(a: &str, b: &str, c: &Comparison) -> String {
    let rows: [(&str, f64, Option<f64>); 6] = [
        ("max_abs", c.max_abs, Some(c.max_abs_theta)),
        ("max_rel", c.max_rel, Some(c.max_rel_theta)),
        ("l2_projected", c.l2_projected, None),
        ("l2_grid", c.l2_grid, None),
        ("a_peak", c.a_peak.value, Some(c.a_peak.theta)),
        ("b_peak", c.b_peak.value, Some(c.b_peak.theta)),
    ];
    let mut out = format!(
        "a  {a}\nb  {b}\n\n{:<14}{:<25}{}\n",
        "metric", "value", "theta"
    );
    for (name, value, theta) in rows {
        let theta = theta.map_or_else(String::new, |t| format!("{t:?}"));
        out.push_str(format!("{name:<14}{:<25}{theta}", format!("{value:?}")).trim_end());
        out.push('\n');
    }
    out
}

/// The members of `compare --format json`, in order.
#[derive(Serialize)]
struct Report<'a> {
    a: &'a RawValue,
    b: &'a RawValue,
    max_abs: f64,
    max_abs_theta: f64,
    max_rel: f64,
    max_rel_theta: f64,
    l2_projected: f64,
    l2_grid: f64,
    a_peak: f64,
    a_peak_theta: f64,
    b_peak: f64,
    b_peak_theta: f64,
}

/// One JSON object and a newline: `a` and `b` (each side's canonical JSON, given as JSON text),
/// each metric by name, `max_abs_theta`, `max_rel_theta`, `a_peak`, `a_peak_theta`, `b_peak`,
/// `b_peak_theta`; numbers in round-trip form.
pub fn json(a: &str, b: &str, c: &Comparison) -> String {
    let raw = |text| serde_json::from_str::<&RawValue>(text).expect("canonical JSON is JSON");
    let report = Report {
        a: raw(a),
        b: raw(b),
        max_abs: c.max_abs,
        max_abs_theta: c.max_abs_theta,
        max_rel: c.max_rel,
        max_rel_theta: c.max_rel_theta,
        l2_projected: c.l2_projected,
        l2_grid: c.l2_grid,
        a_peak: c.a_peak.value,
        a_peak_theta: c.a_peak.theta,
        b_peak: c.b_peak.value,
        b_peak_theta: c.b_peak.theta,
    };
    crate::json::to_string(&report) + "\n"
}

/// `Err(CheckFailed)` (exit 1) listing every exceeded bound, one line each.
pub fn check_bounds(c: &Comparison, bounds: &[Bound]) -> Result<()> {
    let exceeded: Vec<String> = bounds
        .iter()
        .filter(|b| b.metric.of(c) > b.limit)
        .map(|b| {
            format!(
                "compare: {} = {:?} exceeds --max-error {}={:?}",
                b.metric.name(),
                b.metric.of(c),
                b.metric.name(),
                b.limit
            )
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
