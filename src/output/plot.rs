//! Figure → SVG and PNG bytes, drawn with plotters and the embedded DejaVu Sans face.
//!
//! Owns the page layout (figure title, panel grid, axes, ticks, legend), the automatic
//! ranges ("PlotRange → All") and the in-memory PNG encoding. It must not compute curves,
//! decide what to plot, or touch the file system: callers hand it a finished [`Figure`] and
//! write the returned bytes themselves.
//!
//! Cartesian panels draw lines, dots, lines with dots, or bars; surface panels draw a 3D
//! axes box with back panes, depth-sorted translucent surface meshes and 3D lines, using the
//! camera geometry of [`super::plot3d`].
//!
//! Both formats share one drawing routine, parameterised by a device scale `k` (device pixels
//! per CSS pixel): the PNG is drawn at `k = png_scale`; the SVG at `k = SVG_UNITS_PER_PX` and
//! then given a `viewBox` that maps it back to the canvas size, so that coordinates and line
//! widths keep sub-pixel precision although plotters works in integer device units.

use std::ops::Range;
use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::coord::ranged1d::{DefaultFormatting, KeyPointHint};
use plotters::element::DashedPathElement;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};
use plotters::style::{FontFamily, FontStyle, register_font};

use super::plot3d::{self, P3, Projector, View};
use crate::series::{Canvas, Dash, Figure, Mark, Panel, PanelKind, Rgb, Series, XUnit, YScale};

/// Why a figure could not be turned into bytes.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    /// The canvas cannot be rasterized (zero or non-finite size or scale, or too many pixels).
    #[error(
        "canvas {width_px}×{height_px} px at scale {scale} and font size {font_px} px cannot be drawn: {reason}"
    )]
    Canvas {
        /// Requested width in CSS pixels.
        width_px: u32,
        /// Requested height in CSS pixels.
        height_px: u32,
        /// Device pixels per CSS pixel.
        scale: f64,
        /// Base font size in CSS pixels.
        font_px: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// The figure has more panels than grid cells.
    #[error("{panels} panels do not fit a {rows}×{cols} grid")]
    Layout {
        /// Number of panels.
        panels: usize,
        /// Grid rows.
        rows: usize,
        /// Grid columns.
        cols: usize,
    },
    /// A series cannot be drawn in its panel (a surface-panel series without z values, or a
    /// grid that does not match the number of points).
    #[error("series \"{label}\": {reason}")]
    Series {
        /// The series' legend label.
        label: String,
        /// What is wrong with it.
        reason: String,
    },
    /// The embedded font could not be parsed.
    #[error("the embedded DejaVu Sans font could not be loaded")]
    Font,
    /// plotters reported a drawing error.
    #[error("drawing failed: {0}")]
    Draw(String),
    /// The PNG encoder failed.
    #[error("PNG encoding failed: {0}")]
    Encode(#[from] png::EncodingError),
}

/// Renders `figure` as a standalone SVG document (UTF-8 bytes).
///
/// Text stays text, in `font-family="DejaVu Sans, sans-serif"`; the font itself is not embedded.
pub fn svg(figure: &Figure) -> Result<Vec<u8>, PlotError> {
    let canvas = &figure.canvas;
    let (width, height) = device_size(canvas, SVG_UNITS_PER_PX)?;
    let mut document = String::with_capacity(SVG_CAPACITY);
    {
        let root = SVGBackend::with_string(&mut document, (width, height)).into_drawing_area();
        draw_figure(&root, figure, SVG_UNITS_PER_PX)?;
    }
    Ok(finish_svg(&document, canvas, (width, height)).into_bytes())
}

/// Renders `figure` as a PNG of (width_px·png_scale) × (height_px·png_scale) pixels.
///
/// 8-bit RGB, tagged sRGB, no time stamp: identical figures give identical bytes.
pub fn png(figure: &Figure) -> Result<Vec<u8>, PlotError> {
    let scale = figure.canvas.png_scale;
    let (width, height) = device_size(&figure.canvas, scale)?;
    let mut rgb = vec![0u8; width as usize * height as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut rgb, (width, height)).into_drawing_area();
        draw_figure(&root, figure, scale)?;
    }
    encode_png(&rgb, width, height)
}

/// SVG device units per CSS pixel: plotters draws on an integer grid, so 4 gives 0.25 px
/// precision for curve vertices and line widths (1.5 px = 6 units).
const SVG_UNITS_PER_PX: f64 = 4.0;
/// Initial SVG buffer size: a typical 10-curve figure is ~100-200 KB.
const SVG_CAPACITY: usize = 1 << 18;
/// Largest raster accepted: 2²⁶ pixels (64 Mpx, a 192 MB RGB buffer).
const MAX_DEVICE_PIXELS: u64 = 1 << 26;

/// Name under which the embedded face is registered; the SVG names it first.
const FONT_NAME: &str = "DejaVu Sans";
/// Em of the face per plotters text size: ab_glyph scales DejaVu Sans so that ascender −
/// descender (1901 + 483 font units) spans the size, and one em is 2048 units.
const EM_PER_SIZE: f64 = 2048.0 / 2384.0;
/// `font-family` written into the SVG: the embedded face, then the generic fallback.
const SVG_FONT_FAMILY: &str = "DejaVu Sans, sans-serif";

/// Default curve width in CSS pixels (multiplied by `Style::width`).
const BASE_LINE_PX: f64 = 1.5;
/// Dash and gap lengths of dashed curves, in multiples of the curve's width.
const DASHED: (f64, f64) = (4.0, 2.5);
/// Dot and gap lengths of dotted curves, in multiples of the curve's width.
const DOTTED: (f64, f64) = (1.0, 1.5);
/// Radius of the dots of a scatter (`Mark::Points`), in CSS pixels.
const POINT_RADIUS_PX: f64 = 1.5;
/// Radius of the dots on a line (`Mark::LinePoints`) and of legend dots, in CSS pixels.
const MARKER_RADIUS_PX: f64 = 3.0;
/// Bar width as a fraction of the median spacing of a series' x values.
const BAR_FRACTION: f64 = 0.6;
/// Bar width, as a fraction of the x span, of a series with a single x value.
const LONE_BAR_FRACTION: f64 = 0.05;
/// Opacity of surface meshes: lines and mesh cells behind them stay faintly visible.
const SURFACE_OPACITY: f64 = 0.8;
/// Brightness of a surface's mesh lines relative to its colour.
const MESH_DARKEN: f64 = 0.7;
/// Fraction of the data span added above (and below, unless clamped at 0) an automatic linear range.
const AUTO_MARGIN: f64 = 0.05;

/// Font sizes relative to `Canvas::font_px`.
const AXIS_LABEL_EM: f64 = 1.1;
const PANEL_TITLE_EM: f64 = 1.2;
const FIGURE_TITLE_EM: f64 = 1.4;
/// Minimum distance between tick labels in base text sizes (x: centre to centre; y: line to line).
const X_TICK_SPACING_EM: f64 = 4.0;
const Y_TICK_SPACING_EM: f64 = 3.0;
/// Free space between neighbouring tick labels along a 3D edge, in base text sizes.
const TICK_CLEARANCE_EM: f64 = 0.8;
/// Finest tick count tried to give a short linear axis two labelled ticks (any range holds
/// two multiples of a step a tenth of its span).
const MIN_TICKS_SEARCH: f64 = 12.0;
/// Degree steps that read naturally on an angle axis, finest first.
const DEGREE_STEPS: [f64; 8] = [1.0, 2.0, 5.0, 15.0, 30.0, 45.0, 90.0, 180.0];
/// Mantissas of "nice" linear steps.
const NICE_MANTISSAS: [f64; 5] = [1.0, 2.0, 2.5, 5.0, 10.0];
/// Mantissas of steps between labelled decades (a step of 25 decades reads badly).
const DECADE_MANTISSAS: [f64; 4] = [1.0, 2.0, 5.0, 10.0];
/// At most this many decades get light lines at 2…9 × 10ᵏ.
const MAX_MINOR_DECADES: f64 = 8.0;

/// Text; frame, axes and ticks; major and minor grid lines; legend border.
const INK: RGBColor = RGBColor(0x22, 0x22, 0x22);
const FRAME: RGBColor = RGBColor(0x55, 0x55, 0x55);
const GRID: RGBColor = RGBColor(0xE3, 0xE3, 0xE3);
const MINOR_GRID: RGBColor = RGBColor(0xF1, 0xF1, 0xF1);
const LEGEND_BORDER: RGBColor = RGBColor(0xBB, 0xBB, 0xBB);
/// 3D back panes, their grid lines and their edges.
const PANE: RGBColor = RGBColor(0xF4, 0xF4, 0xF4);
const PANE_GRID: RGBColor = RGBColor(0xDD, 0xDD, 0xDD);
const PANE_EDGE: RGBColor = RGBColor(0xC4, 0xC4, 0xC4);
/// Number of heights tried for the legend box, from the top to the bottom of the plot area.
const LEGEND_HEIGHTS: i32 = 5;
/// Legend background opacity: curves under the box stay faintly visible.
const LEGEND_OPACITY: f64 = 0.85;

/// Registers the embedded face once per process; later calls return the first outcome.
fn ensure_font() -> Result<(), PlotError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        let bytes = dejavu::sans::regular();
        // "sans-serif" too, so that any plotters default style finds the same face.
        register_font(FONT_NAME, FontStyle::Normal, bytes).is_ok()
            && register_font("sans-serif", FontStyle::Normal, bytes).is_ok()
    });
    if ok { Ok(()) } else { Err(PlotError::Font) }
}

/// Device size of `canvas` at `scale`, after checking that it can be drawn.
fn device_size(canvas: &Canvas, scale: f64) -> Result<(u32, u32), PlotError> {
    let fail = |reason| PlotError::Canvas {
        width_px: canvas.width_px,
        height_px: canvas.height_px,
        scale,
        font_px: canvas.font_px,
        reason,
    };
    if !(scale.is_finite() && scale > 0.0) {
        return Err(fail("the scale must be a positive number"));
    }
    if !(canvas.font_px.is_finite() && canvas.font_px > 0.0) {
        return Err(fail("the font size must be a positive number"));
    }
    let width = (f64::from(canvas.width_px) * scale).round();
    let height = (f64::from(canvas.height_px) * scale).round();
    if width < 1.0 || height < 1.0 {
        return Err(fail("the raster would be empty"));
    }
    if width * height > MAX_DEVICE_PIXELS as f64 {
        return Err(fail("the raster would exceed 2^26 pixels"));
    }
    Ok((width as u32, height as u32))
}

/// Maps a plotters error (generic over the backend) to [`PlotError::Draw`].
fn draw_err<E: std::error::Error + Send + Sync>(e: DrawingAreaErrorKind<E>) -> PlotError {
    PlotError::Draw(e.to_string())
}

/// Sizes in device pixels for one render: everything scales with `k` and the base font size.
struct Metrics {
    /// Device pixels per CSS pixel.
    k: f64,
    /// plotters text size of the tick labels in device pixels (their em is `font_px · k`):
    /// the unit of all other text sizes and of the layout spacings.
    unit: f64,
}

impl Metrics {
    /// `units` base text sizes in whole device pixels.
    fn px(&self, units: f64) -> u32 {
        (units * self.unit).round().max(1.0) as u32
    }
    /// A hairline (grid, frame, ticks): one CSS pixel.
    fn hairline(&self) -> u32 {
        self.k.round().max(1.0) as u32
    }
    /// Text style at `units` times the base size.
    fn font(&self, units: f64) -> TextStyle<'static> {
        TextStyle::from((FontFamily::Name(FONT_NAME), units * self.unit).into_font()).color(&INK)
    }
    /// Stroke of a curve drawn `multiplier` times the default width.
    fn curve_style(&self, colour: Rgb, multiplier: f64) -> ShapeStyle {
        let width = (BASE_LINE_PX * multiplier.max(0.0) * self.k)
            .round()
            .max(1.0);
        ShapeStyle {
            color: RGBColor(colour.0, colour.1, colour.2).to_rgba(),
            filled: false,
            stroke_width: width as u32,
        }
    }
    /// Radius in whole device pixels of a dot of `radius_px` CSS pixels.
    fn dot(&self, radius_px: f64) -> u32 {
        (radius_px * self.k).round().max(1.0) as u32
    }
    /// A fill in `colour` at `opacity`.
    fn fill(&self, colour: Rgb, opacity: f64) -> ShapeStyle {
        RGBColor(colour.0, colour.1, colour.2).mix(opacity).filled()
    }
    /// A hairline stroke in `colour`.
    fn line(&self, colour: RGBColor) -> ShapeStyle {
        ShapeStyle {
            color: colour.to_rgba(),
            filled: false,
            stroke_width: self.hairline(),
        }
    }
}

/// Draws the whole figure onto `root` at `k` device pixels per CSS pixel.
fn draw_figure<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    figure: &Figure,
    k: f64,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    ensure_font()?;
    let (rows, cols) = (figure.rows.max(1), figure.cols.max(1));
    if figure.panels.len() > rows * cols {
        return Err(PlotError::Layout {
            panels: figure.panels.len(),
            rows: figure.rows,
            cols: figure.cols,
        });
    }
    let m = Metrics {
        k,
        unit: figure.canvas.font_px * k / EM_PER_SIZE,
    };
    root.fill(&WHITE).map_err(draw_err)?;
    let body = titled(root, &figure.title, FIGURE_TITLE_EM, &m)?;
    for (panel, cell) in figure.panels.iter().zip(body.split_evenly((rows, cols))) {
        draw_panel(&cell, panel, &m)?;
    }
    root.present().map_err(draw_err)
}

/// Draws `title` (`size` base text sizes) centred at the top of `area`, if not empty, and
/// returns the area below it.
fn titled<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    size: f64,
    m: &Metrics,
) -> Result<DrawingArea<DB, Shift>, PlotError>
where
    DB::ErrorType: 'static,
{
    if title.is_empty() {
        return Ok(area.clone());
    }
    let style = m.font(size);
    let pad = f64::from(m.px(0.5));
    // plotters' raster text puts the baseline size/2 below a top anchor, so ascenders rise
    // ≈0.3 × size above it (ascent 1901/2384 of the size for DejaVu Sans): start that much lower.
    let top = (pad + 0.3 * size * m.unit).round() as i32;
    let (_, text_h) = area.estimate_text_size(title, &style).map_err(draw_err)?;
    let (width, _) = area.dim_in_pixel();
    let centred = style.pos(Pos::new(HPos::Center, VPos::Top));
    area.draw_text(title, &centred, (width as i32 / 2, top))
        .map_err(draw_err)?;
    Ok(area.split_vertically(top + text_h as i32 + pad as i32).1)
}

/// Draws one panel (title, axes, series, legend) into its grid cell.
fn draw_panel<DB: DrawingBackend>(
    cell: &DrawingArea<DB, Shift>,
    panel: &Panel,
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let area = titled(cell, &panel.title, PANEL_TITLE_EM, m)?;
    match &panel.kind {
        PanelKind::Cartesian | PanelKind::Polar => draw_cartesian(&area, panel, m),
        PanelKind::Surface {
            z_label,
            z_range,
            elevation_deg,
            azimuth_deg,
        } => {
            let view = View::new(*elevation_deg, *azimuth_deg);
            draw_surface(&area, panel, (z_label, *z_range), view, m)
        }
    }
}

/// Draws a 2D panel: axes, each series in its mark, legend.
fn draw_cartesian<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let tick_font = m.font(1.0);
    let label_font = m.font(AXIS_LABEL_EM);
    let tick_len = m.px(0.35);
    let (margin_top, margin_right, margin_side) = (m.px(0.8), m.px(1.4), m.px(0.4));
    let (_, tick_h) = area.estimate_text_size("0", &tick_font).map_err(draw_err)?;
    let (_, label_h) = area
        .estimate_text_size("θ", &label_font)
        .map_err(draw_err)?;
    let label_gap = m.px(0.5);
    let x_area = 2 * tick_len + tick_h + label_gap + label_h;

    // y ticks first: their widest label decides the width left for the x axis.
    let (width, height) = area.dim_in_pixel();
    let plot_h = height
        .saturating_sub(margin_top + margin_side + x_area)
        .max(1);
    let y = Axis::y(panel, f64::from(plot_h) / (Y_TICK_SPACING_EM * m.unit));
    let mut widest = 0;
    for &tick in &y.ticks {
        let (w, _) = area
            .estimate_text_size(&y.label(tick), &tick_font)
            .map_err(draw_err)?;
        widest = widest.max(w);
    }
    let y_area = 2 * tick_len + widest + label_gap + label_h;
    let plot_w = width
        .saturating_sub(margin_side + margin_right + y_area)
        .max(1);
    let x = Axis::x(panel, f64::from(plot_w) / (X_TICK_SPACING_EM * m.unit));

    let mut chart = ChartBuilder::on(area)
        .margin_top(margin_top)
        .margin_right(margin_right)
        .margin_left(margin_side)
        .margin_bottom(margin_side)
        .x_label_area_size(x_area)
        .y_label_area_size(y_area)
        .build_cartesian_2d(x.clone(), y.clone())
        .map_err(draw_err)?;
    let x_fmt = |v: &f64| x.label(*v);
    let y_fmt = |v: &f64| y.label(*v);
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style(tick_font.clone())
        .axis_desc_style(label_font)
        .bold_line_style(m.line(GRID))
        .light_line_style(m.line(MINOR_GRID))
        .axis_style(m.line(FRAME))
        .set_all_tick_mark_size(tick_len)
        .draw()
        .map_err(draw_err)?;

    let plot = chart.plotting_area().strip_coord_spec();
    let (pw, ph) = plot.dim_in_pixel();
    let to_plot_px = |(vx, vy): (f64, f64)| {
        (
            (vx - x.lo) / (x.hi - x.lo) * f64::from(pw),
            (y.hi - vy) / (y.hi - y.lo) * f64::from(ph),
        )
    };
    // What each series covers, in plot pixels, for the legend to avoid.
    let mut covered: Vec<Vec<(f64, f64)>> = Vec::new();
    for series in &panel.series {
        let colour = series.style.colour;
        let mark = series.style.mark;
        if matches!(mark, Mark::Line | Mark::LinePoints) {
            let style = m.curve_style(colour, series.style.width);
            for piece in visible_pieces(series, panel, &x, &y) {
                draw_piece(&mut chart, &piece, style, series.style.dash)?;
                covered.push(piece.into_iter().map(to_plot_px).collect());
            }
        }
        if matches!(mark, Mark::Points | Mark::LinePoints) {
            let radius = m.dot(if mark == Mark::Points {
                POINT_RADIUS_PX
            } else {
                MARKER_RADIUS_PX
            });
            let dots = visible_points(series, panel, &x, &y);
            let fill = m.fill(colour, 1.0);
            chart
                .draw_series(dots.iter().map(|&p| Circle::new(p, radius, fill)))
                .map_err(draw_err)?;
            let r = f64::from(radius);
            covered.extend(dots.into_iter().map(|p| {
                let (px, py) = to_plot_px(p);
                vec![(px - r, py), (px + r, py)]
            }));
        }
        if mark == Mark::Bars {
            let bars = visible_bars(series, panel, &x, &y);
            let fill = m.fill(colour, 1.0);
            chart
                .draw_series(bars.iter().map(|&corners| Rectangle::new(corners, fill)))
                .map_err(draw_err)?;
            covered.extend(bars.into_iter().map(|[(x0, y0), (x1, y1)]| {
                let centre = (x0 + x1) / 2.0;
                vec![to_plot_px((centre, y0)), to_plot_px((centre, y1))]
            }));
        }
    }

    outline(
        &plot,
        [(0, 0), (pw as i32 - 1, ph as i32 - 1)],
        m.line(FRAME),
    )?;
    if panel.legend {
        let entries: Vec<(&Series, Sample)> = panel
            .series
            .iter()
            .map(|s| (s, Sample::of(s.style.mark)))
            .collect();
        draw_legend(&plot, &entries, &covered, &tick_font, m)?;
    }
    Ok(())
}

/// Draws a 3D panel: back panes with grid lines, surface meshes far to near, 3D lines and
/// dots over them, the labelled axis edges, and the legend.
///
/// A series with a grid of at least 2 × 2 points is a surface; any other series is a 3D line
/// (bars are drawn as lines), as is a grid of a single row or column. Mesh cells reaching
/// outside the displayed ranges are left out; lines are clipped to the box.
fn draw_surface<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    (z_label, z_range): (&str, Option<(f64, f64)>),
    view: View,
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let z_values = z_columns(panel)?;
    let tick_font = m.font(1.0);
    let label_font = m.font(AXIS_LABEL_EM);
    let text = |s: &str, font: &TextStyle| {
        area.estimate_text_size(s, font)
            .map(|(w, h)| (f64::from(w), f64::from(h)))
            .map_err(draw_err)
    };
    let tick_len = f64::from(m.px(0.35));
    let gap = f64::from(m.px(0.4));
    let (_, tick_h) = text("0", &tick_font)?;
    let (_, label_h) = text("θ", &label_font)?;
    let (width, height) = area.dim_in_pixel();
    let (width, height) = (f64::from(width), f64::from(height));
    // The box fills the area less room for tick labels and axis labels on the sides and below.
    let fit = |tick_w: f64| {
        let side = tick_len + tick_w + label_h + 3.0 * gap;
        let below = tick_len + tick_h + label_h + 3.0 * gap;
        let right = (width - side).max(side + 1.0);
        let bottom = (height - below).max(2.0 * gap + 1.0);
        Projector::fit(view, [side, right, 2.0 * gap, bottom])
    };

    // Tick counts from a first layout with a typical label width; the final layout makes
    // room for the widest label.
    let edges = view.axis_edges();
    let typical_w = text("−0.00", &tick_font)?.0;
    let first = fit(typical_w);
    let max_ticks = |edge: &plot3d::Edge| {
        let (a, b) = (first.px(edge.from), first.px(edge.to));
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let length = dx.hypot(dy);
        // Neighbouring labels must clear each other across the screen or down it; labels
        // set off diagonally need less room along a slanted edge than on a 2D axis.
        let across = typical_w + TICK_CLEARANCE_EM * m.unit;
        let down = tick_h + TICK_CLEARANCE_EM * m.unit;
        let spacing = (across * length / dx.abs()).min(down * length / dy.abs());
        if spacing.is_finite() && spacing > 0.0 {
            length / spacing + 1.0
        } else {
            2.0
        }
    };
    let axes = [
        Axis::x(panel, max_ticks(&edges[0])),
        Axis::y(panel, max_ticks(&edges[1])),
        Axis::z(panel, z_range, max_ticks(&edges[2])),
    ];
    let mut tick_w = 0.0f64;
    for axis in &axes {
        for &tick in &axis.ticks {
            tick_w = tick_w.max(text(&axis.label(tick), &tick_font)?.0);
        }
    }
    let projector = fit(tick_w);
    let ranges = axes.each_ref().map(|a| (a.lo, a.hi));
    let px = |p: P3| {
        let (x, y) = projector.px(p);
        (x.round() as i32, y.round() as i32)
    };
    let ring = |points: &[P3]| -> Vec<(i32, i32)> {
        points
            .iter()
            .chain(points.first())
            .map(|&p| px(p))
            .collect()
    };
    // Everything drawn, in area pixels, for the legend to avoid.
    let mut covered: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut cover = |path: &[(i32, i32)]| {
        covered.push(
            path.iter()
                .map(|&(x, y)| (f64::from(x), f64::from(y)))
                .collect(),
        );
    };

    // Back panes and their grid lines.
    let far = view.far_sides();
    for (axis, &high) in far.iter().enumerate() {
        let corners = plot3d::face(axis, high);
        area.draw(&Polygon::new(ring(&corners), PANE.filled()))
            .map_err(draw_err)?;
        for other in [(axis + 1) % 3, (axis + 2) % 3] {
            let across = 3 - axis - other;
            for &tick in &axes[other].ticks {
                let mut a = corners[0];
                a[other] = plot3d::to_box(other, tick, ranges[other]);
                a[across] = -plot3d::BOX_ASPECT[across] / 2.0;
                let mut b = a;
                b[across] = -a[across];
                area.draw(&PathElement::new([px(a), px(b)], m.line(PANE_GRID)))
                    .map_err(draw_err)?;
            }
        }
        let outline = ring(&corners);
        area.draw(&PathElement::new(outline.clone(), m.line(PANE_EDGE)))
            .map_err(draw_err)?;
        cover(&outline);
    }

    // Series in box coordinates (NaN where a point cannot be drawn).
    let placed: Vec<Vec<P3>> = panel
        .series
        .iter()
        .zip(&z_values)
        .map(|(series, zs)| {
            series
                .points
                .iter()
                .zip(zs.iter())
                .map(|(&(x, y), &z)| {
                    let shown = x_display(x, panel.x_unit).zip(y_display(y, panel.y_scale));
                    match shown {
                        Some((x, y)) if z.is_finite() => {
                            let v = [x, y, z];
                            [0, 1, 2].map(|i| plot3d::to_box(i, v[i], ranges[i]))
                        }
                        _ => [f64::NAN; 3],
                    }
                })
                .collect()
        })
        .collect();
    let is_surface = |s: &Series| matches!(s.grid, Some((rows, cols)) if rows >= 2 && cols >= 2);

    // Surface meshes, far to near.
    let mut quads = Vec::new();
    for (i, (series, points)) in panel.series.iter().zip(&placed).enumerate() {
        if let (true, Some(grid)) = (is_surface(series), series.grid) {
            plot3d::push_quads(&mut quads, &view, points, grid, i);
        }
    }
    plot3d::back_to_front(&mut quads);
    for quad in &quads {
        let colour = panel.series[quad.surface].style.colour;
        let shade = |c: u8| (f64::from(c) * quad.shade).round() as u8;
        let shaded = Rgb(shade(colour.0), shade(colour.1), shade(colour.2));
        let outline = ring(&quad.corners);
        area.draw(&Polygon::new(
            &outline[..4],
            m.fill(shaded, SURFACE_OPACITY),
        ))
        .map_err(draw_err)?;
        // Edge by edge: the raster backend mitres the joins of wide polylines, which spike
        // far out at the sharp corners of sliver cells.
        for edge in outline.windows(2) {
            area.draw(&PathElement::new(edge, m.line(mesh_colour(colour))))
                .map_err(draw_err)?;
        }
        cover(&outline);
    }

    // Lines and dots over the surfaces.
    for (series, points) in panel.series.iter().zip(&placed) {
        if is_surface(series) {
            continue;
        }
        let (colour, mark) = (series.style.colour, series.style.mark);
        if mark != Mark::Points {
            let style = m.curve_style(colour, series.style.width);
            for piece in plot3d::visible_pieces(points) {
                let path: Vec<(i32, i32)> = piece.iter().map(|&p| px(p)).collect();
                match dash_pattern(series.style.dash, &style) {
                    None => area.draw(&PathElement::new(path.clone(), style)),
                    Some((on, off)) => {
                        area.draw(&DashedPathElement::new(path.clone(), on, off, style))
                    }
                }
                .map_err(draw_err)?;
                cover(&path);
            }
        }
        if matches!(mark, Mark::Points | Mark::LinePoints) {
            let radius = m.dot(if mark == Mark::Points {
                POINT_RADIUS_PX
            } else {
                MARKER_RADIUS_PX
            });
            for &p in points.iter().filter(|&&p| plot3d::inside(p)) {
                area.draw(&Circle::new(px(p), radius, m.fill(colour, 1.0)))
                    .map_err(draw_err)?;
                let (x, y) = px(p);
                cover(&[(x - radius as i32, y), (x + radius as i32, y)]);
            }
        }
    }

    // Labelled edges: ticks and their labels point away from the box, the axis label beyond.
    let centre = projector.px([0.0; 3]);
    let titles = [panel.x_label.as_str(), panel.y_label.as_str(), z_label];
    for (i, edge) in edges.iter().enumerate() {
        area.draw(&PathElement::new(
            [px(edge.from), px(edge.to)],
            m.line(FRAME),
        ))
        .map_err(draw_err)?;
        let mid = projector.px(edge.midpoint());
        let out = outward((mid.0 - centre.0, mid.1 - centre.1), i == 2);
        let (pos, corner) = anchor_towards(out);
        let style = tick_font.pos(pos);
        let mut reach = 0.0f64;
        for &tick in &axes[i].ticks {
            let (x, y) = projector.px(edge.at(plot3d::to_box(i, tick, ranges[i])));
            let end = (x + out.0 * tick_len, y + out.1 * tick_len);
            let tick_mark = [(x, y), end].map(|(x, y)| (x.round() as i32, y.round() as i32));
            area.draw(&PathElement::new(tick_mark, m.line(FRAME)))
                .map_err(draw_err)?;
            let label = axes[i].label(tick);
            let size = text(&label, &tick_font)?;
            let at = (end.0 + out.0 * gap, end.1 + out.1 * gap);
            area.draw_text(&label, &style, (at.0.round() as i32, at.1.round() as i32))
                .map_err(draw_err)?;
            reach = reach.max(out.0.abs() * size.0 + out.1.abs() * size.1);
            cover(&text_box(at, size, corner));
        }
        if !titles[i].is_empty() {
            let (w, h) = text(titles[i], &label_font)?;
            // The z label reads upwards.
            let size = if i == 2 { (h, w) } else { (w, h) };
            let along =
                tick_len + 2.0 * gap + reach + (out.0.abs() * size.0 + out.1.abs() * size.1) / 2.0;
            let at = (mid.0 + out.0 * along, mid.1 + out.1 * along);
            let centred = label_font.pos(Pos::new(HPos::Center, VPos::Center));
            let style = if i == 2 {
                centred.transform(FontTransform::Rotate270)
            } else {
                centred
            };
            area.draw_text(
                titles[i],
                &style,
                (at.0.round() as i32, at.1.round() as i32),
            )
            .map_err(draw_err)?;
            cover(&text_box(at, size, (0.5, 0.5)));
        }
    }

    if panel.legend {
        let entries: Vec<(&Series, Sample)> = panel
            .series
            .iter()
            .map(|s| {
                let sample = match s.style.mark {
                    _ if is_surface(s) => Sample::Patch,
                    Mark::Bars => Sample::Line,
                    mark => Sample::of(mark),
                };
                (s, sample)
            })
            .collect();
        draw_legend(area, &entries, &covered, &tick_font, m)?;
    }
    Ok(())
}

/// The z values of each series of a surface panel, after checking that every point has one
/// and that each grid matches its number of points.
fn z_columns(panel: &Panel) -> Result<Vec<&[f64]>, PlotError> {
    panel
        .series
        .iter()
        .map(|s| {
            let fail = |reason: String| PlotError::Series {
                label: s.label.clone(),
                reason,
            };
            let n = s.points.len();
            let z: &[f64] = match &s.z {
                Some(z) => z,
                None if n == 0 => &[],
                None => return Err(fail("a surface panel needs a z value per point".to_owned())),
            };
            if z.len() != n {
                return Err(fail(format!("{n} points but {} z values", z.len())));
            }
            if let Some((rows, cols)) = s.grid {
                if rows.checked_mul(cols) != Some(n) {
                    return Err(fail(format!(
                        "a {rows}×{cols} grid does not match {n} points"
                    )));
                }
            }
            Ok(z)
        })
        .collect()
}

/// Sine of 22.5°: a label direction leaning less than this toward an axis counts as along it.
const LEAN: f64 = 0.382_683_432_365_089_8;

/// Unit screen direction of `d`; horizontal only when `horizontal` (the upright z axis).
fn outward((dx, dy): (f64, f64), horizontal: bool) -> (f64, f64) {
    let (dx, dy) = if horizontal { (dx, 0.0) } else { (dx, dy) };
    let length = dx.hypot(dy);
    if length > 0.0 {
        (dx / length, dy / length)
    } else {
        (0.0, 1.0)
    }
}

/// The text anchor for a label set off in direction `out` from its point, and that anchor's
/// place in the label's box as fractions of its width and height (0 = left or top).
fn anchor_towards((dx, dy): (f64, f64)) -> (Pos, (f64, f64)) {
    let (h, fx) = if dx > LEAN {
        (HPos::Left, 0.0)
    } else if dx < -LEAN {
        (HPos::Right, 1.0)
    } else {
        (HPos::Center, 0.5)
    };
    let (v, fy) = if dy > LEAN {
        (VPos::Top, 0.0)
    } else if dy < -LEAN {
        (VPos::Bottom, 1.0)
    } else {
        (VPos::Center, 0.5)
    };
    (Pos::new(h, v), (fx, fy))
}

/// The outline of a text box of `(w, h)` whose anchor at `at` sits at `(fx, fy)` in it.
fn text_box(at: (f64, f64), (w, h): (f64, f64), (fx, fy): (f64, f64)) -> [(i32, i32); 5] {
    let (x0, y0) = (at.0 - fx * w, at.1 - fy * h);
    let [x0, y0, x1, y1] = [x0, y0, x0 + w, y0 + h].map(|v| v.round() as i32);
    [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]
}

/// The darker colour of a surface's mesh lines.
fn mesh_colour(colour: Rgb) -> RGBColor {
    let dim = |c: u8| (f64::from(c) * MESH_DARKEN).round() as u8;
    RGBColor(dim(colour.0), dim(colour.1), dim(colour.2))
}

/// Draws one unbroken piece of a curve (display coordinates) in its dash pattern.
fn draw_piece<DB: DrawingBackend>(
    chart: &mut ChartContext<DB, Cartesian2d<Axis, Axis>>,
    piece: &[(f64, f64)],
    style: ShapeStyle,
    dash: Dash,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let points = piece.iter().copied();
    match dash_pattern(dash, &style) {
        None => chart.draw_series(LineSeries::new(points, style)).map(drop),
        Some((on, off)) => chart
            .draw_series(DashedLineSeries::new(points, on, off, style))
            .map(drop),
    }
    .map_err(draw_err)
}

/// Dash and gap lengths in device pixels for `dash` drawn with `style`; `None` when solid.
fn dash_pattern(dash: Dash, style: &ShapeStyle) -> Option<(f64, f64)> {
    let width = f64::from(style.stroke_width);
    match dash {
        Dash::Solid => None,
        Dash::Dashed => Some((DASHED.0 * width, DASHED.1 * width)),
        Dash::Dotted => Some((DOTTED.0 * width, DOTTED.1 * width)),
    }
}

/// What a legend entry shows next to its label.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Sample {
    /// A short stretch of the line in its dash pattern.
    Line,
    /// A dot.
    Dot,
    /// A line with a dot in its middle.
    LineDot,
    /// A small filled box (bars).
    Bar,
    /// A translucent box with a mesh-coloured border (surfaces).
    Patch,
}

impl Sample {
    /// The sample for a 2D series drawn with `mark`.
    fn of(mark: Mark) -> Sample {
        match mark {
            Mark::Line => Sample::Line,
            Mark::Points => Sample::Dot,
            Mark::LinePoints => Sample::LineDot,
            Mark::Bars => Sample::Bar,
        }
    }
}

/// Draws the legend inside `plot` where it hides the least of what is drawn.
///
/// `covered` are the drawn curves, dots and bars in plot-area pixels. Series with an empty
/// label get no entry.
fn draw_legend<DB: DrawingBackend>(
    plot: &DrawingArea<DB, Shift>,
    entries: &[(&Series, Sample)],
    covered: &[Vec<(f64, f64)>],
    font: &TextStyle,
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let entries: Vec<&(&Series, Sample)> = entries
        .iter()
        .filter(|(s, _)| !s.label.is_empty())
        .collect();
    if entries.is_empty() {
        return Ok(());
    }
    let (pad, sample, gap, row) = (m.px(0.5), m.px(2.2), m.px(0.5), m.px(1.35));
    let mut text_w = 0;
    for (s, _) in &entries {
        text_w = text_w.max(plot.estimate_text_size(&s.label, font).map_err(draw_err)?.0);
    }
    let box_w = (2 * pad + sample + gap + text_w) as i32;
    let box_h = (2 * pad + row * entries.len() as u32) as i32;
    let (pw, ph) = plot.dim_in_pixel();
    let (x0, y0) = legend_position(
        (pw as i32, ph as i32),
        (box_w, box_h),
        m.px(0.6) as i32,
        covered,
    );

    let background = WHITE.mix(LEGEND_OPACITY).filled();
    let bounds = [(x0, y0), (x0 + box_w, y0 + box_h)];
    plot.draw(&Rectangle::new(bounds, background))
        .map_err(draw_err)?;
    outline(plot, bounds, m.line(LEGEND_BORDER))?;
    let label_style = font.pos(Pos::new(HPos::Left, VPos::Center));
    for (i, (s, kind)) in entries.iter().enumerate() {
        let cy = y0 + (pad + row * i as u32 + row / 2) as i32;
        let sx = x0 + pad as i32;
        let colour = s.style.colour;
        let mid = sx + sample as i32 / 2;
        let (half_w, half_h) = (sample as i32 / 4, row as i32 * 3 / 10);
        let patch = [(mid - half_w, cy - half_h), (mid + half_w, cy + half_h)];
        if matches!(kind, Sample::Line | Sample::LineDot) {
            let style = m.curve_style(colour, s.style.width);
            let line = [(sx, cy), (sx + sample as i32, cy)];
            match dash_pattern(s.style.dash, &style) {
                None => plot.draw(&PathElement::new(line, style)),
                Some((on, off)) => plot.draw(&DashedPathElement::new(line, on, off, style)),
            }
            .map_err(draw_err)?;
        }
        match kind {
            Sample::Line => {}
            Sample::Dot | Sample::LineDot => plot
                .draw(&Circle::new(
                    (mid, cy),
                    m.dot(MARKER_RADIUS_PX),
                    m.fill(colour, 1.0),
                ))
                .map_err(draw_err)?,
            Sample::Bar => plot
                .draw(&Rectangle::new(patch, m.fill(colour, 1.0)))
                .map_err(draw_err)?,
            Sample::Patch => {
                plot.draw(&Rectangle::new(patch, m.fill(colour, SURFACE_OPACITY)))
                    .map_err(draw_err)?;
                outline(plot, patch, m.line(mesh_colour(colour)))?;
            }
        }
        let text_x = sx + (sample + gap) as i32;
        plot.draw_text(&s.label, &label_style, (text_x, cy))
            .map_err(draw_err)?;
    }
    Ok(())
}

/// Top-left corner for a legend box of `size` in a plot area of `plot` pixels: among
/// [`LEGEND_HEIGHTS`] heights along the right, left and centre, the position hiding the least
/// curve length (`pieces`, in plot pixels). Ties go to the higher, then right, left, centre.
fn legend_position(
    (plot_w, plot_h): (i32, i32),
    (box_w, box_h): (i32, i32),
    inset: i32,
    pieces: &[Vec<(f64, f64)>],
) -> (i32, i32) {
    let bottom = (plot_h - inset - box_h).max(inset);
    let right = (plot_w - inset - box_w).max(inset);
    let columns = [right, inset, (right + inset) / 2];
    let rows: Vec<i32> = (0..LEGEND_HEIGHTS)
        .map(|i| inset + (bottom - inset) * i / (LEGEND_HEIGHTS - 1))
        .collect();
    // Hidden curve length per position, row-major; rows and columns reject segments separately.
    let mut hidden = vec![0.0; rows.len() * columns.len()];
    for pair in pieces.iter().flat_map(|piece| piece.windows(2)) {
        let ((ax, ay), (bx, by)) = (pair[0], pair[1]);
        for (r, &y0) in rows.iter().enumerate() {
            let (y_top, y_bottom) = (f64::from(y0), f64::from(y0 + box_h));
            if ay.max(by) < y_top || ay.min(by) > y_bottom {
                continue;
            }
            for (c, &x0) in columns.iter().enumerate() {
                let (x_left, x_right) = (f64::from(x0), f64::from(x0 + box_w));
                if ax.max(bx) < x_left || ax.min(bx) > x_right {
                    continue;
                }
                let bounds = [x_left, x_right, y_top, y_bottom];
                if let Some(Clipped { start, end, .. }) = clip(pair[0], pair[1], bounds) {
                    hidden[r * columns.len() + c] += (end.0 - start.0).hypot(end.1 - start.1);
                }
            }
        }
    }
    let mut best = 0;
    for (i, &length) in hidden.iter().enumerate() {
        if length < hidden[best] {
            best = i;
        }
    }
    (columns[best % columns.len()], rows[best / columns.len()])
}

/// Strokes the border of a rectangle. A closed path rather than an unfilled `Rectangle`,
/// whose SVG form would lose the stroke width.
fn outline<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    [(x0, y0), (x1, y1)]: [(i32, i32); 2],
    style: ShapeStyle,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let corners = [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)];
    area.draw(&PathElement::new(corners, style))
        .map_err(draw_err)
}

/// How tick values are written.
#[derive(Clone, Copy)]
enum TickFormat {
    /// Fixed decimals, with an optional unit suffix (`°`).
    Fixed {
        decimals: usize,
        suffix: &'static str,
    },
    /// The value is a base-10 exponent: written `10ᵏ`.
    Decade,
}

/// One axis in display units (degrees or radians on x; values or log₁₀ values on y).
#[derive(Clone)]
struct Axis {
    lo: f64,
    hi: f64,
    /// Labelled ticks with bold grid lines.
    ticks: Vec<f64>,
    /// Unlabelled light grid lines (log axes: 2…9 × 10ᵏ).
    minor: Vec<f64>,
    format: TickFormat,
}

impl Axis {
    /// The x axis of `panel`, with at most about `max_ticks` ticks.
    ///
    /// An automatic θ range is the data's; an automatic plain range adds a margin (at least
    /// half a bar spacing when bars are drawn). Plain axes whose x values are all whole
    /// numbers (indices) tick at whole numbers.
    fn x(panel: &Panel, max_ticks: f64) -> Axis {
        let unit = panel.x_unit;
        let data = || {
            panel
                .series
                .iter()
                .flat_map(|s| s.points.iter())
                .filter_map(move |&(theta, _)| x_display(theta, unit))
        };
        let automatic = || match extent(data()) {
            None => default_x(unit),
            Some((lo, hi)) if unit == XUnit::Plain => {
                let half_bar = panel
                    .series
                    .iter()
                    .filter(|s| s.style.mark == Mark::Bars)
                    .filter_map(|s| median_spacing(s, unit))
                    .fold(0.0, f64::max)
                    / 2.0;
                let pad = (AUTO_MARGIN * (hi - lo)).max(half_bar);
                (lo - pad, hi + pad)
            }
            Some(range) => range,
        };
        let given = panel
            .x_range
            .and_then(|(a, b)| Some((x_display(a, unit)?, x_display(b, unit)?)));
        let (lo, hi) = match given {
            Some((a, b)) => (a.min(b), a.max(b)),
            None => automatic(),
        };
        let (lo, hi) = widen_if_flat(lo, hi);
        let whole = unit == XUnit::Plain && data().all(|v| v.fract() == 0.0);
        let (step, decimals) = match unit {
            XUnit::Degrees => degree_step(hi - lo, max_ticks),
            XUnit::Plain if whole => {
                let step = nice_step(hi - lo, max_ticks, &DECADE_MANTISSAS).0;
                (step.max(1.0), 0)
            }
            XUnit::Radians | XUnit::Plain | XUnit::Slope => {
                nice_step(hi - lo, max_ticks, &NICE_MANTISSAS)
            }
        };
        let suffix = match unit {
            XUnit::Degrees => "°",
            XUnit::Radians | XUnit::Plain | XUnit::Slope => "",
        };
        Axis {
            lo,
            hi,
            ticks: multiples(lo, hi, step),
            minor: Vec::new(),
            format: TickFormat::Fixed { decimals, suffix },
        }
    }

    /// The value axis of `panel`, with at most about `max_ticks` ticks. An automatic linear
    /// range includes 0 when bars are drawn.
    fn y(panel: &Panel, max_ticks: f64) -> Axis {
        let scale = panel.y_scale;
        let data = || {
            panel
                .series
                .iter()
                .flat_map(|s| s.points.iter())
                .filter_map(move |&(_, v)| y_display(v, scale))
        };
        let given = panel.y_range.and_then(|(a, b)| {
            let (a, b) = (y_display(a, scale)?, y_display(b, scale)?);
            Some((a.min(b), a.max(b)))
        });
        match scale {
            YScale::Linear => {
                let bars = panel.series.iter().any(|s| s.style.mark == Mark::Bars);
                let base = bars.then_some(0.0);
                Axis::linear(given, extent(data().chain(base)), max_ticks)
            }
            YScale::Log => {
                let (lo, hi) = given.unwrap_or_else(|| match extent(data()) {
                    Some((a, b)) => (a.floor(), b.ceil()),
                    None => (0.0, 1.0),
                });
                let (lo, hi) = if hi - lo < 1.0 && given.is_none() {
                    (lo, lo + 1.0)
                } else {
                    widen_if_flat(lo, hi)
                };
                let step = nice_step(hi - lo, max_ticks, &DECADE_MANTISSAS).0.max(1.0);
                let ticks = multiples(lo, hi, step);
                let minor = if step == 1.0 && hi - lo <= MAX_MINOR_DECADES {
                    (lo.floor() as i32..hi.ceil() as i32)
                        .flat_map(|d| (2..10).map(move |m| f64::from(d) + f64::from(m).log10()))
                        .filter(|v| (lo..=hi).contains(v))
                        .collect()
                } else {
                    Vec::new()
                };
                Axis {
                    lo,
                    hi,
                    ticks,
                    minor,
                    format: TickFormat::Decade,
                }
            }
        }
    }

    /// The z axis of a surface panel: `given` or the extent of the series' z values.
    fn z(panel: &Panel, given: Option<(f64, f64)>, max_ticks: f64) -> Axis {
        let data = panel
            .series
            .iter()
            .filter_map(|s| s.z.as_deref())
            .flatten()
            .copied()
            .filter(|v| v.is_finite());
        let given = given.filter(|(a, b)| a.is_finite() && b.is_finite());
        Axis::linear(
            given.map(|(a, b)| (a.min(b), a.max(b))),
            extent(data),
            max_ticks,
        )
    }

    /// A linear axis over `given`, else over the data `extent` as "PlotRange → All".
    fn linear(given: Option<(f64, f64)>, extent: Option<(f64, f64)>, max_ticks: f64) -> Axis {
        let (lo, hi) = given.unwrap_or_else(|| auto_linear(extent));
        let (lo, hi) = widen_if_flat(lo, hi);
        // A short axis still gets two labelled ticks: finer steps until it does.
        let mut max_ticks = max_ticks;
        let (mut step, mut decimals) = nice_step(hi - lo, max_ticks, &NICE_MANTISSAS);
        while multiples(lo, hi, step).len() < 2 && max_ticks < MIN_TICKS_SEARCH {
            max_ticks += 1.0;
            (step, decimals) = nice_step(hi - lo, max_ticks, &NICE_MANTISSAS);
        }
        Axis {
            lo,
            hi,
            ticks: multiples(lo, hi, step),
            minor: Vec::new(),
            format: TickFormat::Fixed {
                decimals,
                suffix: "",
            },
        }
    }

    /// The tick label of display value `v`.
    fn label(&self, v: f64) -> String {
        match self.format {
            TickFormat::Fixed { decimals, suffix } => {
                let v = if v.abs() < 1e-12 * (self.hi - self.lo) {
                    0.0
                } else {
                    v
                };
                format!("{v:.decimals$}{suffix}").replace('-', "−")
            }
            TickFormat::Decade => {
                let exponent = v.round() as i64;
                let digits: String = exponent
                    .to_string()
                    .chars()
                    .map(|c| match c {
                        '-' => '⁻',
                        d => SUPERSCRIPT_DIGITS[d.to_digit(10).unwrap_or(0) as usize],
                    })
                    .collect();
                format!("10{digits}")
            }
        }
    }
}

/// The axis as a plotters coordinate: linear in display units, ticks as bold key points and
/// the minor lines as light ones.
impl Ranged for Axis {
    type FormatOption = DefaultFormatting;
    type ValueType = f64;

    fn map(&self, value: &f64, limit: (i32, i32)) -> i32 {
        let t = (value - self.lo) / (self.hi - self.lo);
        limit.0 + (f64::from(limit.1 - limit.0) * t).round() as i32
    }

    fn key_points<Hint: KeyPointHint>(&self, hint: Hint) -> Vec<f64> {
        if hint.weight().allow_light_points() {
            self.minor.clone()
        } else {
            self.ticks.clone()
        }
    }

    fn range(&self) -> Range<f64> {
        self.lo..self.hi
    }
}

const SUPERSCRIPT_DIGITS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];

/// θ (radians) in display units, if finite.
fn x_display(theta: f64, unit: XUnit) -> Option<f64> {
    let x = match unit {
        XUnit::Degrees => theta.to_degrees(),
        XUnit::Slope => theta.tan(),
        XUnit::Radians | XUnit::Plain => theta,
    };
    x.is_finite().then_some(x)
}

/// A value in display units (log₁₀ on log axes), if it can be drawn.
fn y_display(v: f64, scale: YScale) -> Option<f64> {
    match scale {
        YScale::Linear => v.is_finite().then_some(v),
        YScale::Log => (v > 0.0 && v.is_finite()).then(|| v.log10()),
    }
}

/// The x range shown when a panel has no data: 0 to π/2.
fn default_x(unit: XUnit) -> (f64, f64) {
    match unit {
        XUnit::Degrees => (0.0, 90.0),
        XUnit::Radians => (0.0, std::f64::consts::FRAC_PI_2),
        XUnit::Plain => (0.0, 1.0),
        XUnit::Slope => (0.0, 4.0),
    }
}

/// Minimum and maximum of `values`, `None` when empty.
fn extent(values: impl Iterator<Item = f64>) -> Option<(f64, f64)> {
    values.fold(None, |acc, v| match acc {
        None => Some((v, v)),
        Some((lo, hi)) => Some((lo.min(v), hi.max(v))),
    })
}

/// PlotRange → All on a linear axis: the data extent plus a margin, from 0 when all values are ≥ 0.
fn auto_linear(extent: Option<(f64, f64)>) -> (f64, f64) {
    let Some((lo, hi)) = extent else {
        return (0.0, 1.0);
    };
    let lo = if lo >= 0.0 { 0.0 } else { lo };
    let span = hi - lo;
    let lo = if lo == 0.0 {
        0.0
    } else {
        lo - AUTO_MARGIN * span
    };
    (lo, hi + AUTO_MARGIN * span)
}

/// Opens up an empty range (a flat curve, a single point) around its value.
fn widen_if_flat(lo: f64, hi: f64) -> (f64, f64) {
    if hi - lo > 1e-12 * lo.abs().max(hi.abs()) && hi - lo > f64::MIN_POSITIVE {
        return (lo, hi);
    }
    let pad = if lo == 0.0 { 1.0 } else { lo.abs() * 0.5 };
    (lo - pad, hi + pad)
}

/// A step `mantissa × 10ⁿ` giving at most about `max_ticks` ticks over `span`, and its decimals.
fn nice_step(span: f64, max_ticks: f64, mantissas: &[f64]) -> (f64, usize) {
    let raw = span / (max_ticks.floor() - 1.0).max(1.0);
    let magnitude = 10f64.powf(raw.log10().floor());
    let mantissa = mantissas
        .iter()
        .copied()
        .find(|&m| m * magnitude >= raw * (1.0 - 1e-9))
        .unwrap_or(10.0);
    let step = mantissa * magnitude;
    let decimals =
        (-(step.log10() + 1e-9).floor()).max(0.0) as usize + usize::from(mantissa == 2.5);
    (step, decimals)
}

/// A step from [`DEGREE_STEPS`] giving at most about `max_ticks` ticks, else a nice step.
fn degree_step(span: f64, max_ticks: f64) -> (f64, usize) {
    let limit = max_ticks.floor().max(2.0);
    DEGREE_STEPS
        .into_iter()
        .filter(|&step| step <= span)
        .find(|&step| (span / step).floor() + 1.0 <= limit)
        .map_or_else(
            || nice_step(span, max_ticks, &NICE_MANTISSAS),
            |step| (step, 0),
        )
}

/// The multiples of `step` in `[lo, hi]`.
fn multiples(lo: f64, hi: f64, step: f64) -> Vec<f64> {
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    (first..=last).map(|i| i as f64 * step).collect()
}

/// The median gap between the distinct x values of `series` (display units), if it has two.
fn median_spacing(series: &Series, unit: XUnit) -> Option<f64> {
    let mut xs: Vec<f64> = series
        .points
        .iter()
        .filter_map(|&(theta, _)| x_display(theta, unit))
        .collect();
    xs.sort_by(f64::total_cmp);
    let mut gaps: Vec<f64> = xs
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|&g| g > 0.0)
        .collect();
    gaps.sort_by(f64::total_cmp);
    gaps.get(gaps.len() / 2).copied()
}

/// The points of `series` inside the axes box, in display coordinates.
fn visible_points(series: &Series, panel: &Panel, x: &Axis, y: &Axis) -> Vec<(f64, f64)> {
    series
        .points
        .iter()
        .filter_map(|&(theta, v)| x_display(theta, panel.x_unit).zip(y_display(v, panel.y_scale)))
        .filter(|&(vx, vy)| (x.lo..=x.hi).contains(&vx) && (y.lo..=y.hi).contains(&vy))
        .collect()
}

/// The bars of `series` as display-coordinate rectangles clipped to the axes box: from 0
/// (the bottom of a log axis) to each value, [`BAR_FRACTION`] of the median x spacing wide.
fn visible_bars(series: &Series, panel: &Panel, x: &Axis, y: &Axis) -> Vec<[(f64, f64); 2]> {
    let width = median_spacing(series, panel.x_unit)
        .map_or(LONE_BAR_FRACTION * (x.hi - x.lo), |gap| BAR_FRACTION * gap);
    let base = match panel.y_scale {
        YScale::Linear => 0.0f64.clamp(y.lo, y.hi),
        YScale::Log => y.lo,
    };
    series
        .points
        .iter()
        .filter_map(|&(theta, v)| x_display(theta, panel.x_unit).zip(y_display(v, panel.y_scale)))
        .filter_map(|(centre, top)| {
            let (x0, x1) = (
                (centre - width / 2.0).max(x.lo),
                (centre + width / 2.0).min(x.hi),
            );
            let top = top.clamp(y.lo, y.hi);
            (x0 < x1 && top != base).then_some([(x0, base), (x1, top)])
        })
        .collect()
}

/// The drawable parts of `series` in display coordinates: broken at undrawable points
/// (non-finite, or ≤ 0 on a log axis) and clipped to the axes box.
fn visible_pieces(series: &Series, panel: &Panel, x: &Axis, y: &Axis) -> Vec<Vec<(f64, f64)>> {
    let bounds = [x.lo, x.hi, y.lo, y.hi];
    let mut pieces = Vec::new();
    let mut current: Vec<(f64, f64)> = Vec::new();
    let mut flush = |current: &mut Vec<(f64, f64)>| {
        if current.len() >= 2 {
            pieces.push(std::mem::take(current));
        } else {
            current.clear();
        }
    };
    let mut previous: Option<(f64, f64)> = None;
    for &(theta, v) in series.points.iter() {
        let point = x_display(theta, panel.x_unit).zip(y_display(v, panel.y_scale));
        match (previous, point) {
            (_, None) => flush(&mut current),
            (None, Some(p)) => {
                if clip(p, p, bounds).is_some() {
                    current.push(p);
                }
            }
            (Some(a), Some(b)) => match clip(a, b, bounds) {
                None => flush(&mut current),
                Some(Clipped {
                    start,
                    end,
                    entered,
                    left,
                }) => {
                    if entered {
                        flush(&mut current);
                    }
                    if current.is_empty() {
                        current.push(start);
                    }
                    current.push(end);
                    if left {
                        flush(&mut current);
                    }
                }
            },
        }
        previous = point;
    }
    flush(&mut current);
    pieces
}

/// The part of a segment inside a box.
struct Clipped {
    start: (f64, f64),
    end: (f64, f64),
    /// The segment starts outside the box.
    entered: bool,
    /// The segment ends outside the box.
    left: bool,
}

/// Liang–Barsky: the part of segment a→b inside `[x0, x1] × [y0, y1]`.
fn clip(a: (f64, f64), b: (f64, f64), [x0, x1, y0, y1]: [f64; 4]) -> Option<Clipped> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| (a.0 + t * dx, a.1 + t * dy);
    Some(Clipped {
        start: at(t0),
        end: at(t1),
        entered: t0 > 0.0,
        left: t1 < 1.0,
    })
}

/// Gives the SVG its CSS size, font family and font sizes.
///
/// The drawing was made at `SVG_UNITS_PER_PX` units per pixel, so the `viewBox` keeps those
/// units. plotters' SVG backend writes `font-family="<registered name>" font-size="size / 1.24"`;
/// the family gets its generic fallback, and the size becomes the em size that the raster
/// backend uses for the same text style, so that SVG and PNG text have the same extent.
fn finish_svg(document: &str, canvas: &Canvas, (width, height): (u32, u32)) -> String {
    /// plotters-svg 0.3.7 divides the style size by this to get `font-size`.
    const PLOTTERS_SVG_DIVISOR: f64 = 1.24;
    let drawn = format!(r#"<svg width="{width}" height="{height}" "#);
    let sized = format!(
        r#"<svg width="{}" height="{}" "#,
        canvas.width_px, canvas.height_px
    );
    let document = document.replacen(&drawn, &sized, 1);
    let marker = format!(r#"font-family="{FONT_NAME}" font-size=""#);
    let mut parts = document.split(marker.as_str());
    let mut out = String::with_capacity(document.len() + document.len() / 16);
    out.push_str(parts.next().unwrap_or_default());
    for part in parts {
        let (size, rest) = part.split_once('"').unwrap_or(("", part));
        let em = size.parse::<f64>().unwrap_or(0.0) * PLOTTERS_SVG_DIVISOR * EM_PER_SIZE;
        out.push_str(&format!(
            r#"font-family="{SVG_FONT_FAMILY}" font-size="{em:.2}"{rest}"#
        ));
    }
    out
}

/// Encodes packed 8-bit RGB pixels as a PNG with fixed settings: fast deflate and the Sub
/// filter, ~6× faster than adaptive filtering for files ~1.6× larger (plots are mostly flat).
fn encode_png(rgb: &[u8], width: u32, height: u32) -> Result<Vec<u8>, PlotError> {
    let mut out = Vec::with_capacity(rgb.len() / 16);
    let mut encoder = png::Encoder::new(&mut out, width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Fast);
    encoder.set_filter(png::FilterType::Sub);
    encoder.set_adaptive_filter(png::AdaptiveFilterType::NonAdaptive);
    encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(rgb)?;
    writer.finish()?;
    Ok(out)
}

#[cfg(test)]
mod tests {
    use std::f64::consts::{FRAC_PI_2, PI};
    use std::sync::Arc;

    use super::*;
    use crate::series::{Style, Theme};

    const RED: u32 = 0xDB2E2E;
    const BLUE: u32 = 0x2689D1;
    const ORANGE: u32 = 0xFF9900;

    fn series(label: &str, hex: u32, width: f64, dash: Dash, points: Vec<(f64, f64)>) -> Series {
        Series {
            label: label.to_owned(),
            curve: "{}".to_owned(),
            style: Style {
                colour: Rgb::from_hex(hex),
                width,
                dash,
                mark: Mark::Line,
            },
            points: Arc::new(points),
            z: None,
            grid: None,
        }
    }

    fn marked(mut series: Series, mark: Mark) -> Series {
        series.style.mark = mark;
        series
    }

    fn in_3d(mut series: Series, z: Vec<f64>, grid: Option<(usize, usize)>) -> Series {
        series.z = Some(Arc::new(z));
        series.grid = grid;
        series
    }

    fn sampled(f: impl Fn(f64) -> f64) -> Vec<(f64, f64)> {
        (0..=200)
            .map(|i| f64::from(i) / 200.0 * FRAC_PI_2)
            .map(|theta| (theta, f(theta)))
            .collect()
    }

    fn beckmann(alpha_b: f64) -> Vec<(f64, f64)> {
        sampled(|theta| {
            let cos = theta.cos();
            let tan2 = theta.tan().powi(2);
            (-tan2 / (alpha_b * alpha_b)).exp() / (PI * alpha_b * alpha_b * cos.powi(4))
        })
    }

    fn panel(x_unit: XUnit, y_scale: YScale, series: Vec<Series>) -> Panel {
        Panel {
            title: String::new(),
            x_label: "θ".to_owned(),
            y_label: "D(θ)".to_owned(),
            x_unit,
            kind: PanelKind::Cartesian,
            y_scale,
            x_range: None,
            y_range: None,
            legend: true,
            series,
        }
    }

    fn figure(panels: Vec<Panel>) -> Figure {
        Figure {
            id: "sample".to_owned(),
            title: "NDF and Fresnel".to_owned(),
            rows: 1,
            cols: panels.len().max(1),
            canvas: Canvas {
                width_px: 400,
                height_px: 250,
                png_scale: 2.0,
                font_px: 12.0,
            },
            theme: Theme::Notebook,
            panels,
        }
    }

    /// A log panel in radians (a dashed series) and a linear panel in degrees (a thick one).
    fn sample() -> Figure {
        let mut log = panel(
            XUnit::Radians,
            YScale::Log,
            vec![
                series("α_b = 0.4", RED, 1.0, Dash::Dashed, beckmann(0.4)),
                series("α_b = 0.8", BLUE, 1.0, Dash::Solid, beckmann(0.8)),
            ],
        );
        log.title = "Beckmann".to_owned();
        let schlick = |f0: f64| sampled(move |theta| f0 + (1.0 - f0) * (1.0 - theta.cos()).powi(5));
        let mut fresnel = panel(
            XUnit::Degrees,
            YScale::Linear,
            vec![
                series("F₀ = 0.04", ORANGE, 2.0, Dash::Solid, schlick(0.04)),
                series("F₀ = 0.5", RED, 1.0, Dash::Dotted, schlick(0.5)),
            ],
        );
        fresnel.y_label = "F".to_owned();
        figure(vec![log, fresnel])
    }

    const BLACK: u32 = 0x000000;
    const STEEL: u32 = 0x1F77B4;

    /// Singular values of a Fresnel curve matrix, normalized by their sum: the first three
    /// from MATH.md's spectrum check, then a geometric tail.
    fn spectrum() -> Vec<f64> {
        let mut values = vec![0.91356, 0.97961 - 0.91356, 0.99477 - 0.97961];
        let tail = 1.0 - 0.99477;
        values.extend((1..=17).map(|k| tail * 0.5f64.powi(k) / (1.0 - 0.5f64.powi(17))));
        values
    }

    /// A smooth stand-in for the Gulbrandsen coefficient manifold: (c₀, c₂, c₃) at (r, g).
    fn manifold(r: f64, g: f64) -> [f64; 3] {
        let c0 = r + 0.2 * g * r * (1.0 - r);
        let c2 = 0.3 * (PI * r).sin() * (2.0 * g - 1.0) * (1.0 - 0.3 * r);
        let c3 = 0.8 * (g - 0.5) * (1.0 - r) * (PI * r).cos();
        [c0, c2, c3]
    }

    /// `n` values evenly spaced over [0, 1].
    fn unit_steps(n: usize) -> impl Iterator<Item = f64> + Clone {
        (0..n).map(move |i| i as f64 / (n - 1) as f64)
    }

    /// The manifold over an `n × n` (r, g) grid, row-major in r.
    fn manifold_grid(n: usize) -> Vec<[f64; 3]> {
        let gs = unit_steps(n);
        unit_steps(n)
            .flat_map(|r| gs.clone().map(move |g| manifold(r, g)))
            .collect()
    }

    /// The edge of the manifold at edge tint `g`, sampled at 100 values of r.
    fn manifold_edge(g: f64) -> Vec<[f64; 3]> {
        unit_steps(100).map(|r| manifold(r, g)).collect()
    }

    fn xy(points: &[[f64; 3]]) -> Vec<(f64, f64)> {
        points.iter().map(|p| (p[0], p[1])).collect()
    }

    fn zs(points: &[[f64; 3]]) -> Vec<f64> {
        points.iter().map(|p| p[2]).collect()
    }

    fn surface_kind(z_range: Option<(f64, f64)>) -> PanelKind {
        PanelKind::Surface {
            z_label: "c₃".to_owned(),
            z_range,
            elevation_deg: 65.0,
            azimuth_deg: -45.0,
        }
    }

    /// A plain-axis spectrum (bars, line with dots, a dashed level), a 2500-point scatter with
    /// two lines, and a 20 × 20 surface with two 3D lines.
    fn fresnel_sample() -> Figure {
        let values = spectrum();
        let index = |i: usize| i as f64;
        let bars: Vec<(f64, f64)> = values
            .iter()
            .enumerate()
            .map(|(i, &v)| (index(i), v))
            .collect();
        let cumulative: Vec<(f64, f64)> = values
            .iter()
            .scan(0.0, |sum, &v| {
                *sum += v;
                Some(*sum)
            })
            .enumerate()
            .map(|(i, v)| (index(i), v))
            .collect();
        let mut spectrum = panel(
            XUnit::Plain,
            YScale::Linear,
            vec![
                marked(series("sₖ / Σs", STEEL, 1.0, Dash::Solid, bars), Mark::Bars),
                marked(
                    series("cumulative", ORANGE, 1.0, Dash::Solid, cumulative),
                    Mark::LinePoints,
                ),
                series(
                    "0.99",
                    RED,
                    1.0,
                    Dash::Dashed,
                    vec![(0.0, 0.99), (19.0, 0.99)],
                ),
            ],
        );
        spectrum.title = "Spectrum".to_owned();
        spectrum.x_label = "Number of basis elements".to_owned();
        spectrum.y_label = "Cumulative singular values".to_owned();

        let dielectric = manifold_edge(0.0);
        let conductor = manifold_edge(1.0);
        let mut scatter = panel(
            XUnit::Plain,
            YScale::Linear,
            vec![
                marked(
                    series("", STEEL, 1.0, Dash::Solid, xy(&manifold_grid(50))),
                    Mark::Points,
                ),
                series("g = 0", RED, 1.0, Dash::Solid, xy(&dielectric)),
                series("g = 1", BLACK, 1.0, Dash::Solid, xy(&conductor)),
            ],
        );
        scatter.title = "Gulbrandsen parametrization".to_owned();
        scatter.x_label = "c₀".to_owned();
        scatter.y_label = "c₂".to_owned();
        scatter.x_range = Some((0.0, 1.0));
        scatter.y_range = Some((-0.35, 0.35));

        let grid = manifold_grid(20);
        let mut surface = panel(
            XUnit::Plain,
            YScale::Linear,
            vec![
                in_3d(
                    series("manifold", STEEL, 1.0, Dash::Solid, xy(&grid)),
                    zs(&grid),
                    Some((20, 20)),
                ),
                in_3d(
                    series("g = 0", RED, 1.0, Dash::Solid, xy(&dielectric)),
                    zs(&dielectric),
                    None,
                ),
                in_3d(
                    series("g = 1", BLACK, 1.0, Dash::Solid, xy(&conductor)),
                    zs(&conductor),
                    None,
                ),
            ],
        );
        surface.kind = surface_kind(Some((-1.0, 1.0)));
        surface.title = "Coefficient manifold".to_owned();
        surface.x_label = "c₀".to_owned();
        surface.y_label = "c₂".to_owned();
        surface.x_range = Some((0.0, 1.0));
        surface.y_range = Some((-0.4, 0.4));

        let mut figure = figure(vec![spectrum, scatter, surface]);
        figure.title = "Fresnel decomposition".to_owned();
        figure.canvas.width_px = 1350;
        figure.canvas.height_px = 450;
        figure
    }

    fn decode(bytes: &[u8]) -> (u32, u32, Vec<u8>) {
        let mut reader = png::Decoder::new(bytes).read_info().expect("PNG header");
        let mut pixels = vec![0; reader.output_buffer_size()];
        let info = reader.next_frame(&mut pixels).expect("PNG data");
        pixels.truncate(info.buffer_size());
        (info.width, info.height, pixels)
    }

    fn polylines_in(svg: &str, hex: u32) -> usize {
        let stroke = format!(r##"stroke="#{hex:06X}""##);
        svg.lines()
            .filter(|l| l.starts_with("<polyline") && l.contains(&stroke))
            .count()
    }

    #[test]
    fn svg_keeps_labels_as_text_in_the_embedded_face() {
        let svg = String::from_utf8(svg(&sample()).unwrap()).unwrap();
        assert!(svg.starts_with(r#"<svg width="400" height="250" viewBox="0 0 1600 1000""#));
        assert!(svg.trim_end().ends_with("</svg>"));
        assert_eq!(svg.matches("<text").count(), svg.matches("</text>").count());
        for label in [
            "NDF and Fresnel",
            "Beckmann",
            "θ",
            "α_b = 0.4",
            "F₀ = 0.04",
            "10⁰",
            "90°",
        ] {
            assert!(svg.contains(&format!("\n{label}\n</text>")), "{label}");
        }
        let families = svg.matches("font-family=").count();
        assert!(families > 10);
        assert_eq!(
            svg.matches(r#"font-family="DejaVu Sans, sans-serif""#)
                .count(),
            families
        );
    }

    #[test]
    fn svg_draws_each_series_and_its_legend_sample() {
        let svg = String::from_utf8(svg(&sample()).unwrap()).unwrap();
        // Solid: one polyline for the curve, one for the legend sample.
        assert_eq!(polylines_in(&svg, BLUE), 2);
        assert_eq!(polylines_in(&svg, ORANGE), 2);
        // Dashed and dotted series (both red): one polyline per dash.
        assert!(polylines_in(&svg, RED) > 20);
        let thick = format!(r##"stroke="#{ORANGE:06X}" stroke-width="12""##);
        assert!(svg.contains(&thick), "thick = 2 × 1.5 px × 4 units");
    }

    #[test]
    fn png_has_the_scaled_size_and_shows_the_curves() {
        let (width, height, pixels) = decode(&png(&sample()).unwrap());
        assert_eq!((width, height), (800, 500));
        let has = |[r, g, b]: [u8; 3]| pixels.chunks_exact(3).any(|p| p == [r, g, b]);
        assert!(has([0xFF, 0x99, 0x00]) && has([0x26, 0x89, 0xD1]) && has([0xDB, 0x2E, 0x2E]));
    }

    #[test]
    fn renders_are_byte_identical_across_runs_and_threads() {
        let figure = sample();
        let (svg0, png0) = (svg(&figure).unwrap(), png(&figure).unwrap());
        std::thread::scope(|scope| {
            let runs: Vec<_> = (0..3)
                .map(|_| scope.spawn(|| (svg(&figure).unwrap(), png(&figure).unwrap())))
                .collect();
            for run in runs {
                let (svg1, png1) = run.join().unwrap();
                assert!(svg1 == svg0 && png1 == png0);
            }
        });
    }

    #[test]
    fn degenerate_figures_render() {
        let flat = series("1/π", BLUE, 1.0, Dash::Solid, sampled(|_| 1.0 / PI));
        let single = series("one", RED, 1.0, Dash::Dashed, vec![(0.3, 2.0)]);
        let zeros = series("zero", RED, 1.0, Dash::Solid, sampled(|_| 0.0));
        let nan = series("nan", RED, 1.0, Dash::Dotted, sampled(|_| f64::NAN));
        let empty = series("", RED, 1.0, Dash::Solid, Vec::new());
        let mut clipped = panel(XUnit::Degrees, YScale::Linear, vec![flat.clone()]);
        clipped.y_range = Some((0.5, 0.1));
        clipped.x_range = Some((0.2, 0.2));
        let figures = [
            figure(vec![panel(
                XUnit::Degrees,
                YScale::Linear,
                vec![flat.clone()],
            )]),
            figure(vec![panel(XUnit::Radians, YScale::Log, vec![flat])]),
            figure(vec![panel(
                XUnit::Radians,
                YScale::Linear,
                vec![single.clone()],
            )]),
            figure(vec![panel(XUnit::Degrees, YScale::Log, vec![single])]),
            figure(vec![panel(
                XUnit::Degrees,
                YScale::Log,
                vec![zeros.clone()],
            )]),
            figure(vec![panel(
                XUnit::Radians,
                YScale::Linear,
                vec![zeros, nan],
            )]),
            figure(vec![panel(XUnit::Degrees, YScale::Log, vec![empty])]),
            figure(vec![panel(XUnit::Degrees, YScale::Linear, Vec::new())]),
            figure(vec![clipped]),
            figure(Vec::new()),
        ];
        for figure in &figures {
            svg(figure).unwrap();
            let (width, height, _) = decode(&png(figure).unwrap());
            assert_eq!((width, height), (800, 500));
        }
    }

    #[test]
    fn unusable_canvases_and_grids_are_errors() {
        let mut figure = sample();
        figure.canvas.png_scale = 0.0;
        assert!(matches!(png(&figure), Err(PlotError::Canvas { .. })));
        figure.canvas.png_scale = f64::NAN;
        assert!(matches!(png(&figure), Err(PlotError::Canvas { .. })));
        let mut figure = sample();
        figure.canvas.width_px = 0;
        assert!(matches!(svg(&figure), Err(PlotError::Canvas { .. })));
        let mut figure = sample();
        figure.cols = 1;
        assert!(matches!(svg(&figure), Err(PlotError::Layout { .. })));
    }

    #[test]
    fn degree_axes_tick_at_angles() {
        let axis = Axis::x(&panel(XUnit::Degrees, YScale::Linear, vec![]), 10.0);
        assert_eq!(axis.ticks, [0.0, 15.0, 30.0, 45.0, 60.0, 75.0, 90.0]);
        assert_eq!(axis.label(45.0), "45°");
        let narrow = Axis::x(&panel(XUnit::Degrees, YScale::Linear, vec![]), 4.0);
        assert_eq!(narrow.ticks, [0.0, 30.0, 60.0, 90.0]);
    }

    #[test]
    fn automatic_ranges_show_every_point() {
        let values = |v: &[f64]| {
            let points = v
                .iter()
                .enumerate()
                .map(|(i, &y)| (i as f64 * 0.1, y))
                .collect();
            vec![series("s", RED, 1.0, Dash::Solid, points)]
        };
        let linear = |v: &[f64]| Axis::y(&panel(XUnit::Radians, YScale::Linear, values(v)), 8.0);
        let positive = linear(&[1.0, 3.0, 2.0]);
        assert_eq!(positive.lo, 0.0);
        assert!((positive.hi - 3.0 * (1.0 + AUTO_MARGIN)).abs() < 1e-12);
        let signed = linear(&[-1.0, 1.0]);
        assert!((signed.lo + 1.1).abs() < 1e-12 && (signed.hi - 1.1).abs() < 1e-12);
        let flat = linear(&[1.0 / PI, 1.0 / PI]);
        assert!(flat.lo == 0.0 && flat.hi > 1.0 / PI);
        let zero = linear(&[0.0, 0.0]);
        assert!(zero.lo < 0.0 && zero.hi > 0.0);

        let log = Axis::y(
            &panel(XUnit::Radians, YScale::Log, values(&[0.0, 2e-3, 40.0])),
            8.0,
        );
        assert_eq!((log.lo, log.hi), (-3.0, 2.0));
        assert_eq!(log.ticks, [-3.0, -2.0, -1.0, 0.0, 1.0, 2.0]);
        assert_eq!(log.label(-3.0), "10⁻³");
        assert_eq!(log.minor.len(), 5 * 8);
    }

    #[test]
    fn curves_break_at_undrawable_points_and_clip_to_the_axes() {
        let points = vec![
            (0.0, 1.0),
            (0.1, 2.0),
            (0.2, 0.0),
            (0.3, 2.0),
            (0.4, 20.0),
            (0.5, 2.0),
        ];
        let s = series("s", RED, 1.0, Dash::Solid, points);
        let mut p = panel(XUnit::Radians, YScale::Log, vec![s.clone()]);
        p.y_range = Some((0.5, 10.0));
        let (x, y) = (Axis::x(&p, 8.0), Axis::y(&p, 8.0));
        let pieces = visible_pieces(&s, &p, &x, &y);
        assert_eq!(pieces.len(), 3);
        assert_eq!(pieces[0].len(), 2);
        let top = 1.0;
        assert!(
            pieces[1]
                .last()
                .is_some_and(|&(_, v)| (v - top).abs() < 1e-12)
        );
        assert!(
            pieces[2]
                .first()
                .is_some_and(|&(_, v)| (v - top).abs() < 1e-12)
        );
    }

    #[test]
    fn the_legend_avoids_the_curves() {
        // A curve through the top corners: the legend goes below it, on the right.
        let top = vec![vec![(0.0, 30.0), (400.0, 30.0)]];
        assert_eq!(legend_position((400, 300), (100, 50), 10, &top), (290, 67));
        assert_eq!(legend_position((400, 300), (100, 50), 10, &[]), (290, 10));
    }

    #[test]
    fn new_marks_and_surfaces_render_with_their_labels() {
        let figure = fresnel_sample();
        let svg = String::from_utf8(svg(&figure).unwrap()).unwrap();
        for label in [
            "Fresnel decomposition",
            "Number of basis elements",
            "Cumulative singular values",
            "sₖ / Σs",
            "cumulative",
            "Gulbrandsen parametrization",
            "c₀",
            "c₂",
            "c₃",
            "manifold",
            "g = 1",
            "15",
        ] {
            assert!(svg.contains(&format!("\n{label}\n</text>")), "{label}");
        }
        // Whole-number ticks on the index axis.
        assert!(!svg.contains("\n2.5\n</text>"));
        // 2500 scatter dots, 20 line dots and 1 legend dot; 361 mesh cells and 1 legend patch.
        let steel = format!(r##"fill="#{STEEL:06X}""##);
        let dots = svg
            .lines()
            .filter(|l| l.starts_with("<circle") && l.contains(&steel))
            .count();
        assert_eq!(dots, 2500);
        let orange = format!(r##"fill="#{ORANGE:06X}""##);
        let marker_dots = svg
            .lines()
            .filter(|l| l.starts_with("<circle") && l.contains(&orange))
            .count();
        assert_eq!(marker_dots, 20 + 1);
        assert_eq!(svg.matches("<polygon").count(), 3 + 361);
        // 20 bars, the legend box of the bars and the legend patch of the surface.
        assert_eq!(
            svg.lines()
                .filter(|l| l.starts_with("<rect") && l.contains(&steel))
                .count(),
            20 + 1 + 1
        );
        // The 3D lines: one polyline each, plus a legend sample.
        assert_eq!(polylines_in(&svg, BLACK), 2 + 2);

        let (width, height, pixels) = decode(&png(&figure).unwrap());
        assert_eq!((width, height), (2700, 900));
        let has = |[r, g, b]: [u8; 3]| pixels.chunks_exact(3).any(|p| p == [r, g, b]);
        assert!(has([0x1F, 0x77, 0xB4]) && has([0xFF, 0x99, 0x00]) && has([0, 0, 0]));
    }

    #[test]
    fn new_marks_and_surfaces_render_identically_across_threads() {
        let figure = fresnel_sample();
        let (svg0, png0) = (svg(&figure).unwrap(), png(&figure).unwrap());
        std::thread::scope(|scope| {
            let runs: Vec<_> = (0..2)
                .map(|_| scope.spawn(|| (svg(&figure).unwrap(), png(&figure).unwrap())))
                .collect();
            for run in runs {
                let (svg1, png1) = run.join().unwrap();
                assert!(svg1 == svg0 && png1 == png0);
            }
        });
    }

    #[test]
    fn degenerate_surfaces_and_marks_render() {
        let grid = manifold_grid(5);
        let surface = |series: Vec<Series>| {
            let mut p = panel(XUnit::Plain, YScale::Linear, series);
            p.kind = surface_kind(None);
            figure(vec![p])
        };
        let flat: Vec<f64> = vec![0.5; grid.len()];
        let row = manifold_edge(0.5);
        let lone_bar = marked(
            series("one", RED, 1.0, Dash::Solid, vec![(3.0, 2.0)]),
            Mark::Bars,
        );
        let log_bars = marked(
            series(
                "log",
                RED,
                1.0,
                Dash::Solid,
                vec![(1.0, 0.0), (2.0, 1e-3), (3.0, 1.0)],
            ),
            Mark::Bars,
        );
        let nan_dots = marked(
            series(
                "nan",
                RED,
                1.0,
                Dash::Solid,
                vec![(f64::NAN, 1.0), (1.0, f64::NAN)],
            ),
            Mark::LinePoints,
        );
        let figures = [
            surface(vec![in_3d(
                series("flat", STEEL, 1.0, Dash::Solid, xy(&grid)),
                flat,
                Some((5, 5)),
            )]),
            surface(vec![in_3d(
                series("row", STEEL, 1.0, Dash::Dashed, xy(&row)),
                zs(&row),
                Some((1, 100)),
            )]),
            surface(vec![in_3d(
                series("", STEEL, 1.0, Dash::Solid, Vec::new()),
                Vec::new(),
                Some((0, 0)),
            )]),
            surface(vec![series("empty", STEEL, 1.0, Dash::Solid, Vec::new())]),
            surface(vec![in_3d(
                marked(
                    series("nan", RED, 1.0, Dash::Solid, vec![(f64::NAN, 0.0); 4]),
                    Mark::Points,
                ),
                vec![f64::NAN; 4],
                Some((2, 2)),
            )]),
            surface(Vec::new()),
            figure(vec![panel(XUnit::Plain, YScale::Linear, vec![lone_bar])]),
            figure(vec![panel(XUnit::Plain, YScale::Log, vec![log_bars])]),
            figure(vec![panel(XUnit::Degrees, YScale::Linear, vec![nan_dots])]),
            figure(vec![panel(
                XUnit::Plain,
                YScale::Linear,
                vec![marked(
                    series("none", RED, 1.0, Dash::Solid, Vec::new()),
                    Mark::Points,
                )],
            )]),
        ];
        for figure in &figures {
            svg(figure).unwrap();
            let (width, height, _) = decode(&png(figure).unwrap());
            assert_eq!((width, height), (800, 500));
        }
    }

    #[test]
    fn surface_series_without_matching_z_are_errors() {
        let grid = manifold_grid(4);
        let mut p = panel(
            XUnit::Plain,
            YScale::Linear,
            vec![series("no z", STEEL, 1.0, Dash::Solid, xy(&grid))],
        );
        p.kind = surface_kind(None);
        let missing = figure(vec![p.clone()]);
        assert!(matches!(svg(&missing), Err(PlotError::Series { label, .. }) if label == "no z"));
        assert!(matches!(png(&missing), Err(PlotError::Series { .. })));
        p.series[0] = in_3d(p.series[0].clone(), zs(&grid), Some((3, 4)));
        assert!(matches!(
            svg(&figure(vec![p.clone()])),
            Err(PlotError::Series { .. })
        ));
        p.series[0] = in_3d(p.series[0].clone(), vec![0.0; 3], None);
        assert!(matches!(
            svg(&figure(vec![p])),
            Err(PlotError::Series { .. })
        ));
    }

    #[test]
    fn plain_axes_pad_the_data_and_tick_whole_indices() {
        let points = (0..20).map(|i| (f64::from(i), 1.0)).collect();
        let bars = vec![marked(
            series("s", RED, 1.0, Dash::Solid, points),
            Mark::Bars,
        )];
        let axis = Axis::x(&panel(XUnit::Plain, YScale::Linear, bars), 12.0);
        assert!((axis.lo + 0.95).abs() < 1e-12 && (axis.hi - 19.95).abs() < 1e-12);
        assert_eq!(
            axis.ticks,
            [0.0, 2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 18.0]
        );
        assert_eq!(axis.label(4.0), "4");
        let two = vec![marked(
            series("s", RED, 1.0, Dash::Solid, vec![(1.0, 1.0), (2.0, -1.0)]),
            Mark::Bars,
        )];
        let p = panel(XUnit::Plain, YScale::Linear, two);
        let (x, y) = (Axis::x(&p, 8.0), Axis::y(&p, 8.0));
        assert_eq!((x.lo, x.hi), (0.5, 2.5));
        assert!(y.lo < -1.0 && y.hi > 0.0);
        let bars = visible_bars(&p.series[0], &p, &x, &y);
        assert_eq!(bars.len(), 2);
        assert!((bars[0][1].0 - bars[0][0].0 - BAR_FRACTION).abs() < 1e-12);
    }

    /// Writes the sample figures to the temporary directory to look at, with render times.
    #[test]
    #[ignore]
    fn write_sample_figures() {
        let dir = std::env::temp_dir();
        let fresnel = fresnel_sample();
        let mut automatic = fresnel.panels[2].clone();
        automatic.kind = surface_kind(None);
        (automatic.x_range, automatic.y_range) = (None, None);
        automatic.title = "Automatic ranges".to_owned();
        let mut manifold = figure(vec![fresnel.panels[2].clone(), automatic]);
        (manifold.canvas.width_px, manifold.canvas.height_px) = (900, 400);
        for (name, figure) in [
            ("ndfplot-fresnel", fresnel),
            ("ndfplot-manifold", manifold),
            ("ndfplot-ndf", sample()),
        ] {
            let start = std::time::Instant::now();
            let svg_bytes = svg(&figure).unwrap();
            let svg_time = start.elapsed();
            let start = std::time::Instant::now();
            let png_bytes = png(&figure).unwrap();
            let png_time = start.elapsed();
            eprintln!(
                "{name}: svg {svg_time:?} ({} B), png {png_time:?} ({} B)",
                svg_bytes.len(),
                png_bytes.len()
            );
            std::fs::write(dir.join(format!("{name}.svg")), svg_bytes).unwrap();
            std::fs::write(dir.join(format!("{name}.png")), png_bytes).unwrap();
        }
    }
}
