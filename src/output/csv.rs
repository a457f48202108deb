//! Every CSV ndfplot writes goes through [`Table`]: RFC 4180 quoting where a field needs it (as
//! the csv crate's writer quotes, which a test holds it to), `\n` line ends, numbers in the
//! shortest round-trip form of docs/contracts.md. It also owns the figure CSV (docs/contracts.md): long
//! format, one row per sampled point, `panel,series,curve,x,y` (plus `z` when the figure has
//! surface panels).
//!
//! Pure serialization into memory: it never evaluates a curve or touches a file.

use crate::pipeline::figure::Figure;
use std::io::Write;

/// A CSV document being written into memory, one row at a time: fields are appended to the
/// current row and [`Table::end_row`] ends it. Every row must have as many fields as the header.
pub struct Table {
    out: Vec<u8>,
    /// Fields in the current row so far.
    fields: usize,
}

impl Table {
    /// A table whose first row is `header`, with room for about `bytes` bytes.
    pub fn new<T: AsRef<[u8]>>(header: impl IntoIterator<Item = T>, bytes: usize) -> Table {
        let mut table = Table::rows(bytes);
        for name in header {
            table.text_bytes(name.as_ref());
        }
        table.end_row();
        table
    }

    /// A table of rows only (no header), to be joined to one that has it, with room for about
    /// `bytes` bytes.
    pub fn rows(bytes: usize) -> Table {
        Table {
            out: Vec::with_capacity(bytes),
            fields: 0,
        }
    }

    /// Appends `field` as text, quoted when it holds a comma, a quote or a line break (quotes
    /// doubled inside), or when it is an empty row's only field.
    pub fn text(&mut self, field: &str) {
        self.text_bytes(field.as_bytes());
    }

    fn text_bytes(&mut self, field: &[u8]) {
        self.separate();
        self.out.extend_from_slice(&quoted(field));
    }

    /// Appends `fields` already written by [`quoted_fields`], counted as `count` fields: text that
    /// repeats on many rows is quoted once.
    pub fn quoted_fields(&mut self, fields: &QuotedFields) {
        self.separate();
        self.out.extend_from_slice(&fields.text);
        self.fields += fields.count - 1;
    }

    /// Appends `value` in shortest round-trip form (`{:?}`: `1.0`, `0.1`, `1e-300`).
    pub fn number(&mut self, value: f64) {
        self.separate();
        write!(self.out, "{value:?}").expect("writing to memory cannot fail");
    }

    /// Appends a number already written in shortest round-trip form.
    fn formatted_number(&mut self, text: &[u8]) {
        self.separate();
        self.out.extend_from_slice(text);
    }

    /// Appends a whole number.
    pub fn count(&mut self, value: usize) {
        self.separate();
        write!(self.out, "{value}").expect("writing to memory cannot fail");
    }

    /// Starts a field: a comma unless it is the first of its row.
    fn separate(&mut self) {
        if self.fields > 0 {
            self.out.push(b',');
        }
        self.fields += 1;
    }

    /// Ends the current row. A row whose one field is empty text is written `""`, so that the
    /// line is not read as blank.
    pub fn end_row(&mut self) {
        let one_empty_field = self.fields == 1 && matches!(self.out.last(), None | Some(b'\n'));
        if one_empty_field {
            self.out.extend_from_slice(b"\"\"");
        }
        self.out.push(b'\n');
        self.fields = 0;
    }

    /// The CSV bytes.
    pub fn into_bytes(self) -> Vec<u8> {
        self.out
    }

    /// The CSV text.
    pub fn into_string(self) -> String {
        String::from_utf8(self.out).expect("every field was UTF-8")
    }
}

/// A list of numbers in shortest round-trip form, kept while the next list is the same.
#[derive(Default)]
struct FormattedGrid {
    values: Vec<f64>,
    text: Vec<u8>,
    ends: Vec<usize>,
}

impl FormattedGrid {
    /// Formats `values` unless they are (bit for bit) the ones already formatted.
    fn format(&mut self, values: impl Iterator<Item = f64> + Clone) {
        if values
            .clone()
            .map(f64::to_bits)
            .eq(self.values.iter().map(|v| v.to_bits()))
        {
            return;
        }
        self.values.clear();
        self.text.clear();
        self.ends.clear();
        for value in values {
            write!(self.text, "{value:?}").expect("writing to memory cannot fail");
            self.values.push(value);
            self.ends.push(self.text.len());
        }
    }

    /// The text of the `i`-th value.
    fn text(&self, i: usize) -> &[u8] {
        let start = if i == 0 { 0 } else { self.ends[i - 1] };
        &self.text[start..self.ends[i]]
    }
}

/// Several leading fields of a row, quoted once for many rows ([`Table::quoted_fields`]).
pub struct QuotedFields {
    text: Vec<u8>,
    count: usize,
}

/// `fields` joined by commas, each quoted as [`Table::text`] quotes it.
pub fn quoted_fields(fields: &[&str]) -> QuotedFields {
    let quoted: Vec<Vec<u8>> = fields
        .iter()
        .map(|f| quoted(f.as_bytes()).into_owned())
        .collect();
    QuotedFields {
        text: quoted.join(&b","[..]),
        count: fields.len(),
    }
}

/// `field` as a CSV field: as is, or in quotes with its quotes doubled when it holds a comma, a
/// quote, `\r` or `\n`.
fn quoted(field: &[u8]) -> std::borrow::Cow<'_, [u8]> {
    if !field
        .iter()
        .any(|b| matches!(b, b',' | b'"' | b'\r' | b'\n'))
    {
        return std::borrow::Cow::Borrowed(field);
    }
    let mut out = Vec::with_capacity(field.len() + 8);
    out.push(b'"');
    for &b in field {
        if b == b'"' {
            out.push(b'"');
        }
        out.push(b);
    }
    out.push(b'"');
    std::borrow::Cow::Owned(out)
}

/// The CSV bytes of a figure: header `panel,series,curve,x,y` (and `,z` when any series has z
/// values), then every point of every series, panels and series in order; `x` is θ in radians
/// for curves. Series without z leave the z field empty. A point whose value is not finite (a ratio
/// where its divisor underflowed) has no row: numbers printed are always finite.
pub fn figure_csv(figure: &Figure) -> Vec<u8> {
    // Room for every row: its panel, series and curve, and up to 25 bytes per number.
    let bytes: usize = figure
        .panels
        .iter()
        .flat_map(|p| &p.series)
        .map(|s| s.points.len() * (s.curve.len() * 2 + 16 + 3 * 25))
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
    let mut table = Table::new(header, 64 + bytes);
    // The series of a table panel usually share one x grid: it is formatted once.
    let mut grid = FormattedGrid::default();
    for (p, panel) in figure.panels.iter().enumerate() {
        let p = p.to_string();
        for (s, series) in panel.series.iter().enumerate() {
            let leading = quoted_fields(&[&p, &s.to_string(), &series.curve]);
            grid.format(series.points.iter().map(|&(x, _)| x));
            for (i, &(_, y)) in series.points.iter().enumerate() {
                // A non-finite value is never printed: its row is left out (the lint names it).
                if !y.is_finite() {
                    continue;
                }
                table.quoted_fields(&leading);
                table.formatted_number(grid.text(i));
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
    fn text_fields_are_quoted_as_the_csv_crate_quotes_them() {
        let fields = [
            "",
            "plain",
            "a,b",
            "say \"hi\"",
            "line\nbreak",
            "cr\rhere",
            " spaced ",
            "{\"ndf\":\"phong\"}",
            "θ_deg",
            "'single'",
            "tab\there",
            ";",
        ];
        for a in fields {
            for b in fields {
                let mut theirs = csv::WriterBuilder::new()
                    .flexible(true)
                    .from_writer(Vec::new());
                theirs.write_record([a, b]).unwrap();
                theirs.write_record([a]).unwrap();
                let theirs = theirs.into_inner().unwrap();
                let mut ours = Table::rows(0);
                ours.text(a);
                ours.text(b);
                ours.end_row();
                ours.text(a);
                ours.end_row();
                assert_eq!(ours.into_bytes(), theirs, "{a:?} {b:?}");
                let mut joined = Table::rows(0);
                joined.quoted_fields(&quoted_fields(&[a, b]));
                joined.number(0.5);
                joined.end_row();
                let mut separate = Table::rows(0);
                separate.text(a);
                separate.text(b);
                separate.number(0.5);
                separate.end_row();
                assert_eq!(joined.into_bytes(), separate.into_bytes());
            }
        }
    }

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
