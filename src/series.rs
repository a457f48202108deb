//! The evaluated figure: the one result type between the sampler and every exporter.
//!
//! Exporters (SVG, PNG, CSV) turn a [`Figure`] into bytes and never decide what to compute.

use crate::provenance::Provenance;
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

/// Fraction of the data span added above an automatic linear range, and below it when the
/// data go negative (a range of non-negative data starts at 0).
pub const AUTO_MARGIN: f64 = 0.05;
/// Most decades an automatic log radius of a polar panel spans below the decade of the
/// maximum: deeper tails would squeeze the lobe into a ring near the rim.
pub const POLAR_DECADES: f64 = 4.0;

impl YScale {
    /// `v` in display units: `v` on a linear scale, log₁₀ `v` on a log scale; `None` when it
    /// cannot be drawn (not finite, or ≤ 0 on a log scale).
    pub fn display(self, v: f64) -> Option<f64> {
        match self {
            YScale::Linear => v.is_finite().then_some(v),
            YScale::Log => (v > 0.0 && v.is_finite()).then(|| v.log10()),
        }
    }

    /// The displayed range in display units ("PlotRange → All"): `given` (data units, either
    /// order; ignored unless both ends can be displayed), else from the data `extent` (display
    /// units, `None` for no data). Linear: from 0 when the data are ≥ 0, else [`AUTO_MARGIN`] of
    /// the span below the minimum, to [`AUTO_MARGIN`] of the span above the maximum; (0, 1)
    /// without data. Log: the decade at or below the minimum to the decade at or above the
    /// maximum, at least one decade; (0, 1) without data. An empty range (a flat curve) is
    /// opened around its value: ±1 at 0, else ±half its magnitude.
    pub fn range(self, given: Option<(f64, f64)>, extent: Option<(f64, f64)>) -> (f64, f64) {
        match (self, self.shown(given)) {
            (_, Some((lo, hi))) => widen_if_flat(lo, hi),
            (YScale::Linear, None) => {
                let Some((lo, hi)) = extent else {
                    return (0.0, 1.0);
                };
                let lo = lo.min(0.0);
                let margin = AUTO_MARGIN * (hi - lo);
                let lo = if lo == 0.0 { 0.0 } else { lo - margin };
                widen_if_flat(lo, hi + margin)
            }
            (YScale::Log, None) => match extent {
                Some((lo, hi)) => {
                    let (lo, hi) = (lo.floor(), hi.ceil());
                    (lo, hi.max(lo + 1.0))
                }
                None => (0.0, 1.0),
            },
        }
    }

    /// The radial range of a polar panel in display units: the centre's value to the rim's.
    /// As [`YScale::range`], except that an automatic log range starts at most
    /// [`POLAR_DECADES`] below the decade of the maximum (values below it sit at the centre).
    pub fn radial_range(self, given: Option<(f64, f64)>, extent: Option<(f64, f64)>) -> (f64, f64) {
        let (lo, hi) = self.range(given, extent);
        match (self, self.shown(given), extent) {
            (YScale::Log, None, Some((_, max))) => (lo.max(max.floor() - POLAR_DECADES), hi),
            _ => (lo, hi),
        }
    }

    /// A given range in display units, low end first, if both ends can be displayed.
    fn shown(self, given: Option<(f64, f64)>) -> Option<(f64, f64)> {
        let (a, b) = given?;
        let (a, b) = (self.display(a)?, self.display(b)?);
        Some((a.min(b), a.max(b)))
    }
}

/// `(lo, hi)`, or when it is empty (a flat curve, a single point) a range around its value:
/// ±1 at 0, else ±half its magnitude.
pub fn widen_if_flat(lo: f64, hi: f64) -> (f64, f64) {
    if hi - lo > 1e-12 * lo.abs().max(hi.abs()) && hi - lo > f64::MIN_POSITIVE {
        return (lo, hi);
    }
    let pad = if lo == 0.0 { 1.0 } else { lo.abs() * 0.5 };
    (lo - pad, hi + pad)
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
    /// first appearance across the figure (one spec colour, one palette colour in every panel),
    /// the k-th distinct colour also dashed solid, dashed, dotted or dash-dot (k mod 4) unless its
    /// series has a dash of its own, so curves differ without colour.
    ColourBlind,
    /// Light ink and grid on a dark background; series colours darker than a relative luminance
    /// of 0.35 mixed towards white until they reach it.
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
    /// Which ndfplot drew it from which spec; every drawn format embeds it, tables do not.
    pub provenance: Provenance,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn automatic_ranges_follow_the_plot_range_rule() {
        let (lo, hi) = YScale::Linear.range(None, Some((1.0, 3.0)));
        assert!(
            lo == 0.0 && (hi - 3.15).abs() < 1e-12,
            "margin of the span from 0"
        );
        let (lo, hi) = YScale::Linear.range(None, Some((-1.0, 1.0)));
        assert!((lo + 1.1).abs() < 1e-12 && (hi - 1.1).abs() < 1e-12);
        assert_eq!(YScale::Linear.range(None, Some((0.0, 0.0))), (-1.0, 1.0));
        assert_eq!(YScale::Linear.range(Some((2.0, 1.0)), None), (1.0, 2.0));
        assert_eq!(YScale::Log.range(None, Some((-2.7, 1.2))), (-3.0, 2.0));
        assert_eq!(YScale::Log.range(None, Some((1.0, 1.0))), (1.0, 2.0));
        assert_eq!(
            YScale::Log.range(Some((0.0, 10.0)), None),
            (0.0, 1.0),
            "0 has no log"
        );
        assert_eq!(YScale::Log.range(Some((1e-3, 10.0)), None), (-3.0, 1.0));
    }

    #[test]
    fn polar_log_radii_reach_at_most_four_decades_below_the_peak() {
        assert_eq!(
            YScale::Log.radial_range(None, Some((-9.0, 1.2))),
            (-3.0, 2.0)
        );
        assert_eq!(
            YScale::Log.radial_range(None, Some((-1.5, 1.2))),
            (-2.0, 2.0)
        );
        assert_eq!(
            YScale::Log.radial_range(Some((1e-6, 10.0)), Some((-9.0, 1.2))),
            (-6.0, 1.0)
        );
        assert_eq!(
            YScale::Linear.radial_range(None, Some((0.0, 2.0))),
            YScale::Linear.range(None, Some((0.0, 2.0)))
        );
    }
}
