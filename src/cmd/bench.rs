//! `ndfplot bench`: measures run time against error (see [`crate::bench`]) and writes
//! `<DIR>/bench.csv` and the log–log figure `<DIR>/bench.svg` and `<DIR>/bench.png`.
//!
//! Owns the figure of the measurements; the measuring is the library's, the writing `output::write`'s.
//! Its outputs are timings: never part of the catalogue or of `render --check`.

use crate::bench::{self, Row};
use crate::error::{Error, Result};
use crate::figure::{Figure, Panel, Series};
use crate::look::{Axes, Canvas, Dash, Mark, PanelKind, Rgb, Style, Theme, XUnit, YScale};
use crate::ndf::Family;
use crate::output::{plot, write};
use crate::provenance::Provenance;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Figure size in CSS pixels: three panels side by side, tall enough for the drawing panel to keep
/// a useful plot above its ten-entry legend.
const CANVAS: Canvas = Canvas {
    width_px: 1500,
    height_px: 760,
    png_scale: 1.0,
    font_px: 13.0,
};
/// Floor of the plotted errors: exact results (error 0) would vanish from a log axis; the
/// references resolve 1e-15 at best.
const ERROR_FLOOR: f64 = 1e-17;
/// Colours of the normalization routes and throughput methods (Solarized accents, as the catalogue).
const PALETTE: [u32; 6] = [0x268BD2, 0xDC322F, 0x859900, 0xB58900, 0x6C71C4, 0x2AA198];

/// Runs every measurement with the system clock and writes the CSV and the figure into `dir`;
/// an output folder that cannot be written fails before anything is measured.
pub fn run(dir: &Path) -> Result<Vec<PathBuf>> {
    write::check_writable(dir)?;
    let rows = bench::run(&bench::SystemClock::new(), &bench::Settings::standard());
    write_outputs(dir, &rows)
}

/// Writes `bench.csv`, `bench.svg` and `bench.png` of `rows` into `dir`.
pub fn write_outputs(dir: &Path, rows: &[Row]) -> Result<Vec<PathBuf>> {
    let figure = figure(rows);
    let drawing_failed = |e| Error::Numerics(format!("bench: drawing failed: {e}"));
    let svg = plot::svg(&figure).map_err(drawing_failed)?;
    let png = plot::png(&figure).map_err(drawing_failed)?;
    write::write_files(
        dir,
        &[
            ("bench.csv", bench::csv(rows).into_bytes()),
            ("bench.svg", svg),
            ("bench.png", png),
        ],
    )
}

fn style(colour: u32, dash: Dash, mark: Mark) -> Style {
    Style {
        colour: Rgb::from_hex(colour),
        width: 1.0,
        dash,
        mark,
    }
}

fn series(label: String, style: Style, points: Vec<(f64, f64)>) -> Series {
    Series {
        label,
        curve: String::new(),
        style,
        points: Arc::new(points),
        z: None,
        grid: None,
    }
}

fn panel(title: &str, x_label: &str, y_label: &str, series: Vec<Series>) -> Panel {
    Panel {
        axes: Axes {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            x_unit: XUnit::Plain,
            kind: PanelKind::Cartesian,
            y_scale: YScale::Log,
            x_range: None,
            y_range: None,
            legend: true,
        },
        series,
    }
}

/// A short label of a case: `phong 2048`, `trowbridge_reitz 0.01`.
fn short(case: &str) -> String {
    let words: Vec<&str> = case
        .split(|c: char| "{}\":,".contains(c))
        .filter(|w| !w.is_empty())
        .collect();
    let family = words.get(1).copied().unwrap_or(case);
    let values: Vec<&str> = words.iter().skip(3).step_by(2).copied().collect();
    format!("{family} {}", values.join(" "))
}

/// A family's name short enough for an axis label of all families: a name of several words by their
/// initials (`torrance_sparrow` → `TS`).
fn short_family(family: Family) -> String {
    let name = family.name();
    if name.contains('_') {
        name.split('_')
            .filter_map(|word| word.chars().next())
            .collect::<String>()
            .to_uppercase()
    } else {
        name.to_string()
    }
}

/// The figure: (a) drawn error in px against time per curve, uniform dashed and adaptive solid;
/// (b) relative error of each normalization route against time; (c) samples per second per family
/// and method. Times on log₁₀ axes.
pub fn figure(rows: &[Row]) -> Figure {
    let log_time = |r: &Row| r.seconds.max(f64::MIN_POSITIVE).log10();
    let mut drawing = Vec::new();
    let mut cases: Vec<&str> = rows
        .iter()
        .filter(|r| r.section == "drawing")
        .map(|r| r.case.as_str())
        .collect();
    cases.dedup();
    for case in &cases {
        let colour = Family::ALL
            .into_iter()
            .find(|f| case.contains(&format!("\"{}\"", f.name())))
            .map_or(0x000000, Family::colour);
        for (method, dash) in [("uniform", Dash::Dashed), ("adaptive", Dash::Solid)] {
            let points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.section == "drawing" && r.case == *case && r.method == method)
                .map(|r| (log_time(r), r.error.max(ERROR_FLOOR)))
                .collect();
            drawing.push(series(
                format!("{} {method}", short(case)),
                style(colour, dash, Mark::LinePoints),
                points,
            ));
        }
    }
    let mut routes: Vec<&str> = rows
        .iter()
        .filter(|r| r.section == "normalization")
        .map(|r| r.method.as_str())
        .collect();
    routes.sort();
    routes.dedup();
    let normalization = routes
        .iter()
        .enumerate()
        .map(|(i, route)| {
            let points = rows
                .iter()
                .filter(|r| r.section == "normalization" && r.method == *route)
                .map(|r| (log_time(r), r.error.max(ERROR_FLOOR)))
                .collect();
            series(
                route.to_string(),
                style(PALETTE[i % PALETTE.len()], Dash::Solid, Mark::Points),
                points,
            )
        })
        .collect();
    let methods = ["eval_1_thread", "eval_all_threads"];
    let throughput = methods
        .iter()
        .enumerate()
        .map(|(i, method)| {
            let points = Family::ALL
                .iter()
                .enumerate()
                .filter_map(|(k, family)| {
                    let r = rows.iter().find(|r| {
                        r.section == "throughput" && r.method == *method && r.case == family.name()
                    })?;
                    Some(((k + 1) as f64, r.samples as f64 / r.seconds / 1e6))
                })
                .collect();
            series(
                method.to_string(),
                style(PALETTE[i], Dash::Solid, Mark::LinePoints),
                points,
            )
        })
        .collect();
    let families: Vec<String> = Family::ALL
        .iter()
        .enumerate()
        .map(|(k, f)| format!("{} {}", k + 1, short_family(*f)))
        .collect();
    Figure {
        id: "bench".into(),
        title: "ndfplot bench: time against error".into(),
        rows: 1,
        cols: 3,
        canvas: CANVAS,
        theme: Theme::Notebook,
        provenance: Provenance::without_spec(),
        panels: vec![
            panel(
                "(a) drawing a curve",
                "log₁₀ time per curve (s)",
                "max deviation (px)",
                drawing,
            ),
            panel(
                "(b) normalization routes",
                "log₁₀ time per N (s)",
                "relative error",
                normalization,
            ),
            panel(
                "(c) throughput, uniform grid",
                &families.join(", "),
                "M samples/s",
                throughput,
            ),
        ],
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(section: &'static str, case: &str, method: &str, setting: f64, error: f64) -> Row {
        Row {
            section,
            case: case.into(),
            method: method.into(),
            setting,
            samples: 1000,
            seconds: 1e-4 * setting,
            error,
        }
    }

    #[test]
    fn outputs_are_the_table_and_the_figure_as_svg_and_png() {
        let curve = r#"{"ndf":"phong","alpha_p":2048.0}"#;
        let rows = [
            row("drawing", curve, "uniform", 16.0, 16.5),
            row("drawing", curve, "uniform", 1024.0, 0.1),
            row("drawing", curve, "adaptive", 0.25, 0.2),
            row("normalization", "abc", "stable", 1.0, 1e-16),
            row("throughput", "beckmann", "eval_all_threads", 2.0, 0.0),
        ];
        let dir = std::env::temp_dir().join(format!("ndfplot-bench-out-{}", std::process::id()));
        let written = write_outputs(&dir, &rows).unwrap();
        let names: Vec<String> = written
            .iter()
            .map(|p| p.file_name().unwrap().to_string_lossy().into_owned())
            .collect();
        assert_eq!(names, ["bench.csv", "bench.svg", "bench.png"]);
        let read = |name: &str| std::fs::read(dir.join(name)).unwrap();
        assert!(
            read("bench.csv").starts_with(b"section,case,method,setting,samples,seconds,error\n")
        );
        assert!(read("bench.svg").starts_with(b"<svg"));
        assert!(read("bench.png").starts_with(b"\x89PNG\r\n\x1a\n"));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
