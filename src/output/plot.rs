//! Figure → SVG and PNG bytes, drawn with plotters and the embedded DejaVu Sans face.
//!
//! Owns the page layout (figure title, panel grid, axes, ticks, legend), the automatic
//! ranges ("PlotRange → All") and the in-memory PNG encoding. It must not compute curves,
//! decide what to plot, or touch the file system: callers hand it a finished [`Figure`] and
//! write the returned bytes themselves.
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

use crate::series::{XUnit, Canvas, Dash, Figure, Panel, Rgb, Series, YScale};

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
/// Fraction of the data span added above (and below, unless clamped at 0) an automatic linear range.
const AUTO_MARGIN: f64 = 0.05;

/// Font sizes relative to `Canvas::font_px`.
const AXIS_LABEL_EM: f64 = 1.1;
const PANEL_TITLE_EM: f64 = 1.2;
const FIGURE_TITLE_EM: f64 = 1.4;
/// Minimum distance between tick labels in base text sizes (x: centre to centre; y: line to line).
const X_TICK_SPACING_EM: f64 = 4.0;
const Y_TICK_SPACING_EM: f64 = 3.0;
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

/// Draws one panel (title, axes, curves, legend) into its grid cell.
fn draw_panel<DB: DrawingBackend>(
    cell: &DrawingArea<DB, Shift>,
    panel: &Panel,
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let area = titled(cell, &panel.title, PANEL_TITLE_EM, m)?;
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

    let mut chart = ChartBuilder::on(&area)
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

    let curves: Vec<Vec<Vec<(f64, f64)>>> = panel
        .series
        .iter()
        .map(|s| visible_pieces(s, panel, &x, &y))
        .collect();
    for (series, pieces) in panel.series.iter().zip(&curves) {
        let style = m.curve_style(series.style.colour, series.style.width);
        for piece in pieces {
            draw_piece(&mut chart, piece, style, series.style.dash)?;
        }
    }

    let plot = chart.plotting_area().strip_coord_spec();
    let (pw, ph) = plot.dim_in_pixel();
    outline(
        &plot,
        [(0, 0), (pw as i32 - 1, ph as i32 - 1)],
        m.line(FRAME),
    )?;
    if panel.legend {
        let to_plot_px = |(vx, vy): (f64, f64)| {
            (
                (vx - x.lo) / (x.hi - x.lo) * f64::from(pw),
                (y.hi - vy) / (y.hi - y.lo) * f64::from(ph),
            )
        };
        let pieces: Vec<Vec<(f64, f64)>> = curves
            .iter()
            .flatten()
            .map(|piece| piece.iter().map(|&p| to_plot_px(p)).collect())
            .collect();
        draw_legend(&plot, &panel.series, &pieces, &tick_font, m)?;
    }
    Ok(())
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

/// Draws the legend inside the plot area where it hides the least of the curves.
///
/// `pieces` are the drawn curves in plot-area pixels. Series with an empty label get no entry.
fn draw_legend<DB: DrawingBackend>(
    plot: &DrawingArea<DB, Shift>,
    series: &[Series],
    pieces: &[Vec<(f64, f64)>],
    font: &TextStyle,
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let entries: Vec<&Series> = series.iter().filter(|s| !s.label.is_empty()).collect();
    if entries.is_empty() {
        return Ok(());
    }
    let (pad, sample, gap, row) = (m.px(0.5), m.px(2.2), m.px(0.5), m.px(1.35));
    let mut text_w = 0;
    for s in &entries {
        text_w = text_w.max(plot.estimate_text_size(&s.label, font).map_err(draw_err)?.0);
    }
    let box_w = (2 * pad + sample + gap + text_w) as i32;
    let box_h = (2 * pad + row * entries.len() as u32) as i32;
    let (pw, ph) = plot.dim_in_pixel();
    let (x0, y0) = legend_position(
        (pw as i32, ph as i32),
        (box_w, box_h),
        m.px(0.6) as i32,
        pieces,
    );

    let background = WHITE.mix(LEGEND_OPACITY).filled();
    let bounds = [(x0, y0), (x0 + box_w, y0 + box_h)];
    plot.draw(&Rectangle::new(bounds, background))
        .map_err(draw_err)?;
    outline(plot, bounds, m.line(LEGEND_BORDER))?;
    let label_style = font.pos(Pos::new(HPos::Left, VPos::Center));
    for (i, s) in entries.iter().enumerate() {
        let cy = y0 + (pad + row * i as u32 + row / 2) as i32;
        let sx = x0 + pad as i32;
        let style = m.curve_style(s.style.colour, s.style.width);
        let line = [(sx, cy), (sx + sample as i32, cy)];
        match dash_pattern(s.style.dash, &style) {
            None => plot.draw(&PathElement::new(line, style)),
            Some((on, off)) => plot.draw(&DashedPathElement::new(line, on, off, style)),
        }
        .map_err(draw_err)?;
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
    /// The θ axis of `panel`, with at most about `max_ticks` ticks.
    fn x(panel: &Panel, max_ticks: f64) -> Axis {
        let unit = panel.x_unit;
        let data = panel
            .series
            .iter()
            .flat_map(|s| s.points.iter())
            .filter_map(|&(theta, _)| x_display(theta, unit));
        let (lo, hi) = match panel.x_range {
            Some((a, b)) => match (x_display(a, unit), x_display(b, unit)) {
                (Some(a), Some(b)) => (a.min(b), a.max(b)),
                _ => extent(data).unwrap_or(default_x(unit)),
            },
            None => extent(data).unwrap_or(default_x(unit)),
        };
        let (lo, hi) = widen_if_flat(lo, hi);
        let (step, decimals) = match unit {
            XUnit::Degrees => degree_step(hi - lo, max_ticks),
            XUnit::Radians | XUnit::Plain => nice_step(hi - lo, max_ticks, &NICE_MANTISSAS),
        };
        let suffix = match unit {
            XUnit::Degrees => "°",
            XUnit::Radians | XUnit::Plain => "",
        };
        Axis {
            lo,
            hi,
            ticks: multiples(lo, hi, step),
            minor: Vec::new(),
            format: TickFormat::Fixed { decimals, suffix },
        }
    }

    /// The value axis of `panel`, with at most about `max_ticks` ticks.
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
                let (lo, hi) = given.unwrap_or_else(|| auto_linear(extent(data())));
                let (lo, hi) = widen_if_flat(lo, hi);
                let (step, decimals) = nice_step(hi - lo, max_ticks, &NICE_MANTISSAS);
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
    use crate::series::Style;

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
            },
            points: Arc::new(points),
        }
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
        let linear =
            |v: &[f64]| Axis::y(&panel(XUnit::Radians, YScale::Linear, values(v)), 8.0);
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
}
