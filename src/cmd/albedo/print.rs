//! The text of one `ndfplot albedo` run: its tables in the long or the matrix shape, as CSV (with
//! or without the `#` metadata lines) or as JSON.
//!
//! - CSV, long: one row per (μ, r) cell (per r for the average). Several tables share one header
//!   led by a `table` column, the union of their columns after it, empty where a table has none.
//! - CSV, matrix: per value (`E`, `turquin_f0_1`, …) a block whose header is the value's name and
//!   the r values, then one row per μ led by μ; the average's block is a header `r` and the r
//!   values, then one row per value led by its name. Blocks are separated by an empty line.
//! - The `#` lines: each metadata key once where every table has the same value, else once per
//!   table as `# key (table): value`; `# table:` lists the tables.
//! - JSON: one object per table (metadata, then `columns` and `rows`, or `mu`, `r` and `values`
//!   holding each value's matrix); several tables are one object keyed by table name.

use serde::ser::{Serialize, SerializeMap, Serializer};

use super::Output;
use crate::output::report::{Cell, Report, ReportFormat, TableShape};

/// The text of `outputs` (at least one) in `format` and `shape`; `comments` keeps the CSV's `#`
/// metadata lines (JSON always carries the metadata).
pub fn text(outputs: &[Output], format: ReportFormat, shape: TableShape, comments: bool) -> String {
    match format {
        ReportFormat::Json => match outputs {
            [one] => crate::spec::json::to_string(&Json(one, shape)) + "\n",
            _ => crate::spec::json::to_string(&Keyed(outputs, shape)) + "\n",
        },
        ReportFormat::Csv | ReportFormat::Table => {
            let mut text = if comments {
                metadata_lines(outputs)
            } else {
                String::new()
            };
            text.push_str(&match shape {
                TableShape::Long => long(outputs).csv(),
                TableShape::Matrix => outputs
                    .iter()
                    .flat_map(matrices)
                    .map(|block| block.csv())
                    .collect::<Vec<_>>()
                    .join("\n"),
            });
            text
        }
    }
}

/// The `# key: value` lines of `outputs`: a key whose value every table shares once, others once
/// per table that has it (`# key (table): value`), `table` as the list of names.
fn metadata_lines(outputs: &[Output]) -> String {
    let mut keys: Vec<&str> = Vec::new();
    for (key, _) in outputs.iter().flat_map(|o| &o.metadata) {
        if !keys.contains(key) {
            keys.push(key);
        }
    }
    let mut text = String::new();
    for key in keys {
        let values: Vec<(&str, String)> = outputs
            .iter()
            .filter_map(|o| {
                let (_, value) = o.metadata.iter().find(|(k, _)| *k == key)?;
                Some((o.name(), value.to_string()))
            })
            .collect();
        let shared = values.len() == outputs.len() && values.iter().all(|(_, v)| *v == values[0].1);
        if key == "table" {
            let names: Vec<&str> = outputs.iter().map(Output::name).collect();
            text.push_str(&format!("# table: {}\n", names.join(",")));
        } else if shared {
            text.push_str(&format!("# {key}: {}\n", values[0].1));
        } else {
            for (table, value) in values {
                text.push_str(&format!("# {key} ({table}): {value}\n"));
            }
        }
    }
    text
}

/// The long shape: one table's report as it is; several under a leading `table` column and the
/// union of their columns, in order of first appearance.
fn long(outputs: &[Output]) -> Report {
    if let [one] = outputs {
        return one.report.clone();
    }
    let mut columns: Vec<&str> = Vec::new();
    for name in outputs.iter().flat_map(|o| o.report.columns()) {
        if !columns.contains(&name.as_str()) {
            columns.push(name);
        }
    }
    let mut report = Report::new(std::iter::once("table").chain(columns.iter().copied()));
    for output in outputs {
        let own = output.report.columns();
        for row in output.report.rows() {
            let mut cells = vec![Cell::Text(output.name().to_string())];
            cells.extend(columns.iter().map(|name| {
                own.iter()
                    .position(|c| c == name)
                    .map_or(Cell::Missing, |k| row[k].clone())
            }));
            report.push(cells);
        }
    }
    report
}

/// The matrix blocks of `output`: per value column, rows μ and columns r (header: the value's
/// name, then r); for the average, one block of a row per value (header: `r`, then r).
fn matrices(output: &Output) -> Vec<Report> {
    let header = |first: &str| {
        std::iter::once(first.to_string())
            .chain(output.roughness.iter().map(|r| format!("{r:?}")))
            .collect::<Vec<_>>()
    };
    let values = &output.report.columns()[output.axis_columns()..];
    let rows = output.report.rows();
    match &output.mu {
        Some(mu) => values
            .iter()
            .enumerate()
            .map(|(k, name)| {
                let k = k + output.axis_columns();
                let mut block = Report::new(header(name));
                for (&mu, cells) in mu.iter().zip(rows.chunks(output.roughness.len())) {
                    block.push(
                        std::iter::once(Cell::Number(mu))
                            .chain(cells.iter().map(|row| row[k].clone()))
                            .collect(),
                    );
                }
                block
            })
            .collect(),
        None => {
            let mut block = Report::new(header("r"));
            for (k, name) in values.iter().enumerate() {
                let k = k + output.axis_columns();
                block.push(
                    std::iter::once(Cell::Text(name.clone()))
                        .chain(rows.iter().map(|row| row[k].clone()))
                        .collect(),
                );
            }
            vec![block]
        }
    }
}

/// One table as a JSON object: its metadata, then `columns` and `rows` (long) or `mu` (tables with
/// a μ axis), `r` and `values` (matrix).
struct Json<'a>(&'a Output, TableShape);

impl Serialize for Json<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        let Json(output, shape) = *self;
        let mut map = serializer.serialize_map(None)?;
        for (key, value) in &output.metadata {
            map.serialize_entry(key, value)?;
        }
        match shape {
            TableShape::Long => {
                map.serialize_entry("columns", output.report.columns())?;
                map.serialize_entry("rows", output.report.rows())?;
            }
            TableShape::Matrix => {
                if let Some(mu) = &output.mu {
                    map.serialize_entry("mu", mu)?;
                }
                map.serialize_entry("r", &output.roughness)?;
                map.serialize_entry("values", &Values(output))?;
            }
        }
        map.end()
    }
}

/// Each value of a table by name: a matrix (an array per μ of the values per r) or, for the
/// average, the array of values per r.
struct Values<'a>(&'a Output);

impl Serialize for Values<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        let output = self.0;
        let first = output.axis_columns();
        let n_r = output.roughness.len();
        let rows = output.report.rows();
        let mut map = serializer.serialize_map(None)?;
        for (k, name) in output.report.columns().iter().enumerate().skip(first) {
            let column = |cells: &[Vec<Cell>]| -> Vec<Cell> {
                cells.iter().map(|row| row[k].clone()).collect()
            };
            match output.mu {
                Some(_) => {
                    let matrix: Vec<Vec<Cell>> = rows.chunks(n_r).map(column).collect();
                    map.serialize_entry(name, &matrix)?;
                }
                None => map.serialize_entry(name, &column(rows))?,
            }
        }
        map.end()
    }
}

/// Several tables as one JSON object keyed by table name.
struct Keyed<'a>(&'a [Output], TableShape);

impl Serialize for Keyed<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        for output in self.0 {
            map.serialize_entry(output.name(), &Json(output, self.1))?;
        }
        map.end()
    }
}

/// What a run wrote, for its closing line: `albedo: wrote e (32 × 32) and average (32) to ggx.csv`.
pub fn summary(outputs: &[Output], place: &str) -> String {
    let tables: Vec<String> = outputs
        .iter()
        .map(|o| format!("{} ({})", o.name(), o.size()))
        .collect();
    let list = match tables.split_last() {
        Some((last, [])) => last.clone(),
        Some((last, rest)) => format!("{} and {last}", rest.join(", ")),
        None => String::new(),
    };
    format!("albedo: wrote {list} to {place}")
}
