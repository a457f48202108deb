//! The reports of the commands that print tables (`compare`, `check`, `coeffs`) in the machine-readable
//! forms of `--format`: one JSON object per line, a JSON array of row objects, or CSV with a header row. A
//! [`Report`] is named columns and rows of [`Cell`]s; numbers are written in the shortest round-trip
//! form of docs/contracts.md in every form.
//!
//! Pure serialization into memory: the commands decide what the cells hold; the readable tables are
//! theirs.

use super::csv::Table;
use crate::model::names::named;
use serde::ser::{Serialize, SerializeMap, SerializeSeq, Serializer};
use serde_json::value::RawValue;

named! {
    /// The forms of a command's report, as `--format` names them; each command offers those it has
    /// (`coeffs` and `albedo` no readable table).
    pub enum ReportFormat {
        /// The readable table the command prints.
        Table = "table",
        /// JSON: an array of row objects, or one object per line where the command streams.
        Json = "json",
        /// CSV with a header row.
        Csv = "csv",
    }
}

named! {
    /// The record formats of `fit --format`: one record per target.
    pub enum RecordFormat {
        /// One JSON object per line.
        Jsonl = "jsonl",
        /// CSV with a header row.
        Csv = "csv",
    }
}

named! {
    /// The layouts of a grid table (`albedo --shape`): one row per cell, or a matrix with a row
    /// per μ and a column per r.
    pub enum TableShape {
        /// One row per cell, the axes' coordinates in its first columns.
        Long = "long",
        /// Rows by the first axis, one column per value of the second.
        Matrix = "matrix",
    }
}

/// One cell of a report.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// A number (JSON number; CSV shortest round-trip form).
    Number(f64),
    /// A count or a line number (JSON integer; CSV digits).
    Count(usize),
    /// A value that does not exist (JSON `null`; CSV empty field): an undefined metric.
    Missing,
    /// Text (JSON string; CSV field).
    Text(String),
    /// JSON text such as a canonical curve, embedded as JSON in JSON and as its text in CSV.
    Json(String),
}

impl Serialize for Cell {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            Cell::Number(v) => serializer.serialize_f64(*v),
            Cell::Count(n) => serializer.serialize_u64(*n as u64),
            Cell::Missing => serializer.serialize_none(),
            Cell::Text(text) => serializer.serialize_str(text),
            Cell::Json(text) => match serde_json::from_str::<&RawValue>(text) {
                Ok(raw) => raw.serialize(serializer),
                Err(_) => serializer.serialize_str(text),
            },
        }
    }
}

/// A table of named columns; every row has one cell per column.
#[derive(Debug, Clone, PartialEq)]
pub struct Report {
    columns: Vec<String>,
    rows: Vec<Vec<Cell>>,
}

/// One row as a JSON object: column name → cell, in column order.
struct Row<'a>(&'a [String], &'a [Cell]);

impl Serialize for Row<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut map = serializer.serialize_map(Some(self.0.len()))?;
        for (name, cell) in self.0.iter().zip(self.1) {
            map.serialize_entry(name, cell)?;
        }
        map.end()
    }
}

/// Every row as JSON objects in a JSON array.
struct Rows<'a>(&'a Report);

impl Serialize for Rows<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(Some(self.0.rows.len()))?;
        for row in &self.0.rows {
            seq.serialize_element(&Row(&self.0.columns, row))?;
        }
        seq.end()
    }
}

impl Report {
    /// An empty report with these column names.
    pub fn new(columns: impl IntoIterator<Item = impl Into<String>>) -> Report {
        Report {
            columns: columns.into_iter().map(Into::into).collect(),
            rows: Vec::new(),
        }
    }

    /// Appends a row; cells beyond the columns are dropped and missing ones are [`Cell::Missing`].
    pub fn push(&mut self, mut row: Vec<Cell>) {
        row.resize(self.columns.len(), Cell::Missing);
        self.rows.push(row);
    }

    /// The column names, in order.
    pub fn columns(&self) -> &[String] {
        &self.columns
    }

    /// The rows, each with one cell per column.
    pub fn rows(&self) -> &[Vec<Cell>] {
        &self.rows
    }

    /// Every row as one compact JSON object and a newline (JSON Lines): `{"<column>": <cell>, …}`.
    pub fn json_lines(&self) -> String {
        self.rows
            .iter()
            .map(|row| crate::spec::json::to_string(&Row(&self.columns, row)) + "\n")
            .collect()
    }

    /// Every row as an object of a compact JSON array, and a newline: `[{"<column>": <cell>, …}, …]`.
    pub fn json_array(&self) -> String {
        crate::spec::json::to_string(&Rows(self)) + "\n"
    }

    /// CSV: the column names, then one line per row.
    pub fn csv(&self) -> String {
        let mut table = Table::new(&self.columns, 64 * self.columns.len());
        self.csv_into(&mut table);
        table.into_string()
    }

    /// CSV of the rows only, one line each: what follows [`Report::csv`]'s header when a command
    /// writes rows as it computes them.
    pub fn csv_rows(&self) -> String {
        let mut table = Table::rows(0);
        self.csv_into(&mut table);
        table.into_string()
    }

    fn csv_into(&self, table: &mut Table) {
        for row in &self.rows {
            for cell in row {
                match cell {
                    Cell::Number(v) => table.number(*v),
                    Cell::Count(n) => table.count(*n),
                    Cell::Missing => table.text(""),
                    Cell::Text(text) | Cell::Json(text) => table.text(text),
                }
            }
            table.end_row();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_form_names_the_columns_and_keeps_numbers_exact() {
        let mut report = Report::new(["curve", "value", "theta"]);
        report.push(vec![
            Cell::Json(r#"{"ndf":"phong","alpha_p":1.0}"#.into()),
            Cell::Number(0.1),
            Cell::Missing,
        ]);
        report.push(vec![
            Cell::Text("x, y".into()),
            Cell::Number(1e-300),
            Cell::Count(7),
        ]);
        assert_eq!(
            report.json_lines(),
            "{\"curve\":{\"ndf\":\"phong\",\"alpha_p\":1.0},\"value\":0.1,\"theta\":null}\n{\"curve\":\"x, y\",\"value\":1e-300,\"theta\":7}\n"
        );
        assert_eq!(
            report.json_array(),
            "[{\"curve\":{\"ndf\":\"phong\",\"alpha_p\":1.0},\"value\":0.1,\"theta\":null},{\"curve\":\"x, y\",\"value\":1e-300,\"theta\":7}]\n"
        );
        assert_eq!(
            report.csv(),
            "curve,value,theta\n\"{\"\"ndf\"\":\"\"phong\"\",\"\"alpha_p\"\":1.0}\",0.1,\n\"x, y\",1e-300,7\n"
        );
        assert_eq!(
            Report::new(report.columns()).csv() + &report.csv_rows(),
            report.csv()
        );
    }
}
