//! `ndfplot render`: scene specs (or the built-in catalogue) to SVG, PNG, PDF and CSV files, and an
//! HTML page per interactive scene.
//!
//! Every spec is read and validated before anything is evaluated or written, so a bad spec
//! writes no file at all; then the plan is evaluated in parallel and each output is written
//! atomically.

use crate::catalogue::CATALOGUE;
use crate::check_outputs;
use crate::error::{Error, Result};
use crate::input::{parse_json, read_file};
use crate::output::{csv::figure_csv, html, pdf, plot, write};
use crate::plan::{Outputs, plan};
use crate::problem::{Problem, Problems};
use crate::progress::Progress;
use crate::provenance::Provenance;
use crate::sample::{Evaluated, evaluate_all};
use crate::scene::{self, Scene};
use crate::series::{Figure, Panel, Series, XUnit};
use rayon::prelude::*;
use std::path::{Path, PathBuf};

/// An output format of `render`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Format {
    /// Scalable vector graphics with text kept as text.
    Svg,
    /// Raster image with text drawn from the embedded font.
    Png,
    /// One-page vector PDF of the SVG, text in the embedded font; only when asked for.
    Pdf,
    /// The sampled points, long format (CONTRACTS.md).
    Csv,
    /// A self-contained interactive page, for scenes with sliders only.
    Html,
}

impl Format {
    /// Every format, in output order.
    pub const ALL: [Format; 5] = [
        Format::Svg,
        Format::Png,
        Format::Pdf,
        Format::Csv,
        Format::Html,
    ];

    /// File extension.
    pub fn extension(self) -> &'static str {
        match self {
            Format::Svg => "svg",
            Format::Png => "png",
            Format::Pdf => "pdf",
            Format::Csv => "csv",
            Format::Html => "html",
        }
    }

    /// Parses a comma-separated list such as `svg,csv`.
    pub fn parse_list(text: &str) -> Result<Vec<Format>> {
        let mut formats = Vec::new();
        for word in text.split(',').map(str::trim) {
            let format = Format::ALL.into_iter().find(|f| f.extension() == word).ok_or_else(|| {
                Error::Usage(format!("--format: unknown format (got \"{word}\", expected a comma list of svg, png, pdf, csv, html)"))
            })?;
            if !formats.contains(&format) {
                formats.push(format);
            }
        }
        formats.sort();
        Ok(formats)
    }
}

/// Command-line overrides of every scene's canvas.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct CanvasOverride {
    /// Figure width in CSS pixels; the height follows proportionally unless also given.
    pub width: Option<f64>,
    /// Figure height in CSS pixels.
    pub height: Option<f64>,
    /// PNG pixels per CSS pixel.
    pub png_scale: Option<f64>,
    /// Base font size in CSS pixels.
    pub font_px: Option<f64>,
}

/// What to render and where.
#[derive(Debug, Clone)]
pub struct RenderOptions {
    /// Spec files or folders; empty for the built-in catalogue.
    pub paths: Vec<PathBuf>,
    /// Output folder.
    pub out: PathBuf,
    /// Formats to produce.
    pub formats: Vec<Format>,
    /// Canvas overrides.
    pub canvas: CanvasOverride,
}

/// A spec's source name, text, and the folder its data paths resolve against (`None` for the
/// built-in catalogue).
type Source = (String, String, Option<PathBuf>);

/// The spec sources named by `paths` (files, or folders whose `*.json` are taken sorted by name),
/// or the built-in catalogue when `paths` is empty.
pub fn sources(paths: &[PathBuf]) -> Result<Vec<Source>> {
    if paths.is_empty() {
        return Ok(CATALOGUE
            .iter()
            .map(|(name, text)| (format!("configs/{name}"), text.to_string(), None))
            .collect());
    }
    let mut sources = Vec::new();
    for path in paths {
        if path.is_dir() {
            let entries =
                std::fs::read_dir(path).map_err(|e| Error::io(path.display().to_string(), e))?;
            let mut files: Vec<PathBuf> = entries
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "json") && p.is_file())
                .collect();
            files.sort();
            for file in files {
                let name = file.display().to_string();
                sources.push((name.clone(), read_file(&name)?, Some(path.clone())));
            }
        } else {
            let name = path.display().to_string();
            let folder = path.parent().map(Path::to_path_buf).unwrap_or_default();
            sources.push((name.clone(), read_file(&name)?, Some(folder)));
        }
    }
    Ok(sources)
}

/// Parses and validates every source; all problems of all sources are reported together, and
/// duplicate ids across sources are problems too. On success there is one scene per source, in
/// the order of `sources`.
pub fn load_scenes(sources: &[Source], canvas: CanvasOverride) -> Result<Vec<Scene>> {
    let mut scenes = Vec::new();
    let mut failures = Vec::new();
    for (name, text, base_dir) in sources {
        let parsed = parse_json(text, name).and_then(|node| {
            scene::parse(&node, base_dir.as_deref()).map_err(|list| Problems {
                source: name.clone(),
                list,
            })
        });
        match parsed.and_then(|s| apply_override(s, canvas, name)) {
            Ok(scene) => {
                if let Some(first) = scenes
                    .iter()
                    .position(|(_, other): &(String, Scene)| other.id == scene.id)
                {
                    failures.push(Problems {
                        source: name.clone(),
                        list: vec![Problem::new(
                            "id",
                            format!(
                                "duplicate id (got \"{}\", already used by {})",
                                scene.id, scenes[first].0
                            ),
                        )],
                    });
                } else {
                    scenes.push((name.clone(), scene));
                }
            }
            Err(problems) => failures.push(problems),
        }
    }
    if failures.is_empty() {
        Ok(scenes.into_iter().map(|(_, s)| s).collect())
    } else {
        Err(Error::Input(failures))
    }
}

fn apply_override(
    mut scene: Scene,
    over: CanvasOverride,
    source: &str,
) -> std::result::Result<Scene, Problems> {
    let canvas = &mut scene.canvas;
    let (w, h) = (f64::from(canvas.width_px), f64::from(canvas.height_px));
    let (width, height) = match (over.width, over.height) {
        (Some(width), None) => (width, h * width / w),
        (width, height) => (width.unwrap_or(w), height.unwrap_or(h)),
    };
    canvas.width_px = width.round().max(16.0) as u32;
    canvas.height_px = height.round().max(16.0) as u32;
    canvas.png_scale = over.png_scale.unwrap_or(canvas.png_scale);
    canvas.font_px = over.font_px.unwrap_or(canvas.font_px);
    scene::check_canvas(canvas).map_err(|message| Problems {
        source: source.to_string(),
        list: vec![Problem::new("", message)],
    })?;
    Ok(scene)
}

/// Builds the figure of `scene`, drawn from the spec `provenance` records, from its evaluated jobs
/// (`feeds[panel][series]` → job index).
pub fn figure(
    scene: &Scene,
    provenance: &Provenance,
    feeds: &[Vec<usize>],
    evaluated: &[Evaluated],
) -> Figure {
    let panels = scene
        .panels
        .iter()
        .zip(feeds)
        .map(|(panel, feed)| {
            let named = panel
                .curves
                .iter()
                .map(|c| (c.label.clone(), c.curve.canonical_json(), c.style))
                .chain(
                    panel
                        .data
                        .iter()
                        .map(|d| (d.label.clone(), d.dataset.canonical_json(), d.style)),
                );
            Panel {
                title: panel.title.clone(),
                x_label: panel.x_label.clone(),
                y_label: panel.y_label.clone(),
                x_unit: panel.x_unit,
                kind: panel.kind.clone(),
                y_scale: panel.y_scale,
                x_range: match panel.x_unit {
                    XUnit::Plain => panel.x_range,
                    _ => Some(panel.theta_range()),
                },
                y_range: panel.y_range,
                legend: panel.legend,
                series: named
                    .zip(feed)
                    .map(|((label, curve, style), &job)| Series {
                        label,
                        curve,
                        style,
                        points: evaluated[job].points.clone(),
                        z: evaluated[job].z.clone(),
                        grid: evaluated[job].grid,
                    })
                    .collect(),
            }
        })
        .collect();
    Figure {
        id: scene.id.clone(),
        title: scene.title.clone(),
        rows: scene.rows,
        cols: scene.cols,
        canvas: scene.canvas,
        theme: scene.theme,
        panels,
        provenance: provenance.clone(),
    }
}

/// The bytes of one output of a figure (see [`encode_all`]).
pub fn encode(figure: &Figure, format: Format) -> Result<Vec<u8>> {
    Ok(encode_all(figure, &[format])?.remove(0))
}

/// The bytes of each of `formats` of a figure, in order. The PDF is converted from the figure's
/// SVG, which is drawn once when both are asked for.
pub fn encode_all(figure: &Figure, formats: &[Format]) -> Result<Vec<Vec<u8>>> {
    let plot_error =
        |e: plot::PlotError| Error::Numerics(format!("{}: drawing failed: {e}", figure.id));
    let mut svg: Option<Vec<u8>> = None;
    let mut encoded = Vec::with_capacity(formats.len());
    for &format in formats {
        encoded.push(match format {
            Format::Svg | Format::Pdf => {
                let svg = match svg {
                    Some(ref drawn) => drawn,
                    None => svg.insert(plot::svg(figure).map_err(plot_error)?),
                };
                if format == Format::Svg {
                    svg.clone()
                } else {
                    pdf::from_svg(svg, &figure.title, &figure.provenance).map_err(|e| {
                        Error::Numerics(format!("{}: PDF conversion failed: {e}", figure.id))
                    })?
                }
            }
            Format::Png => plot::png(figure).map_err(plot_error)?,
            Format::Csv => figure_csv(figure),
            Format::Html => unreachable!("pages are built from scenes, by `pages`"),
        });
    }
    Ok(encoded)
}

/// The interactive page of every scene that has sliders.
fn pages(scenes: &[Scene]) -> Result<Vec<(String, Vec<u8>)>> {
    scenes
        .iter()
        .filter_map(|s| s.interactive.as_ref().map(|i| (s, i)))
        .map(|(scene, interactive)| {
            Ok((
                format!("{}.html", scene.id),
                html::page(scene, interactive).map_err(Error::Numerics)?,
            ))
        })
        .collect()
}

/// Renders the scenes of `options` into its output folder; returns the files written.
pub fn run(options: &RenderOptions) -> Result<Vec<PathBuf>> {
    run_with_stats(options).map(|(written, _)| written)
}

/// Where a render run spent its time and work.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct RenderStats {
    /// Reading, planning and evaluating (wall time).
    pub evaluation: std::time::Duration,
    /// Drawing SVG, PNG and PDF, rasterization, PNG compression and PDF conversion included
    /// (wall time).
    pub drawing: std::time::Duration,
    /// Formatting CSV and writing every file (wall time).
    pub encoding: std::time::Duration,
    /// Curve evaluations over all jobs.
    pub evaluations: usize,
    /// Outputs produced per format, in [`Format::ALL`] order without HTML: SVG, PNG, PDF, CSV.
    pub produced: [usize; 4],
}

/// [`run`], also returning where the time went.
pub fn run_with_stats(options: &RenderOptions) -> Result<(Vec<PathBuf>, RenderStats)> {
    run_with_progress(options, true)
}

/// [`run_with_stats`] with a progress bar on stderr unless `quiet` (see [`Progress`]).
pub fn run_with_progress(
    options: &RenderOptions,
    quiet: bool,
) -> Result<(Vec<PathBuf>, RenderStats)> {
    let (outputs, mut stats) = encode_outputs(options, false, quiet)?;
    let stage = std::time::Instant::now();
    let written = write_outputs(&options.out, &outputs)?;
    stats.encoding += stage.elapsed();
    Ok((written, stats))
}

/// `render --check DIR`: re-renders the CSVs of `options` (writing nothing) and compares them with
/// DIR's at a relative `tolerance`; prints every difference, and fails (exit 1) on any. The tables
/// are planned as a run with `options.formats` plans them (adaptive tables depend on whether PNG
/// is drawn), but only CSV is encoded.
pub fn check(options: &RenderOptions, dir: &Path, tolerance: f64, quiet: bool) -> Result<()> {
    let mut options = options.clone();
    if !options.formats.contains(&Format::Csv) {
        options.formats.push(Format::Csv);
    }
    let (outputs, _) = encode_outputs(&options, true, quiet)?;
    let (report, ok) = check_outputs::compare(dir, &outputs, tolerance)?;
    crate::stdout::print(&report)?;
    if ok {
        Ok(())
    } else {
        Err(Error::CheckFailed(format!(
            "error: render --check: the CSVs differ from {}",
            dir.display()
        )))
    }
}

/// Output files as (file name, bytes).
type Files = Vec<(String, Vec<u8>)>;

/// Every output of `options` as (file name, bytes), sorted by name, without writing anything; only
/// the CSVs when `tables_only`.
fn encode_outputs(
    options: &RenderOptions,
    tables_only: bool,
    quiet: bool,
) -> Result<(Files, RenderStats)> {
    let start = std::time::Instant::now();
    let sources = sources(&options.paths)?;
    let scenes = load_scenes(&sources, options.canvas)?;
    let provenance: Vec<Provenance> = sources
        .iter()
        .map(|(_, text, _)| Provenance::of_spec(text.as_bytes()))
        .collect();
    let has = |f: Format| options.formats.contains(&f);
    let outputs = Outputs {
        drawn: !tables_only && (has(Format::Svg) || has(Format::Png) || has(Format::Pdf)),
        table: has(Format::Csv),
    };
    let plan = plan(&scenes, outputs, has(Format::Png));
    let encoded_formats = if tables_only {
        1
    } else {
        options
            .formats
            .iter()
            .filter(|&&f| f != Format::Html)
            .count()
    };
    let progress = Progress::new(
        (plan.jobs.len() + scenes.len() * encoded_formats) as u64,
        quiet,
    );
    progress.stage("evaluating");
    let evaluated = evaluate_all(&plan)?;
    progress.advance(plan.jobs.len() as u64);
    progress.stage("encoding");
    let mut stats = RenderStats {
        evaluation: start.elapsed(),
        evaluations: evaluated.iter().map(|e| e.evaluations).sum(),
        ..RenderStats::default()
    };
    let mut outputs: Vec<(String, Vec<u8>)> = Vec::new();
    for (kind, feeds) in [(true, &plan.drawn), (false, &plan.table)] {
        let Some(feeds) = feeds else { continue };
        let stage = std::time::Instant::now();
        let formats: Vec<Format> = options
            .formats
            .iter()
            .copied()
            .filter(|&f| f != Format::Html && (f != Format::Csv) == kind)
            .collect();
        let figures: Vec<Figure> = scenes
            .iter()
            .zip(&provenance)
            .zip(feeds)
            .map(|((s, p), f)| figure(s, p, f, &evaluated))
            .collect();
        let encoded: Vec<Vec<(String, Vec<u8>)>> = figures
            .par_iter()
            .map(|fig| {
                let bytes = encode_all(fig, &formats)?;
                progress.advance(formats.len() as u64);
                Ok(formats
                    .iter()
                    .map(|format| format!("{}.{}", fig.id, format.extension()))
                    .zip(bytes)
                    .collect())
            })
            .collect::<Result<_>>()?;
        for &format in &formats {
            stats.produced[format as usize] += figures.len();
        }
        outputs.extend(encoded.into_iter().flatten());
        *(if kind {
            &mut stats.drawing
        } else {
            &mut stats.encoding
        }) += stage.elapsed();
    }
    let stage = std::time::Instant::now();
    if has(Format::Html) && !tables_only {
        outputs.extend(pages(&scenes)?);
    }
    outputs.sort_by(|a, b| a.0.cmp(&b.0));
    stats.encoding += stage.elapsed();
    Ok((outputs, stats))
}

fn write_outputs(dir: &Path, outputs: &[(String, Vec<u8>)]) -> Result<Vec<PathBuf>> {
    write::ensure_dir(dir)?;
    let mut written = Vec::with_capacity(outputs.len());
    for (name, bytes) in outputs {
        write::remove_stale(dir, name)?;
        write::write_atomic(dir, name, bytes)?;
        written.push(dir.join(name));
    }
    Ok(written)
}
