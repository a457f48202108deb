//! `render --check DIR`: compares the figure CSVs a render would write with those already in a
//! folder, at a relative tolerance, and lists every figure and curve that differs and by how much;
//! for a figure whose values all match, compares its freshly drawn SVG with the stored one (when
//! there is one), to catch changes that only affect the drawing (title, colours, styles, theme,
//! legend, sizes).
//!
//! CSVs are compared cell by cell (docs/contracts.md: across machines they agree to 1e-12 relative);
//! SVGs token by token, the text exactly and the numbers inside tags within
//! [`SVG_GRID_TOLERANCE`]; PNG bytes never. This module reads the folder and never writes anything.
//!
//! What the folder holds is untrusted input: a stored file is read only when it is a regular file
//! in the folder itself (never through a symbolic link, never a FIFO or a device) and no larger
//! than [`stored_limit`]; anything else is refused by name. The report never prints a stored
//! header, cell or file name whole: stored text appears only as a short [`excerpt`] with its
//! control characters escaped.

use crate::error::{Error, Result};
use crate::model::math::tolerance::relative_difference;
use crate::problem::{excerpt, one_line};
use crate::spec::datafile::{Refused, read_regular};
use std::collections::BTreeMap;
use std::path::Path;

/// Default `--tolerance`: the cross-machine agreement docs/contracts.md promises for figure CSVs.
pub const DEFAULT_TOLERANCE: f64 = 1e-12;

/// Largest difference between two whole numbers inside SVG tags (coordinates on the quarter-pixel
/// grid) that still counts as the same drawing: a value's last bits, which may differ across
/// machines, can move a rounded vertex by one grid step.
pub const SVG_GRID_TOLERANCE: f64 = 1.0;

/// How many times larger than its rendered counterpart a stored file may be and still be read. A
/// stored CSV that matches has the same rows, the same `curve` text, and numbers that differ in
/// their last digits: a rendered row is at least 14 bytes (`0,0,c,0.0,0.0`), the same row with
/// every number at its longest (24 characters, `-2.2250738585072014e-308`) under 4.5 times that;
/// a matching SVG differs by at most a digit per coordinate. A stored file beyond the bound cannot
/// match, so it is reported as differing without being read: reading it could only cost memory
/// (a parsed CSV takes about 20 times its size).
pub const STORED_SIZE_FACTOR: u64 = 8;

/// Added to [`STORED_SIZE_FACTOR`] times the rendered size: room for small files, line-end and
/// header variants, 1 MiB.
pub const STORED_SIZE_SLACK: u64 = 1 << 20;

/// The most bytes read of a stored file whose rendered counterpart has `rendered` bytes.
pub fn stored_limit(rendered: usize) -> u64 {
    (rendered as u64)
        .saturating_mul(STORED_SIZE_FACTOR)
        .saturating_add(STORED_SIZE_SLACK)
}

/// One series of a figure CSV: the `curve` column of its first row, and every row's cells from
/// `curve` on (`curve`, `x`, `y`, and `z` when present).
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
        .map_err(|e| one_line(&e.to_string()).into_owned())?
        .iter()
        .map(str::to_string)
        .collect();
    if header.len() < 5 || header[..3] != ["panel", "series", "curve"] {
        return Err(format!(
            "not a figure CSV (got header \"{}\", expected panel,series,curve,x,y[,z])",
            excerpt(&header.join(","))
        ));
    }
    let mut series: BTreeMap<(u64, u64), SeriesRows> = BTreeMap::new();
    for (i, record) in reader.records().enumerate() {
        let record = record.map_err(|e| one_line(&e.to_string()).into_owned())?;
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
                    excerpt(&header[k]),
                    excerpt(&record[k])
                )
            })
        };
        let entry = series.entry((index(0)?, index(1)?)).or_default();
        if entry.rows.is_empty() {
            entry.curve = record[2].to_string();
        }
        entry
            .rows
            .push(record.iter().skip(2).map(str::to_string).collect());
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

/// Compares one series cell by cell, its `curve` text exactly and its numbers at a relative
/// `tolerance`; `None` when every cell matches. A text difference counts as infinitely large.
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
                        column: header[2 + k].clone(),
                        x: a[1].clone(),
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
/// one line each, naming the panel, the series and its curve. Stored text (a header, a curve) is
/// quoted only as an [`excerpt`].
fn compare_tables(name: &str, rendered: &Table, stored: &Table, tolerance: f64) -> Vec<String> {
    if rendered.header != stored.header {
        return vec![format!(
            "{name}: header differs (rendered {}, stored {})",
            excerpt(&rendered.header.join(",")),
            excerpt(&stored.header.join(","))
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
                one_line(&a.curve),
                a.rows.len()
            )),
            (None, Some(b)) => lines.push(format!(
                "{at} {}: extra in the stored CSV ({} rows)",
                excerpt(&b.curve),
                b.rows.len()
            )),
            (Some(a), Some(b)) if a.curve != b.curve => {
                lines.push(format!(
                    "{at}: curve differs (rendered {}, stored {})",
                    one_line(&a.curve),
                    excerpt(&b.curve)
                ));
            }
            (Some(a), Some(b)) => {
                if a.rows.len() != b.rows.len() {
                    lines.push(format!(
                        "{at} {}: {} rows rendered, {} stored",
                        one_line(&a.curve),
                        a.rows.len(),
                        b.rows.len()
                    ));
                }
                if let Some(w) = compare_rows(&rendered.header, a, b, tolerance) {
                    let by = if w.relative.is_finite() {
                        format!(" by {:.3e} relative", w.relative)
                    } else {
                        String::new()
                    };
                    lines.push(format!(
                        "{at} {}: {} differs{by} at x = {} (rendered {}, stored {}; {} of {} rows differ)",
                        one_line(&a.curve),
                        one_line(&w.column),
                        excerpt(&w.x),
                        excerpt(&w.rendered),
                        excerpt(&w.stored),
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

/// One token of an SVG: a number inside a tag, or any other text.
#[derive(Debug, PartialEq)]
enum Token<'a> {
    Number(&'a str, f64),
    Text(&'a str),
}

/// The tokens of `svg` without its `<metadata>` (provenance, not drawing): inside tags, runs of
/// word characters that are numbers become [`Token::Number`]; everything else is text.
fn tokens(svg: &str) -> Vec<Token<'_>> {
    let svg = match (svg.find("<metadata>"), svg.find("</metadata>")) {
        (Some(start), Some(end)) if start < end => {
            return [&svg[..start], &svg[end..]]
                .iter()
                .flat_map(|part| tokens(part))
                .collect();
        }
        _ => svg,
    };
    let word = |c: char| c.is_alphanumeric() || matches!(c, '#' | '.' | '-' | '_');
    let mut out = Vec::new();
    let mut in_tag = false;
    let mut rest = svg;
    while let Some(c) = rest.chars().next() {
        let len = if word(c) {
            rest.find(|c| !word(c)).unwrap_or(rest.len())
        } else {
            c.len_utf8()
        };
        let (token, tail) = rest.split_at(len);
        match c {
            '<' => in_tag = true,
            '>' => in_tag = false,
            _ => {}
        }
        let number = token.parse::<f64>().ok().filter(|v| v.is_finite());
        out.push(match number {
            Some(v) if in_tag && word(c) => Token::Number(token, v),
            _ => Token::Text(token),
        });
        rest = tail;
    }
    out
}

/// Where the drawing `rendered` first differs from `stored`, as `rendered "…", stored "…"` with
/// the element it is in; `None` when they are the same drawing: equal text, and numbers equal
/// except whole numbers within [`SVG_GRID_TOLERANCE`].
fn drawing_difference(rendered: &str, stored: &str) -> Option<String> {
    let (a, b) = (tokens(rendered), tokens(stored));
    let same = |x: &Token, y: &Token| match (x, y) {
        (Token::Number(p, u), Token::Number(q, v)) => {
            p == q || (!p.contains('.') && !q.contains('.') && (u - v).abs() <= SVG_GRID_TOLERANCE)
        }
        _ => x == y,
    };
    let first = (0..a.len().max(b.len())).find(|&i| match (a.get(i), b.get(i)) {
        (Some(x), Some(y)) => !same(x, y),
        _ => true,
    })?;
    let text = |tokens: &[Token], i: usize| match tokens.get(i) {
        Some(Token::Number(t, _) | Token::Text(t)) => excerpt(t),
        None => "(end)".into(),
    };
    let element = a[..first.min(a.len())]
        .iter()
        .rposition(|t| *t == Token::Text("<"))
        .and_then(|open| match a.get(open + 1) {
            Some(Token::Text(name)) if name.starts_with(char::is_alphabetic) => {
                Some(format!(" in <{name}>"))
            }
            _ => None,
        })
        .unwrap_or_default();
    Some(format!(
        "{element}: rendered \"{}\", stored \"{}\"",
        text(&a, first),
        text(&b, first)
    ))
}

/// Compares `rendered`, the (file name, bytes) of every figure CSV and SVG of a run, with the files
/// in `dir`. For the values: a CSV missing from `dir`, a non-hidden `*.csv` in `dir` that the run
/// does not produce, and every series whose cells differ (numbers by more than `tolerance`
/// relative) are listed. For the drawing: a figure whose values all match but whose SVG differs
/// from the one in `dir` (see [`drawing_difference`]; figures without a stored SVG are not
/// compared). Returns the report (one line per difference, then a summary naming how many figures
/// differ in their values and in their drawing only) and whether everything matched.
///
/// A stored file is read only through [`read_stored`]: a link, a FIFO, a device or a folder under
/// a name the run compares is an error naming it (exit 2); one beyond [`stored_limit`] is listed
/// as differing, unread.
pub fn compare(
    dir: &Path,
    rendered: &[(String, Vec<u8>)],
    tolerance: f64,
) -> Result<(String, bool)> {
    let shown = one_line(&dir.display().to_string()).into_owned();
    let entries = std::fs::read_dir(dir).map_err(|e| Error::io(&shown, e))?;
    let mut stored_names = Vec::new();
    for entry in entries {
        let name = entry
            .map_err(|e| Error::io(&shown, e))?
            .file_name()
            .to_string_lossy()
            .into_owned();
        if (name.ends_with(".csv") || name.ends_with(".svg")) && !name.starts_with('.') {
            stored_names.push(name);
        }
    }
    stored_names.sort();
    let read = |name: &str, rendered: &[u8]| read_stored(&dir.join(name), rendered.len());
    let csvs: Vec<&(String, Vec<u8>)> = rendered
        .iter()
        .filter(|(n, _)| n.ends_with(".csv"))
        .collect();
    let mut lines = Vec::new();
    let (mut values_differ, mut drawings_differ) = (0, 0);
    for (name, bytes) in &csvs {
        let before = lines.len();
        if !stored_names.contains(name) {
            lines.push(format!("{name}: missing from {shown}"));
        } else {
            match read(name, bytes)? {
                Err(too_large) => lines.push(format!("{name}: {too_large}")),
                Ok(stored) => match (parse_table(bytes), parse_table(&stored)) {
                    (Ok(a), Ok(b)) => lines.extend(compare_tables(name, &a, &b, tolerance)),
                    (_, Err(message)) => {
                        lines.push(format!("{name}: stored CSV unreadable: {message}"))
                    }
                    (Err(message), _) => {
                        return Err(Error::Numerics(format!(
                            "{name}: rendered CSV unreadable: {message}"
                        )));
                    }
                },
            }
        }
        if lines.len() > before {
            values_differ += 1;
            continue;
        }
        let svg_name = name.replace(".csv", ".svg");
        let drawn = rendered.iter().find(|(n, _)| *n == svg_name);
        if let (Some((_, drawn)), true) = (drawn, stored_names.contains(&svg_name)) {
            let difference = match read(&svg_name, drawn)? {
                Err(too_large) => Some(format!(": {too_large}")),
                Ok(stored) => drawing_difference(
                    &String::from_utf8_lossy(drawn),
                    &String::from_utf8_lossy(&stored),
                ),
            };
            if let Some(difference) = difference {
                lines.push(format!(
                    "{svg_name}: the drawing differs though every value matches (title, colours, styles, theme, legend or size){difference}"
                ));
                drawings_differ += 1;
            }
        }
    }
    for name in stored_names
        .iter()
        .filter(|n| n.ends_with(".csv") && !csvs.iter().any(|(r, _)| r == *n))
    {
        lines.push(format!(
            "{}: extra in {shown} (no scene of this run writes it)",
            one_line(name)
        ));
        values_differ += 1;
    }
    let total = csvs.len();
    let ok = lines.is_empty();
    lines.push(if ok {
        format!(
            "render --check: all {total} CSVs match {shown} within {tolerance:e} relative, and their stored SVGs the drawing"
        )
    } else {
        let differ = values_differ + drawings_differ;
        let figures = if differ == 1 {
            "1 figure differs".to_owned()
        } else {
            format!("{differ} figures differ")
        };
        format!(
            "render --check: {figures} from {shown} ({total} rendered): {values_differ} in their values beyond {tolerance:e} relative, {drawings_differ} in their drawing only"
        )
    });
    Ok((lines.join("\n") + "\n", ok))
}

/// The bytes of the stored file `path`, whose rendered counterpart has `rendered` bytes, read
/// with [`read_regular`] up to [`stored_limit`]: `Ok(Err(line))` with the report's words when it
/// is too large to match (nothing read); an error naming the file when it is a symbolic link, not
/// a regular file or cannot be read.
fn read_stored(path: &Path, rendered: usize) -> Result<std::result::Result<Vec<u8>, String>> {
    let limit = stored_limit(rendered);
    let shown = path.display().to_string();
    match read_regular(path, limit) {
        Ok(bytes) => Ok(Ok(bytes)),
        Err(Refused::TooLarge(len)) => Ok(Err(format!(
            "stored file too large to match (got {len} bytes, expected at most {limit}: \
             {STORED_SIZE_FACTOR} times the rendered {rendered} bytes plus {} MiB); not read",
            STORED_SIZE_SLACK >> 20
        ))),
        Err(Refused::Io(e)) => Err(Error::io(shown, e)),
        Err(refused) => Err(Error::io(
            shown,
            std::io::Error::other(format!(
                "not read: {refused}; render --check reads only the regular files in its folder"
            )),
        )),
    }
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
    fn every_cell_is_compared_including_the_curve_of_later_rows() {
        let changed = CSV.replace("0,0,A,0.5,2.0", "0,0,Z,0.5,2.0");
        let lines = diff(&changed, CSV, 1e-12);
        assert_eq!(
            lines,
            [
                "f.csv: panel 0, series 0 A: curve differs at x = 0.5 (rendered Z, stored A; 1 of 2 rows differ)"
            ]
        );
    }

    const SVG: &str = "<svg width=\"100\">\n<metadata>ndfplot-version=0.1.0</metadata>\n\
        <text x=\"50\" font-size=\"78.40\" fill=\"#222222\">\nScene 1\n</text>\n\
        <polyline fill=\"none\" stroke=\"#268BD2\" points=\"10,20 30,-40\"/>\n</svg>\n";

    #[test]
    fn drawings_match_within_a_grid_step_and_differ_in_any_text_colour_or_size() {
        assert_eq!(drawing_difference(SVG, SVG), None);
        for same in [
            SVG.replace("30,-40", "31,-41"),
            SVG.replace("version=0.1.0", "version=0.2.0"),
        ] {
            assert_eq!(drawing_difference(&same, SVG), None, "{same}");
        }
        for (changed, expected) in [
            ("Scene 1", " in <text>: rendered \"2\", stored \"1\""),
            (
                "Scene 1",
                " in <text>: rendered \"Figure\", stored \"Scene\"",
            ),
            (
                "#268BD2",
                " in <polyline>: rendered \"#DC322F\", stored \"#268BD2\"",
            ),
            ("78.40", " in <text>: rendered \"78.41\", stored \"78.40\""),
            ("30,-40", " in <polyline>: rendered \"32\", stored \"30\""),
        ] {
            let replacement = expected.split('"').nth(1).unwrap();
            let with = match changed {
                "Scene 1" if replacement == "2" => "Scene 2".to_string(),
                "Scene 1" => "Figure 1".to_string(),
                "30,-40" => "32,-40".to_string(),
                _ => replacement.to_string(),
            };
            let drawn = SVG.replace(changed, &with);
            assert_eq!(drawing_difference(&drawn, SVG).as_deref(), Some(expected));
        }
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
