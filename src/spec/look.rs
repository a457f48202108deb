//! The vocabulary a figure is described in: colours, line styles, marks, axis units and scales,
//! panel kinds, the canvas and the theme, and a panel's [`Axes`].
//!
//! Plain data shared by the spec (which validates it), the layout (which places it) and the
//! exporters (which draw it); no stage logic lives here.

/// An sRGB colour, 8 bits per channel.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct Rgb(pub u8, pub u8, pub u8);

/// Largest relative luminance of a curve on a white page: the WCAG contrast (1 + 0.05)/(L + 0.05) is then
/// at least 3.0 (L ≤ 0.30), with a margin for the rounding of the channels.
pub const MAX_LUMINANCE_ON_WHITE: f64 = 0.29;
/// CIE lightness L* of the darkest and of the lightest shade of a sweep on a white page: the lightest has
/// [`MAX_LUMINANCE_ON_WHITE`] (L* ≈ 60.7), the darkest is still a colour rather than black.
pub const SWEEP_LIGHTNESS: (f64, f64) = (27.0, 60.5);
/// Mixing steps searched when a colour is given a luminance: 1/1024 moves a channel by at most a
/// quarter level, so the channel rounding decides the result.
const MIX_STEPS: u32 = 1024;

impl Rgb {
    /// White.
    pub const WHITE: Rgb = Rgb(255, 255, 255);
    /// Black.
    pub const BLACK: Rgb = Rgb(0, 0, 0);

    /// Builds a colour from `0xRRGGBB`.
    pub fn from_hex(hex: u32) -> Rgb {
        Rgb((hex >> 16) as u8, (hex >> 8) as u8, hex as u8)
    }

    /// WCAG 2 relative luminance: 0.2126 R + 0.7152 G + 0.0722 B of the linearised sRGB channels.
    pub fn luminance(self) -> f64 {
        let linear = |c: u8| {
            let c = f64::from(c) / 255.0;
            if c <= 0.04045 {
                c / 12.92
            } else {
                ((c + 0.055) / 1.055).powf(2.4)
            }
        };
        0.2126 * linear(self.0) + 0.7152 * linear(self.1) + 0.0722 * linear(self.2)
    }

    /// WCAG 2 contrast ratio with `other`: (L₁ + 0.05)/(L₂ + 0.05), the lighter over the darker.
    pub fn contrast(self, other: Rgb) -> f64 {
        let (a, b) = (self.luminance(), other.luminance());
        (a.max(b) + 0.05) / (a.min(b) + 0.05)
    }

    /// This colour mixed towards `target` by `t` ∈ [0, 1], each channel rounded.
    pub fn mix(self, target: Rgb, t: f64) -> Rgb {
        let channel =
            |a: u8, b: u8| (f64::from(a) + t * (f64::from(b) - f64::from(a))).round() as u8;
        Rgb(
            channel(self.0, target.0),
            channel(self.1, target.1),
            channel(self.2, target.2),
        )
    }

    /// The colour of this hue, mixed towards black or towards white, whose luminance is the first to
    /// reach `luminance` from this side (darkening: at most it; lightening: at least it).
    pub fn with_luminance(self, luminance: f64) -> Rgb {
        let own = self.luminance();
        let darker = luminance < own;
        let target = if darker { Rgb::BLACK } else { Rgb::WHITE };
        (0..=MIX_STEPS)
            .map(|step| self.mix(target, f64::from(step) / f64::from(MIX_STEPS)))
            .find(|c| {
                if darker {
                    c.luminance() <= luminance
                } else {
                    c.luminance() >= luminance
                }
            })
            .unwrap_or(target)
    }
}

/// `text` with its math-text markup characters (`\\`, `_`, `^`, `{`, `}`) escaped, so that a drawn
/// label shows it as written: for names made of identifiers (`lazanyi_term`, `closed_form`).
pub fn literal(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if matches!(c, '\\' | '_' | '^' | '{' | '}') {
            out.push('\\');
        }
        out.push(c);
    }
    out
}

/// CIE lightness L* (0 black … 100 white) of relative luminance `y`.
pub fn lightness(y: f64) -> f64 {
    if y > 216.0 / 24389.0 {
        116.0 * y.cbrt() - 16.0
    } else {
        y * 24389.0 / 27.0
    }
}

/// Relative luminance of CIE lightness `l` (the inverse of [`lightness`]).
pub fn luminance_of_lightness(l: f64) -> f64 {
    if l > 8.0 {
        ((l + 16.0) / 116.0).powi(3)
    } else {
        l * 27.0 / 24389.0
    }
}

/// The k-th of n shades of a hue, darker (k = 0) to lighter, evenly spaced in CIE lightness over
/// [`SWEEP_LIGHTNESS`]: the curves of one sweep keep their hue, stay apart in the legend, and each
/// has at least 3:1 contrast on a white page ([`MAX_LUMINANCE_ON_WHITE`]).
pub fn shade(base: Rgb, k: usize, n: usize) -> Rgb {
    let (dark, light) = SWEEP_LIGHTNESS;
    let l = dark + (light - dark) * k as f64 / (n - 1).max(1) as f64;
    base.with_luminance(luminance_of_lightness(l))
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
    /// Which member of its entry's sweep the series is (its shade of the entry's colour), when the
    /// entry gives several curves: a legend shows the sweep as one entry.
    pub sweep: Option<SweepMember>,
}

/// A series' place in the sweep of its spec entry: member `index` of `count` (≥ 2), darkest first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct SweepMember {
    /// 0-based position in the entry's curves.
    pub index: usize,
    /// Number of curves the entry gives.
    pub count: usize,
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
    /// A 2D map: a series' z over its rectilinear (x, y) grid drawn as coloured cells
    /// ([`viridis`]), with a colour bar.
    Heatmap {
        /// Colour bar label.
        z_label: String,
        /// z range the colours span; `None` = the data's extent.
        z_range: Option<(f64, f64)>,
    },
}

/// Viridis (van der Walt and Smith's perceptually uniform sequential colour map, matplotlib's
/// default) at ten evenly spaced points, 0 to 1.
const VIRIDIS: [u32; 10] = [
    0x440154, 0x482878, 0x3E4A89, 0x31688E, 0x26828E, 0x1F9E89, 0x35B779, 0x6DCD59, 0xB4DE2C,
    0xFDE725,
];

/// The viridis colour of `t` ∈ [0, 1] (clamped; NaN is 0), interpolated linearly in sRGB between
/// the points of [`VIRIDIS`]: dark violet at 0, yellow at 1, lightness rising throughout.
pub fn viridis(t: f64) -> Rgb {
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let at = t * (VIRIDIS.len() - 1) as f64;
    let i = (at.floor() as usize).min(VIRIDIS.len() - 2);
    Rgb::from_hex(VIRIDIS[i]).mix(Rgb::from_hex(VIRIDIS[i + 1]), at - i as f64)
}

/// Scale of an axis.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scale {
    /// Linear.
    Linear,
    /// Base-10 logarithmic (non-positive values are not drawn).
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

impl Canvas {
    /// Largest PNG drawn, in pixels: 2²⁶ (8192 × 8192). Its drawing buffer (RGBA) and the
    /// encoded rows (RGB) take 7 bytes a pixel, 470 MB at the cap.
    pub const MAX_PNG_PIXELS: u64 = 1 << 26;

    /// The PNG's width and height in pixels: each side times `png_scale`, rounded.
    pub fn png_size(&self) -> (f64, f64) {
        (
            (f64::from(self.width_px) * self.png_scale).round(),
            (f64::from(self.height_px) * self.png_scale).round(),
        )
    }
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
    /// Scale of the x axis, applied to the displayed value (θ in its unit, tan θ, or the plain
    /// quantity): logarithmic only on 2D panels.
    pub x_scale: Scale,
    /// 2D, or 3D with its z axis and view.
    pub kind: PanelKind,
    /// Scale of the y axis.
    pub y_scale: Scale,
    /// Displayed x range (radians on θ axes, within [0, π/2]); `None` = automatic.
    pub x_range: Option<(f64, f64)>,
    /// Displayed y range; `None` = automatic, every point visible (PlotRange → All).
    pub y_range: Option<(f64, f64)>,
    /// Whether and where the legend is drawn.
    pub legend: LegendPlace,
    /// Whether grid lines are drawn at the ticks.
    pub grid: bool,
    /// The x ticks the spec asks for; `None` = chosen by the locator.
    pub x_ticks: Option<TickChoice>,
    /// The y ticks the spec asks for; `None` = chosen by the locator.
    pub y_ticks: Option<TickChoice>,
}

/// Where a panel's legend goes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LegendPlace {
    /// Inside the plot area where it hides no curve, else outside (the default).
    Best,
    /// Inside the plot area at this corner, whatever it hides (outside when it does not fit).
    Corner(Corner),
    /// Outside, right of the plot area (a grid's panels: in the row's band below).
    Right,
    /// Outside, below the plot area.
    Below,
    /// No legend.
    None,
}

/// A corner of a plot area.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Corner {
    /// Top right.
    UpperRight,
    /// Top left.
    UpperLeft,
    /// Bottom left.
    LowerLeft,
    /// Bottom right.
    LowerRight,
}

impl Corner {
    /// The corner as a spec names it (`upper right`).
    pub fn name(self) -> &'static str {
        match self {
            Corner::UpperRight => "upper right",
            Corner::UpperLeft => "upper left",
            Corner::LowerLeft => "lower left",
            Corner::LowerRight => "lower right",
        }
    }
}

/// Ticks a spec asks for on an axis of a 2D panel.
#[derive(Debug, Clone, PartialEq)]
pub enum TickChoice {
    /// At most this many nice ticks, chosen by the locator.
    Count(usize),
    /// Exactly these values, in the unit the axis shows (those outside its range are not drawn).
    At(Vec<f64>),
}

impl Axes {
    /// The axes of a 2D panel with these labels, unit and scale, and every other choice automatic:
    /// no title, ranges showing every point, the legend at its best place, grid lines, ticks from
    /// the locator.
    pub fn cartesian(x_label: &str, y_label: &str, x_unit: XUnit, y_scale: Scale) -> Axes {
        Axes {
            title: String::new(),
            x_label: x_label.to_owned(),
            y_label: y_label.to_owned(),
            x_unit,
            x_scale: Scale::Linear,
            kind: PanelKind::Cartesian,
            y_scale,
            x_range: None,
            y_range: None,
            legend: LegendPlace::Best,
            grid: true,
            x_ticks: None,
            y_ticks: None,
        }
    }

    /// The θ interval the panel's curves are sampled on: the visible range, [0, π/2] by default
    /// and for plain x axes.
    pub fn theta_range(&self) -> (f64, f64) {
        match self.x_unit {
            XUnit::Plain => (0.0, std::f64::consts::FRAC_PI_2),
            _ => self.x_range.unwrap_or((0.0, std::f64::consts::FRAC_PI_2)),
        }
    }
}

/// Default panel height / width: 1/φ, Mathematica's default `AspectRatio`.
pub const DEFAULT_ASPECT_RATIO: f64 = 0.618_033_988_749_894_9;

/// Extra default canvas height, in CSS pixels, of a figure with a title: room for the title
/// (1.4 em of the default 14 px font) and its spacing.
pub const DEFAULT_TITLE_BAND_PX: f64 = 40.0;

/// Default figure width in CSS pixels: 640 for one column, 480 per column otherwise.
pub fn default_width(cols: usize) -> f64 {
    if cols <= 1 {
        640.0
    } else {
        480.0 * cols as f64
    }
}

/// Default figure height in CSS pixels for `rows × cols` panels of aspect ratio `aspect` on a
/// figure `width` wide, plus [`DEFAULT_TITLE_BAND_PX`] when `titled`; rounded, not yet clamped.
pub fn default_height(rows: usize, cols: usize, width: f64, aspect: f64, titled: bool) -> f64 {
    let title_band = if titled { DEFAULT_TITLE_BAND_PX } else { 0.0 };
    (rows as f64 * width / cols as f64 * aspect + title_band).round()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ndf::Family;

    #[test]
    fn sweep_shades_have_3_to_1_contrast_on_white_and_rise_in_lightness() {
        let bases = Family::ALL
            .map(|f| Rgb::from_hex(f.colour()))
            .into_iter()
            .chain([0xD33682, 0x268BD2, 0xFFFF00, 0xFFFFFF, 0x000000].map(Rgb::from_hex));
        for base in bases {
            for n in 2..=12 {
                let shades: Vec<Rgb> = (0..n).map(|k| shade(base, k, n)).collect();
                for (k, c) in shades.iter().enumerate() {
                    assert!(c.contrast(Rgb::WHITE) >= 3.0, "{base:?} {k}/{n}: {c:?}");
                }
                for pair in shades.windows(2) {
                    let (a, b) = (
                        lightness(pair[0].luminance()),
                        lightness(pair[1].luminance()),
                    );
                    assert!(b > a + 1.0, "{base:?} n = {n}: {a} then {b}");
                }
            }
        }
    }

    #[test]
    fn viridis_runs_from_violet_to_yellow_rising_in_lightness() {
        assert_eq!(viridis(0.0), Rgb::from_hex(0x440154));
        assert_eq!(viridis(1.0), Rgb::from_hex(0xFDE725));
        assert_eq!(viridis(f64::NAN), viridis(-1.0));
        assert_eq!(viridis(2.0), viridis(1.0));
        let lightness_at = |t: f64| lightness(viridis(t).luminance());
        for i in 0..64 {
            let (a, b) = (f64::from(i) / 64.0, f64::from(i + 1) / 64.0);
            assert!(lightness_at(b) > lightness_at(a), "{a} to {b}");
        }
    }

    #[test]
    fn literal_escapes_every_markup_character() {
        assert_eq!(literal("lazanyi_term"), "lazanyi\\_term");
        assert_eq!(literal(r"a^{b}\c"), r"a\^\{b\}\\c");
        assert_eq!(literal("α = 0.3"), "α = 0.3");
    }

    #[test]
    fn lightness_and_luminance_are_inverse_and_contrast_is_symmetric() {
        for l in [0.0, 5.0, 8.0, 27.0, 60.5, 100.0] {
            assert!(
                (lightness(luminance_of_lightness(l)) - l).abs() < 1e-9,
                "{l}"
            );
        }
        assert!((Rgb::WHITE.contrast(Rgb::BLACK) - 21.0).abs() < 1e-9);
        let (a, b) = (Rgb::from_hex(0x849900), Rgb::from_hex(0x2689D1));
        assert_eq!(a.contrast(b), b.contrast(a));
    }
}
