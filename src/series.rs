//! The evaluated figure: the one result type between the sampler and every exporter.
//!
//! Exporters (SVG, PNG, CSV) turn a [`Figure`] into bytes and never decide what to compute.

use std::sync::Arc;

/// An sRGB colour, 8 bits per channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Rgb(pub u8, pub u8, pub u8);

impl Rgb {
    /// Builds a colour from `0xRRGGBB`.
    pub fn from_hex(hex: u32) -> Rgb {
        Rgb((hex >> 16) as u8, (hex >> 8) as u8, hex as u8)
    }
}

/// Line pattern of a series.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Dash {
    /// Continuous line.
    Solid,
    /// Long dashes.
    Dashed,
    /// Short dots.
    Dotted,
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Style {
    /// Line colour.
    pub colour: Rgb,
    /// Line width in multiples of the default width (1.0 normal, 2.0 "thick").
    pub width: f64,
    /// Line pattern.
    pub dash: Dash,
    /// How points are marked.
    pub mark: Mark,
}

/// What the x axis shows: θ (data always in radians) in a display unit, or a plain quantity.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum XUnit {
    /// θ labelled in radians.
    Radians,
    /// θ labelled in degrees (x values multiplied by 180/π for display).
    Degrees,
    /// Not an angle (an index, a coefficient): x shown as is.
    Plain,
    /// The microfacet slope tan θ (data still θ in radians; displayed and ranged as tan θ).
    Slope,
}

/// How a series' points are marked.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Mark {
    /// A polyline through the points.
    Line,
    /// A small dot per point, no line (a scatter plot).
    Points,
    /// A polyline with a dot at each point.
    LinePoints,
    /// A vertical bar from 0 to each point.
    Bars,
}

/// The kind of a panel.
#[derive(Debug, Clone, PartialEq)]
pub enum PanelKind {
    /// A 2D plot of y against x.
    Cartesian,
    /// The lobe in the plane of incidence: each point (θ, v) drawn at angle θ from the vertical
    /// normal and radius v (or log₁₀ v above the radial floor on a log y scale), mirrored over
    /// −θ so the half-disc spans −π/2 … π/2; circular grid at radius ticks, spokes at angle ticks.
    Polar,
    /// A 3D plot: series carry z values; a series with a `grid` is a surface, others are 3D lines.
    Surface {
        /// z axis label.
        z_label: String,
        /// Displayed z range; `None` = automatic.
        z_range: Option<(f64, f64)>,
        /// Camera elevation above the x–y plane, degrees.
        elevation_deg: f64,
        /// Camera azimuth around the z axis, degrees.
        azimuth_deg: f64,
    },
}

/// Scale of the y axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum YScale {
    /// Linear y.
    Linear,
    /// Base-10 logarithmic y (non-positive values are not drawn).
    Log,
}

/// One drawn series: a polyline of (θ, value) points with its style and legend label.
#[derive(Debug, Clone)]
pub struct Series {
    /// Legend label, e.g. `α_b = 0.4`.
    pub label: String,
    /// Canonical curve JSON, used as the `curve` column of the CSV.
    pub curve: String,
    /// Drawing style.
    pub style: Style,
    /// Points (x, y): for curves (θ in radians, value) with θ increasing. Shared when several
    /// panels show one curve.
    pub points: Arc<Vec<(f64, f64)>>,
    /// z per point, for series in surface panels; `None` elsewhere.
    pub z: Option<Arc<Vec<f64>>>,
    /// `Some((rows, cols))` when the points form a row-major grid to draw as a surface mesh.
    pub grid: Option<(usize, usize)>,
}

/// One panel (sub-plot) of a figure.
#[derive(Debug, Clone)]
pub struct Panel {
    /// Panel title; empty for none.
    pub title: String,
    /// x axis label.
    pub x_label: String,
    /// y axis label.
    pub y_label: String,
    /// What the x axis shows.
    pub x_unit: XUnit,
    /// 2D or 3D.
    pub kind: PanelKind,
    /// Scale of the y axis.
    pub y_scale: YScale,
    /// Displayed x range (radians for θ axes); `None` = the range of the data.
    pub x_range: Option<(f64, f64)>,
    /// Displayed y range; `None` = automatic, every point visible (PlotRange → All).
    pub y_range: Option<(f64, f64)>,
    /// Whether to draw a legend.
    pub legend: bool,
    /// Series in drawing order.
    pub series: Vec<Series>,
}

/// Page geometry and typography of a figure.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Canvas {
    /// Figure width in CSS pixels (SVG user units).
    pub width_px: u32,
    /// Figure height in CSS pixels.
    pub height_px: u32,
    /// PNG pixels per CSS pixel (2.0 gives a 2× raster).
    pub png_scale: f64,
    /// Base font size in CSS pixels (tick labels; titles are larger).
    pub font_px: f64,
}

/// Colours and line distinctions of a figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Theme {
    /// The notebooks' palette on white: series keep their spec colours.
    #[default]
    Notebook,
    /// Okabe–Ito colour-blind-safe palette, assigned to the series' distinct colours in order of
    /// first appearance, with dash patterns and widths cycling so curves differ without colour.
    ColourBlind,
    /// Light ink and grid on a dark background; series colours lightened to keep contrast.
    Dark,
}

/// A figure ready for export: panels laid out on a `rows × cols` grid, filled row by row.
#[derive(Debug, Clone)]
pub struct Figure {
    /// Scene id; output files are `<id>.<ext>`.
    pub id: String,
    /// Figure title drawn above the panels; empty for none.
    pub title: String,
    /// Grid rows.
    pub rows: usize,
    /// Grid columns.
    pub cols: usize,
    /// Size and typography.
    pub canvas: Canvas,
    /// Colours and line distinctions.
    pub theme: Theme,
    /// Panels, row-major; `panels.len() <= rows * cols`.
    pub panels: Vec<Panel>,
}
