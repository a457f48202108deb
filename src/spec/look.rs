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
/// CIE lightness L* of the darkest and of the lightest shade of a sweep on a white page: the
/// ceiling is the lightest a curve may be at 3:1 contrast ([`MAX_LUMINANCE_ON_WHITE`], L* ≈ 60.7);
/// the floor keeps the darkest shade a colour (its hue and chroma kept) rather than near-black, so
/// that the dark ends of two families in one panel do not merge.
pub const SWEEP_LIGHTNESS: (f64, f64) = (30.0, 60.5);
/// How far a sweep's hue turns from its darkest to its lightest shade, in degrees of CIELAB hue
/// (cubehelix's idea, kept small so that the family stays recognisable): centred on the base hue,
/// it adds about 1 ΔE00 per neighbour pair to what lightness alone gives.
pub const SWEEP_HUE_TURN_DEG: f64 = 30.0;
/// Largest sweep whose neighbouring shades are at least [`MIN_SHADE_DELTA_E`] apart for every family
/// colour (measured by a test): the lightness band a hue has on a white page holds no more.
pub const SWEEP_HELD: usize = 3;
/// Least CIEDE2000 difference of neighbouring shades of a sweep of up to [`SWEEP_HELD`] members.
pub const MIN_SHADE_DELTA_E: f64 = 10.0;
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

/// A colour in CIELAB (D65 white, the sRGB primaries): lightness `l` (0 … 100) and the opponent
/// axes `a` (green − red) and `b` (blue − yellow).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lab {
    /// Lightness L*.
    pub l: f64,
    /// a*.
    pub a: f64,
    /// b*.
    pub b: f64,
}

/// D65 white in CIE XYZ (Y = 1), the white point of sRGB.
const D65: [f64; 3] = [0.950_47, 1.0, 1.088_83];
/// Linear sRGB → XYZ (IEC 61966-2-1).
const RGB_TO_XYZ: [[f64; 3]; 3] = [
    [0.412_456_4, 0.357_576_1, 0.180_437_5],
    [0.212_672_9, 0.715_152_2, 0.072_175_0],
    [0.019_333_9, 0.119_192_0, 0.950_304_1],
];
/// XYZ → linear sRGB (the inverse of [`RGB_TO_XYZ`]).
const XYZ_TO_RGB: [[f64; 3]; 3] = [
    [3.240_454_2, -1.537_138_5, -0.498_531_4],
    [-0.969_266_0, 1.876_010_8, 0.041_556_0],
    [0.055_643_4, -0.204_025_9, 1.057_225_2],
];
/// Machado, Oliveira and Fernandes 2009, "A physiologically-based model for simulation of color
/// vision deficiency", Table 1: deuteranopia at severity 1.0, on linear RGB.
const DEUTERANOPIA: [[f64; 3]; 3] = [
    [0.367_322, 0.860_646, -0.227_968],
    [0.280_085, 0.672_501, 0.047_413],
    [-0.011_820, 0.042_940, 0.968_881],
];

fn apply(m: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    m.map(|row| row[0] * v[0] + row[1] * v[1] + row[2] * v[2])
}

fn to_linear(c: u8) -> f64 {
    let c = f64::from(c) / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

fn from_linear(c: f64) -> u8 {
    let c = c.clamp(0.0, 1.0);
    let c = if c <= 0.003_130_8 {
        12.92 * c
    } else {
        1.055 * c.powf(1.0 / 2.4) - 0.055
    };
    (c * 255.0).round() as u8
}

impl Rgb {
    fn linear(self) -> [f64; 3] {
        [to_linear(self.0), to_linear(self.1), to_linear(self.2)]
    }

    fn of_linear(v: [f64; 3]) -> Rgb {
        Rgb(from_linear(v[0]), from_linear(v[1]), from_linear(v[2]))
    }

    /// The colour in CIELAB.
    pub fn lab(self) -> Lab {
        let xyz = apply(&RGB_TO_XYZ, self.linear());
        let f = |t: f64| {
            if t > 216.0 / 24389.0 {
                t.cbrt()
            } else {
                (24389.0 / 27.0 * t + 16.0) / 116.0
            }
        };
        let [fx, fy, fz] = [0, 1, 2].map(|i| f(xyz[i] / D65[i]));
        Lab {
            l: 116.0 * fy - 16.0,
            a: 500.0 * (fx - fy),
            b: 200.0 * (fy - fz),
        }
    }

    /// How a deuteranope sees this colour (Machado et al. 2009, severity 1.0).
    pub fn deuteranopia(self) -> Rgb {
        Rgb::of_linear(apply(&DEUTERANOPIA, self.linear()))
    }
}

impl Lab {
    /// The colour of lightness `l`, chroma `c` and hue `h` (degrees).
    pub fn lch(l: f64, c: f64, h: f64) -> Lab {
        let h = h.to_radians();
        Lab {
            l,
            a: c * h.cos(),
            b: c * h.sin(),
        }
    }

    /// Chroma C* = √(a² + b²).
    pub fn chroma(self) -> f64 {
        self.a.hypot(self.b)
    }

    /// Hue angle in degrees, 0 … 360.
    pub fn hue(self) -> f64 {
        self.b.atan2(self.a).to_degrees().rem_euclid(360.0)
    }

    /// Linear sRGB of this colour, possibly outside [0, 1].
    fn linear(self) -> [f64; 3] {
        let fy = (self.l + 16.0) / 116.0;
        let finv = |t: f64| {
            if t.powi(3) > 216.0 / 24389.0 {
                t.powi(3)
            } else {
                (116.0 * t - 16.0) * 27.0 / 24389.0
            }
        };
        let xyz = [
            finv(fy + self.a / 500.0) * D65[0],
            finv(fy) * D65[1],
            finv(fy - self.b / 200.0) * D65[2],
        ];
        apply(&XYZ_TO_RGB, xyz)
    }

    /// The sRGB colour of this lightness and hue with the largest chroma up to this one that sRGB
    /// holds (chroma reduced by bisection, so that lightness and hue stay), channels rounded.
    pub fn to_rgb(self) -> Rgb {
        let inside = |lab: Lab| {
            lab.linear()
                .iter()
                .all(|c| (-1e-9..=1.0 + 1e-9).contains(c))
        };
        if inside(self) {
            return Rgb::of_linear(self.linear());
        }
        let (c, h) = (self.chroma(), self.hue());
        let (mut lo, mut hi) = (0.0, c);
        for _ in 0..40 {
            let mid = 0.5 * (lo + hi);
            if inside(Lab::lch(self.l, mid, h)) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Rgb::of_linear(Lab::lch(self.l, lo, h).linear())
    }
}

/// CIEDE2000 colour difference of `x` and `y` (Sharma, Wu and Dalal 2005, with kL = kC = kH = 1):
/// about 1 is a just-noticeable difference; 10 tells two curves apart at a glance.
pub fn delta_e00(x: Lab, y: Lab) -> f64 {
    let pow7 = |v: f64| v.powi(7);
    let c_mean = 0.5 * (x.chroma() + y.chroma());
    let g = 0.5 * (1.0 - (pow7(c_mean) / (pow7(c_mean) + pow7(25.0))).sqrt());
    let prime = |lab: Lab| {
        let a = (1.0 + g) * lab.a;
        let c = a.hypot(lab.b);
        let h = if c == 0.0 {
            0.0
        } else {
            lab.b.atan2(a).to_degrees().rem_euclid(360.0)
        };
        (c, h)
    };
    let ((c1, h1), (c2, h2)) = (prime(x), prime(y));
    let dl = y.l - x.l;
    let dc = c2 - c1;
    let dh = if c1 * c2 == 0.0 {
        0.0
    } else {
        let d = h2 - h1;
        if d > 180.0 {
            d - 360.0
        } else if d < -180.0 {
            d + 360.0
        } else {
            d
        }
    };
    let dh_big = 2.0 * (c1 * c2).sqrt() * (dh / 2.0).to_radians().sin();
    let l_mean = 0.5 * (x.l + y.l);
    let cp_mean = 0.5 * (c1 + c2);
    let h_mean = if c1 * c2 == 0.0 {
        h1 + h2
    } else if (h1 - h2).abs() > 180.0 {
        if h1 + h2 < 360.0 {
            0.5 * (h1 + h2 + 360.0)
        } else {
            0.5 * (h1 + h2 - 360.0)
        }
    } else {
        0.5 * (h1 + h2)
    };
    let cos = |deg: f64| deg.to_radians().cos();
    let t =
        1.0 - 0.17 * cos(h_mean - 30.0) + 0.24 * cos(2.0 * h_mean) + 0.32 * cos(3.0 * h_mean + 6.0)
            - 0.20 * cos(4.0 * h_mean - 63.0);
    let d_theta = 30.0 * (-((h_mean - 275.0) / 25.0).powi(2)).exp();
    let r_c = 2.0 * (pow7(cp_mean) / (pow7(cp_mean) + pow7(25.0))).sqrt();
    let s_l = 1.0 + 0.015 * (l_mean - 50.0).powi(2) / (20.0 + (l_mean - 50.0).powi(2)).sqrt();
    let s_c = 1.0 + 0.045 * cp_mean;
    let s_h = 1.0 + 0.015 * cp_mean * t;
    let r_t = -(2.0 * d_theta).to_radians().sin() * r_c;
    let (l, c, h) = (dl / s_l, dc / s_c, dh_big / s_h);
    (l * l + c * c + h * h + r_t * c * h).sqrt()
}

/// The k-th of n shades of a hue, darker (k = 0) to lighter: CIE lightness evenly spaced over
/// [`SWEEP_LIGHTNESS`], the base's chroma kept as far as sRGB holds it at that lightness, the hue
/// turning by [`SWEEP_HUE_TURN_DEG`] across the sweep. The curves of one sweep keep their family's
/// hue, stay apart (at least [`MIN_SHADE_DELTA_E`] between neighbours up to [`SWEEP_HELD`]
/// members), none is near-black, and each has at least 3:1 contrast on a white page
/// ([`MAX_LUMINANCE_ON_WHITE`]).
pub fn shade(base: Rgb, k: usize, n: usize) -> Rgb {
    let (dark, light) = SWEEP_LIGHTNESS;
    let t = k as f64 / (n - 1).max(1) as f64;
    let lab = base.lab();
    let hue = lab.hue() + SWEEP_HUE_TURN_DEG * (t - 0.5);
    let mut l = dark + (light - dark) * t;
    loop {
        let colour = Lab::lch(l, lab.chroma(), hue).to_rgb();
        if colour.luminance() <= MAX_LUMINANCE_ON_WHITE || l <= dark {
            return colour;
        }
        // Channel rounding took the lightest shade over the contrast bound: a little darker.
        l -= 0.1;
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
    /// The size the figure prints at, when its spec or preset gave one in inches or
    /// centimetres; `None` for a size in pixels.
    pub print: Option<PrintSize>,
    /// No page colour behind the figure: the SVG and PDF draw none, the PNG has an alpha channel.
    pub transparent: bool,
    /// The typeface of all text.
    pub face: Face,
}

/// A figure's typeface: one of the embedded DejaVu families, with its slanted face for variables.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Face {
    /// DejaVu Sans and DejaVu Sans Oblique (the default, as matplotlib's).
    #[default]
    Sans,
    /// DejaVu Serif and DejaVu Serif Italic, for a paper set in a serif text face.
    Serif,
}

impl Face {
    /// The faces by name, as a scene's `font` spells them.
    pub const NAMES: &'static [(&'static str, Face)] =
        &[("sans", Face::Sans), ("serif", Face::Serif)];

    /// The face called `name`, if one is.
    pub fn named(name: &str) -> Option<Face> {
        Face::NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, f)| *f)
    }
}

/// A figure's size in a print unit, exactly as given: the SVG states it in that unit, the PNG
/// has round(size × dpi) pixels a side and the PDF page is that size in points.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrintSize {
    /// Width in `unit`.
    pub width: f64,
    /// Height in `unit`.
    pub height: f64,
    /// The unit of both.
    pub unit: PrintUnit,
}

/// A print unit of a figure's size.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PrintUnit {
    /// Inches: [`CSS_PX_PER_INCH`] CSS pixels.
    Inch,
    /// Centimetres: an inch over 2.54.
    Centimetre,
}

impl PrintUnit {
    /// CSS pixels per unit.
    pub fn css_px(self) -> f64 {
        match self {
            PrintUnit::Inch => CSS_PX_PER_INCH,
            PrintUnit::Centimetre => CSS_PX_PER_INCH / 2.54,
        }
    }

    /// The unit's symbol in SVG and CSS lengths: `in`, `cm`.
    pub fn symbol(self) -> &'static str {
        match self {
            PrintUnit::Inch => "in",
            PrintUnit::Centimetre => "cm",
        }
    }
}

impl PrintSize {
    /// Width and height in CSS pixels, unrounded.
    pub fn css_px(&self) -> (f64, f64) {
        let k = self.unit.css_px();
        (self.width * k, self.height * k)
    }
}

impl Canvas {
    /// Largest PNG drawn, in pixels: 2²⁶ (8192 × 8192). Its drawing buffer (RGBA) and the
    /// encoded rows (RGB) take 7 bytes a pixel, 470 MB at the cap.
    pub const MAX_PNG_PIXELS: u64 = 1 << 26;

    /// The PNG's width and height in pixels: each side times `png_scale`, rounded; a side of
    /// a [`PrintSize`] is taken unrounded (3.3 in at 300 dpi is 990 pixels).
    pub fn png_size(&self) -> (f64, f64) {
        let (w, h) = self
            .print
            .map_or((f64::from(self.width_px), f64::from(self.height_px)), |p| {
                p.css_px()
            });
        ((w * self.png_scale).round(), (h * self.png_scale).round())
    }

    /// The PNG's resolution in pixels per inch: `png_scale` × [`CSS_PX_PER_INCH`].
    pub fn dpi(&self) -> f64 {
        self.png_scale * CSS_PX_PER_INCH
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
    /// Reference lines, bands and notes drawn with the curves (`annotations`), in spec order.
    pub annotations: Vec<Annotation>,
}

/// One of a panel's `annotations`: something marked on the plot besides the curves, in the units
/// its axes show (θ in the x axis' unit, y as plotted).
#[derive(Debug, Clone, PartialEq)]
pub enum Annotation {
    /// A reference line across the plot area at `at` on `axis` (`{"x": v}` is vertical,
    /// `{"y": v}` horizontal), with its `label` (may be empty) at its upper or right end.
    Line {
        /// The axis whose value the line marks.
        axis: Dimension,
        /// The value.
        at: f64,
        /// Text beside the line's end.
        label: String,
    },
    /// A shaded band across the plot area from `from` to `to` on `axis` (`{"x": [a, b]}`), with
    /// its `label` (may be empty) inside its top left corner.
    Band {
        /// The axis whose interval the band covers.
        axis: Dimension,
        /// Low end.
        from: f64,
        /// High end.
        to: f64,
        /// Text inside the band.
        label: String,
    },
    /// `text` beside a dot at the data point `at` (`{"text": "…", "at": [x, y]}`).
    Note {
        /// The point (x, y).
        at: (f64, f64),
        /// The text, up and right of the point.
        text: String,
    },
}

/// An axis of a 2D panel.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Dimension {
    /// The horizontal axis.
    X,
    /// The vertical axis.
    Y,
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
    /// Multiples of π/d on a radian axis (`"ticks": "pi"`), labelled `π/4`, `3π/8`.
    Pi,
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
            annotations: Vec::new(),
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

/// Default base font size in CSS pixels.
pub const DEFAULT_FONT_PX: f64 = 14.0;

/// Extra default canvas height, in CSS pixels, of a figure with a title: room for the title
/// (1.4 em of the default 14 px font) and its spacing.
pub const DEFAULT_TITLE_BAND_PX: f64 = 40.0;

/// Font sizes relative to `Canvas::font_px`: axis labels, panel titles, the figure title.
pub const AXIS_LABEL_EM: f64 = 1.1;
/// Panel title size relative to `Canvas::font_px`.
pub const PANEL_TITLE_EM: f64 = 1.2;
/// Figure title size relative to `Canvas::font_px`.
pub const FIGURE_TITLE_EM: f64 = 1.4;

/// Default figure width in CSS pixels: 640 for one column, 480 per column otherwise.
pub fn default_width(cols: usize) -> f64 {
    if cols <= 1 {
        640.0
    } else {
        480.0 * cols as f64
    }
}

/// Default figure height in CSS pixels for `rows × cols` panels of aspect ratio `aspect` on a
/// figure `width` wide, plus [`DEFAULT_TITLE_BAND_PX`] scaled to `font_px` when `titled`;
/// rounded, not yet clamped.
pub fn default_height(
    (rows, cols): (usize, usize),
    width: f64,
    aspect: f64,
    font_px: f64,
    titled: bool,
) -> f64 {
    let title_band = if titled { title_band_px(font_px) } else { 0.0 };
    (rows as f64 * width / cols as f64 * aspect + title_band).round()
}

/// The band of a one-line figure title over base text of `font_px`: [`DEFAULT_TITLE_BAND_PX`]
/// scaled from [`DEFAULT_FONT_PX`].
pub fn title_band_px(font_px: f64) -> f64 {
    DEFAULT_TITLE_BAND_PX * font_px / DEFAULT_FONT_PX
}

/// Least size tick labels print at, in points: what journals ask of figure text.
pub const MIN_PRINT_PT: f64 = 6.0;

/// The width a figure `width` CSS pixels wide with `cols` columns of panels is placed at in a
/// paper when it is sized in pixels, in CSS pixels: one column (3.3 in) for one column of panels
/// no wider than the default, the page's text width (7 in) for more panels or a wider one.
pub fn placed_width_px(width: f64, cols: usize) -> f64 {
    let column = cols <= 1 && width <= default_width(1);
    let inches = if column { 3.3 } else { 7.0 };
    inches * CSS_PX_PER_INCH
}

/// The size in points that base text of `font_px` prints at on `canvas`: at its print size
/// when it has one, else with the canvas placed at [`placed_width_px`] of its `cols` (shrunk
/// to fit, never enlarged).
pub fn printed_pt(canvas: &Canvas, cols: usize) -> f64 {
    let scale = match canvas.print {
        Some(_) => 1.0,
        None => {
            let width = f64::from(canvas.width_px);
            (placed_width_px(width, cols) / width).min(1.0)
        }
    };
    canvas.font_px * scale * 72.0 / CSS_PX_PER_INCH
}

/// The default base text size of a canvas `width` CSS pixels wide with `cols` columns of panels:
/// [`DEFAULT_FONT_PX`], or more on a canvas wider than [`placed_width_px`], so that its tick
/// labels print at [`MIN_PRINT_PT`] when placed there.
pub fn default_font_px(width: f64, cols: usize) -> f64 {
    let least = MIN_PRINT_PT * CSS_PX_PER_INCH / 72.0 * width / placed_width_px(width, cols);
    DEFAULT_FONT_PX.max(least)
}

/// A paper's figure size in one word: the width of a column or of a page, 8 pt text, 300 dpi.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Preset {
    /// One column of a two-column paper: 3.3 in wide.
    PaperColumn,
    /// A page's text width: 7 in wide.
    PaperPage,
}

impl Preset {
    /// The presets by name, as a spec's `preset` and `render --preset` spell them.
    pub const NAMES: &'static [(&'static str, Preset)] = &[
        ("paper-column", Preset::PaperColumn),
        ("paper-page", Preset::PaperPage),
    ];
    /// Text size of every preset, in points: a journal's caption size.
    pub const FONT_PT: f64 = 8.0;
    /// PNG resolution of every preset, in pixels per inch: print resolution.
    pub const DPI: f64 = 300.0;
    /// Least height of a panel, in inches: at 8 pt, a panel title, the x tick labels and the x
    /// label take about 0.55 in, and a legend that fits inside no plot a band below the row;
    /// at 2.2 in every catalogue figure keeps its plots at page width (a test renders them).
    pub const MIN_PANEL_HEIGHT_IN: f64 = 2.2;

    /// Most panels a paper-page figure sets side by side: at 7 in, four panels of 1.75 in each
    /// keep their tick labels apart at 8 pt.
    pub const MAX_PAGE_COLUMNS: usize = 4;
    /// Tallest a paper-column figure grows by stacking its panels before it takes a second column
    /// of panels, in inches: about a page's text height.
    pub const MAX_COLUMN_HEIGHT_IN: f64 = 9.0;

    /// The panel grid of a figure of `panels` panels laid out `rows × cols` by its spec, at this
    /// preset. Paper-column stacks the panels in one column (row by row, in order), or in two
    /// when one column would be taller than [`Preset::MAX_COLUMN_HEIGHT_IN`] at
    /// [`Preset::MIN_PANEL_HEIGHT_IN`] a panel; paper-page keeps the spec's grid when it has at
    /// most [`Preset::MAX_PAGE_COLUMNS`] columns, else reflows to that many. A grid that already
    /// fits is returned as given.
    pub fn grid(self, panels: usize, (rows, cols): (usize, usize)) -> (usize, usize) {
        let panels = panels.max(1);
        let most = match self {
            Preset::PaperColumn => {
                let one_column = panels as f64 * Preset::MIN_PANEL_HEIGHT_IN;
                if one_column <= Preset::MAX_COLUMN_HEIGHT_IN {
                    1
                } else {
                    2
                }
            }
            Preset::PaperPage => Preset::MAX_PAGE_COLUMNS,
        };
        if cols <= most {
            (rows, cols)
        } else {
            (panels.div_ceil(most), most)
        }
    }

    /// The preset called `name`, if one is.
    pub fn named(name: &str) -> Option<Preset> {
        Preset::NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, p)| *p)
    }

    /// The figure's width in inches.
    pub fn width_in(self) -> f64 {
        match self {
            Preset::PaperColumn => 3.3,
            Preset::PaperPage => 7.0,
        }
    }

    /// The canvas of a figure at this preset: [`Preset::canvas_at`] the preset's width.
    pub fn canvas(self, grid: (usize, usize), aspect: f64, titles: &Titles) -> Canvas {
        self.canvas_at(self.width_in() * CSS_PX_PER_INCH, grid, aspect, titles)
    }

    /// The canvas of a `rows × cols` figure `width` CSS pixels wide with the preset's text: each
    /// row of panels `aspect` times as tall as a panel is wide but at least
    /// [`Preset::MIN_PANEL_HEIGHT_IN`], plus the lines its panel titles wrap to beyond the
    /// first, plus the figure title's band ([`Titles::extra_height`]), rounded up to 0.01 in;
    /// [`Preset::FONT_PT`] text and [`Preset::DPI`]; it prints at that size.
    pub fn canvas_at(
        self,
        width: f64,
        (rows, cols): (usize, usize),
        aspect: f64,
        titles: &Titles,
    ) -> Canvas {
        let font_px = Preset::FONT_PT * CSS_PX_PER_INCH / 72.0;
        let cols = cols.max(1);
        let panel =
            (width / cols as f64 * aspect).max(Preset::MIN_PANEL_HEIGHT_IN * CSS_PX_PER_INCH);
        let height = rows as f64 * panel + titles.extra_height(width, cols, font_px);
        // To a hundredth of an inch: a size a caption can state.
        let height = (height / CSS_PX_PER_INCH * 100.0 - 1e-9).ceil() / 100.0 * CSS_PX_PER_INCH;
        Canvas {
            width_px: width.round() as u32,
            height_px: height.round() as u32,
            png_scale: Preset::DPI / CSS_PX_PER_INCH,
            font_px,
            print: Some(PrintSize {
                width: width / CSS_PX_PER_INCH,
                height: height / CSS_PX_PER_INCH,
                unit: PrintUnit::Inch,
            }),
            transparent: false,
            face: Face::Sans,
        }
    }
}

/// CSS pixels per inch, as SVG and CSS define them.
pub const CSS_PX_PER_INCH: f64 = 96.0;

/// The titles a preset's canvas makes room for: the figure's, and each panel's by row.
#[derive(Debug, Clone, Default)]
pub struct Titles {
    /// The figure title (empty for none).
    pub figure: String,
    /// Each panel's title, in grid order.
    pub panels: Vec<String>,
}

impl Titles {
    /// Average advance of a title's glyph, in ems: DejaVu Sans's is about 0.55 em for mixed text;
    /// taken on the wide side so that the estimate of wrapped lines is too many, not too few.
    const GLYPH_EM: f64 = 0.6;
    /// Height of a title line, in the title's ems, with the gap between lines.
    const LINE_EM: f64 = 1.25;

    /// The lines `text` wraps to at `em` base text sizes of `font_px` across `width` CSS pixels
    /// (less one base size of padding each side); 0 for no text. An estimate from
    /// [`Titles::GLYPH_EM`]: markup characters (`_ ^ { } $ \`) are not counted.
    pub fn lines(text: &str, em: f64, font_px: f64, width: f64) -> usize {
        let glyphs = text.chars().filter(|c| !"_^{}$\\".contains(*c)).count();
        if glyphs == 0 {
            return 0;
        }
        let room = (width - 2.0 * font_px).max(font_px);
        ((glyphs as f64 * Titles::GLYPH_EM * em * font_px / room).ceil() as usize).max(1)
    }

    /// Height the titles take beyond what [`Preset::MIN_PANEL_HEIGHT_IN`] holds (one line of
    /// panel title) on a figure `width` CSS pixels wide in `cols` columns with `font_px` text:
    /// [`DEFAULT_TITLE_BAND_PX`] scaled to the text for the figure title's first line and
    /// a line per further line; a line per further line of each row's longest panel title.
    pub fn extra_height(&self, width: f64, cols: usize, font_px: f64) -> f64 {
        let line = |em: f64| Titles::LINE_EM * em * font_px;
        let figure = match Titles::lines(&self.figure, FIGURE_TITLE_EM, font_px, width) {
            0 => 0.0,
            n => title_band_px(font_px) + (n - 1) as f64 * line(FIGURE_TITLE_EM),
        };
        let cell = width / cols.max(1) as f64;
        let panels: usize = self
            .panels
            .chunks(cols.max(1))
            .map(|row| {
                row.iter()
                    .map(|t| Titles::lines(t, PANEL_TITLE_EM, font_px, cell).saturating_sub(1))
                    .max()
                    .unwrap_or(0)
            })
            .sum();
        figure + panels as f64 * line(PANEL_TITLE_EM)
    }
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

    /// Sharma, Wu and Dalal 2005, Table 1: pairs 1, 7, 17 and 25 of the CIEDE2000 test data.
    #[test]
    fn delta_e00_matches_sharmas_test_data() {
        let lab = |l, a, b| Lab { l, a, b };
        for (x, y, expected) in [
            (
                lab(50.0, 2.6772, -79.7751),
                lab(50.0, 0.0, -82.7485),
                2.0425,
            ),
            (lab(50.0, 0.0, 0.0), lab(50.0, -1.0, 2.0), 2.3669),
            (lab(50.0, 2.5, 0.0), lab(73.0, 25.0, -18.0), 27.1492),
            (
                lab(60.2574, -34.0099, 36.2677),
                lab(60.4626, -34.1751, 39.4387),
                1.2644,
            ),
        ] {
            let got = delta_e00(x, y);
            assert!((got - expected).abs() < 1e-4, "{x:?} {y:?}: {got}");
            assert!((delta_e00(y, x) - got).abs() < 1e-9);
        }
        let c = Rgb::from_hex(0x3C96DF);
        assert!(
            delta_e00(
                c.lab(),
                Lab::lch(c.lab().l, c.lab().chroma(), c.lab().hue())
                    .to_rgb()
                    .lab()
            ) < 0.5
        );
    }

    /// The least CIEDE2000 difference of neighbouring shades of an n-member sweep of `base`.
    fn least_neighbour_delta(base: Rgb, n: usize) -> f64 {
        (0..n - 1)
            .map(|k| delta_e00(shade(base, k, n).lab(), shade(base, k + 1, n).lab()))
            .fold(f64::INFINITY, f64::min)
    }

    #[test]
    fn sweep_shades_are_apart_even_and_never_near_black() {
        // Measured (least neighbour ΔE00 over the seven families): n = 3: ≥ 13.9, n = 4: ≥ 9.0,
        // n = 5: ≥ 6.6, no shade below L* = 30 and the darkest keeping its chroma. Before (mixed
        // towards black down to L* = 27, the darkest near-black): n = 3: 14.6, n = 4: 9.4, n = 5: 6.8.
        let mut report = Vec::new();
        for family in Family::ALL {
            let base = Rgb::from_hex(family.colour());
            for n in 2..=SWEEP_HELD {
                let least = least_neighbour_delta(base, n);
                assert!(least >= MIN_SHADE_DELTA_E, "{family:?} n = {n}: {least:.1}");
            }
            report.push(format!(
                "{family:?}: {:.1} {:.1} {:.1}",
                least_neighbour_delta(base, 3),
                least_neighbour_delta(base, 4),
                least_neighbour_delta(base, 5)
            ));
            assert!(least_neighbour_delta(base, 4) >= 8.0, "{family:?}");
            for n in 2..=12 {
                let lightness: Vec<f64> = (0..n).map(|k| shade(base, k, n).lab().l).collect();
                // No near-black: the darkest keeps the floor and its chroma.
                assert!(
                    lightness[0] >= SWEEP_LIGHTNESS.0 - 0.5,
                    "{family:?} {lightness:?}"
                );
                assert!(shade(base, 0, n).lab().chroma() >= 0.6 * base.lab().chroma().min(40.0));
                // Even steps, to channel rounding.
                let step = (lightness[n - 1] - lightness[0]) / (n - 1) as f64;
                for pair in lightness.windows(2) {
                    assert!(
                        (pair[1] - pair[0] - step).abs() < 0.6,
                        "{family:?} n = {n}: {lightness:?}"
                    );
                }
            }
        }
        eprintln!("{}", report.join("\n"));
    }

    #[test]
    fn family_colours_stay_apart_in_normal_vision_and_under_deuteranopia() {
        // Before (the notebook's Solarized hues), under deuteranopia: TR–SGD 1.6, ABC–Beckmann 3.3,
        // TR–Phong 6.2, SGD–Phong 7.8 ΔE00. Now every pair is at least 9.
        let families = Family::ALL;
        for (i, a) in families.iter().enumerate() {
            for b in &families[i + 1..] {
                let (x, y) = (Rgb::from_hex(a.colour()), Rgb::from_hex(b.colour()));
                let normal = delta_e00(x.lab(), y.lab());
                let deutan = delta_e00(x.deuteranopia().lab(), y.deuteranopia().lab());
                assert!(normal >= 12.0, "{a:?}–{b:?}: {normal:.1}");
                assert!(deutan >= 8.0, "{a:?}–{b:?} under deuteranopia: {deutan:.1}");
            }
            let c = Rgb::from_hex(a.colour());
            assert!(c.contrast(Rgb::WHITE) >= 3.0, "{a:?}");
        }
    }

    #[test]
    fn presets_are_a_papers_width_8_pt_and_300_dpi_with_room_for_each_panel_row() {
        let untitled = Titles::default();
        let column =
            Preset::named("paper-column")
                .unwrap()
                .canvas((1, 1), DEFAULT_ASPECT_RATIO, &untitled);
        assert_eq!(column.width_px, 317); // 3.3 in at 96 px/in, rounded
        assert!((column.font_px - 8.0 * 96.0 / 72.0).abs() < 1e-12);
        assert!((column.png_scale * 96.0 - 300.0).abs() < 1e-12);
        // 3.3 in × 0.618 = 2.04 in is under the least panel height.
        assert_eq!(
            column.height_px,
            (Preset::MIN_PANEL_HEIGHT_IN * 96.0).round() as u32
        );
        let tall = Preset::PaperColumn.canvas((1, 1), 1.0, &untitled);
        assert_eq!(tall.height_px, 317);
        let titled = Titles {
            figure: "A short title".into(),
            panels: vec!["α_b = 0.2".into(); 6],
        };
        let page = Preset::PaperPage.canvas((2, 3), DEFAULT_ASPECT_RATIO, &titled);
        assert_eq!(page.width_px, 672);
        // Panels 2.33 in wide would be 1.44 in tall: each row gets the least panel height, and the
        // title its band at 8 pt.
        let band = title_band_px(page.font_px);
        assert_eq!(
            page.height_px,
            (2.0 * Preset::MIN_PANEL_HEIGHT_IN * 96.0 + band).round() as u32
        );
        assert_eq!(Preset::named("paper"), None);
    }

    #[test]
    fn a_long_title_wraps_and_its_lines_get_room_at_a_presets_width() {
        let font_px = Preset::FONT_PT * CSS_PX_PER_INCH / 72.0;
        assert_eq!(Titles::lines("", FIGURE_TITLE_EM, font_px, 317.0), 0);
        assert_eq!(
            Titles::lines("Beckmann", FIGURE_TITLE_EM, font_px, 317.0),
            1
        );
        // 83 glyphs of 0.6 × 1.4 × 10.7 px on 296 px: three lines.
        let long = "Torrance–Sparrow peak-fitted to Phong (thick); dashed: the notebook's α_{ts} matched by hand";
        assert_eq!(Titles::lines(long, FIGURE_TITLE_EM, font_px, 317.0), 3);
        let short = Titles {
            figure: "Beckmann".into(),
            panels: vec![],
        };
        let wrapped = Titles {
            figure: long.into(),
            panels: vec![],
        };
        let line = 1.25 * FIGURE_TITLE_EM * font_px;
        let (a, b) = (
            short.extra_height(317.0, 1, font_px),
            wrapped.extra_height(317.0, 1, font_px),
        );
        assert!((b - a - 2.0 * line).abs() < 1e-9, "{a} {b}");
    }

    #[test]
    fn column_figures_stack_their_panels_and_page_figures_keep_up_to_four_a_row() {
        let column = Preset::PaperColumn;
        assert_eq!(column.grid(2, (1, 2)), (2, 1));
        assert_eq!(
            column.grid(4, (2, 2)),
            (4, 1),
            "four panels of 2.2 in fit 9 in"
        );
        assert_eq!(column.grid(6, (2, 3)), (3, 2), "six would be 13.2 in tall");
        assert_eq!(column.grid(8, (2, 4)), (4, 2));
        assert_eq!(column.grid(1, (1, 1)), (1, 1));
        let page = Preset::PaperPage;
        assert_eq!(page.grid(6, (2, 3)), (2, 3));
        assert_eq!(page.grid(8, (2, 4)), (2, 4));
        assert_eq!(page.grid(6, (1, 6)), (2, 4));
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
