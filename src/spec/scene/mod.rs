//! Scenes (figure specs): the JSON format and its validation into a [`Scene<Spec>`] that holds only
//! valid curves, styles and axes. Every problem of a spec is reported with its JSON path.
//!
//! The spec stage reads nothing but the spec and computes nothing: fits, Belcour coefficients,
//! `l2_grid` errors in labels and data files are described ([`CurveSpec`], [`Label`],
//! [`data::DataSpec`]) and left to [`crate::pipeline::resolve`], which makes the [`Scene<Resolved>`] (plain
//! [`Scene`]) the later stages take.
//!
//! A scene is an `id`, a `title`, a grid of panels (a row by default, like Mathematica's
//! `GraphicsRow`), canvas settings and, per panel, axes, a legend and curves. Curves use the
//! curve format of `eval`; any parameter may be swept (see [`sweep`]).

pub mod data;
pub mod interactive;
pub mod reader;
pub mod sweep;

use crate::model::curve::{Curve, Kind};
use crate::model::dataset::Dataset;
use crate::model::transform::Transform;
use crate::problem::{Problem, join_index, join_key, suggestion};
use crate::spec::curve::{self, CurveSpec, Fitted, Label, Model, ParamValue, Part};
use crate::spec::json::{Node, Value};
use crate::spec::look::{self, CSS_PX_PER_INCH};
use crate::spec::look::{
    Annotation, Axes, Canvas, Corner, Dash, Dimension, LegendPlace, Mark, PanelKind, Rgb, Scale,
    Style, SweepMember, Theme, TickChoice, XUnit, shade,
};
use reader::Reader;
use std::f64::consts::FRAC_PI_2;
use sweep::{MAX_CURVES_PER_SCENE, Sweep};

/// Most samples one curve may have (docs/contracts.md).
pub const MAX_SAMPLES_PER_CURVE: usize = 10_000_000;
/// Most points one scene's table may have, summed over its curves (curves × uniform samples) and
/// data series: the default 1000 samples for 5000 curves (the 10 000 curves of
/// [`MAX_CURVES_PER_SCENE`] at 500 samples). Its CSV is about 500 MB, and a run at the cap stays
/// under 1 GiB.
pub const MAX_POINTS_PER_SCENE: usize = 5_000_000;
/// Most integrals (albedo values, [`crate::model::curve::Curve::integrals_per_value`]) one scene
/// may ask for, counted before any is computed: each curve of integrals at its table's samples
/// plus its drawing's most (an adaptive drawing's evaluation cap, or its samples). The default
/// 1000 samples and adaptive drawing make 2033 a curve: 49 albedo curves a scene. `eval`
/// holds its θ count × curves of integrals to it too.
pub const MAX_INTEGRALS: usize = 100_000;
/// Default number of uniform samples per curve over the visible θ range.
pub const DEFAULT_SAMPLES: usize = 1000;
/// Largest figure side in CSS pixels; beyond it rasters exhaust memory for no visible gain.
pub const MAX_SIDE_PX: f64 = 20_000.0;
/// Keys a scene may have.
pub const SCENE_KEYS: &[&str] = &[
    "$schema",
    "id",
    "title",
    "layout",
    "aspect_ratio",
    "width",
    "height",
    "font_px",
    "font_pt",
    "png_scale",
    "dpi",
    "unit",
    "preset",
    "sampling",
    "theme",
    "panel_letters",
    "background",
    "font",
    "panels",
    "interactive",
];
/// Names of the paper presets (`preset`), as [`look::Preset::NAMES`] has them.
pub const PRESETS: &[&str] = &["paper-column", "paper-page"];
/// Names of the themes (`theme`), in [`Theme`] order; `color-blind` is the other spelling of
/// `colour-blind`.
pub const THEMES: &[&str] = &["notebook", "colour-blind", "color-blind", "dark"];
/// Keys of `layout`.
pub const LAYOUT_KEYS: &[&str] = &["rows", "cols"];
/// Keys of `sampling` (exactly one of them).
pub const SAMPLING_KEYS: &[&str] = &["uniform", "adaptive"];
/// Keys of `sampling.adaptive`.
pub const ADAPTIVE_KEYS: &[&str] = &["tolerance_px"];
/// Keys a panel may have.
pub const PANEL_KEYS: &[&str] = &[
    "title",
    "kind",
    "view",
    "transform",
    "x",
    "y",
    "z",
    "camera",
    "legend",
    "grid",
    "curves",
    "annotations",
];
/// Keys of one of a panel's `annotations`: `x` or `y` (a value: a line; `[a, b]`: a band) with a
/// `label`, or `text` with `at`.
pub const ANNOTATION_KEYS: &[&str] = &["x", "y", "label", "text", "at"];
/// Most annotations a panel may have.
pub const MAX_ANNOTATIONS: usize = 64;
/// Panel kinds (`kind`).
pub const PANEL_KINDS: &[&str] = &["cartesian", "surface", "heatmap"];
/// Views of a cartesian panel (`view`).
pub const VIEWS: &[&str] = &["cartesian", "polar"];
/// Value transforms a panel applies to its NDF curves (`transform`).
pub const PANEL_TRANSFORMS: &[&str] = &["projected", "slope"];
/// The slope range (tan θ) a slope axis shows when its `range` is not given.
pub const DEFAULT_SLOPE_RANGE: (f64, f64) = (0.0, 4.0);
/// Keys of a panel's `x` axis.
pub const X_KEYS: &[&str] = &["unit", "scale", "range", "label", "ticks"];
/// Units of an `x` axis.
pub const X_UNITS: &[&str] = &["radians", "degrees", "slope", "plain"];
/// Keys of a surface or heat-map panel's `z` axis.
pub const Z_KEYS: &[&str] = &["range", "label"];
/// Keys of a surface panel's `camera`.
pub const CAMERA_KEYS: &[&str] = &["elevation", "azimuth"];
/// Keys of a panel's `y` axis.
pub const Y_KEYS: &[&str] = &["scale", "range", "label", "ticks"];
/// Scales of an axis.
pub const SCALES: &[&str] = &["linear", "log"];
/// Keys of a scene curve beyond its model parameters (`color` is the other spelling of `colour`).
pub const CURVE_EXTRA_KEYS: &[&str] = &["style", "colour", "color", "label", "mark", "width"];
/// Places a panel's `legend` may name, besides `true` and `false`.
pub const LEGEND_PLACES: &[&str] = &[
    "best",
    "upper right",
    "upper left",
    "lower left",
    "lower right",
    "right",
    "below",
    "none",
];
/// A scene's `font`: the embedded typefaces, as [`look::Face::NAMES`] has them.
pub const FONTS: &[&str] = &["sans", "serif"];
/// A scene's `background`: the theme's page colour, or none.
pub const BACKGROUNDS: &[&str] = &["opaque", "transparent"];
/// Units of a scene's `width` and `height` (`unit`): CSS pixels, inches, centimetres.
pub const SIZE_UNITS: &[&str] = &["px", "in", "cm"];
/// Most ticks a spec may ask for by count.
pub const MAX_TICK_COUNT: usize = 20;
/// Least and most line width a curve's `width` may set, in multiples of the default.
pub const LINE_WIDTHS: (f64, f64) = (0.25, 10.0);
/// Words of a series' `style`.
pub const STYLE_WORDS: &[&str] = &["thick", "dashed", "dotted", "solid"];
/// Values of a series' `mark`.
pub const MARKS: &[&str] = &["line", "points", "line_points", "bars"];

/// How curves are sampled over θ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Sampling {
    /// `n` evenly spaced θ over the panel's visible range, both ends included.
    Uniform(usize),
    /// Bisection where the drawn polyline would be more than `tolerance_px` from the curve, for
    /// figures and tables alike (see [`crate::pipeline::adaptive`]).
    Adaptive {
        /// Largest distance, in output pixels, between the polyline and the true curve.
        tolerance_px: f64,
    },
    /// No `"sampling"` key: figures adaptive at [`DEFAULT_TOLERANCE_PX`], CSV tables on a uniform
    /// grid of [`DEFAULT_SAMPLES`] points (tables stay uniform unless the spec asks otherwise).
    Default,
}

impl Sampling {
    /// The sampling of drawn outputs (SVG, PNG).
    pub fn for_drawing(self) -> Sampling {
        match self {
            Sampling::Default => Sampling::Adaptive {
                tolerance_px: DEFAULT_TOLERANCE_PX,
            },
            given => given,
        }
    }

    /// The sampling of tables (CSV).
    pub fn for_table(self) -> Sampling {
        match self {
            Sampling::Default => Sampling::Uniform(DEFAULT_SAMPLES),
            given => given,
        }
    }
}

/// Default adaptive tolerance: a quarter pixel, below what anti-aliasing can show.
pub const DEFAULT_TOLERANCE_PX: f64 = 0.25;
/// Smallest accepted tolerance: finer than 1/1000 px changes no pixel and only burns the budget.
pub const MIN_TOLERANCE_PX: f64 = 1e-3;

/// What a scene's series hold at a stage: [`Spec`] as the spec describes them, [`Resolved`] ready
/// to evaluate.
pub trait Stage: std::fmt::Debug + Clone {
    /// A curve.
    type Curve: std::fmt::Debug + Clone;
    /// A curve's legend label.
    type Label: std::fmt::Debug + Clone;
    /// A data series.
    type Data: std::fmt::Debug + Clone;
}

/// The spec stage's scenes ([`parse`]): every key and domain checked, the numerics and data files
/// described but not computed or read.
#[derive(Debug, Clone)]
pub struct Spec;

impl Stage for Spec {
    type Curve = CurveSpec;
    type Label = Label;
    type Data = data::DataSpec;
}

/// Resolved scenes ([`crate::pipeline::resolve`]): curves ready to evaluate, labels written out, data read.
#[derive(Debug, Clone)]
pub struct Resolved;

impl Stage for Resolved {
    type Curve = Curve;
    type Label = String;
    type Data = Dataset;
}

/// One curve as a scene shows it.
#[derive(Debug, Clone)]
pub struct SceneCurve<S: Stage = Resolved> {
    /// The validated curve.
    pub curve: S::Curve,
    /// Legend label.
    pub label: S::Label,
    /// Line style.
    pub style: Style,
}

/// A data series (not a function of θ) as a scene shows it.
#[derive(Debug, Clone)]
pub struct SceneData<S: Stage = Resolved> {
    /// The validated dataset.
    pub dataset: S::Data,
    /// Legend label.
    pub label: String,
    /// Line or mark style.
    pub style: Style,
}

/// A validated panel.
#[derive(Debug, Clone)]
pub struct ScenePanel<S: Stage = Resolved> {
    /// Titles, axes, scales, ranges and legend.
    pub axes: Axes,
    /// Curves in drawing order.
    pub curves: Vec<SceneCurve<S>>,
    /// Data series (not functions of θ), drawn after the curves.
    pub data: Vec<SceneData<S>>,
}

/// A validated scene.
#[derive(Debug, Clone)]
pub struct Scene<S: Stage = Resolved> {
    /// Id, matching `^[a-z0-9][a-z0-9_-]{0,63}$`; output files are `<id>.<ext>`.
    pub id: String,
    /// Figure title (may be empty).
    pub title: String,
    /// Grid rows.
    pub rows: usize,
    /// Grid columns.
    pub cols: usize,
    /// Size and typography.
    pub canvas: Canvas,
    /// Height of a panel over its width (`aspect_ratio`), for a canvas sized again by preset.
    pub aspect_ratio: f64,
    /// Sampling rule.
    pub sampling: Sampling,
    /// Colours and line distinctions.
    pub theme: Theme,
    /// Panels, row-major.
    pub panels: Vec<ScenePanel<S>>,
    /// Sliders and the curves they drive, for scenes with an `interactive` key.
    pub interactive: Option<interactive::Interactive>,
}

/// A spec with problems: the problems, and the fallible work (fits, data files) of the parts that
/// passed, so that resolve can report its problems together with the spec's own.
#[derive(Debug, Clone)]
pub struct Invalid {
    /// The spec's problems, in the order found.
    pub problems: Vec<Problem>,
    /// The fallible work the spec describes, in the order met.
    pub pending: Vec<Pending>,
}

/// A piece of work a spec leaves to resolve that can fail.
#[derive(Debug, Clone)]
pub enum Pending {
    /// A fit.
    Fit(Box<Fitted>),
    /// A data file to read.
    Csv(data::CsvFile),
}

/// Whether `id` is a valid scene id: `^[a-z0-9][a-z0-9_-]{0,63}$` (docs/contracts.md). Such an id
/// cannot name a path outside the output folder, a hidden file or a device.
pub fn valid_id(id: &str) -> bool {
    let bytes = id.as_bytes();
    !bytes.is_empty()
        && bytes.len() <= 64
        && (bytes[0].is_ascii_lowercase() || bytes[0].is_ascii_digit())
        && bytes
            .iter()
            .all(|&b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'_' || b == b'-')
}

/// Validates a parsed scene document into its description; every problem is returned with its
/// JSON path. Data files named by the spec are read from `data`, the spec's folder and the
/// folders allowed beside it (`None`: no data files); they are not read, nor is anything computed.
pub fn parse(
    node: &Node,
    data: Option<&crate::spec::datafile::DataScope>,
) -> Result<Scene<Spec>, Invalid> {
    let mut reader = Reader {
        data: data.cloned(),
        ..Reader::default()
    };
    let scene = read_scene(&mut reader, node);
    match scene {
        Some(scene) if reader.problems.is_empty() => Ok(scene),
        _ => Err(Invalid {
            problems: reader.problems,
            pending: reader.pending,
        }),
    }
}

fn read_scene(reader: &mut Reader, node: &Node) -> Option<Scene<Spec>> {
    let sliders = reader
        .object(node, "", SCENE_KEYS)
        .and_then(|object| interactive::read_sliders(reader, &object));
    // The figure at the sliders' start values; `interactive::read` checks their whole ranges.
    let at_start = interactive::at_start(reader, node, sliders.as_deref());
    let Value::Object(members) = &at_start.value else {
        return None;
    };
    let object = reader::Object::from_members(members, "");
    let id = match reader.string(&object, "id") {
        Some(id) if valid_id(&id) => Some(id),
        Some(id) => {
            reader.report("id", format!("invalid id (got \"{}\", expected ^[a-z0-9][a-z0-9_-]{{0,63}}$: lower-case letters, digits, '-' and '_', no paths)", crate::problem::excerpt(&id)));
            None
        }
        None => {
            if object.get("id").is_none() {
                reader.report(
                    "id",
                    "missing scene id (expected a string matching ^[a-z0-9][a-z0-9_-]{0,63}$)",
                );
            }
            None
        }
    };
    let title = reader.text(&object, "title").unwrap_or_default();
    let sampling = read_sampling(reader, &object);
    let theme = read_theme(reader, &object);
    let mut panels = read_panels(reader, &object);
    if reader.boolean(&object, "panel_letters") == Some(true) {
        for (i, panel) in panels.iter_mut().flatten().enumerate() {
            panel.axes.title = lettered(i, &panel.axes.title);
        }
    }
    let panel_count = panels.as_ref().map_or(1, Vec::len);
    let grid = read_layout(reader, &object, panel_count);
    let preset = reader
        .choice(&object, "preset", PRESETS)
        .and_then(look::Preset::named);
    let (rows, cols) = preset.map_or(grid, |p| p.grid(panel_count, grid));
    let aspect_ratio = read_aspect_ratio(reader, &object);
    let titles = look::Titles {
        figure: title.clone(),
        panels: panels
            .iter()
            .flatten()
            .map(|p| p.axes.title.clone())
            .collect(),
    };
    let canvas = read_canvas(reader, &object, preset, (rows, cols), aspect_ratio, &titles);
    if sliders.is_some() {
        check_interactive_views(reader, panels.as_deref().unwrap_or_default());
    }
    let interactive = interactive::read(reader, node, sliders, panels.as_deref());
    Some(Scene {
        id: id?,
        title,
        rows,
        cols,
        canvas: canvas?,
        aspect_ratio,
        sampling: sampling?,
        theme,
        panels: panels?,
        interactive,
    })
}

/// `title` of the panel at `index` with its letter in front, as papers letter their panels:
/// `(a) title`, `(b)` alone for no title; past `(z)`, `(aa)`, `(ab)`, ….
pub fn lettered(index: usize, title: &str) -> String {
    let letter = |k: usize| char::from(b'a' + (k % 26) as u8);
    let name: String = if index < 26 {
        letter(index).to_string()
    } else {
        [letter(index / 26 - 1), letter(index)].iter().collect()
    };
    if title.is_empty() {
        format!("({name})")
    } else {
        format!("({name}) {title}")
    }
}

/// The scene's `theme`, [`Theme::Notebook`] when absent (or invalid, which is reported).
fn read_theme(reader: &mut Reader, object: &reader::Object) -> Theme {
    theme_named(reader.choice(object, "theme", THEMES).unwrap_or("notebook"))
}

/// The theme called `name`, one of [`THEMES`].
pub fn theme_named(name: &str) -> Theme {
    match name {
        "colour-blind" | "color-blind" => Theme::ColourBlind,
        "dark" => Theme::Dark,
        _ => Theme::Notebook,
    }
}

/// Reports panels an interactive page cannot draw: its pages plot y against θ on cartesian axes,
/// x linear.
fn check_interactive_views(reader: &mut Reader, panels: &[ScenePanel<Spec>]) {
    for (i, panel) in panels.iter().enumerate() {
        let path = join_index("panels", i);
        if panel.axes.kind == PanelKind::Polar {
            reader.report(
                join_key(&path, "view"),
                "interactive pages draw cartesian panels (got \"polar\", expected \"cartesian\")",
            );
        }
        if panel.axes.x_unit == XUnit::Slope {
            reader.report(
                join_key(&join_key(&path, "x"), "unit"),
                "interactive pages draw θ axes (got \"slope\", expected radians or degrees)",
            );
        }
        if panel.axes.x_scale == Scale::Log {
            reader.report(
                join_key(&join_key(&path, "x"), "scale"),
                "interactive pages draw linear x axes (got \"log\", expected \"linear\")",
            );
        }
    }
}

fn read_sampling(reader: &mut Reader, object: &reader::Object) -> Option<Sampling> {
    let Some(node) = object.get("sampling") else {
        return Some(Sampling::Default);
    };
    let path = object.path_of("sampling");
    let sampling = reader.object(node, &path, SAMPLING_KEYS)?;
    match (sampling.get("uniform"), sampling.get("adaptive")) {
        (Some(_), None) => {
            let expected = format!("a whole number from 2 to {MAX_SAMPLES_PER_CURVE}");
            let ok = |v: f64| v.fract() == 0.0 && (2.0..=MAX_SAMPLES_PER_CURVE as f64).contains(&v);
            reader
                .number(&sampling, "uniform", ok, &expected)
                .map(|n| Sampling::Uniform(n as usize))
        }
        (None, Some(adaptive)) => {
            let adaptive_path = sampling.path_of("adaptive");
            let adaptive = reader.object(adaptive, &adaptive_path, ADAPTIVE_KEYS)?;
            if adaptive.get("tolerance_px").is_none() {
                return Some(Sampling::Adaptive {
                    tolerance_px: DEFAULT_TOLERANCE_PX,
                });
            }
            let expected = format!("a number of pixels from {MIN_TOLERANCE_PX} to {MAX_SIDE_PX}");
            let ok = |v: f64| (MIN_TOLERANCE_PX..=MAX_SIDE_PX).contains(&v);
            reader
                .number(&adaptive, "tolerance_px", ok, &expected)
                .map(|tolerance_px| Sampling::Adaptive { tolerance_px })
        }
        _ => {
            reader.report(path, "expected exactly one of \"uniform\" (samples per curve) or \"adaptive\" ({\"tolerance_px\": t})");
            None
        }
    }
}

fn read_layout(reader: &mut Reader, object: &reader::Object, panel_count: usize) -> (usize, usize) {
    let row = (1, panel_count.max(1));
    let Some(node) = object.get("layout") else {
        return row;
    };
    let path = object.path_of("layout");
    let Some(layout) = reader.object(node, &path, LAYOUT_KEYS) else {
        return row;
    };
    let whole = |v: f64| v.fract() == 0.0 && (1.0..=100.0).contains(&v);
    let rows = reader
        .number(&layout, "rows", whole, "a whole number from 1 to 100")
        .unwrap_or(1.0) as usize;
    let cols = reader.number(&layout, "cols", whole, "a whole number from 1 to 100");
    let cols = cols.map_or_else(|| panel_count.div_ceil(rows).max(1), |c| c as usize);
    if rows * cols < panel_count {
        reader.report(
            path,
            format!(
                "a {rows} × {cols} grid has room for {} panels (got {panel_count} panels)",
                rows * cols
            ),
        );
    }
    (rows, cols)
}

/// The scene's `aspect_ratio` (panel height over width), [`look::DEFAULT_ASPECT_RATIO`] when absent.
fn read_aspect_ratio(reader: &mut Reader, object: &reader::Object) -> f64 {
    reader
        .number(
            object,
            "aspect_ratio",
            |v| (0.05..=20.0).contains(&v),
            "0.05 to 20",
        )
        .unwrap_or(look::DEFAULT_ASPECT_RATIO)
}

fn read_canvas(
    reader: &mut Reader,
    object: &reader::Object,
    preset: Option<look::Preset>,
    (rows, cols): (usize, usize),
    aspect: f64,
    titles: &look::Titles,
) -> Option<Canvas> {
    let unit = reader.choice(object, "unit", SIZE_UNITS).unwrap_or("px");
    // A size in inches or centimetres, or a preset's unless pixels are asked for, prints exactly.
    let print_unit = match unit {
        "in" => Some(look::PrintUnit::Inch),
        "cm" => Some(look::PrintUnit::Centimetre),
        _ if preset.is_some() && object.get("unit").is_none() => Some(look::PrintUnit::Inch),
        _ => None,
    };
    let px_per_unit = match unit {
        "px" => 1.0,
        _ => print_unit.map_or(1.0, look::PrintUnit::css_px),
    };
    let side = |v: f64| (16.0..=MAX_SIDE_PX).contains(&(v * px_per_unit));
    let side_text = format!(
        "{} to {} {unit}",
        crate::spec::numbers::pretty(16.0 / px_per_unit),
        crate::spec::numbers::pretty(MAX_SIDE_PX / px_per_unit)
    );
    let width = reader
        .number(object, "width", side, &side_text)
        .map(|w| w * px_per_unit);
    let height = reader
        .number(object, "height", side, &side_text)
        .map(|h| h * px_per_unit);
    // A width the spec gives replaces the preset's, and the height follows it.
    let preset = preset.map(|p| match width {
        Some(w) => p.canvas_at(w, (rows, cols), aspect, titles),
        None => p.canvas((rows, cols), aspect, titles),
    });
    // The preset's size unrounded, so that a printed size stays exact.
    let preset_size = preset.map(|c| {
        c.print
            .map_or((f64::from(c.width_px), f64::from(c.height_px)), |p| {
                p.css_px()
            })
    });
    let width = width
        .or(preset_size.map(|s| s.0))
        .unwrap_or(look::default_width(cols));
    let one_of = |reader: &mut Reader, a: &str, b: &str| {
        let both = object.get(a).is_some() && object.get(b).is_some();
        if both {
            reader.report(b, format!("give {a} or {b}, not both (got both)"));
        }
        !both
    };
    let font_px = reader
        .number(
            object,
            "font_px",
            |v| (4.0..=200.0).contains(&v),
            "4 to 200",
        )
        .or_else(|| {
            reader
                .number(
                    object,
                    "font_pt",
                    |v| (3.0..=150.0).contains(&v),
                    "3 to 150",
                )
                .map(|pt| pt * CSS_PX_PER_INCH / 72.0)
        })
        .or(preset.map(|c| c.font_px))
        .unwrap_or_else(|| look::default_font_px(width, cols));
    let height = height.or(preset_size.map(|s| s.1)).unwrap_or_else(|| {
        let titled = !titles.figure.is_empty();
        look::default_height((rows, cols), width, aspect, font_px, titled).clamp(16.0, MAX_SIDE_PX)
    });
    let png_scale = reader
        .number(
            object,
            "png_scale",
            |v| (0.1..=16.0).contains(&v),
            "0.1 to 16",
        )
        .or_else(|| {
            reader
                .number(
                    object,
                    "dpi",
                    |v| (10.0..=1536.0).contains(&v),
                    "10 to 1536",
                )
                .map(|dpi| dpi / CSS_PX_PER_INCH)
        })
        .or(preset.map(|c| c.png_scale))
        .unwrap_or(2.0);
    if !(one_of(reader, "font_px", "font_pt") & one_of(reader, "png_scale", "dpi")) {
        return None;
    }
    let canvas = Canvas {
        width_px: width.round() as u32,
        height_px: height.round() as u32,
        png_scale,
        font_px,
        print: print_unit.map(|unit| look::PrintSize {
            width: width / unit.css_px(),
            height: height / unit.css_px(),
            unit,
        }),
        transparent: reader.choice(object, "background", BACKGROUNDS) == Some("transparent"),
        face: reader
            .choice(object, "font", FONTS)
            .and_then(look::Face::named)
            .unwrap_or_default(),
    };
    check_canvas(&canvas)
        .map_err(|message| reader.report("png_scale", message))
        .ok()?;
    Some(canvas)
}

/// Rejects canvases whose PNG would exceed [`Canvas::MAX_PNG_PIXELS`].
pub fn check_canvas(canvas: &Canvas) -> Result<(), String> {
    let (width, height) = canvas.png_size();
    let pixels = width * height;
    if pixels > Canvas::MAX_PNG_PIXELS as f64 {
        Err(format!(
            "the PNG would have {pixels:.0} pixels (got {}×{} px at scale {}, expected at most {} pixels)",
            canvas.width_px,
            canvas.height_px,
            canvas.png_scale,
            Canvas::MAX_PNG_PIXELS
        ))
    } else {
        Ok(())
    }
}

fn read_panels(reader: &mut Reader, object: &reader::Object) -> Option<Vec<ScenePanel<Spec>>> {
    let Some(node) = object.get("panels") else {
        reader.report(
            "panels",
            "missing panels (expected a list of panel objects)",
        );
        return None;
    };
    let Value::Array(items) = &node.value else {
        reader.report("panels", format!("expected a list of panels (got {node})"));
        return None;
    };
    if items.is_empty() {
        reader.report(
            "panels",
            "a scene needs at least one panel (got [], expected a list of panel objects)",
        );
        return None;
    }
    let mut panels = Vec::with_capacity(items.len());
    let mut total_curves = 0;
    for (i, item) in items.iter().enumerate() {
        if let Some(panel) = read_panel(reader, item, &join_index("panels", i)) {
            total_curves += panel.curves.len() + panel.data.len();
            panels.push(panel);
        }
    }
    if total_curves > MAX_CURVES_PER_SCENE {
        reader.report(
            "panels",
            format!(
                "too many curves (got {total_curves}, expected at most {MAX_CURVES_PER_SCENE})"
            ),
        );
        return None;
    }
    (panels.len() == items.len()).then_some(panels)
}

fn read_panel(reader: &mut Reader, node: &Node, path: &str) -> Option<ScenePanel<Spec>> {
    let panel = reader.object(node, path, PANEL_KEYS)?;
    let title = reader.text(&panel, "title").unwrap_or_default();
    let legend = read_legend(reader, &panel);
    let grid = reader.boolean(&panel, "grid").unwrap_or(true);
    let x_path = panel.path_of("x");
    let y_path = panel.path_of("y");
    let x = panel
        .get("x")
        .and_then(|n| reader.object(n, &x_path, X_KEYS));
    let y = panel
        .get("y")
        .and_then(|n| reader.object(n, &y_path, Y_KEYS));
    // Read before the series, whose problems end the panel, so that all of them are reported.
    let y_scale = match y.and_then(|y| reader.choice(&y, "scale", SCALES)) {
        Some("log") => Scale::Log,
        _ => Scale::Linear,
    };
    let x_scale = match x.and_then(|x| reader.choice(&x, "scale", SCALES)) {
        Some("log") => Scale::Log,
        _ => Scale::Linear,
    };
    let x_ticks = x.and_then(|x| read_ticks(reader, &x, Some(x_scale)));
    let y_ticks = y.and_then(|y| read_ticks(reader, &y, Some(y_scale)));
    let mut series = read_series(reader, &panel)?;
    let transform = read_transform(reader, &panel, &mut series.curves);
    let only_data = series.curves.is_empty() && !series.data.iter().any(|d| d.dataset.is_theta());
    let x_unit = match x.and_then(|x| reader.choice(&x, "unit", X_UNITS)) {
        Some("degrees") => XUnit::Degrees,
        Some("radians") => XUnit::Radians,
        Some("slope") => XUnit::Slope,
        Some(_) => XUnit::Plain,
        None if only_data => XUnit::Plain,
        None if transform == Some(Transform::Slope) => XUnit::Slope,
        None => XUnit::Radians,
    };
    let pi_ticks = |ticks: &Option<TickChoice>| matches!(ticks, Some(TickChoice::Pi));
    if pi_ticks(&x_ticks) && (x_unit != XUnit::Radians || x_scale == Scale::Log) {
        reader.report(
            join_key(&x_path, "ticks"),
            "\"pi\" ticks are for a linear θ axis in radians (got another unit or a log scale)",
        );
    }
    if pi_ticks(&y_ticks) {
        reader.report(
            join_key(&y_path, "ticks"),
            "\"pi\" ticks are for a θ axis in radians (got the y axis)",
        );
    }
    if x_unit == XUnit::Plain && !only_data {
        reader.report(
            &x_path,
            "curves of θ need an angle axis (got unit \"plain\", expected radians, degrees or slope)",
        );
    }
    let x_range = read_x_range(reader, x.as_ref(), x_unit, x_scale);
    let y_range = y.and_then(|y| match y_scale {
        Scale::Log => reader.interval(&y, "range", |v| v > 0.0, "both > 0 on a log axis"),
        Scale::Linear => reader.interval(&y, "range", f64::is_finite, "finite"),
    });
    let kind = read_kind(reader, &panel, &series, x_unit)?;
    if x_scale == Scale::Log && kind != PanelKind::Cartesian {
        reader.report(
            join_key(&x_path, "scale"),
            "a log x axis is drawn on cartesian panels only (got \"log\" on a polar, surface or heat-map panel, expected \"linear\")",
        );
    }
    if y_scale == Scale::Log && matches!(kind, PanelKind::Heatmap { .. }) {
        reader.report(
            join_key(&y_path, "scale"),
            "a heat-map panel draws its grid on linear axes (got \"log\", expected \"linear\")",
        );
    }
    let annotations = read_annotations(reader, &panel, (x_scale, y_scale));
    if !annotations.is_empty() && kind != PanelKind::Cartesian {
        reader.report(
            panel.path_of("annotations"),
            "annotations are drawn on cartesian panels (got a polar, surface or heat-map panel)",
        );
    }
    let (default_x_label, default_y_label) = match (series.curves.first(), series.data.first()) {
        (Some(first), _) => default_curve_labels(first, x_unit, transform),
        (None, Some(first)) => data::default_labels(&first.dataset),
        (None, None) => (String::new(), String::new()),
    };
    Some(ScenePanel {
        axes: Axes {
            title,
            x_label: x
                .and_then(|x| reader.text(&x, "label"))
                .unwrap_or(default_x_label),
            y_label: y
                .and_then(|y| reader.text(&y, "label"))
                .unwrap_or(default_y_label),
            x_unit,
            x_scale,
            kind,
            y_scale,
            x_range,
            y_range,
            legend,
            grid,
            x_ticks,
            y_ticks,
            annotations,
        },
        curves: series.curves,
        data: series.data,
    })
}

/// A panel's `annotations` (at most [`MAX_ANNOTATIONS`]), each checked against the axes' scales
/// (`(x, y)`): values finite, and > 0 on a log axis. Problems are reported and the bad entries
/// left out.
fn read_annotations(
    reader: &mut Reader,
    panel: &reader::Object,
    (x_scale, y_scale): (Scale, Scale),
) -> Vec<Annotation> {
    let Some(node) = panel.get("annotations") else {
        return Vec::new();
    };
    let path = panel.path_of("annotations");
    let Value::Array(items) = &node.value else {
        reader.report(path, format!("expected a list of annotations (got {node})"));
        return Vec::new();
    };
    if items.len() > MAX_ANNOTATIONS {
        reader.report(
            path,
            format!(
                "too many annotations (got {}, expected at most {MAX_ANNOTATIONS})",
                items.len()
            ),
        );
        return Vec::new();
    }
    let mut out = Vec::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        let at = join_index(&path, i);
        let Some(object) = reader.object(item, &at, ANNOTATION_KEYS) else {
            continue;
        };
        let ok = |scale: Scale| move |v: f64| v.is_finite() && (scale == Scale::Linear || v > 0.0);
        let expected = |scale: Scale| match scale {
            Scale::Log => "a finite number > 0 on a log axis",
            Scale::Linear => "a finite number",
        };
        let label = reader.text(&object, "label").unwrap_or_default();
        let kinds = ["x", "y", "text"]
            .iter()
            .filter(|k| object.get(k).is_some())
            .count();
        if kinds != 1 {
            reader.report(
                at,
                "expected exactly one of \"x\" (a vertical line or band), \"y\" (a horizontal one) or \"text\" with \"at\"",
            );
            continue;
        }
        let axis_of = |key: &str| match key {
            "x" => (Dimension::X, x_scale),
            _ => (Dimension::Y, y_scale),
        };
        if let Some(key) = ["x", "y"].into_iter().find(|k| object.get(k).is_some()) {
            let (axis, scale) = axis_of(key);
            let is_band = matches!(object.get(key).map(|n| &n.value), Some(Value::Array(_)));
            let annotation = if is_band {
                reader
                    .interval(&object, key, ok(scale), expected(scale))
                    .map(|(from, to)| Annotation::Band {
                        axis,
                        from,
                        to,
                        label,
                    })
            } else {
                reader
                    .number(&object, key, ok(scale), expected(scale))
                    .map(|v| Annotation::Line { axis, at: v, label })
            };
            out.extend(annotation);
            continue;
        }
        let text = reader.text(&object, "text").unwrap_or_default();
        let point = object.get("at").and_then(|n| match &n.value {
            Value::Array(items) => match items.as_slice() {
                [
                    Node {
                        value: Value::Number(x),
                        ..
                    },
                    Node {
                        value: Value::Number(y),
                        ..
                    },
                ] if ok(x_scale)(x.value) && ok(y_scale)(y.value) => Some((x.value, y.value)),
                _ => None,
            },
            _ => None,
        });
        match point {
            Some(point) => out.push(Annotation::Note { at: point, text }),
            None => reader.report(
                join_key(&at, "at"),
                "expected the data point [x, y] of the text, finite (and > 0 on a log axis)",
            ),
        }
    }
    out
}

/// A panel's `legend`: `true` (default) or `false`, or one of [`LEGEND_PLACES`].
fn read_legend(reader: &mut Reader, panel: &reader::Object) -> LegendPlace {
    let Some(node) = panel.get("legend") else {
        return LegendPlace::Best;
    };
    match &node.value {
        Value::Bool(true) => LegendPlace::Best,
        Value::Bool(false) => LegendPlace::None,
        _ => match reader.choice(panel, "legend", LEGEND_PLACES) {
            Some("upper right") => LegendPlace::Corner(Corner::UpperRight),
            Some("upper left") => LegendPlace::Corner(Corner::UpperLeft),
            Some("lower left") => LegendPlace::Corner(Corner::LowerLeft),
            Some("lower right") => LegendPlace::Corner(Corner::LowerRight),
            Some("right") => LegendPlace::Right,
            Some("below") => LegendPlace::Below,
            Some("none") => LegendPlace::None,
            _ => LegendPlace::Best,
        },
    }
}

/// An axis' `ticks`: a count (2 to [`MAX_TICK_COUNT`]), a list of values in the unit the axis
/// shows, each finite (and > 0 on a log axis, `scale` `Some(Log)`), or `"pi"` (multiples of π/d;
/// the panel checks that the axis is a linear radian axis).
fn read_ticks(
    reader: &mut Reader,
    axis: &reader::Object,
    scale: Option<Scale>,
) -> Option<TickChoice> {
    let node = axis.get("ticks")?;
    let path = axis.path_of("ticks");
    match &node.value {
        Value::Number(n)
            if n.value.fract() == 0.0 && (2.0..=MAX_TICK_COUNT as f64).contains(&n.value) =>
        {
            Some(TickChoice::Count(n.value as usize))
        }
        Value::String(s) if s == "pi" => Some(TickChoice::Pi),
        Value::Array(items) if !items.is_empty() => {
            let log = scale == Some(Scale::Log);
            let mut values = Vec::with_capacity(items.len());
            for (i, item) in items.iter().enumerate() {
                match &item.value {
                    Value::Number(n) if n.value.is_finite() && (!log || n.value > 0.0) => {
                        values.push(n.value)
                    }
                    _ => {
                        let expected = if log {
                            "a number > 0 on a log axis"
                        } else {
                            "a finite number"
                        };
                        reader.report(
                            join_index(&path, i),
                            format!("invalid tick (got {item}, expected {expected})"),
                        );
                        return None;
                    }
                }
            }
            values.sort_by(f64::total_cmp);
            values.dedup();
            Some(TickChoice::At(values))
        }
        _ => {
            reader.report(
                path,
                format!("expected a whole count from 2 to {MAX_TICK_COUNT}, a list of values or \"pi\" (got {node})"),
            );
            None
        }
    }
}

/// The panel's `transform` (one of [`PANEL_TRANSFORMS`]), applied to each of its curves; a curve
/// the transform does not apply to (a Fresnel curve), or a panel without curves for it to apply
/// to (only data series), is reported under `transform`.
fn read_transform(
    reader: &mut Reader,
    panel: &reader::Object,
    curves: &mut [SceneCurve<Spec>],
) -> Option<Transform> {
    let transform = Transform::from_name(reader.choice(panel, "transform", PANEL_TRANSFORMS)?)?;
    let at = panel.path_of("transform");
    if curves.is_empty() {
        reader.report(
            at,
            format!(
                "the {} view applies to NDF curves (got a panel without curves, expected at least one NDF curve)",
                transform.name()
            ),
        );
        return None;
    }
    for entry in curves.iter_mut() {
        match curve::transformed(transform, entry.curve.clone(), &at) {
            Ok(transformed) => entry.curve = transformed,
            Err(problem) => {
                reader.problems.push(problem);
                return None;
            }
        }
    }
    Some(transform)
}

/// The x range in radians of θ: given in degrees, radians or slope (tan θ, converted with atan)
/// per `unit`; a slope axis without a range shows [`DEFAULT_SLOPE_RANGE`], since tan θ is unbounded.
fn read_x_range(
    reader: &mut Reader,
    x: Option<&reader::Object>,
    unit: XUnit,
    scale: Scale,
) -> Option<(f64, f64)> {
    let log = scale == Scale::Log;
    // A log axis shows no 0: its range must start above it.
    let above = |low: f64| move |v: f64| if log { v > low } else { v >= low };
    let range = |reader: &mut Reader, test: &dyn Fn(f64) -> bool, expected: &str| {
        x.and_then(|x| reader.interval(x, "range", test, expected))
    };
    let given = match unit {
        XUnit::Degrees => range(
            reader,
            &|v| above(0.0)(v) && v <= 90.0,
            if log {
                "degrees within (0, 90] on a log axis"
            } else {
                "degrees within [0, 90]"
            },
        )
        .map(|(a, b)| (a.to_radians(), b.to_radians().min(FRAC_PI_2))),
        XUnit::Radians => range(
            reader,
            &|v| above(0.0)(v) && v <= FRAC_PI_2,
            if log {
                "radians within (0, π/2] on a log axis"
            } else {
                "radians within [0, π/2]"
            },
        ),
        XUnit::Slope => range(
            reader,
            &|v| v.is_finite() && above(0.0)(v),
            if log {
                "slopes tan θ, finite and > 0 on a log axis"
            } else {
                "slopes tan θ, finite and ≥ 0"
            },
        )
        .or((!log).then_some(DEFAULT_SLOPE_RANGE))
        .map(|(a, b)| (a.atan(), b.atan())),
        XUnit::Plain => range(
            reader,
            &|v| v.is_finite() && (!log || v > 0.0),
            if log {
                "finite and > 0 on a log axis"
            } else {
                "finite"
            },
        ),
    };
    if let Some(x) = x.filter(|x| log && unit != XUnit::Plain && x.get("range").is_none()) {
        reader.report(
            x.path_of("scale"),
            "a log θ axis needs a range above 0 (got none, expected e.g. \"range\": [0.001, 1.5707963267948966] in the axis' unit)",
        );
    }
    given
}

/// Default axis labels of a panel whose first series is `first`, a curve of θ.
fn default_curve_labels(
    first: &SceneCurve<Spec>,
    unit: XUnit,
    transform: Option<Transform>,
) -> (String, String) {
    let view_angle = !matches!(first.curve.kind(), Kind::Ndf("d") | Kind::Fresnel);
    let x_label = match (unit, view_angle) {
        (XUnit::Degrees, false) => "θ (degrees)",
        (XUnit::Degrees, true) => "θ_o (degrees)",
        (XUnit::Slope, _) => "slope tan θ",
        (_, false) => "θ (radians)",
        (_, true) => "θ_o (radians)",
    };
    let y_label = match (&first.curve, transform) {
        (CurveSpec::Difference { op, .. }, _) => {
            let symbol = first.curve.kind().symbol();
            return (x_label.to_string(), op.axis_label(Some(symbol)));
        }
        (CurveSpec::Quantity { quantity, .. }, _) => quantity.axis_label(),
        (curve, _) if curve.kind() == Kind::Fresnel => "F(θ)",
        (_, Some(Transform::Projected)) => "D(θ) cos θ",
        (_, Some(Transform::Slope)) => "P₂₂ = D(θ) cos⁴θ",
        _ => "D(θ)",
    };
    (x_label.to_string(), y_label.to_string())
}

/// The panel kind: `"kind": "surface"` with its `z` axis and `camera`, `"kind": "heatmap"` with its
/// `z` axis; otherwise a cartesian panel in its `view` (a polar view needs curves of θ on an angle
/// axis).
fn read_kind(
    reader: &mut Reader,
    panel: &reader::Object,
    series: &PanelSeries,
    x_unit: XUnit,
) -> Option<PanelKind> {
    let kind = reader.choice(panel, "kind", PANEL_KINDS);
    if let Some(kind @ ("surface" | "heatmap")) = kind {
        if let Some(view) = panel.get("view") {
            reader.report(
                panel.path_of("view"),
                format!(
                    "a {kind} panel has no view (got {view}, expected a cartesian panel for a view)"
                ),
            );
        }
        return if kind == "surface" {
            read_surface(reader, panel, series)
        } else {
            read_heatmap(reader, panel, series, x_unit)
        };
    }
    for key in ["z", "camera"] {
        if panel.get(key).is_some() {
            reader.report(panel.path_of(key), "only surface and heat-map panels have this key (got it on a cartesian panel, expected \"kind\": \"surface\" or \"heatmap\" with it)");
        }
    }
    if let Some(i) = series.data.iter().position(|d| d.dataset.has_z()) {
        reader.report(
            panel.path_of("curves"),
            format!("series {i} has a z axis: it needs \"kind\": \"surface\" or \"heatmap\""),
        );
    }
    match reader.choice(panel, "view", VIEWS) {
        Some("polar") => {
            if !matches!(x_unit, XUnit::Radians | XUnit::Degrees) {
                let unit = if x_unit == XUnit::Slope {
                    "slope"
                } else {
                    "plain"
                };
                reader.report(
                    panel.path_of("view"),
                    format!("a polar view draws θ as an angle (got x unit \"{unit}\", expected radians or degrees)"),
                );
                return None;
            }
            Some(PanelKind::Polar)
        }
        _ => Some(PanelKind::Cartesian),
    }
}

/// A surface panel: only data series with a z coefficient, its `z` axis and `camera`.
fn read_surface(
    reader: &mut Reader,
    panel: &reader::Object,
    series: &PanelSeries,
) -> Option<PanelKind> {
    if !series.curves.is_empty() || series.data.iter().any(|d| !d.dataset.has_z()) {
        reader.report(
            panel.path_of("curves"),
            "a surface panel shows only data series with a z coefficient",
        );
        return None;
    }
    let (z_label, z_range) = read_z(reader, panel, series);
    let camera_path = panel.path_of("camera");
    let camera = panel
        .get("camera")
        .and_then(|n| reader.object(n, &camera_path, CAMERA_KEYS));
    let angle = |reader: &mut Reader, key: &str, default: f64| {
        camera
            .and_then(|v| {
                reader.number(
                    &v,
                    key,
                    |a| (-360.0..=360.0).contains(&a),
                    "degrees within [-360, 360]",
                )
            })
            .unwrap_or(default)
    };
    Some(PanelKind::Surface {
        z_label,
        z_range,
        // The notebook's view_init(elev=65, azim=-45).
        elevation_deg: angle(reader, "elevation", 65.0),
        azimuth_deg: angle(reader, "azimuth", -45.0),
    })
}

/// A surface or heat-map panel's `z` axis: its label (by default its first series') and range.
fn read_z(
    reader: &mut Reader,
    panel: &reader::Object,
    series: &PanelSeries,
) -> (String, Option<(f64, f64)>) {
    let z_path = panel.path_of("z");
    let z = panel
        .get("z")
        .and_then(|n| reader.object(n, &z_path, Z_KEYS));
    let label = z.and_then(|z| reader.text(&z, "label")).unwrap_or_else(|| {
        series
            .data
            .first()
            .map(|d| data::z_label(&d.dataset))
            .unwrap_or_default()
    });
    let range = z.and_then(|z| reader.interval(&z, "range", f64::is_finite, "finite"));
    (label, range)
}

/// A heat-map panel: exactly one data series of z over a rectilinear grid (an albedo series), on
/// plain linear axes, with its `z` axis (the colour bar); no curves of θ and no camera.
fn read_heatmap(
    reader: &mut Reader,
    panel: &reader::Object,
    series: &PanelSeries,
    x_unit: XUnit,
) -> Option<PanelKind> {
    let before = reader.problems.len();
    if !series.curves.is_empty() {
        reader.report(
            panel.path_of("curves"),
            "a heat-map panel shows one grid of values, not curves of θ (expected one data series such as {\"data\": \"albedo\"})",
        );
    } else if series.data.len() != 1 || !series.data[0].dataset.is_map() {
        reader.report(
            panel.path_of("curves"),
            format!(
                "a heat-map panel shows exactly one data series of z over a grid (got {} series, expected one {{\"data\": \"albedo\"}})",
                series.data.len()
            ),
        );
    }
    if let Some(camera) = panel.get("camera") {
        reader.report(
            panel.path_of("camera"),
            format!("a heat-map panel has no camera (got {camera}, expected \"kind\": \"surface\" for a 3D view)"),
        );
    }
    // Curves of θ (reported above) make the default unit an angle.
    if x_unit != XUnit::Plain && series.curves.is_empty() {
        reader.report(
            join_key(&panel.path_of("x"), "unit"),
            "a heat-map panel's x axis is its grid's (expected \"plain\" or no unit)",
        );
    }
    let (z_label, z_range) = read_z(reader, panel, series);
    (reader.problems.len() == before).then_some(PanelKind::Heatmap { z_label, z_range })
}

/// The series of one panel: curves of θ, then data series.
struct PanelSeries {
    curves: Vec<SceneCurve<Spec>>,
    data: Vec<SceneData<Spec>>,
}

fn read_series(reader: &mut Reader, panel: &reader::Object) -> Option<PanelSeries> {
    let path = panel.path_of("curves");
    let Some(node) = panel.get("curves") else {
        reader.report(
            path,
            "missing curves (expected a list of curve or data objects)",
        );
        return None;
    };
    let Value::Array(items) = &node.value else {
        reader.report(path, format!("expected a list of curves (got {node})"));
        return None;
    };
    if items.is_empty() {
        reader.report(
            path,
            "a panel needs at least one curve (got [], expected a list of curve or data objects)",
        );
        return None;
    }
    let mut curves = Vec::new();
    let mut data = Vec::new();
    let before = reader.problems.len();
    for (i, item) in items.iter().enumerate() {
        let item_path = join_index(&path, i);
        if data::is_sampled_difference(item) {
            data.extend(data::read_difference(reader, item, &item_path));
        } else if data::is_data(item) {
            data.extend(data::read_entry(reader, item, &item_path));
        } else {
            read_curve_entry(reader, item, &item_path, &mut curves);
        }
        if curves.len() + data.len() > MAX_CURVES_PER_SCENE {
            reader.report(
                path,
                format!("too many curves (expected at most {MAX_CURVES_PER_SCENE})"),
            );
            return None;
        }
    }
    (reader.problems.len() == before).then_some(PanelSeries { curves, data })
}

/// Expands one curve entry (possibly swept) into `out`.
fn read_curve_entry(reader: &mut Reader, node: &Node, path: &str, out: &mut Vec<SceneCurve<Spec>>) {
    let entry_start = reader.problems.len();
    if curve::is_difference(node) {
        return sweep::difference_entry(reader, node, path, out);
    }
    if curve::is_published(node) {
        return sweep::published_entry(reader, node, path, out);
    }
    if curve::is_metal(node) {
        return sweep::metal_entry(reader, node, path, out);
    }
    let Some(resolved) = reader.accept(curve::read_keys(node, path, CURVE_EXTRA_KEYS)) else {
        return;
    };
    let Some((entry, label_template)) = entry_with_label(reader, node, path) else {
        return;
    };
    if let Some(template) = &label_template {
        let params: Vec<&str> = resolved.params.iter().map(|p| p.name).collect();
        if let Some(name) = curve::unknown_placeholder(template, &params) {
            let listed: Vec<String> = params.iter().map(|p| format!("{{{p}}}")).collect();
            reader.report(
                join_key(path, "label"),
                format!(
                    "unknown placeholder {{{}}} (expected one of: {}){}",
                    crate::problem::excerpt(name),
                    listed.join(", "),
                    crate::problem::suggestion(name, params.iter().copied())
                ),
            );
        }
    }
    let base_style = read_style(reader, &entry, default_colour(resolved.model));

    // Per parameter, its values; absent keys take their defaults.
    let mut sweeps: Vec<(usize, Sweep)> = Vec::new();
    let mut fitted = None;
    for (i, (spec, param_node)) in resolved.params.iter().zip(&resolved.nodes).enumerate() {
        let sweep = match param_node {
            None => Some(Sweep {
                values: vec![sweep::SweepValue {
                    value: spec.default.expect("resolve() reports missing keys"),
                    label: String::new(),
                }],
                varies: false,
            }),
            // Described after the loop, once the other parameters (its fixed keys) are known.
            Some(n) if sweep::is_fit(n) && fitted.is_none() => {
                fitted = Some((i, *n));
                Some(Sweep {
                    values: vec![],
                    varies: true,
                })
            }
            Some(n) => sweep::expand(reader, spec.name, spec.kind, n, &join_key(path, spec.name)),
        };
        let Some(sweep) = sweep else { return };
        let position = param_node.map_or(usize::MAX, |n| n.line * 1_000_000 + n.col);
        sweeps.push((position, sweep));
    }
    // The fitted parameter (if any) and its fits, one per target curve.
    let mut fits = Vec::new();
    if let Some((i, n)) = fitted {
        let others: Vec<&Sweep> = sweeps.iter().map(|(_, s)| s).collect();
        let Some(found) = sweep::fit(
            reader,
            resolved.model,
            &resolved.params,
            &others,
            i,
            n,
            path,
        ) else {
            return;
        };
        fits = found;
    }
    let Some(style) = base_style else { return };
    let len = |i: usize| match fitted {
        Some((free, _)) if free == i => fits.len(),
        _ => sweeps[i].1.values.len(),
    };
    let count: usize = (0..sweeps.len()).map(len).product();
    if count > MAX_CURVES_PER_SCENE {
        reader.report(
            path,
            format!("the sweep gives {count} curves (expected at most {MAX_CURVES_PER_SCENE})"),
        );
        return;
    }
    // Product over swept keys in document order, the last key varying fastest.
    let mut order: Vec<usize> = (0..sweeps.len()).collect();
    order.sort_by_key(|&i| sweeps[i].0);
    let any_varies = sweeps.iter().any(|(_, s)| s.varies);
    let free = fitted.map(|(free, _)| free);
    for k in 0..count {
        let mut choice = vec![0; sweeps.len()];
        let mut rest = k;
        for &i in order.iter().rev() {
            choice[i] = rest % len(i);
            rest /= len(i);
        }
        let values: Vec<Option<ParamValue>> = sweeps
            .iter()
            .zip(&choice)
            .enumerate()
            .map(|(i, ((_, s), &c))| (free != Some(i)).then(|| s.values[c].value))
            .collect();
        let curve = match free {
            Some(free) => {
                let fitted = CurveSpec::Fitted(Box::new(fits[choice[free]].clone()));
                match resolved.showing_quantity(fitted, path) {
                    Ok(curve) => curve,
                    Err(problem) => {
                        if !reader.problems[entry_start..].contains(&problem) {
                            reader.problems.push(problem);
                        }
                        continue;
                    }
                }
            }
            None => {
                let values: Vec<ParamValue> = values.iter().flatten().copied().collect();
                match resolved.build(&values, path) {
                    Ok(curve) => curve,
                    Err(problem) => {
                        // One report per offending value, however many combinations it appears in;
                        // only this entry's reports can repeat it, so only they are searched (a
                        // search of every report so far made validation quadratic in them).
                        if !reader.problems[entry_start..].contains(&problem) {
                            reader.problems.push(problem);
                        }
                        continue;
                    }
                }
            }
        };
        let label = match &label_template {
            Some(template) => Label::Template {
                template: template.clone(),
                values: resolved.params.iter().map(|p| p.name).zip(values).collect(),
            },
            None => Label::Auto(
                order
                    .iter()
                    .filter(|&&i| !any_varies || sweeps[i].1.varies)
                    .filter_map(|&i| match free {
                        Some(free) if free == i => Some(Part::Fitted),
                        _ => {
                            let text = &sweeps[i].1.values[choice[i]].label;
                            (!text.is_empty()).then(|| Part::Text(text.clone()))
                        }
                    })
                    .collect(),
            ),
        };
        out.push(SceneCurve {
            curve,
            label,
            style: sweep_style(style, k, count),
        });
    }
}

/// A curve entry whose keys were checked, as an object, with its `label` text if it has one.
fn entry_with_label<'a>(
    reader: &mut Reader,
    node: &'a Node,
    path: &'a str,
) -> Option<(reader::Object<'a>, Option<String>)> {
    let Value::Object(members) = &node.value else {
        return None;
    };
    let entry = reader::Object::from_members(members, path);
    let label = reader.text(&entry, "label");
    Some((entry, label))
}

/// The style of curve k of an entry's n: its shade of the entry's colour (the family's, or the one the
/// entry gives), unless the entry shows a single curve.
fn sweep_style(style: Style, k: usize, n: usize) -> Style {
    if n <= 1 {
        style
    } else {
        Style {
            colour: shade(style.colour, k, n),
            sweep: Some(SweepMember { index: k, count: n }),
            ..style
        }
    }
}

fn default_colour(model: Model) -> Rgb {
    match model {
        Model::Ndf(family) => Rgb::from_hex(family.colour()),
        // Solarized blue for Fresnel curves unless overridden.
        Model::Fresnel(_) => Rgb::from_hex(0x268BD2),
    }
}

/// Reads `style` (words from [`STYLE_WORDS`]), `colour` or `color` (#RRGGBB; not both) and `mark` of a
/// series entry.
pub(crate) fn read_style(
    reader: &mut Reader,
    entry: &reader::Object,
    colour: Rgb,
) -> Option<Style> {
    let mut style = Style {
        colour,
        width: 1.0,
        dash: Dash::Solid,
        mark: Mark::Line,
        sweep: None,
    };
    let before = reader.problems.len();
    if let Some(node) = entry.get("style") {
        let path = entry.path_of("style");
        let words: Vec<(&Node, String)> = match &node.value {
            Value::String(_) => vec![(node, path.clone())],
            Value::Array(items) => items
                .iter()
                .enumerate()
                .map(|(i, n)| (n, join_index(&path, i)))
                .collect(),
            _ => {
                reader.report(
                    &path,
                    format!(
                        "expected a style word or a list of them (got {node}, expected any of: {})",
                        STYLE_WORDS.join(", ")
                    ),
                );
                vec![]
            }
        };
        for (word_node, word_path) in words {
            match &word_node.value {
                Value::String(word) => match word.as_str() {
                    "thick" => style.width = 2.0,
                    "dashed" => style.dash = Dash::Dashed,
                    "dotted" => style.dash = Dash::Dotted,
                    "solid" => style.dash = Dash::Solid,
                    other => reader.report(
                        word_path,
                        format!(
                            "unknown style (got \"{}\", expected any of: {}){}",
                            crate::problem::excerpt(other),
                            STYLE_WORDS.join(", "),
                            suggestion(other, STYLE_WORDS.iter().copied())
                        ),
                    ),
                },
                _ => reader.report(
                    word_path,
                    format!("expected a style word (got {word_node})"),
                ),
            }
        }
    }
    if let Some(width) = reader.number(
        entry,
        "width",
        |w| (LINE_WIDTHS.0..=LINE_WIDTHS.1).contains(&w),
        "0.25 to 10 times the default line width",
    ) {
        style.width = width;
    }
    match reader.choice(entry, "mark", MARKS) {
        Some("points") => style.mark = Mark::Points,
        Some("line_points") => style.mark = Mark::LinePoints,
        Some("bars") => style.mark = Mark::Bars,
        _ => {}
    }
    let colour_key = match (entry.get("colour"), entry.get("color")) {
        (Some(_), Some(_)) => {
            reader.report(
                entry.path_of("color"),
                "colour given twice (got both \"colour\" and \"color\", expected one of the two spellings)",
            );
            "colour"
        }
        (None, Some(_)) => "color",
        _ => "colour",
    };
    if let Some(text) = reader.string(entry, colour_key) {
        match parse_hex_colour(&text) {
            Some(colour) => style.colour = colour,
            None => reader.report(
                entry.path_of(colour_key),
                format!(
                    "invalid colour (got \"{}\", expected #RRGGBB)",
                    crate::problem::excerpt(&text)
                ),
            ),
        }
    }
    (reader.problems.len() == before).then_some(style)
}

/// Parses `#RRGGBB`.
pub fn parse_hex_colour(text: &str) -> Option<Rgb> {
    let hex = text.strip_prefix('#')?;
    (hex.len() == 6 && hex.chars().all(|c| c.is_ascii_hexdigit()))
        .then(|| Rgb::from_hex(u32::from_str_radix(hex, 16).expect("six hex digits")))
}
