//! The vocabulary a figure is described in: colours, line styles, marks, axis units and scales,
//! panel kinds, the canvas and the theme, and a panel's [`Axes`].
//!
//! Plain data shared by the spec (which validates it), the layout (which places it) and the
//! exporters (which draw it); no stage logic lives here.

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
    /// first appearance across the figure (one spec colour, one palette colour in every panel),
    /// the k-th distinct colour also dashed solid, dashed, dotted or dash-dot (k mod 4) unless its
    /// series has a dash of its own, so curves differ without colour.
    ColourBlind,
    /// Light ink and grid on a dark background; series colours darker than a relative luminance
    /// of 0.35 mixed towards white until they reach it.
    Dark,
}

/// What a panel shows around its series: titles, axes, scales, ranges and legend. The spec
/// stage validates it and the figure carries it to the exporters unchanged (but for the
/// θ axis range, which the figure states explicitly).
#[derive(Debug, Clone, PartialEq)]
pub struct Axes {
    /// Panel title; empty for none.
    pub title: String,
    /// x axis label.
    pub x_label: String,
    /// y axis label.
    pub y_label: String,
    /// What the x axis shows: θ in a display unit, or a plain quantity.
    pub x_unit: XUnit,
    /// 2D, or 3D with its z axis and view.
    pub kind: PanelKind,
    /// Scale of the y axis.
    pub y_scale: YScale,
    /// Displayed x range (radians on θ axes, within [0, π/2]); `None` = automatic.
    pub x_range: Option<(f64, f64)>,
    /// Displayed y range; `None` = automatic, every point visible (PlotRange → All).
    pub y_range: Option<(f64, f64)>,
    /// Whether a legend is drawn.
    pub legend: bool,
}

impl Axes {
    /// The θ interval the panel's curves are sampled on: the visible range, [0, π/2] by default
    /// and for plain x axes.
    pub fn theta_range(&self) -> (f64, f64) {
        match self.x_unit {
            XUnit::Plain => (0.0, std::f64::consts::FRAC_PI_2),
            _ => self.x_range.unwrap_or((0.0, std::f64::consts::FRAC_PI_2)),
        }
    }
}
