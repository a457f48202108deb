//! Every CSV ndfplot writes goes through [`Table`]: the csv crate's writer (RFC 4180 quoting where
//! a field needs it, `\n` line ends) with numbers in the shortest round-trip form of CONTRACTS.md.
//! It also owns the figure CSV (CONTRACTS.md): long format, one row per sampled point,
//! `panel,series,curve,x,y` (plus `z` when the figure has surface panels).
//!
//! Pure serialization into memory: it never evaluates a curve or touches a file.

use crate::figure::Figure;
use std::fmt::Write;

/// A CSV document being written into memory, one row at a time: fields are appended to the
/// current row and [`Table::end_row`] ends it. Every row must have as many fields as the header.
pub struct Table {
    writer: csv::Writer<Vec<u8>>,
    /// Reused text of the number being written, so a row costs no allocation.
    number: String,
}

impl Table {
    /// A table whose first row is `header`, with room for about `bytes` bytes.
    pub fn new<T: AsRef<[u8]>>(header: impl IntoIterator<Item = T>, bytes: usize) -> Table {
        let mut writer = csv::Writer::from_writer(Vec::with_capacity(bytes));
        writer
            .write_record(header)
            .expect("writing to memory cannot fail");
        Table {
            writer,
            number: String::with_capacity(32),
        }
    }

    /// A table of rows only (no header), to be joined to one that has it, with room for about
    /// `bytes` bytes.
    pub fn rows(bytes: usize) -> Table {
        Table {
            writer: csv::Writer::from_writer(Vec::with_capacity(bytes)),
            number: String::with_capacity(32),
        }
    }

    /// Appends `field` as text, quoted when it holds a comma, a quote or a line break.
    pub fn text(&mut self, field: &str) {
        self.writer
            .write_field(field)
            .expect("writing to memory cannot fail");
    }

    /// Appends `value` in shortest round-trip form (`{:?}`: `1.0`, `0.1`, `1e-300`).
    pub fn number(&mut self, value: f64) {
        self.formatted(format_args!("{value:?}"));
    }

    /// Appends a whole number.
    pub fn count(&mut self, value: usize) {
        self.formatted(format_args!("{value}"));
    }

    fn formatted(&mut self, text: std::fmt::Arguments) {
        self.number.clear();
        self.number
            .write_fmt(text)
            .expect("writing to a String cannot fail");
        self.writer
            .write_field(&self.number)
            .expect("writing to memory cannot fail");
    }

    /// Ends the current row.
    pub fn end_row(&mut self) {
        self.writer
            .write_record(None::<&[u8]>)
            .expect("every row has as many fields as the header");
    }

    /// The CSV bytes.
    pub fn into_bytes(self) -> Vec<u8> {
        self.writer
            .into_inner()
            .expect("writing to memory cannot fail")
    }

    /// The CSV text.
    pub fn into_string(self) -> String {
        String::from_utf8(self.into_bytes()).expect("every field was UTF-8")
    }
}

/// The CSV bytes of a figure: header `panel,series,curve,x,y` (and `,z` when any series has z
/// values), then every point of every series, panels and series in order; `x` is θ in radians
/// for curves. Series without z leave the z field empty.
pub fn figure_csv(figure: &Figure) -> Vec<u8> {
    let points: usize = figure
        .panels
        .iter()
        .flat_map(|p| &p.series)
        .map(|s| s.points.len())
        .sum();
    let with_z = figure
        .panels
        .iter()
        .flat_map(|p| &p.series)
        .any(|s| s.z.is_some());
    let header: &[&str] = if with_z {
        &["panel", "series", "curve", "x", "y", "z"]
    } else {
        &["panel", "series", "curve", "x", "y"]
    };
    let mut table = Table::new(header, 64 + points * 80);
    for (p, panel) in figure.panels.iter().enumerate() {
        let p = p.to_string();
        for (s, series) in panel.series.iter().enumerate() {
            let s = s.to_string();
            for (i, &(x, y)) in series.points.iter().enumerate() {
                table.text(&p);
                table.text(&s);
                table.text(&series.curve);
                table.number(x);
                table.number(y);
                match series.z.as_ref().map(|z| z[i]) {
                    Some(z) => table.number(z),
                    None if with_z => table.text(""),
                    None => {}
                }
                table.end_row();
            }
        }
    }
    table.into_bytes()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_are_quoted_only_where_needed_and_numbers_round_trip() {
        let mut table = Table::new(["theta", "value"], 0);
        table.text(r#"{"ndf":"phong","alpha_p":1.0}"#);
        table.number(1e-7);
        table.end_row();
        table.number(0.1);
        table.text("");
        table.end_row();
        assert_eq!(
            table.into_string(),
            "theta,value\n\"{\"\"ndf\"\":\"\"phong\"\",\"\"alpha_p\"\":1.0}\",1e-7\n0.1,\n"
        );
    }
}
