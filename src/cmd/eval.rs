//! `ndfplot eval`: a curve's values at given angles, as CSV on standard output (docs/contracts.md).
//!
//! The table is streamed: rows are computed a batch at a time (in parallel, the same bytes on any
//! number of threads) and written before the next batch is computed, so 10⁷ angles × many curves
//! run in constant memory.

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::model::curve::Curve;
use crate::model::grid::linspace_at;
use crate::output::csv::Table;
use crate::spec::angle::AngleUnit;
use crate::spec::scene::MAX_INTEGRALS;

/// Largest θ count of a `start:stop:count` list (docs/contracts.md).
pub const MAX_THETA_COUNT: u64 = 10_000_000;

/// Values (θ and curve values) computed and formatted per batch before it is written: with about
/// 20 bytes a value, a batch holds some 5 MB of text whatever the number of rows or curves.
const BATCH_VALUES: usize = 1 << 18;
/// Rows a worker formats at a time within a batch.
const PIECE_ROWS: usize = 1024;

/// One angle of a θ list: the value as given (radians or degrees) and θ in radians.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Angle {
    /// The value in the unit it was given in, as printed in the θ column.
    pub given: f64,
    /// θ in radians, where the curves are evaluated.
    pub radians: f64,
}

/// The angles of `--theta`, in order: listed one by one, or `count` evenly spaced ones produced on
/// demand (so that 10⁷ of them take no memory).
#[derive(Debug, Clone, PartialEq)]
pub enum ThetaList {
    /// A comma list, each angle checked.
    Listed(Vec<Angle>),
    /// numpy's `linspace(start, stop, count)` in `unit`, both ends checked (the values between lie
    /// between them).
    Spaced {
        /// First value, in `unit`.
        start: f64,
        /// Last value, in `unit`.
        stop: f64,
        /// Number of values, 1 to [`MAX_THETA_COUNT`].
        count: usize,
        /// Unit the ends were given in.
        unit: AngleUnit,
    },
}

impl ThetaList {
    /// Number of angles.
    pub fn len(&self) -> usize {
        match self {
            ThetaList::Listed(angles) => angles.len(),
            ThetaList::Spaced { count, .. } => *count,
        }
    }

    /// Whether there are no angles (never, for a parsed list).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The `i`-th angle; `i` < [`ThetaList::len`].
    pub fn get(&self, i: usize) -> Angle {
        match self {
            ThetaList::Listed(angles) => angles[i],
            &ThetaList::Spaced {
                start,
                stop,
                count,
                unit,
            } => {
                let given = linspace_at(start, stop, count, i);
                Angle {
                    given,
                    radians: unit.to_radians(given),
                }
            }
        }
    }
}

/// Parses a θ list: comma-separated numbers or `start:stop:count` (numpy linspace, taken in the unit
/// given), in `unit` (radians may be multiples of π, [`crate::spec::angle::pi_multiple`]; degrees are
/// converted as θ = d·π/180). Every θ must lie in [0, π/2].
pub fn parse_theta_list(text: &str, unit: AngleUnit) -> Result<ThetaList> {
    let bad = |what: String| Error::Usage(format!("--theta: {what}"));
    let number = |s: &str| unit.parse(s).map_err(bad);
    let angle = |given: f64| {
        let radians = unit.check(given).map_err(bad)?;
        Ok(Angle { given, radians })
    };
    if !text.contains(':') {
        let items: Vec<&str> = text.split(',').collect();
        if items.len() as u64 > MAX_THETA_COUNT {
            return Err(bad(format!("more than {MAX_THETA_COUNT} values")));
        }
        return items
            .into_iter()
            .map(|item| angle(number(item)?))
            .collect::<Result<_>>()
            .map(ThetaList::Listed);
    }
    if text.contains(',') {
        return Err(bad(format!(
            "use either a comma list or start:stop:count, not both (got \"{}\")",
            crate::problem::excerpt(text)
        )));
    }
    let parts: Vec<&str> = text.split(':').collect();
    let [start, stop, count] = parts[..] else {
        return Err(bad(format!(
            "expected start:stop:count (got \"{}\")",
            crate::problem::excerpt(text)
        )));
    };
    let count: u64 = count.trim().parse().map_err(|_| {
        bad(format!(
            "count must be a whole number from 1 to {MAX_THETA_COUNT} (got \"{}\")",
            crate::problem::excerpt(count.trim())
        ))
    })?;
    if !(1..=MAX_THETA_COUNT).contains(&count) {
        return Err(bad(format!(
            "count must be from 1 to {MAX_THETA_COUNT} (got {count})"
        )));
    }
    let (start, stop) = (number(start)?, number(stop)?);
    angle(start)?;
    angle(stop)?;
    Ok(ThetaList::Spaced {
        start,
        stop,
        count: count as usize,
        unit,
    })
}

/// The angles of `eval --theta @FILE`: `text` (read from `name`) holds one angle per line in the
/// syntax of a `--theta` item; blank lines and lines starting with `#` are skipped. A bad line is
/// named by its number, the file by its whole name (control characters escaped).
pub fn parse_theta_file(text: &str, name: &str, unit: AngleUnit) -> Result<ThetaList> {
    let shown = crate::problem::one_line(name);
    let mut angles = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let item = line.trim();
        if item.is_empty() || item.starts_with('#') {
            continue;
        }
        if angles.len() as u64 >= MAX_THETA_COUNT {
            return Err(Error::Usage(format!(
                "--theta: {shown}: more than {MAX_THETA_COUNT} values"
            )));
        }
        let at = |e: Error| match e {
            Error::Usage(message) => Error::Usage(message.replacen(
                "--theta:",
                &format!("--theta: {shown}:{}:", i + 1),
                1,
            )),
            other => other,
        };
        if item.contains([',', ':']) {
            return Err(at(Error::Usage(format!(
                "--theta: one angle per line (got \"{}\")",
                crate::problem::excerpt(item)
            ))));
        }
        match parse_theta_list(item, unit).map_err(at)? {
            ThetaList::Listed(one) => angles.extend(one),
            ThetaList::Spaced { .. } => unreachable!("a line without ':' is a list"),
        }
    }
    if angles.is_empty() {
        return Err(Error::Usage(format!(
            "--theta: {shown}: no angle (expected one per line)"
        )));
    }
    Ok(ThetaList::Listed(angles))
}

/// The angles of `eval --theta @FILE --theta-column NAME`: `text` (read from `name`) is CSV with a
/// header row, and every cell of the column `column` is an angle in the syntax of a `--theta` item.
/// A missing column names the columns there are; a bad cell is named by its line; the file by its
/// whole name (control characters escaped).
pub fn parse_theta_column(
    text: &str,
    name: &str,
    column: &str,
    unit: AngleUnit,
) -> Result<ThetaList> {
    let shown = crate::problem::one_line(name);
    let bad = |what: String| Error::Usage(format!("--theta-column: {shown}: {what}"));
    let mut reader = csv::ReaderBuilder::new()
        .trim(csv::Trim::All)
        .comment(Some(b'#'))
        .from_reader(text.as_bytes());
    let headers = reader
        .headers()
        .map_err(|e| bad(format!("not CSV ({e})")))?
        .clone();
    let Some(index) = headers.iter().position(|h| h == column) else {
        let names: Vec<&str> = headers.iter().collect();
        return Err(bad(format!(
            "no column \"{}\" (expected one of: {}){}",
            crate::problem::excerpt(column),
            names.join(", "),
            crate::problem::suggestion(column, names.iter().copied())
        )));
    };
    let mut angles = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| bad(format!("not CSV ({e})")))?;
        let line = record.position().map_or(0, |p| p.line());
        let cell = record.get(index).unwrap_or_default();
        if cell.is_empty() || cell.contains([',', ':']) {
            return Err(bad(format!(
                "line {line}: not one angle (got \"{}\")",
                crate::problem::excerpt(cell)
            )));
        }
        if angles.len() as u64 >= MAX_THETA_COUNT {
            return Err(bad(format!("more than {MAX_THETA_COUNT} values")));
        }
        match parse_theta_list(cell, unit) {
            Ok(ThetaList::Listed(one)) => angles.extend(one),
            Ok(ThetaList::Spaced { .. }) => unreachable!("a cell without ':' is a list"),
            Err(Error::Usage(message)) => {
                let why = message.strip_prefix("--theta: ").unwrap_or(&message);
                return Err(bad(format!("line {line}: {why}")));
            }
            Err(other) => return Err(other),
        }
    }
    if angles.is_empty() {
        return Err(bad("no angle (expected one per row)".into()));
    }
    Ok(ThetaList::Listed(angles))
}

/// The integrals (albedo values) a table of `curves` at `thetas` computes, refused past
/// [`MAX_INTEGRALS`] before any is computed.
pub fn check_integrals(curves: &[Curve], thetas: &ThetaList) -> Result<()> {
    let per_theta: usize = curves.iter().map(Curve::integrals_per_value).sum();
    let total = per_theta.saturating_mul(thetas.len());
    if total > MAX_INTEGRALS {
        return Err(crate::error::Error::Usage(format!(
            "--theta: too much integration (got {} angles × {per_theta} albedo curves = {total} integrals, expected at most {MAX_INTEGRALS})",
            thetas.len()
        )));
    }
    Ok(())
}

/// Writes the CSV table through `sink`: `theta,value` for one curve, else
/// `theta,<canonical curve JSON>…`; one row per θ in input order, numbers in shortest round-trip
/// form. The θ column holds the angles as given, in `unit`, and is named `theta` for radians,
/// `theta_deg` for degrees.
///
/// Rows go to `sink` a batch at a time as they are computed; when `sink` returns `Ok(false)` (the
/// reader has gone) nothing more is computed. A curve that gives a non-finite value is an error
/// naming it and θ; the rows of the batches before it have been written.
pub fn write_table(
    curves: &[Curve],
    thetas: &ThetaList,
    unit: AngleUnit,
    sink: &mut dyn FnMut(&[u8]) -> Result<bool>,
) -> Result<()> {
    let theta_name = unit.name("theta");
    let header: Vec<String> = if let [_] = curves {
        vec![theta_name, "value".into()]
    } else {
        std::iter::once(theta_name)
            .chain(curves.iter().map(Curve::canonical_json))
            .collect()
    };
    if !sink(&Table::new(header, 0).into_bytes())? {
        return Ok(());
    }
    let batch_rows = (BATCH_VALUES / (curves.len() + 1)).max(1);
    let mut first = 0;
    while first < thetas.len() {
        let last = (first + batch_rows).min(thetas.len());
        let pieces: Vec<Vec<u8>> = (first..last)
            .step_by(PIECE_ROWS)
            .collect::<Vec<_>>()
            .into_par_iter()
            .map(|from| rows(curves, thetas, from..(from + PIECE_ROWS).min(last)))
            .collect::<Result<_>>()?;
        for piece in pieces {
            if !sink(&piece)? {
                return Ok(());
            }
        }
        first = last;
    }
    Ok(())
}

/// The CSV rows (no header) of the angles `range` of `thetas`: each curve evaluated over the range in
/// one block ([`Curve::eval_many`], the bits of `Curve::eval`), then the rows written in order.
fn rows(curves: &[Curve], thetas: &ThetaList, range: std::ops::Range<usize>) -> Result<Vec<u8>> {
    let angles: Vec<Angle> = range.map(|i| thetas.get(i)).collect();
    let radians: Vec<f64> = angles.iter().map(|a| a.radians).collect();
    let mut values = vec![0.0; radians.len() * curves.len()];
    for (curve, column) in curves
        .iter()
        .zip(values.chunks_exact_mut(radians.len().max(1)))
    {
        curve.eval_many(&radians, column);
    }
    let mut table = Table::rows(angles.len() * 24 * (curves.len() + 1));
    for (row, angle) in angles.iter().enumerate() {
        table.number(angle.given);
        for (c, curve) in curves.iter().enumerate() {
            let value = values[c * angles.len() + row];
            if !value.is_finite() {
                return Err(Error::Numerics(format!(
                    "{} gave a non-finite value at theta = {:?}",
                    curve.canonical_json(),
                    angle.radians
                )));
            }
            table.number(value);
        }
        table.end_row();
    }
    Ok(table.into_bytes())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::grid::linspace;
    use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

    fn radians(text: &str, unit: AngleUnit) -> Result<Vec<f64>> {
        parse_theta_list(text, unit)
            .map(|list| (0..list.len()).map(|i| list.get(i).radians).collect())
    }

    fn curves(texts: &[&str]) -> Vec<Curve> {
        texts
            .iter()
            .map(|text| {
                let spec = crate::spec::curve::parse(&crate::spec::json::parse(text).unwrap(), "")
                    .unwrap();
                crate::pipeline::resolve::curve(&spec).unwrap()
            })
            .collect()
    }

    fn table(curves: &[Curve], thetas: &ThetaList, unit: AngleUnit) -> String {
        let mut bytes = Vec::new();
        write_table(curves, thetas, unit, &mut |b| {
            bytes.extend_from_slice(b);
            Ok(true)
        })
        .unwrap();
        String::from_utf8(bytes).unwrap()
    }

    #[test]
    fn theta_lists() {
        let rad = AngleUnit::Radians;
        assert_eq!(
            radians("0,0.1, 1.5707963267948966", rad).unwrap(),
            [0.0, 0.1, FRAC_PI_2]
        );
        assert_eq!(
            radians("0,pi/4,pi/2", rad).unwrap(),
            [0.0, FRAC_PI_4, FRAC_PI_2]
        );
        assert_eq!(
            radians("0:pi/2:3", rad).unwrap(),
            [0.0, FRAC_PI_4, FRAC_PI_2]
        );
        assert!(radians("pi", rad).is_err());
        let degrees = parse_theta_list("0:90:3", AngleUnit::Degrees).unwrap();
        assert_eq!(
            (0..3)
                .map(|i| (degrees.get(i).given, degrees.get(i).radians))
                .collect::<Vec<_>>(),
            [(0.0, 0.0), (45.0, FRAC_PI_4), (90.0, FRAC_PI_2)]
        );
        assert!(radians("pi/4", AngleUnit::Degrees).is_err());
        for bad in [
            "abc",
            "0:1:0",
            "nan",
            "0:1:100000000000000",
            "0:1",
            "0,1:2:3",
            "-0.1",
            "1.6",
            "0:1.6:3",
            "",
            "inf",
        ] {
            assert!(radians(bad, rad).is_err(), "{bad}");
        }
    }

    #[test]
    fn spaced_lists_are_numpy_linspace_without_being_stored() {
        let list = parse_theta_list("0.1:pi/2:10000000", AngleUnit::Radians).unwrap();
        assert!(matches!(
            list,
            ThetaList::Spaced {
                count: 10_000_000,
                ..
            }
        ));
        let small = parse_theta_list("0.1:1.5:7", AngleUnit::Radians).unwrap();
        let stored = linspace(0.1, 1.5, 7);
        assert!((0..7).all(|i| small.get(i).given == stored[i]));
    }

    #[test]
    fn several_curves_are_named_by_their_quoted_canonical_json() {
        let curves = curves(&[
            r#"{"ndf":"phong","alpha_p":1}"#,
            r#"{"fresnel":"schlick","f0":0.04}"#,
        ]);
        let zero = ThetaList::Listed(vec![Angle {
            given: 0.0,
            radians: 0.0,
        }]);
        assert_eq!(
            table(&curves, &zero, AngleUnit::Radians),
            "theta,\"{\"\"ndf\"\":\"\"phong\"\",\"\"alpha_p\"\":1.0}\",\"{\"\"fresnel\"\":\"\"schlick\"\",\"\"f0\"\":0.04}\"\n\
             0.0,0.477464829275686,0.04\n"
        );
        assert!(table(&curves[..1], &zero, AngleUnit::Degrees).starts_with("theta_deg,value\n"));
    }

    #[test]
    fn streamed_rows_are_every_angle_in_order_across_batches_and_pieces() {
        // One curve: batches of many pieces; 300 curves: batches of less than a piece. Both end
        // in a partial batch.
        let beckmanns: Vec<String> = (1..=300)
            .map(|i| format!(r#"{{"ndf":"beckmann","alpha_b":{}}}"#, f64::from(i) / 100.0))
            .collect();
        let many = curves(&beckmanns.iter().map(String::as_str).collect::<Vec<_>>());
        for curves in [&many[..1], &many[..]] {
            let count = 2 * (BATCH_VALUES / (curves.len() + 1)) + 7;
            let thetas = parse_theta_list(&format!("0:pi/2:{count}"), AngleUnit::Radians).unwrap();
            let grid = linspace(0.0, FRAC_PI_2, count);
            let text = table(curves, &thetas, AngleUnit::Radians);
            let rows: Vec<&str> = text.lines().skip(1).collect();
            assert_eq!(rows.len(), count);
            for (row, &theta) in rows.iter().zip(&grid) {
                let fields: Vec<f64> = row.split(',').map(|f| f.parse().unwrap()).collect();
                assert_eq!(fields[0], theta);
                assert!(
                    fields[1..]
                        .iter()
                        .zip(curves)
                        .all(|(&v, c)| v == c.eval(theta))
                );
            }
        }
    }

    #[test]
    fn a_sink_that_stops_stops_the_computation() {
        let curves = curves(&[r#"{"ndf":"phong","alpha_p":1}"#]);
        let thetas = parse_theta_list("0:pi/2:10000000", AngleUnit::Radians).unwrap();
        let mut calls = 0;
        write_table(&curves, &thetas, AngleUnit::Radians, &mut |_| {
            calls += 1;
            Ok(calls < 2)
        })
        .unwrap();
        assert_eq!(calls, 2, "the header, then one piece");
    }
}
