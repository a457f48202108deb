//! The library entry point of a render: spec sources → validated scenes → resolved scenes → plan
//! → evaluated jobs → figures → encoded outputs → files. `ndfplot render`, `render --check`, the tests, the benches and the
//! fuzzer all call it.
//!
//! Every spec is read, validated and resolved before anything is evaluated or written, so a bad spec
//! writes no file at all; then the plan is evaluated in parallel and each output is written
//! atomically through [`crate::output::write`].

use crate::error::{Error, Result};
use crate::output::stored;
use crate::output::{Format, Points, draw, encode_drawn, encoding_cost, write};
use crate::pipeline::figure::Figure;
use crate::pipeline::plan::{Feeds, Outputs, Plan, plan};
use crate::pipeline::progress::Progress;
use crate::pipeline::provenance::Provenance;
use crate::pipeline::resolve;
use crate::pipeline::sample::{Evaluated, JobError, STEPS_PER_JOB, evaluate_all_counted};
use crate::problem::{Problem, Problems};
use crate::spec::source::{CanvasOverride, Source, load_scenes, sources};
use rayon::prelude::*;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

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
    /// Folders data files may also be read from, beside each spec's own (`--allow-read`).
    pub allow_read: Vec<PathBuf>,
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
    /// Drawing and encoding every output — SVG, PNG and PDF (rasterization, PNG compression and
    /// PDF conversion included), CSV and HTML (wall time).
    pub drawing: std::time::Duration,
    /// Renaming every file into place (wall time): each is written to its temporary as soon as it
    /// is encoded, within `drawing`.
    pub writing: std::time::Duration,
    /// Curve evaluations over all jobs.
    pub evaluations: usize,
    /// Outputs produced per format (formats with none left out).
    pub produced: BTreeMap<Format, usize>,
    /// The figure lint's findings on the drawn figures, one line each (`FILE: panels[i]: …`),
    /// in source order.
    pub warnings: Vec<String>,
    /// Scenes rendered.
    pub scenes: usize,
    /// One line per drawn figure, in source order, for `-v` ([`FigureDetail`]).
    pub figures: Vec<FigureDetail>,
}

/// What `-v` says of one drawn figure: its source, id, size, what it holds and how long its
/// drawing and encoding took.
#[derive(Debug, Clone, PartialEq)]
pub struct FigureDetail {
    /// The spec file or catalogue id.
    pub source: String,
    /// The figure's id (its files' stem).
    pub id: String,
    /// Width and height in CSS pixels.
    pub size_px: (u32, u32),
    /// The printed size, `3.3 × 2.47 in`, when the spec or preset gave one.
    pub print: Option<String>,
    /// Panels.
    pub panels: usize,
    /// Series over all panels.
    pub series: usize,
    /// Points drawn over all series.
    pub points: usize,
    /// The figure lint's findings on it.
    pub warnings: usize,
    /// What the drawing chose where the spec left it open, one line each
    /// (`panels[0]: legend of 4 entries inside the plot, clear of the curves, 1 column at 100 % size`).
    pub decisions: Vec<String>,
    /// Assembling, drawing and encoding its drawn formats (wall time, summed over the workers
    /// that ran its encodings).
    pub drawing: std::time::Duration,
}

impl FigureDetail {
    /// `render: <source>: <id>: 1100 × 800 px (3.3 × 2.4 in), 2 panels, 7 series, 3 214 points,
    /// 0 warnings, drawn in 41 ms`, then one `render: <source>: panels[i]: <decision>` line per
    /// decision.
    pub fn line(&self) -> String {
        let print = self
            .print
            .as_ref()
            .map_or_else(String::new, |p| format!(" ({p})"));
        format!(
            "render: {}: {}: {} × {} px{print}, {} panels, {} series, {} points, {} warnings, drawn in {} ms",
            self.source,
            self.id,
            self.size_px.0,
            self.size_px.1,
            self.panels,
            self.series,
            self.points,
            self.warnings,
            self.drawing.as_millis()
        ) + &self
            .decisions
            .iter()
            .map(|d| format!("\nrender: {}: {d}", self.source))
            .collect::<String>()
    }

    fn of(
        figure: &Figure,
        source: &str,
        linted: &crate::output::plot::Linted,
        drawing: std::time::Duration,
    ) -> Self {
        FigureDetail {
            source: source.to_string(),
            id: figure.id.clone(),
            size_px: (figure.canvas.width_px, figure.canvas.height_px),
            print: figure
                .canvas
                .print
                .map(|p| format!("{:.2} × {:.2} {}", p.width, p.height, p.unit.symbol())),
            panels: figure.panels.len(),
            series: figure.panels.iter().map(|p| p.series.len()).sum(),
            points: figure.point_count(),
            warnings: linted.findings.len(),
            decisions: linted
                .decisions
                .iter()
                .map(|d| match d.panel {
                    Some(i) => format!("panels[{i}]: {}", d.message),
                    None => d.message.clone(),
                })
                .collect(),
            drawing,
        }
    }
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
    // Each file is staged as soon as it is encoded, while other figures are still drawn.
    let staging = write::Staging::new("-o", &options.out);
    let sources = sources(&options.paths, &options.allow_read)?;
    let (staged, mut stats) = encode_sources(&sources, options, quiet, &|name, bytes| {
        staging.stage(name, &bytes)
    })?;
    let stage = std::time::Instant::now();
    let written = staging.commit(staged.into_iter().map(|(_, file)| file).collect())?;
    stats.writing = stage.elapsed();
    Ok((written, stats))
}

/// `render --check DIR`: re-renders the CSVs and SVGs of `options` (writing nothing) and compares
/// them with DIR's ([`stored::compare`]: values at a relative `tolerance`, then the drawing
/// of figures whose values match); prints every difference, and fails (exit 1) on any, else
/// returns the run's stats. Only CSV and SVG are encoded, whatever `options.formats` says.
pub fn check(
    options: &RenderOptions,
    dir: &Path,
    tolerance: f64,
    quiet: bool,
) -> Result<RenderStats> {
    let options = RenderOptions {
        formats: vec![Format::Svg, Format::Csv],
        ..options.clone()
    };
    let (outputs, stats) = encode_outputs(&options, quiet)?;
    let (report, ok) = stored::compare(dir, &outputs, tolerance)?;
    crate::output::stdout::print(&report)?;
    if ok {
        Ok(stats)
    } else {
        let shown = crate::problem::one_line(&dir.display().to_string()).into_owned();
        Err(Error::CheckFailed(format!(
            "error: render --check: the figures differ from {shown}; if the change is intended, render the same specs with -o {shown} (instead of --check {shown}) and commit the result"
        )))
    }
}

/// The drawn figures of the specs at `paths` (empty: the built-in catalogue; data files read from
/// each spec's folder and `allow_read`) under `canvas`, in source order — what SVG, PNG and PDF are
/// encoded from — without encoding or writing anything; the figure lint reads them.
pub fn drawn_figures(
    paths: &[PathBuf],
    allow_read: &[PathBuf],
    canvas: CanvasOverride,
) -> Result<Vec<Figure>> {
    let sources = sources(paths, allow_read)?;
    let scenes = resolve::scenes(load_scenes(&sources, canvas))?;
    let provenance: Vec<Provenance> = sources
        .iter()
        .map(|(_, text, _)| Provenance::of_spec(text.as_bytes()))
        .collect();
    let outputs = Outputs {
        drawn: true,
        table: false,
    };
    let plan = plan(&scenes, outputs);
    let evaluated = evaluate(&plan, &sources, &Progress::new(0, true))?;
    let feeds = plan.drawn.as_ref().expect("drawn outputs were planned");
    Ok(scenes
        .iter()
        .zip(&provenance)
        .zip(feeds)
        .map(|((s, p), f)| Figure::assemble(s, p, f, &evaluated))
        .collect())
}

/// Every job of `plan` evaluated ([`evaluate_all_counted`], counted on `progress`); a job that
/// fails is reported against the spec it came from (`sources`, in scene order): its file, the JSON
/// path of its panel and its series there.
fn evaluate(plan: &Plan, sources: &[Source], progress: &Progress) -> Result<Vec<Evaluated>> {
    evaluate_all_counted(plan, &|steps| progress.advance(steps)).map_err(
        |JobError { job, error }| {
            let message = match error {
                Error::Numerics(message) => message,
                other => other.to_string(),
            };
            match plan.first_use(job) {
                Some((scene, panel, series)) => Error::Input(vec![Problems {
                    source: sources[scene].0.clone(),
                    list: vec![Problem::new(
                        format!("panels[{panel}]"),
                        format!("series {series}: {message}"),
                    )],
                }]),
                None => Error::Numerics(message),
            }
        },
    )
}

/// Output files as (file name, bytes).
type Files = Vec<(String, Vec<u8>)>;

/// Every output of `options` as (file name, bytes), sorted by name, without writing anything.
fn encode_outputs(options: &RenderOptions, quiet: bool) -> Result<(Files, RenderStats)> {
    encode_sources(
        &sources(&options.paths, &options.allow_read)?,
        options,
        quiet,
        &|_, bytes| Ok(bytes),
    )
}

/// `render -o -`: the one output of `options` — one figure in one format — as bytes, for standard
/// output. Several formats, several figures, or no output (`html` for a scene without sliders) is a
/// usage error (exit 2) before anything is written. Returns the bytes and the run's stats
/// (the figure lint's findings among them).
pub fn to_stdout(options: &RenderOptions, quiet: bool) -> Result<(Vec<u8>, RenderStats)> {
    let refuse = |what: String| {
        Err(Error::Usage(format!(
            "-o -: writes one figure in one format to stdout ({what})"
        )))
    };
    if let [_, _, ..] = options.formats[..] {
        let names: Vec<&str> = options.formats.iter().map(|f| f.extension()).collect();
        return refuse(format!(
            "got {} formats: {}; expected one, e.g. --format svg",
            names.len(),
            names.join(",")
        ));
    }
    let sources = sources(&options.paths, &options.allow_read)?;
    if sources.len() != 1 {
        return refuse(format!(
            "got {} specs; expected one spec file, catalogue id or -",
            sources.len()
        ));
    }
    let (mut outputs, stats) = encode_sources(&sources, options, quiet, &|_, bytes| Ok(bytes))?;
    match outputs.pop() {
        Some((_, bytes)) if outputs.is_empty() => Ok((bytes, stats)),
        _ => refuse(format!(
            "{} has no output in --format {}: html is written only for scenes with sliders",
            sources[0].0,
            options
                .formats
                .iter()
                .map(|f| f.extension())
                .collect::<Vec<_>>()
                .join(",")
        )),
    }
}

/// What one scene gave: its files as (format, file name, what was kept of the bytes), the figure
/// lint's findings as lines, and what `-v` says of its drawn figure.
struct Encoded<T> {
    files: Vec<(Format, String, T)>,
    findings: Vec<String>,
    detail: Option<FigureDetail>,
}

/// Scenes per worker thread in one chunk of [`EncodeScope::encode`]: enough that the dearest
/// encodings of a chunk can be run first and the cheap ones fill the cores at its end.
const SCENES_PER_THREAD: usize = 32;

/// What encoding reads: the scenes, their sources and provenance, the evaluated plan, the formats
/// asked for and the progress to advance.
struct EncodeScope<'a> {
    scenes: &'a [crate::spec::scene::Scene],
    provenance: &'a [Provenance],
    sources: &'a [Source],
    plan: &'a Plan,
    evaluated: &'a [Evaluated],
    drawn_formats: &'a [Format],
    table_formats: &'a [Format],
    progress: &'a Progress,
}

/// One scene's figures, assembled from the evaluated plan: the drawn one with its drawing (the
/// SVG, when a format needs it) and what the lint found, and the tabulated one.
struct Assembled {
    drawn: Option<(Figure, Option<Vec<u8>>, crate::output::plot::Linted)>,
    table: Option<Figure>,
    /// Assembling and drawing it (wall time on one worker).
    took: std::time::Duration,
}

impl Assembled {
    /// The figure `points` names, and its drawing when one was made; `None` when the plan has no
    /// such figure.
    fn figure(&self, points: Points) -> Option<(&Figure, Option<&[u8]>)> {
        match points {
            Points::Drawn => self
                .drawn
                .as_ref()
                .map(|(figure, drawing, _)| (figure, drawing.as_deref())),
            Points::Table => self.table.as_ref().map(|figure| (figure, None)),
        }
    }
}

/// One encoding of a chunk: the scene at index `scene` of the chunk in `format`, from the figure
/// `points` names, with its estimated cost ([`encoding_cost`]).
#[derive(Debug, Clone, Copy)]
struct Task {
    scene: usize,
    points: Points,
    format: Format,
    cost: f64,
}

/// What one encoding gave: its file name and what `keep` returned, when the figure has an output
/// in the format.
type Kept<T> = Result<Option<(String, T)>>;

impl EncodeScope<'_> {
    /// Every output of the scenes `range`, each handed to `keep` as soon as it is encoded, as one
    /// [`Encoded`] (or the scene's first failure) per scene in source order.
    ///
    /// Two steps, each in parallel: every scene's figures are assembled and drawn; then every
    /// (scene, format) encoding is run, the dearest first ([`encoding_cost`]), each on the next
    /// free worker — the longest rasterizations start early, and the short ones fill the cores
    /// at the end instead of one large one running alone.
    fn encode<T: Send>(
        &self,
        range: std::ops::Range<usize>,
        keep: &(dyn Fn(&str, Vec<u8>) -> Result<T> + Sync),
    ) -> Vec<Result<Encoded<T>>> {
        let first = range.start;
        let assembled: Vec<Result<Assembled>> =
            range.into_par_iter().map(|i| self.assemble(i)).collect();
        let mut tasks = Vec::new();
        for (k, scene) in assembled.iter().enumerate() {
            let Ok(scene) = scene else { continue };
            for (points, formats) in [
                (Points::Drawn, self.drawn_formats),
                (Points::Table, self.table_formats),
            ] {
                if let Some((figure, drawing)) = scene.figure(points) {
                    tasks.extend(formats.iter().map(|&format| Task {
                        scene: k,
                        points,
                        format,
                        cost: encoding_cost(figure, drawing, format),
                    }));
                }
            }
        }
        // Dearest first; equal costs in source order.
        tasks.sort_by(|a, b| b.cost.total_cmp(&a.cost));
        let done: Vec<(usize, Kept<T>, std::time::Duration)> = tasks
            .iter()
            .enumerate()
            .par_bridge()
            .map(|(t, task)| {
                let (figure, drawing) = assembled[task.scene]
                    .as_ref()
                    .ok()
                    .and_then(|scene| scene.figure(task.points))
                    .expect("a task is made only for a figure assembled");
                let started = std::time::Instant::now();
                let kept = encode_drawn(figure, drawing, task.format)
                    .and_then(|bytes| self.kept(figure, task.format, bytes, keep));
                self.progress.advance(1);
                (t, kept, started.elapsed())
            })
            .collect();
        // Per scene, its encodings in format order: drawn, then tabulated.
        let mut per_scene: Vec<Vec<_>> = (0..assembled.len()).map(|_| Vec::new()).collect();
        for (t, kept, elapsed) in done {
            let Task {
                scene,
                points,
                format,
                ..
            } = tasks[t];
            per_scene[scene].push(((points == Points::Table, format), kept, elapsed));
        }
        assembled
            .into_iter()
            .zip(per_scene)
            .enumerate()
            .map(|(k, (scene, mut encodings))| {
                let scene = scene?;
                encodings.sort_by_key(|(order, ..)| *order);
                let mut encoded = Encoded {
                    files: Vec::new(),
                    findings: Vec::new(),
                    detail: None,
                };
                let mut took = scene.took;
                for ((table, format), kept, elapsed) in encodings {
                    if !table {
                        took += elapsed;
                    }
                    encoded
                        .files
                        .extend(kept?.map(|(name, kept)| (format, name, kept)));
                }
                if let Some((figure, _, linted)) = &scene.drawn {
                    let source = &self.sources[first + k].0;
                    encoded.findings = linted.findings.iter().map(|f| f.line(source)).collect();
                    encoded.detail = Some(FigureDetail::of(figure, source, linted, took));
                }
                Ok(encoded)
            })
            .collect()
    }

    /// Scene `i`'s figures assembled, and its drawing made when a drawn format needs it.
    fn assemble(&self, i: usize) -> Result<Assembled> {
        let started = std::time::Instant::now();
        let (scene, provenance) = (&self.scenes[i], &self.provenance[i]);
        let figure = |feeds: &Option<Feeds>| {
            feeds
                .as_ref()
                .map(|feeds| Figure::assemble(scene, provenance, &feeds[i], self.evaluated))
        };
        let drawn = match figure(&self.plan.drawn) {
            Some(figure) if self.drawn_formats.iter().any(|f| f.from_drawing()) => {
                let (drawing, linted) = draw(&figure)?;
                Some((figure, Some(drawing), linted))
            }
            Some(figure) => Some((figure, None, Default::default())),
            None => None,
        };
        Ok(Assembled {
            drawn,
            table: figure(&self.plan.table),
            took: started.elapsed(),
        })
    }

    /// `bytes` of `figure` in `format`, when there are any, handed to `keep` under the file name
    /// `<id>.<extension>`, as (file name, what `keep` returned).
    fn kept<T>(
        &self,
        figure: &Figure,
        format: Format,
        bytes: Option<Vec<u8>>,
        keep: &(dyn Fn(&str, Vec<u8>) -> Result<T> + Sync),
    ) -> Result<Option<(String, T)>> {
        bytes
            .map(|bytes| {
                let name = format!("{}.{}", figure.id, format.extension());
                keep(&name, bytes).map(|kept| (name, kept))
            })
            .transpose()
    }
}

/// Every output of spec `sources` (already read) under `options`, each handed to `keep` (its file
/// name and bytes) as soon as it is encoded, as (file name, what `keep` returned), sorted by name.
fn encode_sources<T: Send>(
    sources: &[crate::spec::source::Source],
    options: &RenderOptions,
    quiet: bool,
    keep: &(dyn Fn(&str, Vec<u8>) -> Result<T> + Sync),
) -> Result<(Vec<(String, T)>, RenderStats)> {
    let start = std::time::Instant::now();
    let scenes = resolve::scenes(load_scenes(sources, options.canvas))?;
    let provenance: Vec<Provenance> = sources
        .iter()
        .map(|(_, text, _)| Provenance::of_spec(text.as_bytes()))
        .collect();
    let needs = |points: Points| options.formats.iter().any(|f| f.points() == points);
    let outputs = Outputs {
        drawn: needs(Points::Drawn),
        table: needs(Points::Table),
    };
    let plan = plan(&scenes, outputs);
    let progress = Progress::new(
        plan.jobs.len() as u64 * STEPS_PER_JOB + (scenes.len() * options.formats.len()) as u64,
        quiet,
    );
    progress.stage("evaluating");
    let evaluated = evaluate(&plan, sources, &progress)?;
    progress.stage("encoding");
    let mut stats = RenderStats {
        evaluation: start.elapsed(),
        evaluations: evaluated.iter().map(|e| e.evaluations).sum(),
        scenes: scenes.len(),
        ..RenderStats::default()
    };
    let formats_of = |points: Points| -> Vec<Format> {
        options
            .formats
            .iter()
            .copied()
            .filter(|f| f.points() == points)
            .collect()
    };
    let (drawn_formats, table_formats) = (formats_of(Points::Drawn), formats_of(Points::Table));
    let stage = std::time::Instant::now();
    let scope = EncodeScope {
        scenes: &scenes,
        provenance: &provenance,
        sources,
        plan: &plan,
        evaluated: &evaluated,
        drawn_formats: &drawn_formats,
        table_formats: &table_formats,
        progress: &progress,
    };
    // Scenes a chunk at a time, so that memory holds the drawings of one chunk however many
    // scenes there are; chunks in source order, so the first failure met is the first in source order.
    let chunk = SCENES_PER_THREAD * rayon::current_num_threads().max(1);
    let mut outputs = Vec::new();
    for first in (0..scenes.len()).step_by(chunk) {
        for encoded in scope.encode(first..(first + chunk).min(scenes.len()), keep) {
            let encoded = encoded?;
            stats.warnings.extend(encoded.findings);
            stats.figures.extend(encoded.detail);
            for (format, name, bytes) in encoded.files {
                *stats.produced.entry(format).or_default() += 1;
                outputs.push((name, bytes));
            }
        }
    }
    outputs.sort_by(|a, b| a.0.cmp(&b.0));
    stats.drawing = stage.elapsed();
    Ok((outputs, stats))
}
