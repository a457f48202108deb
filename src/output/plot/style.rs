//! Sizes, colours and the font of one render: text sizes, line widths, dash patterns and dot
//! radii in device pixels, scaled by the device scale and the base font size.

use std::sync::OnceLock;

use plotters::prelude::*;
use plotters::style::{FontFamily, FontStyle, register_font};

use super::PlotError;
use crate::series::{Dash, Rgb};

/// Name under which the embedded face is registered; the SVG names it first.
pub(super) const FONT_NAME: &str = "DejaVu Sans";
/// Em of the face per plotters text size: ab_glyph scales DejaVu Sans so that ascender −
/// descender (1901 + 483 font units) spans the size, and one em is 2048 units.
pub(super) const EM_PER_SIZE: f64 = 2048.0 / 2384.0;

/// Default curve width in CSS pixels (multiplied by `Style::width`).
pub(super) const BASE_LINE_PX: f64 = 1.5;
/// Dash and gap lengths of dashed curves, in multiples of the curve's width.
pub(super) const DASHED: (f64, f64) = (4.0, 2.5);
/// Dot and gap lengths of dotted curves, in multiples of the curve's width.
pub(super) const DOTTED: (f64, f64) = (1.0, 1.5);
/// Radius of the dots of a scatter (`Mark::Points`), in CSS pixels.
pub(super) const POINT_RADIUS_PX: f64 = 1.5;
/// Radius of the dots on a line (`Mark::LinePoints`) and of legend dots, in CSS pixels.
pub(super) const MARKER_RADIUS_PX: f64 = 3.0;

/// Opacity of surface meshes: lines and mesh cells behind them stay faintly visible.
pub(super) const SURFACE_OPACITY: f64 = 0.8;
/// Brightness of a surface's mesh lines relative to its colour.
pub(super) const MESH_DARKEN: f64 = 0.7;

/// Font sizes relative to `Canvas::font_px`.
pub(super) const AXIS_LABEL_EM: f64 = 1.1;
pub(super) const PANEL_TITLE_EM: f64 = 1.2;
pub(super) const FIGURE_TITLE_EM: f64 = 1.4;

/// Text; frame, axes and ticks; major and minor grid lines; legend border.
pub(super) const INK: RGBColor = RGBColor(0x22, 0x22, 0x22);
pub(super) const FRAME: RGBColor = RGBColor(0x55, 0x55, 0x55);
pub(super) const GRID: RGBColor = RGBColor(0xE3, 0xE3, 0xE3);
pub(super) const MINOR_GRID: RGBColor = RGBColor(0xF1, 0xF1, 0xF1);
pub(super) const LEGEND_BORDER: RGBColor = RGBColor(0xBB, 0xBB, 0xBB);
/// 3D back panes, their grid lines and their edges.
pub(super) const PANE: RGBColor = RGBColor(0xF4, 0xF4, 0xF4);
pub(super) const PANE_GRID: RGBColor = RGBColor(0xDD, 0xDD, 0xDD);
pub(super) const PANE_EDGE: RGBColor = RGBColor(0xC4, 0xC4, 0xC4);

/// Registers the embedded face once per process; later calls return the first outcome.
pub(super) fn ensure_font() -> Result<(), PlotError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        let bytes = dejavu::sans::regular();
        // "sans-serif" too, so that any plotters default style finds the same face.
        register_font(FONT_NAME, FontStyle::Normal, bytes).is_ok()
            && register_font("sans-serif", FontStyle::Normal, bytes).is_ok()
    });
    if ok { Ok(()) } else { Err(PlotError::Font) }
}

/// Sizes in device pixels for one render: everything scales with `k` and the base font size.
pub(super) struct Metrics {
    /// Device pixels per CSS pixel.
    pub(super) k: f64,
    /// plotters text size of the tick labels in device pixels (their em is `font_px · k`):
    /// the unit of all other text sizes and of the layout spacings.
    pub(super) unit: f64,
}

impl Metrics {
    /// `units` base text sizes in whole device pixels.
    pub(super) fn px(&self, units: f64) -> u32 {
        (units * self.unit).round().max(1.0) as u32
    }
    /// A hairline (grid, frame, ticks): one CSS pixel.
    pub(super) fn hairline(&self) -> u32 {
        self.k.round().max(1.0) as u32
    }
    /// Text style at `units` times the base size.
    pub(super) fn font(&self, units: f64) -> TextStyle<'static> {
        TextStyle::from((FontFamily::Name(FONT_NAME), units * self.unit).into_font()).color(&INK)
    }
    /// Stroke of a curve drawn `multiplier` times the default width.
    pub(super) fn curve_style(&self, colour: Rgb, multiplier: f64) -> ShapeStyle {
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
    pub(super) fn dot(&self, radius_px: f64) -> u32 {
        (radius_px * self.k).round().max(1.0) as u32
    }
    /// A fill in `colour` at `opacity`.
    pub(super) fn fill(&self, colour: Rgb, opacity: f64) -> ShapeStyle {
        RGBColor(colour.0, colour.1, colour.2).mix(opacity).filled()
    }
    /// A hairline stroke in `colour`.
    pub(super) fn line(&self, colour: RGBColor) -> ShapeStyle {
        ShapeStyle {
            color: colour.to_rgba(),
            filled: false,
            stroke_width: self.hairline(),
        }
    }
}

/// The darker colour of a surface's mesh lines.
pub(super) fn mesh_colour(colour: Rgb) -> RGBColor {
    let dim = |c: u8| (f64::from(c) * MESH_DARKEN).round() as u8;
    RGBColor(dim(colour.0), dim(colour.1), dim(colour.2))
}

/// Dash and gap lengths in device pixels for `dash` drawn with `style`; `None` when solid.
pub(super) fn dash_pattern(dash: Dash, style: &ShapeStyle) -> Option<(f64, f64)> {
    let width = f64::from(style.stroke_width);
    match dash {
        Dash::Solid => None,
        Dash::Dashed => Some((DASHED.0 * width, DASHED.1 * width)),
        Dash::Dotted => Some((DOTTED.0 * width, DOTTED.1 * width)),
    }
}
