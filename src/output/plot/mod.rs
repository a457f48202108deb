//! Figure → SVG and PNG bytes, drawn with plotters and the embedded DejaVu Sans face.
//!
//! Owns the page layout (figure title, panel grid, axes, ticks, legend), the automatic
//! ranges ("PlotRange → All"), the rasterization and the in-memory PNG encoding. It must not compute curves,
//! decide what to plot, or touch the file system: callers hand it a finished [`Figure`] and
//! write the returned bytes themselves.
//!
//! Cartesian panels draw lines, dots, lines with dots, or bars; surface panels draw a 3D
//! axes box with back panes, depth-sorted translucent surface meshes and 3D lines, using the
//! camera geometry of [`super::plot3d`]; heat-map panels draw coloured cells and a colour bar.
//!
//! There is one drawing: the SVG, drawn at `SVG_UNITS_PER_PX` device units per CSS pixel and
//! given a `viewBox` that maps it back to the canvas size, so that coordinates and line widths
//! keep sub-pixel precision although plotters works in integer device units. The PNG is that SVG
//! rasterized (resvg), as the PDF is that SVG converted, so the three formats cannot disagree.
//!
//! This file holds the entry points and the page layout; each drawing job has its own file:
//! [`axis`] (ranges, ticks, tick labels), [`clip`] (curves cut to the visible box),
//! [`cartesian`], [`surface`] and [`heatmap`] (the panel kinds), [`legend`], [`style`] (sizes, colours,
//! font) and [`encode`] (SVG finishing and PNG encoding).

mod annotate;
mod axis;
mod cartesian;
mod clip;
mod encode;
#[cfg(test)]
pub(crate) mod fixtures;
mod heatmap;
mod legend;
mod lint;
mod mathtext;
mod polar;
mod style;
mod summary;
mod surface;
mod text;
mod theme;
mod ticks;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::plot3d::View;
use crate::pipeline::figure::{Figure, Panel};
use crate::spec::look::{Canvas, PanelKind};
use crate::spec::look::{FIGURE_TITLE_EM, PANEL_TITLE_EM};
use cartesian::{Needs, Shared, draw_cartesian, draw_cartesian_shared};
use encode::{encode_png, finish_svg, rasterize, with_scratch};
use heatmap::draw_heatmap;
use lint::Recorder;
pub use lint::{Finding, lint};
#[cfg(test)]
pub(crate) use mathtext::slanted_letters;
use polar::draw_polar;
use style::{EM_PER_SIZE, Metrics, ensure_font};
use surface::draw_surface;
use text::{LINE_GAP_EM, fit_text};
use theme::Look;

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
/// The figure's provenance is in a `<metadata>` element after the opening tag.
pub fn svg(figure: &Figure) -> Result<Vec<u8>, PlotError> {
    Ok(draw_svg(figure, None)?.0)
}

/// What drawing a figure found and chose: the figure lint's findings (see [`lint`]) and the
/// drawing's own decisions where the spec left them open (where each legend went and at what
/// size), each with its panel, for `-v`.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Linted {
    /// The broken rules.
    pub findings: Vec<Finding>,
    /// The decisions, in the shape of a finding: the panel and the words.
    pub decisions: Vec<Finding>,
}

/// [`svg`] and what drawing it found and chose ([`Linted`]), from one drawing.
pub fn svg_linted(figure: &Figure) -> Result<(Vec<u8>, Linted), PlotError> {
    let (svg, trace) = draw_svg(figure, Some(std::cell::RefCell::default()))?;
    let size = device_size(&figure.canvas, SVG_UNITS_PER_PX)?;
    let trace = trace
        .map(std::cell::RefCell::into_inner)
        .unwrap_or_default();
    let decisions = trace
        .decisions
        .iter()
        .map(|(panel, message)| Finding {
            panel: *panel,
            message: message.clone(),
        })
        .collect();
    Ok((
        svg,
        Linted {
            findings: lint::findings(figure, &trace, size),
            decisions,
        },
    ))
}

/// The SVG of `figure` and the trace it recorded into `trace`, when one is given.
fn draw_svg(figure: &Figure, trace: Recorder) -> Result<(Vec<u8>, Recorder), PlotError> {
    let canvas = &figure.canvas;
    let (width, height) = device_size(canvas, SVG_UNITS_PER_PX)?;
    let mut document = String::with_capacity(SVG_CAPACITY);
    let trace = {
        let root = SVGBackend::with_string(&mut document, (width, height)).into_drawing_area();
        draw_figure(&root, figure, SVG_UNITS_PER_PX, trace)?
    };
    let svg = finish_svg(&document, canvas, (width, height), &figure.provenance).into_bytes();
    Ok((svg, trace))
}

/// The PNG of `figure` from its drawn SVG `svg` (what [`svg`] returned for it): the same drawing
/// rasterized at (width_px·png_scale) × (height_px·png_scale) pixels, anti-aliased, with text
/// from the embedded face. 8-bit RGB (RGBA on a transparent canvas), tagged sRGB, no time stamp:
/// identical figures give identical bytes. The figure's provenance is in `tEXt` chunks (`Software`, `ndfplot-version`,
/// `spec-sha256`).
pub fn png(figure: &Figure, svg: &[u8]) -> Result<Vec<u8>, PlotError> {
    with_scratch(|scratch| {
        let raster = rasterize(svg, &figure.canvas, scratch)?;
        encode_png(&raster, figure.canvas.dpi(), &figure.provenance)
    })
}

/// SVG device units per CSS pixel: plotters draws on an integer grid, so 16 gives 1/16 px
/// precision for curve vertices and line widths (1.5 px = 24 units): 0.2 output pixels at
/// 300 dpi, under the sampler's default quarter-pixel tolerance.
const SVG_UNITS_PER_PX: f64 = 16.0;
/// Initial SVG buffer size: a typical 10-curve figure is ~100-200 KB.
const SVG_CAPACITY: usize = 1 << 18;

/// Maps a plotters error (generic over the backend) to [`PlotError::Draw`].
fn draw_err<E: std::error::Error + Send + Sync>(e: DrawingAreaErrorKind<E>) -> PlotError {
    PlotError::Draw(e.to_string())
}

/// Draws the whole figure onto `root` at `k` device pixels per CSS pixel, recording what it
/// places into `trace` when one is given (for [`lint`]), which it returns.
fn draw_figure<DB: DrawingBackend>(
    root: &DrawingArea<DB, Shift>,
    figure: &Figure,
    k: f64,
    trace: Recorder,
) -> Result<Recorder, PlotError>
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
        palette: theme::palette(figure.theme),
        family: style::family(figure.canvas.face).0,
        trace,
        weight: Metrics::weight_of(figure.canvas.font_px),
    };
    if !figure.canvas.transparent {
        root.fill(&m.palette.background).map_err(draw_err)?;
    }
    let body = titled(root, &figure.title, FIGURE_TITLE_EM, 0, &m)?;
    lint::record_grid_top(&m.trace, f64::from(body.get_base_pixel().1));
    let cells = body.split_evenly((rows, cols));
    let looks = theme::looks(figure);
    let figure = &without_repeated_legends(figure, &looks, &cells, &m)?;
    let layout = grid_layout(&cells, figure, &looks, cols, &m)?;
    for (index, (((panel, looks), cell), place)) in figure
        .panels
        .iter()
        .zip(&looks)
        .zip(&cells)
        .zip(layout)
        .enumerate()
    {
        lint::record_current_panel(&m.trace, index);
        draw_panel(cell, panel, looks, place, &m)?;
    }
    root.present().map_err(draw_err)?;
    Ok(m.trace)
}

/// `figure` with one legend for the panels that share it ([`legend::legend_groups`]): drawn by
/// the first panel of the group whose plot area holds it where it hides no curve, else by the
/// group's first panel; the others' legends are turned off.
fn without_repeated_legends<DB: DrawingBackend>(
    figure: &Figure,
    looks: &[Vec<Look>],
    cells: &[DrawingArea<DB, Shift>],
    m: &Metrics,
) -> Result<Figure, PlotError>
where
    DB::ErrorType: 'static,
{
    let groups = legend::legend_groups(figure, looks);
    let mut holder: Vec<Option<usize>> = vec![None; figure.panels.len()];
    for (i, group) in groups.iter().enumerate() {
        let Some(first) = *group else { continue };
        let shared = groups.iter().filter(|g| **g == Some(first)).count() > 1;
        if !shared || holder[first].is_some() {
            continue;
        }
        let fits = |k: usize| -> Result<bool, PlotError> {
            let panel = &figure.panels[k];
            let area = titled_area(&cells[k], &panel.axes.title, m)?;
            cartesian::legend_fits_inside(&area, panel, &looks[k], m)
        };
        if fits(i)? {
            holder[first] = Some(i);
        } else if groups[i + 1..].iter().all(|g| *g != Some(first)) {
            holder[first] = Some(first);
        }
    }
    let mut figure = figure.clone();
    for (i, panel) in figure.panels.iter_mut().enumerate() {
        let drawn = groups[i].is_none_or(|first| holder[first].is_none_or(|h| h == i));
        if !drawn {
            panel.axes.legend = crate::spec::look::LegendPlace::None;
        }
    }
    Ok(figure)
}

/// The part of `cell` below its panel title's band.
fn titled_area<DB: DrawingBackend>(
    cell: &DrawingArea<DB, Shift>,
    title: &str,
    m: &Metrics,
) -> Result<DrawingArea<DB, Shift>, PlotError>
where
    DB::ErrorType: 'static,
{
    let band = title_block(cell, title, PANEL_TITLE_EM, m)?.band;
    Ok(cell.split_vertically(band).1)
}

/// The layout every panel of a grid shares with its row and column: the row's title band (the
/// tallest title of the row, so that the plot areas start level) and, for the 2D panels of a
/// grid of more than one panel, their [`Shared`] band and label areas, so that plot areas of a
/// row have one height and top and those of the grid one width and left edge. A single panel
/// keeps its own layout (its legend may then also go beside the plot).
fn grid_layout<DB: DrawingBackend>(
    cells: &[DrawingArea<DB, Shift>],
    figure: &Figure,
    looks: &[Vec<Look>],
    cols: usize,
    m: &Metrics,
) -> Result<Vec<(i32, Option<Shared>)>, PlotError>
where
    DB::ErrorType: 'static,
{
    let n = figure.panels.len();
    let mut titles = Vec::with_capacity(n);
    for (panel, cell) in figure.panels.iter().zip(cells) {
        titles.push(title_block(cell, &panel.axes.title, PANEL_TITLE_EM, m)?.band);
    }
    let row_of = |i: usize| i / cols;
    let rows = n.div_ceil(cols);
    let row_title: Vec<i32> = (0..rows)
        .map(|r| {
            (0..n)
                .filter(|&i| row_of(i) == r)
                .map(|i| titles[i])
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut needs: Vec<Option<Needs>> = Vec::with_capacity(n);
    for (i, (panel, cell)) in figure.panels.iter().zip(cells).enumerate() {
        let cartesian = n > 1 && panel.axes.kind == PanelKind::Cartesian;
        needs.push(if cartesian {
            let area = cell.split_vertically(row_title[row_of(i)]).1;
            Some(cartesian::needs(&area, panel, &looks[i], m)?)
        } else {
            None
        });
    }
    let y_area = needs.iter().flatten().map(|d| d.y_area).max().unwrap_or(0);
    let row_max = |r: usize, f: &dyn Fn(&Needs) -> f64| {
        needs
            .iter()
            .enumerate()
            .filter(|(i, _)| row_of(*i) == r)
            .filter_map(|(_, d)| d.as_ref().map(f))
            .fold(0.0, f64::max)
    };
    Ok((0..n)
        .map(|i| {
            let r = row_of(i);
            let shared = needs[i].map(|_| Shared {
                band: row_max(r, &|d| d.band),
                areas: (row_max(r, &|d| f64::from(d.x_area)) as u32, y_area),
            });
            (row_title[r], shared)
        })
        .collect())
}

/// A title as set: its size, its lines with the top each is drawn at, the height of its band.
struct TitleBlock {
    size: f64,
    lines: Vec<(String, i32)>,
    band: i32,
}

/// How `title` (`size` base text sizes) is set at the top of `area`: the size it fits the area's
/// width at ([`fit_text`]), each line with the top it is drawn at, and the height of the band it
/// takes, padding included; an empty title takes none.
fn title_block<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    size: f64,
    m: &Metrics,
) -> Result<TitleBlock, PlotError>
where
    DB::ErrorType: 'static,
{
    if title.is_empty() {
        return Ok(TitleBlock {
            size,
            lines: Vec::new(),
            band: 0,
        });
    }
    let pad = f64::from(m.px(0.5));
    let (width, _) = area.dim_in_pixel();
    let measure = |text: &str, size: f64| mathtext::width(area, text, &m.font(size));
    let (size, lines) = fit_text(title, size, f64::from(width) - 2.0 * pad, measure)?;
    let style = m.font(size);
    // plotters' raster text puts the baseline size/2 below a top anchor, so ascenders rise
    // ≈0.3 × size above it (ascent 1901/2384 of the size for DejaVu Sans): start that much lower.
    let mut top = (pad + 0.3 * size * m.unit).round() as i32;
    let mut placed = Vec::with_capacity(lines.len());
    let count = lines.len();
    for (i, line) in lines.into_iter().enumerate() {
        let (_, text_h) = area.estimate_text_size(&line, &style).map_err(draw_err)?;
        placed.push((line, top));
        top += text_h as i32;
        if i + 1 < count {
            top += m.px(LINE_GAP_EM * size) as i32;
        }
    }
    Ok(TitleBlock {
        size,
        lines: placed,
        band: top + pad as i32,
    })
}

/// Draws `title` (`size` base text sizes) centred at the top of `area`, if not empty, and
/// returns the area below its band, at least `min_band` pixels down (so that the titles of a
/// row end level). A title wider than the area less its padding is shrunk or wrapped
/// ([`fit_text`]), never clipped.
fn titled<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    size: f64,
    min_band: i32,
    m: &Metrics,
) -> Result<DrawingArea<DB, Shift>, PlotError>
where
    DB::ErrorType: 'static,
{
    let TitleBlock { size, lines, band } = title_block(area, title, size, m)?;
    let band = band.max(min_band);
    if band == 0 {
        return Ok(area.clone());
    }
    let (width, height) = area.dim_in_pixel();
    let centred = m.font(size).pos(Pos::new(HPos::Center, VPos::Top));
    for (line, top) in &lines {
        let at = (f64::from(width) / 2.0, f64::from(*top));
        mathtext::draw(area, line, &centred, at, m)?;
    }
    // A title taller than its area leaves it a pixel (the figure lint reports the squeeze).
    let band = band
        .min(i32::try_from(height).unwrap_or(i32::MAX) - 1)
        .max(0);
    Ok(area.split_vertically(band).1)
}

/// Draws one panel (title, axes, series in their `looks`, legend) into its grid cell, its title
/// band at least `title_band` pixels and, for a 2D panel of a grid, what its row and column share.
fn draw_panel<DB: DrawingBackend>(
    cell: &DrawingArea<DB, Shift>,
    panel: &Panel,
    looks: &[Look],
    (title_band, shared): (i32, Option<Shared>),
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let area = titled(cell, &panel.axes.title, PANEL_TITLE_EM, title_band, m)?;
    match (&panel.axes.kind, shared) {
        (PanelKind::Cartesian, Some(shared)) => {
            draw_cartesian_shared(&area, panel, looks, shared, m)
        }
        (PanelKind::Cartesian, None) => draw_cartesian(&area, panel, looks, m),
        (PanelKind::Polar, _) => draw_polar(&area, panel, looks, m),
        (
            PanelKind::Surface {
                z_label,
                z_range,
                elevation_deg,
                azimuth_deg,
            },
            _,
        ) => {
            let view = View::new(*elevation_deg, *azimuth_deg);
            draw_surface(&area, panel, looks, (z_label, *z_range), view, m)
        }
        (PanelKind::Heatmap { z_label, z_range }, _) => {
            draw_heatmap(&area, panel, (z_label, *z_range), m)
        }
    }
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

/// Device size of `canvas` drawn at `scale` device units per CSS pixel, after checking that it
/// can be drawn: positive finite scale and font size, at least one unit a side.
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
    if width.max(height) > f64::from(u32::MAX) {
        return Err(fail("a side would exceed 2^32 device units"));
    }
    Ok((width as u32, height as u32))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::plot::fixtures::{
        BLACK, BLUE, ORANGE, RED, SPEC, STEEL, decode, draw_png, figure, fresnel_sample, in_3d,
        manifold_edge, manifold_grid, marked, panel, polylines_in, sample, sampled, series,
        surface_kind, xy, zs,
    };
    use crate::pipeline::figure::Series;
    use crate::pipeline::provenance::Provenance;
    use crate::spec::look::{Dash, Mark, PanelKind, Scale, Theme, XUnit};
    use std::f64::consts::PI;

    #[test]
    fn svg_keeps_labels_as_text_in_the_embedded_face() {
        let svg = String::from_utf8(svg(&sample()).unwrap()).unwrap();
        assert!(svg.starts_with(r#"<svg width="400" height="250" viewBox="0 0 6400 4000""#));
        assert!(svg.trim_end().ends_with("</svg>"));
        assert_eq!(svg.matches("<text").count(), svg.matches("</text>").count());
        for label in [
            "NDF and Fresnel",
            "Beckmann",
            "θ",
            // F₀ = 0.04: an italic F, a set subscript 0.
            "F",
            " = 0.04",
            "10⁰",
            "90°",
        ] {
            assert!(svg.contains(&format!(">{label}</text>")), "{label}");
        }
        // `α_b = 0.4` is typeset: α, a smaller b, then the rest, with no markup left.
        assert!(!svg.contains("α_b"));
        for run in ["α", "b", " = 0.4"] {
            assert!(svg.contains(&format!(">{run}</text>")), "{run}");
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
    fn svg_and_png_embed_the_provenance_record() {
        let figure = sample();
        let record = Provenance::of_spec(SPEC);
        let svg = String::from_utf8(svg(&figure).unwrap()).unwrap();
        assert_eq!(
            svg.lines().nth(1),
            Some(format!("<metadata>{}</metadata>", record.words().join(" ")).as_str())
        );
        roxmltree::Document::parse(&svg).expect("still well-formed XML");
        let bytes = draw_png(&figure).unwrap();
        let reader = png::Decoder::new(std::io::Cursor::new(bytes.as_slice()))
            .read_info()
            .unwrap();
        let text: Vec<(&str, &str)> = reader
            .info()
            .uncompressed_latin1_text
            .iter()
            .map(|chunk| (chunk.keyword.as_str(), chunk.text.as_str()))
            .collect();
        let hash = record.spec_sha256.as_deref().unwrap();
        assert_eq!(
            text,
            [
                ("Software", record.software().as_str()),
                ("ndfplot-version", record.version),
                ("spec-sha256", hash)
            ]
        );
        let (width, height, _) = decode(&bytes);
        assert_eq!((width, height), (800, 500));
    }

    #[test]
    fn svg_draws_each_series_and_its_legend_sample() {
        let svg = String::from_utf8(svg(&sample()).unwrap()).unwrap();
        // Solid: one polyline for the curve, one for the legend sample.
        assert_eq!(polylines_in(&svg, BLUE), 2);
        assert_eq!(polylines_in(&svg, ORANGE), 2);
        // Dashed and dotted series (both red): one polyline per dash.
        assert!(polylines_in(&svg, RED) > 20);
        let thick = format!(
            r##"stroke="#{ORANGE:06X}" stroke-width="{}""##,
            2.0 * 1.5 * SVG_UNITS_PER_PX
        );
        assert!(
            svg.contains(&thick),
            "thick = 2 × 1.5 px × SVG_UNITS_PER_PX"
        );
    }

    #[test]
    fn png_has_the_scaled_size_and_shows_the_curves() {
        let (width, height, pixels) = decode(&draw_png(&sample()).unwrap());
        assert_eq!((width, height), (800, 500));
        let has = |[r, g, b]: [u8; 3]| pixels.chunks_exact(3).any(|p| p == [r, g, b]);
        assert!(has([0xC7, 0x6A, 0x00]) && has([0x26, 0x89, 0xD1]) && has([0xDB, 0x2E, 0x2E]));
    }

    #[test]
    fn renders_are_byte_identical_across_runs_and_threads() {
        let figure = sample();
        let (svg0, png0) = (svg(&figure).unwrap(), draw_png(&figure).unwrap());
        std::thread::scope(|scope| {
            let runs: Vec<_> = (0..3)
                .map(|_| scope.spawn(|| (svg(&figure).unwrap(), draw_png(&figure).unwrap())))
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
        let mut clipped = panel(XUnit::Degrees, Scale::Linear, vec![flat.clone()]);
        clipped.axes.y_range = Some((0.5, 0.1));
        clipped.axes.x_range = Some((0.2, 0.2));
        let figures = [
            figure(vec![panel(
                XUnit::Degrees,
                Scale::Linear,
                vec![flat.clone()],
            )]),
            figure(vec![panel(XUnit::Radians, Scale::Log, vec![flat])]),
            figure(vec![panel(
                XUnit::Radians,
                Scale::Linear,
                vec![single.clone()],
            )]),
            figure(vec![panel(XUnit::Degrees, Scale::Log, vec![single])]),
            figure(vec![panel(XUnit::Degrees, Scale::Log, vec![zeros.clone()])]),
            figure(vec![panel(XUnit::Radians, Scale::Linear, vec![zeros, nan])]),
            figure(vec![panel(XUnit::Degrees, Scale::Log, vec![empty])]),
            figure(vec![panel(XUnit::Degrees, Scale::Linear, Vec::new())]),
            figure(vec![clipped]),
            figure(Vec::new()),
        ];
        for figure in &figures {
            svg(figure).unwrap();
            let (width, height, _) = decode(&draw_png(figure).unwrap());
            assert_eq!((width, height), (800, 500));
        }
    }

    #[test]
    fn themes_colour_the_page_and_the_series() {
        let dark = Figure {
            theme: Theme::Dark,
            ..sample()
        };
        let (width, _, pixels) = decode(&draw_png(&dark).unwrap());
        assert_eq!(pixels[..3], [0x16, 0x18, 0x1C], "top-left corner");
        let last = pixels.len() - 3;
        assert_eq!(pixels[last..], [0x16, 0x18, 0x1C], "bottom-right corner");
        assert_eq!(width, 800);
        let text = String::from_utf8(svg(&dark).unwrap()).unwrap();
        assert!(text.contains(r##"fill="#E4E6EA""##), "light text");

        let blind = Figure {
            theme: Theme::ColourBlind,
            ..sample()
        };
        let text = String::from_utf8(svg(&blind).unwrap()).unwrap();
        // RED, BLUE, ORANGE in order of appearance: blue, vermillion, bluish green (darkened a
        // little for 3:1 contrast on white).
        let green = theme::on_white(crate::spec::look::Rgb::from_hex(0x009E73));
        let green = u32::from(green.0) << 16 | u32::from(green.1) << 8 | u32::from(green.2);
        for hex in [0x0072B2, 0xD55E00, green] {
            assert!(polylines_in(&text, hex) > 0, "{hex:06X}");
        }
        for hex in [RED, BLUE, ORANGE] {
            assert_eq!(polylines_in(&text, hex), 0, "{hex:06X}");
        }
        // BLUE (solid in the spec) is the second colour: dashed, one polyline per dash.
        assert!(polylines_in(&text, 0xD55E00) > 10);
        assert!(svg(&blind).unwrap() == text.into_bytes());
    }

    #[test]
    fn unusable_canvases_and_grids_are_errors() {
        let mut figure = sample();
        figure.canvas.png_scale = 0.0;
        assert!(matches!(draw_png(&figure), Err(PlotError::Canvas { .. })));
        figure.canvas.png_scale = f64::NAN;
        assert!(matches!(draw_png(&figure), Err(PlotError::Canvas { .. })));
        let mut figure = sample();
        figure.canvas.width_px = 0;
        assert!(matches!(svg(&figure), Err(PlotError::Canvas { .. })));
        // The raster cap is the one validation enforces; the SVG has none.
        let mut figure = sample();
        (figure.canvas.width_px, figure.canvas.height_px) = (8193, 8192);
        figure.canvas.png_scale = 1.0;
        assert!(crate::spec::scene::check_canvas(&figure.canvas).is_err());
        assert!(matches!(
            encode::png_size(&figure.canvas),
            Err(PlotError::Canvas { .. })
        ));
        assert!(svg(&figure).is_ok());
        figure.canvas.width_px = 8192;
        assert!(crate::spec::scene::check_canvas(&figure.canvas).is_ok());
        assert_eq!(encode::png_size(&figure.canvas).unwrap(), (8192, 8192));
        let mut figure = sample();
        figure.cols = 1;
        assert!(matches!(svg(&figure), Err(PlotError::Layout { .. })));
    }

    #[test]
    fn new_marks_and_surfaces_render_with_their_labels() {
        let figure = fresnel_sample();
        let svg = String::from_utf8(svg(&figure).unwrap()).unwrap();
        for label in [
            "Fresnel decomposition",
            "Number of basis elements",
            "Cumulative singular values",
            // sₖ / Σs, c₀, g = 1: italic variables, set subscripts.
            "s",
            "k",
            " / Σs",
            "cumulative",
            "Gulbrandsen parametrization",
            "c",
            "0",
            "2",
            "3",
            "manifold",
            "g",
            " = 1",
            "15",
        ] {
            assert!(svg.contains(&format!(">{label}</text>")), "{label}");
        }
        // Whole-number ticks on the index axis.
        assert!(!svg.contains(">2.5</text>"));
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

        let (width, height, pixels) = decode(&draw_png(&figure).unwrap());
        assert_eq!((width, height), (2700, 900));
        let has = |[r, g, b]: [u8; 3]| pixels.chunks_exact(3).any(|p| p == [r, g, b]);
        assert!(has([0x1F, 0x77, 0xB4]) && has([0xC7, 0x6A, 0x00]) && has([0, 0, 0]));
    }

    #[test]
    fn new_marks_and_surfaces_render_identically_across_threads() {
        let figure = fresnel_sample();
        let (svg0, png0) = (svg(&figure).unwrap(), draw_png(&figure).unwrap());
        std::thread::scope(|scope| {
            let runs: Vec<_> = (0..2)
                .map(|_| scope.spawn(|| (svg(&figure).unwrap(), draw_png(&figure).unwrap())))
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
            let mut p = panel(XUnit::Plain, Scale::Linear, series);
            p.axes.kind = surface_kind(None);
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
            figure(vec![panel(XUnit::Plain, Scale::Linear, vec![lone_bar])]),
            figure(vec![panel(XUnit::Plain, Scale::Log, vec![log_bars])]),
            figure(vec![panel(XUnit::Degrees, Scale::Linear, vec![nan_dots])]),
            figure(vec![panel(
                XUnit::Plain,
                Scale::Linear,
                vec![marked(
                    series("none", RED, 1.0, Dash::Solid, Vec::new()),
                    Mark::Points,
                )],
            )]),
        ];
        for figure in &figures {
            svg(figure).unwrap();
            let (width, height, _) = decode(&draw_png(figure).unwrap());
            assert_eq!((width, height), (800, 500));
        }
    }

    #[test]
    fn surface_series_without_matching_z_are_errors() {
        let grid = manifold_grid(4);
        let mut p = panel(
            XUnit::Plain,
            Scale::Linear,
            vec![series("no z", STEEL, 1.0, Dash::Solid, xy(&grid))],
        );
        p.axes.kind = surface_kind(None);
        let missing = figure(vec![p.clone()]);
        assert!(matches!(svg(&missing), Err(PlotError::Series { label, .. }) if label == "no z"));
        assert!(matches!(draw_png(&missing), Err(PlotError::Series { .. })));
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

    /// The legend boxes of an SVG (its translucent rectangles), as [x, y, width, height] in
    /// SVG units, in drawing order.
    fn legend_boxes(svg: &roxmltree::Document) -> Vec<[f64; 4]> {
        let number = |node: &roxmltree::Node, key| node.attribute(key).unwrap().parse().unwrap();
        svg.descendants()
            .filter(|n| n.has_tag_name("rect") && n.attribute("fill-opacity") == Some("0.85"))
            .map(|n| ["x", "y", "width", "height"].map(|key| number(&n, key)))
            .collect()
    }

    /// Six TR curves `α_tr = 0.4 … 0.9` in the shades of one sweep, and a thick one apart.
    fn tr_sweep(first: f64) -> Vec<Series> {
        let tr = |alpha: f64| {
            sampled(move |t: f64| {
                let (a2, c2) = (alpha * alpha, t.cos().powi(2));
                a2 / (PI * (c2 * (a2 - 1.0) + 1.0).powi(2))
            })
        };
        let mut out: Vec<Series> = (0..6)
            .map(|k| {
                let alpha = first + 0.1 * k as f64;
                let mut s = series(
                    &format!("α_{{tr}} = {}", crate::spec::numbers::pretty(alpha)),
                    0x849900,
                    1.0,
                    Dash::Solid,
                    tr(alpha),
                );
                s.style.colour = crate::spec::look::shade(s.style.colour, k, 6);
                s.style.sweep = Some(crate::spec::look::SweepMember { index: k, count: 6 });
                s
            })
            .collect();
        out.push(series("α_{tr} = 1", 0x849900, 2.0, Dash::Solid, tr(1.0)));
        out
    }

    #[test]
    fn a_sweep_is_one_legend_row_and_panels_that_share_a_legend_draw_it_once() {
        let sweep_panel = |first: f64| panel(XUnit::Radians, Scale::Linear, tr_sweep(first));
        let mut fig = figure(vec![sweep_panel(0.4), sweep_panel(0.4), sweep_panel(0.3)]);
        (fig.canvas.width_px, fig.canvas.height_px) = (1200, 400);
        let text = String::from_utf8(svg(&fig).unwrap()).unwrap();
        let doc = roxmltree::Document::parse(&text).unwrap();
        // Panels 0 and 1 share theirs; panel 2's differs.
        assert_eq!(legend_boxes(&doc).len(), 2);
        let texts: Vec<&str> = doc
            .descendants()
            .filter(|n| n.has_tag_name("text"))
            .filter_map(|n| n.text())
            .collect();
        let rows = |range: &str| texts.iter().filter(|t| t.contains(range)).count();
        assert_eq!(rows(" = 0.4 … 0.9"), 1, "{texts:?}");
        assert_eq!(rows(" = 0.3 … 0.8"), 1);
        assert_eq!(rows(" = 1"), 2, "the thick curve keeps its row");
        assert!(
            !texts.iter().any(|t| t.contains(" = 0.5")),
            "no member rows"
        );
    }

    #[test]
    fn long_legends_stay_in_their_panel_cells_clear_of_the_axis_labels() {
        // Ten Beckmann curves a panel under a panel title, as in the catalogue's comparisons, at
        // the default font size, on canvases too small for the legend to fit inside the plot
        // area: wide and flat (the notebook's two-panel rows), tall, a 2 × 2 grid, polar, tiny.
        let sweep = |n: u32| -> Vec<Series> {
            (0..n)
                .map(|i| {
                    let alpha = 0.2 + 0.08 * f64::from(i);
                    let label = format!("αp = {:.4} (αb = {alpha:.2})", 2.0 / alpha / alpha - 2.0);
                    series(
                        &label,
                        RED,
                        1.0,
                        Dash::Solid,
                        sampled(|t| {
                            let tan2 = t.tan().powi(2);
                            (-tan2 / (alpha * alpha)).exp() / (PI * alpha * alpha * t.cos().powi(4))
                        }),
                    )
                })
                .collect()
        };
        let cartesian = || panel(XUnit::Radians, Scale::Linear, sweep(10));
        let polar = || {
            let mut p = cartesian();
            p.axes.kind = PanelKind::Polar;
            p
        };
        let layouts = [
            ((960, 300), 1, 2, vec![cartesian(), cartesian()]),
            ((480, 600), 1, 1, vec![cartesian()]),
            (
                (640, 400),
                2,
                2,
                vec![cartesian(), cartesian(), cartesian(), polar()],
            ),
            ((960, 300), 1, 2, vec![polar(), polar()]),
            ((200, 120), 1, 1, vec![cartesian()]),
        ];
        for ((width, height), rows, cols, panels) in layouts {
            let mut fig = figure(panels);
            fig.title.clear();
            fig.canvas.font_px = 14.0;
            for (i, p) in fig.panels.iter_mut().enumerate() {
                p.axes.title = "α_b = 0.2 … 0.92".to_owned();
                // Legends of their own: panels with equal legends would share one.
                for s in &mut p.series {
                    s.label.push_str(&format!(" #{i}"));
                }
            }
            (fig.rows, fig.cols) = (rows, cols);
            (fig.canvas.width_px, fig.canvas.height_px) = (width, height);
            let text = String::from_utf8(svg(&fig).unwrap()).unwrap();
            let doc = roxmltree::Document::parse(&text).unwrap();
            let boxes = legend_boxes(&doc);
            assert_eq!(boxes.len(), fig.panels.len(), "{width}×{height}");
            // SVG units: the canvas at SVG_UNITS_PER_PX.
            let (cell_w, cell_h) = (
                f64::from(width) * SVG_UNITS_PER_PX / cols as f64,
                f64::from(height) * SVG_UNITS_PER_PX / rows as f64,
            );
            for (i, [x, y, w, h]) in boxes.iter().copied().enumerate() {
                let (left, top) = ((i % cols) as f64 * cell_w, (i / cols) as f64 * cell_h);
                assert!(
                    x >= left && x + w <= left + cell_w && y >= top && y + h <= top + cell_h,
                    "{width}×{height}, panel {i}: legend {:?} outside its cell",
                    [x, y, w, h]
                );
            }
            // Every entry's label is in a legend box (plotters clips the box to its drawing
            // area, but not the text), and no tick label or axis label is under one.
            let inside = |x: f64, y: f64| {
                boxes
                    .iter()
                    .any(|[bx, by, bw, bh]| x > *bx && x < bx + bw && y > *by && y < by + bh)
            };
            let anchor = |node: &roxmltree::Node| {
                let at = |key| node.attribute(key).unwrap().parse::<f64>().unwrap();
                (at("x"), at("y"))
            };
            let entries = doc.descendants().filter(|n| {
                n.has_tag_name("text") && n.text().unwrap_or_default().trim().starts_with("αp = ")
            });
            assert_eq!(entries.clone().count(), 10 * fig.panels.len());
            for entry in entries {
                let (x, y) = anchor(&entry);
                assert!(inside(x, y), "{width}×{height}: {:?} outside", entry.text());
            }
            let labels = doc.descendants().filter(|n| {
                let content = n.text().unwrap_or_default().trim();
                n.has_tag_name("text")
                    && (content == "θ" || content == "D(θ)" || content.parse::<f64>().is_ok())
            });
            for label in labels {
                let (x, y) = anchor(&label);
                assert!(
                    !inside(x, y),
                    "{width}×{height}: {:?} at {x},{y} under a legend {boxes:?}",
                    label.text()
                );
            }
        }
    }
}
