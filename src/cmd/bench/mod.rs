//! `ndfplot bench`: measures run time against error (see [`crate::cmd::bench::measure`]) and writes
//! `<DIR>/bench.csv` and the log–log figure `<DIR>/bench.svg` and `<DIR>/bench.png`.
//!
//! Owns the figure of the measurements; the measuring is the library's, the writing `output::write`'s.
//! Its outputs are timings: never part of the catalogue or of `render --check`.

pub mod measure;

use crate::error::{Error, Result};
use crate::model::ndf::Family;
use crate::output::{plot, write};
use crate::pipeline::figure::{Figure, Panel, Series};
use crate::pipeline::provenance::Provenance;
use crate::spec::look::{
    Axes, Canvas, Dash, Face, Mark, Rgb, Scale, Style, Theme, TickChoice, XUnit, literal, shade,
};
use measure::Row;
use std::path::{Path, PathBuf};
use std::sync::Arc;

/// Figure size in CSS pixels: four panels, two by two, each tall enough for the drawing panel to
/// keep a useful plot above its ten-entry legend; text that prints at 6 pt at a page's width.
const CANVAS: Canvas = Canvas {
    width_px: 1400,
    height_px: 1400,
    png_scale: 1.0,
    font_px: 17.0,
    print: None,
    transparent: false,
    face: Face::Sans,
};
/// Floor of the plotted errors: exact results (error 0) would vanish from a log axis; the
/// references resolve 1e-15 at best.
const ERROR_FLOOR: f64 = 1e-17;
/// Colours of the normalization routes and throughput methods (Solarized accents, as the catalogue).
const PALETTE: [u32; 6] = [0x268BD2, 0xDC322F, 0x859900, 0xB58900, 0x6C71C4, 0x2AA198];
/// The files a run writes into its folder.
const OUTPUTS: [&str; 3] = ["bench.csv", "bench.svg", "bench.png"];

/// Runs every measurement with the system clock and writes the CSV and the figure into `dir`;
/// an output folder that cannot be written fails before anything is measured.
pub fn run(dir: &Path) -> Result<Vec<PathBuf>> {
    write::refuse_dash_folder("-o", dir, "bench writes three files")?;
    write::check_writable("-o", dir, &OUTPUTS)?;
    let rows = measure::run(&measure::SystemClock::new(), &measure::Settings::standard());
    write_outputs(dir, &rows)
}

/// Writes `bench.csv`, `bench.svg` and `bench.png` of `rows` into `dir`.
pub fn write_outputs(dir: &Path, rows: &[Row]) -> Result<Vec<PathBuf>> {
    let figure = figure(rows);
    let drawing_failed = |e| Error::Numerics(format!("bench: drawing failed: {e}"));
    let svg = plot::svg(&figure).map_err(drawing_failed)?;
    let png = plot::png(&figure, &svg).map_err(drawing_failed)?;
    write::write_files(
        "-o",
        dir,
        &[
            ("bench.csv", measure::csv(rows).into_bytes()),
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
        sweep: None,
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
            ..Axes::cartesian(x_label, y_label, XUnit::Plain, Scale::Log)
        },
        series,
    }
}

/// The family of a drawing case (its canonical curve JSON names it).
fn family_of(case: &str) -> Option<Family> {
    Family::ALL
        .into_iter()
        .find(|f| case.contains(&format!("\"{}\"", f.name())))
}

/// A short label of a case: the family's title and its parameter values (`Phong 2048`,
/// `Trowbridge–Reitz 0.01`).
fn short(case: &str) -> String {
    let words: Vec<&str> = case
        .split(|c: char| "{}\":,".contains(c))
        .filter(|w| !w.is_empty())
        .collect();
    let values: Vec<String> = words
        .iter()
        .skip(3)
        .step_by(2)
        .map(|w| {
            w.parse()
                .map_or_else(|_| literal(w), crate::spec::numbers::pretty)
        })
        .collect();
    match family_of(case) {
        Some(family) => format!("{} {}", family.title(), values.join(" ")),
        None => literal(case),
    }
}

/// log₁₀ of a row's seconds (the x of every time-against-error panel).
fn log_time(row: &Row) -> f64 {
    row.seconds.max(f64::MIN_POSITIVE).log10()
}

/// The series marking the floor at which exact results (error 0) are drawn, across the times of
/// the rows of `sections`; none unless one of them is exact.
fn floor_line(rows: &[Row], sections: &[&str]) -> Option<Series> {
    let shown = || rows.iter().filter(|r| sections.contains(&r.section));
    shown().any(|r| r.error <= ERROR_FLOOR).then(|| {
        let x = span(shown().map(log_time));
        series(
            "error 0 (exact) is drawn at 10^{−17}".to_owned(),
            style(0x777777, Dash::Dotted, Mark::Line),
            vec![(x.0, ERROR_FLOOR), (x.1, ERROR_FLOOR)],
        )
    })
}

/// The extent of `values`, `(0, 1)` when empty.
fn span(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values
        .fold(None, |acc: Option<(f64, f64)>, v| {
            Some(acc.map_or((v, v), |(lo, hi)| (lo.min(v), hi.max(v))))
        })
        .unwrap_or((0.0, 1.0))
}

/// Panel (d): per family, the worst relative error of its Λ routes against time per Λ value, a
/// line in the family's colour from its closed form (the faster end) to the generic quadrature, or a
/// point where quadrature is its only route; and the albedo table's absolute difference from
/// Cycles' against its time, a black point.
fn lambda_panel(rows: &[Row]) -> Panel {
    let point = |r: &Row| (log_time(r), r.error.max(ERROR_FLOOR));
    let mut shown: Vec<Series> = Family::ALL
        .iter()
        .filter_map(|family| {
            let routes: Vec<&Row> = rows
                .iter()
                .filter(|r| r.section == "lambda" && r.case == family.name())
                .collect();
            let names: Vec<String> = routes.iter().map(|r| r.method.replace('_', " ")).collect();
            (!routes.is_empty()).then(|| {
                series(
                    format!("{}: {}", family.title(), names.join(" → ")),
                    style(family.colour(), Dash::Solid, Mark::LinePoints),
                    routes.iter().map(|r| point(r)).collect(),
                )
            })
        })
        .collect();
    shown.extend(
        rows.iter()
            .filter(|r| r.section == "albedo_table")
            .map(|r| {
                series(
                    format!(
                        "{n}×{n} GGX albedo table, {} threads: |E − Cycles|",
                        r.setting,
                        n = measure::CYCLES_TABLE_SIZE
                    ),
                    style(0x000000, Dash::Solid, Mark::LinePoints),
                    vec![point(r)],
                )
            }),
    );
    shown.extend(floor_line(rows, &["lambda", "albedo_table"]));
    let errors = span(shown.iter().flat_map(|s| s.points.iter().map(|p| p.1)));
    let mut panel = panel(
        "(d) Smith Λ routes; one albedo table",
        "log₁₀ time per Λ value or per table (s)",
        "Λ: relative error; table: absolute",
        shown,
    );
    // Three decades of headroom above the largest error leave the legend a place that hides none.
    panel.axes.y_range = Some((errors.0 / 3.0, errors.1 * LEGEND_HEADROOM));
    panel
}

/// Factor above the largest error of panel (d) where its y axis ends.
const LEGEND_HEADROOM: f64 = 1e3;

/// The figure, 2 × 2: (a) drawn error in px against time per curve, uniform dashed and adaptive
/// solid, one shade of its family's colour per case; (b) relative error of each normalization route
/// against time; (c) samples per second on one thread, a bar per family in its colour; (d) Smith Λ
/// routes and the albedo table ([`lambda_panel`]). Times on log₁₀ axes; exact results at a marked
/// floor.
pub fn figure(rows: &[Row]) -> Figure {
    let mut drawing = Vec::new();
    let mut cases: Vec<&str> = rows
        .iter()
        .filter(|r| r.section == "drawing")
        .map(|r| r.case.as_str())
        .collect();
    cases.dedup();
    for case in &cases {
        let family = family_of(case);
        let siblings: Vec<&&str> = cases.iter().filter(|c| family_of(c) == family).collect();
        let k = siblings.iter().position(|c| **c == *case).unwrap_or(0);
        let base = Rgb::from_hex(family.map_or(0x000000, Family::colour));
        let colour = if siblings.len() > 1 {
            shade(base, k, siblings.len())
        } else {
            base
        };
        for (method, dash) in [("uniform", Dash::Dashed), ("adaptive", Dash::Solid)] {
            let points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.section == "drawing" && r.case == *case && r.method == method)
                .map(|r| (log_time(r), r.error.max(ERROR_FLOOR)))
                .collect();
            drawing.push(series(
                format!("{}, {method}", short(case)),
                Style {
                    colour,
                    ..style(0, dash, Mark::LinePoints)
                },
                points,
            ));
        }
    }
    drawing.extend(floor_line(rows, &["drawing"]));
    let mut routes: Vec<&str> = rows
        .iter()
        .filter(|r| r.section == "normalization")
        .map(|r| r.method.as_str())
        .collect();
    routes.sort();
    routes.dedup();
    let mut normalization: Vec<Series> = routes
        .iter()
        .enumerate()
        .map(|(i, route)| {
            let points = rows
                .iter()
                .filter(|r| r.section == "normalization" && r.method == *route)
                .map(|r| (log_time(r), r.error.max(ERROR_FLOOR)))
                .collect();
            series(
                literal(&route.replace('_', " ")),
                style(PALETTE[i % PALETTE.len()], Dash::Solid, Mark::Points),
                points,
            )
        })
        .collect();
    normalization.extend(floor_line(rows, &["normalization"]));
    let throughput = Family::ALL
        .iter()
        .enumerate()
        .filter_map(|(k, family)| {
            let r = rows.iter().find(|r| {
                r.section == "throughput" && r.method == "eval_1_thread" && r.case == family.name()
            })?;
            Some(series(
                family.title().to_owned(),
                style(family.colour(), Dash::Solid, Mark::Bars),
                vec![((k + 1) as f64, r.samples as f64 / r.seconds / 1e6)],
            ))
        })
        .collect();
    let mut speed = panel(
        "(c) eval throughput, one thread",
        "family, in the legend's order",
        "M samples/s",
        throughput,
    );
    speed.axes.y_scale = Scale::Linear;
    speed.axes.x_ticks = Some(TickChoice::At(
        (1..=Family::ALL.len()).map(|k| k as f64).collect(),
    ));
    Figure {
        id: "bench".into(),
        title: "ndfplot bench: time against error".into(),
        rows: 2,
        cols: 2,
        canvas: CANVAS,
        theme: Theme::Notebook,
        provenance: Provenance::without_spec(),
        page: None,
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
            speed,
            lambda_panel(rows),
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
    fn the_figure_names_families_and_routes_and_passes_the_figure_lint() {
        let beckmann = |a: &str| format!(r#"{{"ndf":"beckmann","alpha_b":{a}}}"#);
        let mut rows = Vec::new();
        for case in [beckmann("0.001"), beckmann("0.5")] {
            for (setting, error) in [(16.0, 3.0), (256.0, 0.02), (4096.0, 0.0)] {
                rows.push(row("drawing", &case, "uniform", setting, error));
                rows.push(row(
                    "drawing",
                    &case,
                    "adaptive",
                    setting / 64.0,
                    error / 2.0,
                ));
            }
        }
        for (k, route) in ["closed_form", "quadrature"].iter().enumerate() {
            rows.push(row(
                "normalization",
                "abc",
                route,
                1.0 + k as f64,
                1e-15 * k as f64,
            ));
        }
        for family in Family::ALL {
            rows.push(row("throughput", family.name(), "eval_1_thread", 2.0, 0.0));
        }
        rows.push(row("lambda", "beckmann", "closed_form", 0.1, 1e-14));
        rows.push(row("lambda", "beckmann", "quadrature", 10.0, 1e-12));
        rows.push(row("lambda", "abc", "quadrature", 8.0, 1e-13));
        rows.push(row("albedo_table", "trowbridge_reitz", "table", 2.0, 1e-6));
        let figure = figure(&rows);
        let labels: Vec<&str> = figure
            .panels
            .iter()
            .flat_map(|p| p.series.iter().map(|s| s.label.as_str()))
            .collect();
        for expected in [
            "Beckmann 0.001, uniform",
            "closed form",
            "Torrance–Sparrow",
            "Beckmann: closed form → quadrature",
            "ABC: quadrature",
            "32×32 GGX albedo table, 2 threads: |E − Cycles|",
        ] {
            assert!(labels.contains(&expected), "{expected} not in {labels:?}");
        }
        assert!(labels.iter().any(|l| l.starts_with("error 0 (exact)")));
        assert_eq!(plot::lint(&figure).unwrap(), Vec::<String>::new());
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
