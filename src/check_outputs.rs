//! `render --check DIR`: compares the figure CSVs a render would write with those already in a
//! folder, at a relative tolerance, and lists every figure and curve that differs and by how much.
//!
//! Only CSVs are compared (CONTRACTS.md: across machines they agree to 1e-12 relative; PNG bytes
//! may not). This module reads the folder and never writes anything.

use crate::error::{Error, Result};
use crate::math::tolerance::relative_difference;
use std::collections::BTreeMap;
use std::path::Path;

/// Default `--tolerance`: the cross-machine agreement CONTRACTS.md promises for figure CSVs.
pub const DEFAULT_TOLERANCE: f64 = 1e-12;

/// One series of a figure CSV: its `curve` column and its numeric columns (`x`, `y`, and `z`
/// when present), row by row.
#[derive(Debug, Default)]
struct SeriesRows {
    curve: String,
    rows: Vec<Vec<String>>,
}

/// A parsed figure CSV: the header and the series keyed by (panel, series) in file order.
struct Table {
    header: Vec<String>,
    series: BTreeMap<(u64, u64), SeriesRows>,
}

fn parse_table(bytes: &[u8]) -> std::result::Result<Table, String> {
    let mut reader = csv::ReaderBuilder::new().flexible(true).from_reader(bytes);
    let header: Vec<String> = reader
        .headers()
        .map_err(|e| e.to_string())?
        .iter()
        .map(str::to_string)
        .collect();
    if header.len() < 5 || header[..3] != ["panel", "series", "curve"] {
        return Err(format!(
            "not a figure CSV (got header \"{}\", expected panel,series,curve,x,y[,z])",
            header.join(",")
        ));
    }
    let mut series: BTreeMap<(u64, u64), SeriesRows> = BTreeMap::new();
    for (i, record) in reader.records().enumerate() {
        let record = record.map_err(|e| e.to_string())?;
        let row = i + 2;
        if record.len() != header.len() {
            return Err(format!(
                "row {row}: {} fields (expected {})",
                record.len(),
                header.len()
            ));
        }
        let index = |k: usize| {
            record[k].parse::<u64>().map_err(|_| {
                format!(
                    "row {row}: {} is not an index (got \"{}\")",
                    header[k], &record[k]
                )
            })
        };
        let entry = series.entry((index(0)?, index(1)?)).or_default();
        if entry.rows.is_empty() {
            entry.curve = record[2].to_string();
        }
        entry
            .rows
            .push(record.iter().skip(3).map(str::to_string).collect());
    }
    Ok(Table { header, series })
}

/// The largest relative difference found in one series, where, and how many rows differ.
struct Worst {
    relative: f64,
    column: String,
    x: String,
    rendered: String,
    stored: String,
    rows_differing: usize,
}

/// Compares one series; `None` when every value is within `tolerance`.
fn compare_rows(
    header: &[String],
    rendered: &SeriesRows,
    stored: &SeriesRows,
    tolerance: f64,
) -> Option<Worst> {
    let mut worst: Option<Worst> = None;
    let mut rows_differing = 0;
    for (a, b) in rendered.rows.iter().zip(&stored.rows) {
        let mut row_differs = false;
        for (k, (va, vb)) in a.iter().zip(b).enumerate() {
            let relative = match (va.parse::<f64>(), vb.parse::<f64>()) {
                _ if va == vb => 0.0,
                (Ok(x), Ok(y)) if x.is_finite() && y.is_finite() => relative_difference(x, y),
                _ => f64::INFINITY,
            };
            if relative > tolerance {
                row_differs = true;
                if worst.as_ref().is_none_or(|w| relative > w.relative) {
                    worst = Some(Worst {
                        relative,
                        column: header[3 + k].clone(),
                        x: a[0].clone(),
                        rendered: va.clone(),
                        stored: vb.clone(),
                        rows_differing: 0,
                    });
                }
            }
        }
        rows_differing += usize::from(row_differs);
    }
    worst.map(|w| Worst {
        rows_differing,
        ..w
    })
}

/// Every difference between the figure CSV `rendered` and the stored `stored` of the file `name`,
/// one line each, naming the panel, the series and its curve.
fn compare_tables(name: &str, rendered: &Table, stored: &Table, tolerance: f64) -> Vec<String> {
    if rendered.header != stored.header {
        return vec![format!(
            "{name}: header differs (rendered {}, stored {})",
            rendered.header.join(","),
            stored.header.join(",")
        )];
    }
    let mut lines = Vec::new();
    let keys: std::collections::BTreeSet<&(u64, u64)> =
        rendered.series.keys().chain(stored.series.keys()).collect();
    for key @ (panel, series) in keys {
        let at = format!("{name}: panel {panel}, series {series}");
        match (rendered.series.get(key), stored.series.get(key)) {
            (Some(a), None) => lines.push(format!(
                "{at} {}: missing from the stored CSV ({} rows)",
                a.curve,
                a.rows.len()
            )),
            (None, Some(b)) => lines.push(format!(
                "{at} {}: extra in the stored CSV ({} rows)",
                b.curve,
                b.rows.len()
            )),
            (Some(a), Some(b)) if a.curve != b.curve => {
                lines.push(format!(
                    "{at}: curve differs (rendered {}, stored {})",
                    a.curve, b.curve
                ));
            }
            (Some(a), Some(b)) => {
                if a.rows.len() != b.rows.len() {
                    lines.push(format!(
                        "{at} {}: {} rows rendered, {} stored",
                        a.curve,
                        a.rows.len(),
                        b.rows.len()
                    ));
                }
                if let Some(w) = compare_rows(&rendered.header, a, b, tolerance) {
                    lines.push(format!(
                        "{at} {}: {} differs by {:.3e} relative at x = {} (rendered {}, stored {}; {} of {} rows differ)",
                        a.curve,
                        w.column,
                        w.relative,
                        w.x,
                        w.rendered,
                        w.stored,
                        w.rows_differing,
                        a.rows.len().min(b.rows.len())
                    ));
                }
            }
            (None, None) => unreachable!("the key comes from one of the two tables"),
        }
    }
    lines
}

/// Compares `rendered`, the (file name, bytes) of every figure CSV of a run, with the CSVs in
/// `dir`: a file missing from `dir`, a non-hidden `*.csv` in `dir` that the run does not produce,
/// and every series whose values differ by more than `tolerance` relative are listed. Returns the
/// report (one line per difference, then a summary) and whether everything matched.
pub fn compare(
    dir: &Path,
    rendered: &[(String, Vec<u8>)],
    tolerance: f64,
) -> Result<(String, bool)> {
    let shown = dir.display().to_string();
    let entries = std::fs::read_dir(dir).map_err(|e| Error::io(&shown, e))?;
    let mut stored_names = Vec::new();
    for entry in entries {
        let name = entry
            .map_err(|e| Error::io(&shown, e))?
            .file_name()
            .to_string_lossy()
            .into_owned();
        if name.ends_with(".csv") && !name.starts_with('.') {
            stored_names.push(name);
        }
    }
    stored_names.sort();
    let mut lines = Vec::new();
    let mut differing = 0;
    for (name, bytes) in rendered {
        let path = dir.join(name);
        let before = lines.len();
        if !stored_names.contains(name) {
            lines.push(format!("{name}: missing from {shown}"));
        } else {
            let stored =
                std::fs::read(&path).map_err(|e| Error::io(path.display().to_string(), e))?;
            match (parse_table(bytes), parse_table(&stored)) {
                (Ok(a), Ok(b)) => lines.extend(compare_tables(name, &a, &b, tolerance)),
                (_, Err(message)) => {
                    lines.push(format!("{name}: stored CSV unreadable: {message}"))
                }
                (Err(message), _) => {
                    return Err(Error::Numerics(format!(
                        "{name}: rendered CSV unreadable: {message}"
                    )));
                }
            }
        }
        differing += usize::from(lines.len() > before);
    }
    for name in stored_names
        .iter()
        .filter(|n| !rendered.iter().any(|(r, _)| r == *n))
    {
        lines.push(format!(
            "{name}: extra in {shown} (no scene of this run writes it)"
        ));
        differing += 1;
    }
    let total = rendered.len();
    let ok = lines.is_empty();
    lines.push(if ok {
        format!("render --check: all {total} CSVs match {shown} within {tolerance:e} relative")
    } else {
        format!("render --check: {differing} CSVs differ from {shown} beyond {tolerance:e} relative ({total} rendered)")
    });
    Ok((lines.join("\n") + "\n", ok))
}

#[cfg(test)]
mod tests {
    use super::*;

    const CSV: &str = "panel,series,curve,x,y\n0,0,A,0.0,1.0\n0,0,A,0.5,2.0\n0,1,B,0.0,3.0\n";

    fn diff(a: &str, b: &str, tolerance: f64) -> Vec<String> {
        let (a, b) = (
            parse_table(a.as_bytes()).unwrap(),
            parse_table(b.as_bytes()).unwrap(),
        );
        compare_tables("f.csv", &a, &b, tolerance)
    }

    #[test]
    fn equal_tables_match_and_small_changes_are_caught() {
        assert!(diff(CSV, CSV, 0.0).is_empty());
        let changed = CSV.replace("0.5,2.0", "0.5,2.000000002");
        assert!(diff(&changed, CSV, 1e-8).is_empty());
        let lines = diff(&changed, CSV, 1e-12);
        assert_eq!(lines.len(), 1, "{lines:?}");
        assert!(
            lines[0].starts_with(
                "f.csv: panel 0, series 0 A: y differs by 1.000e-9 relative at x = 0.5"
            ),
            "{lines:?}"
        );
        assert!(lines[0].contains("1 of 2 rows differ"), "{lines:?}");
    }

    #[test]
    fn missing_extra_and_renamed_series_are_listed() {
        let lines = diff(CSV, "panel,series,curve,x,y\n0,0,A,0.0,1.0\n", 1e-12);
        assert!(
            lines
                .iter()
                .any(|l| l.contains("2 rows rendered, 1 stored")),
            "{lines:?}"
        );
        assert!(
            lines
                .iter()
                .any(|l| l.contains("series 1 B: missing from the stored CSV")),
            "{lines:?}"
        );
        let lines = diff(CSV, &CSV.replace(",B,", ",C,"), 1e-12);
        assert_eq!(
            lines,
            ["f.csv: panel 0, series 1: curve differs (rendered B, stored C)"]
        );
        let lines = diff(CSV, &CSV.replace("3.0", "x"), 1e-12);
        assert!(lines[0].contains("stored x"), "{lines:?}");
    }
}
