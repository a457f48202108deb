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
        push_shortest(&mut self.out, value);
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
            push_shortest(&mut self.text, value);
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

/// Appends `value` to `out` exactly as `{value:?}` writes it (docs/contracts.md "Numbers"): the
/// shortest digits that read back as `value`, positional from 1e-4 up to 1e16 with at least one
/// decimal (`0.0001`, `1.0`, `12.5`), scientific elsewhere without a plus sign or padding
/// (`1e-5`, `1.5e16`, `-5e-324`), `NaN`, `inf` and `-inf` as they are. The digits are zmij's
/// (Schubfach: shortest, and of those the nearest, as Rust's own), which writes positional
/// from 1e-5 and its exponents as `e-07`; those two differences are rewritten here. Where two
/// shortest candidates are equally near, zmij takes the even one and Rust the upper: that needs
/// the value's exact decimal expansion to be one digit longer than the shortest, so a value whose
/// expansion has at most 18 significant digits ([`short_exact_decimal`]) is written by Rust's own
/// formatting.
fn push_shortest(out: &mut Vec<u8>, value: f64) {
    if !value.is_finite() || short_exact_decimal(value) {
        write!(out, "{value:?}").expect("writing to memory cannot fail");
        return;
    }
    let mut buffer = zmij::Buffer::new();
    let text = buffer.format_finite(value).as_bytes();
    let magnitude = value.abs();
    let positional = magnitude == 0.0 || (1e-4..1e16).contains(&magnitude);
    // zmij's exponent, where it writes one, is the last 4 or 5 bytes (`e-05`, `e+308`).
    let scientific = text[text.len().saturating_sub(5)..].contains(&b'e');
    if positional && !scientific {
        out.extend_from_slice(text);
        return;
    }
    let (negative, text) = match text.split_first() {
        Some((b'-', rest)) => (true, rest),
        _ => (false, text),
    };
    let (mantissa, exponent) = match text.iter().position(|&b| b == b'e') {
        Some(e) => {
            let (sign, digits) = match &text[e + 1..] {
                [b'-', digits @ ..] => (-1, digits),
                [b'+', digits @ ..] => (1, digits),
                digits => (1, digits),
            };
            let magnitude = digits
                .iter()
                .fold(0i32, |n, &d| 10 * n + i32::from(d - b'0'));
            (&text[..e], sign * magnitude)
        }
        None => (text, 0),
    };
    // The significant digits (at most 17, of zmij's shortest), and the power of ten of the first.
    let whole = mantissa
        .iter()
        .position(|&b| b == b'.')
        .unwrap_or(mantissa.len());
    let mut power = whole as i32 - 1 + exponent;
    let mut digits = [0u8; 24];
    let mut count = 0;
    for &b in mantissa.iter().filter(|b| b.is_ascii_digit()) {
        if count == 0 && b == b'0' {
            power -= 1;
        } else {
            digits[count] = b;
            count += 1;
        }
    }
    while count > 1 && digits[count - 1] == b'0' {
        count -= 1;
    }
    let digits = &digits[..count.max(1)];
    if negative {
        out.push(b'-');
    }
    if positional {
        if power < 0 {
            out.extend_from_slice(b"0.");
            out.extend(std::iter::repeat_n(b'0', (-power - 1) as usize));
            out.extend_from_slice(digits);
        } else {
            let whole = power as usize + 1;
            out.extend_from_slice(&digits[..whole.min(digits.len())]);
            out.extend(std::iter::repeat_n(
                b'0',
                whole.saturating_sub(digits.len()),
            ));
            out.push(b'.');
            match digits.get(whole..) {
                Some(fraction) if !fraction.is_empty() => out.extend_from_slice(fraction),
                _ => out.push(b'0'),
            }
        }
    } else {
        out.push(digits[0]);
        if digits.len() > 1 {
            out.push(b'.');
            out.extend_from_slice(&digits[1..]);
        }
        out.push(b'e');
        if power < 0 {
            out.push(b'-');
        }
        let power = power.unsigned_abs();
        let mut decimal = [0u8; 3];
        let start = match power {
            0..=9 => 2,
            10..=99 => 1,
            _ => 0,
        };
        let mut rest = power;
        for place in decimal.iter_mut().rev() {
            *place = b'0' + (rest % 10) as u8;
            rest /= 10;
        }
        out.extend_from_slice(&decimal[start..]);
    }
}

/// Whether the exact decimal expansion of the finite `value` has at most 18 significant digits.
/// With |value| = m · 2^e, m odd: for e < 0 the expansion's digits are those of m · 5^−e; for
/// e ≥ 0 they are those of m · 2^e with its trailing zeros (the factors 10 = 2 · 5 shared by
/// 2^e and m's fives) removed.
fn short_exact_decimal(value: f64) -> bool {
    const LIMIT: u128 = 1_000_000_000_000_000_000;
    let bits = value.abs().to_bits();
    let (biased, fraction) = ((bits >> 52) as i32, bits & ((1 << 52) - 1));
    let (mut m, mut e) = if biased == 0 {
        (fraction, -1074)
    } else {
        (fraction | (1 << 52), biased - 1075)
    };
    if m == 0 {
        return true;
    }
    e += m.trailing_zeros() as i32;
    m >>= m.trailing_zeros();
    let mut digits = u128::from(m);
    if e < 0 {
        for _ in 0..-e {
            digits *= 5;
            if digits >= LIMIT {
                return false;
            }
        }
    } else {
        while e > 0 && digits % 5 == 0 {
            digits /= 5;
            e -= 1;
        }
        if e >= 64 {
            return false;
        }
        digits <<= e;
    }
    digits < LIMIT
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

    /// `push_shortest` against `{:?}` itself, byte for byte: every power of ten from 1e-324 to
    /// 1e308 (and a few leads) with its neighbours three units in the last place each way, short
    /// decimals, small odd numbers times powers of two (where ties between two shortest
    /// candidates live), the extremes and zeros, and a million random bit patterns.
    #[test]
    fn numbers_are_written_as_debug_writes_them() {
        let mut values = vec![
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            f64::MAX,
            f64::MIN,
            f64::EPSILON,
            f64::from_bits(1),
            -f64::from_bits(1),
            f64::from_bits(0x000F_FFFF_FFFF_FFFF),
            9_999_999_999_999_998.0,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        for power in -324..=308 {
            for lead in [
                "1",
                "9.5",
                "1.25",
                "3.0000000000000004",
                "9.999999999999999",
            ] {
                let Ok(v) = format!("{lead}e{power}").parse::<f64>() else {
                    continue;
                };
                for step in -3i64..=3 {
                    let bits = v.to_bits() as i64 + step;
                    values.extend([f64::from_bits(bits as u64), -f64::from_bits(bits as u64)]);
                }
            }
        }
        for digits in 0..100_000 {
            for scale in [1e-7, 1e-5, 1e-4, 1e-2, 1.0, 1e3, 1e12, 1e15] {
                values.push(digits as f64 * scale);
            }
        }
        // Short dyadic values, where two shortest candidates can be equally near.
        for m in (1..4000).step_by(2) {
            for e in -70..=90 {
                values.push(f64::from(m) * 2f64.powi(e));
            }
        }
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        for _ in 0..1_000_000 {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            values.push(f64::from_bits(state));
        }
        let mut out = Vec::new();
        for v in values {
            out.clear();
            push_shortest(&mut out, v);
            assert_eq!(
                std::str::from_utf8(&out).unwrap(),
                format!("{v:?}"),
                "bits {:#x}",
                v.to_bits()
            );
        }
    }

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
