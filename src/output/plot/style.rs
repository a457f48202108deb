//! Sizes, colours and the font of one render: text sizes, line widths, dash patterns and dot
//! radii in device pixels, scaled by the device scale and the base font size.

use std::sync::OnceLock;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::{FontFamily, FontStyle, register_font};

use super::theme::{Palette, Pattern};
use super::{PlotError, draw_err};
use crate::spec::look::{Face, Mark, Rgb};

/// The family name each embedded typeface is registered under, which the SVG names first, and
/// the generic family the SVG names after it.
pub(super) fn family(face: Face) -> (&'static str, &'static str) {
    match face {
        Face::Sans => ("DejaVu Sans", "sans-serif"),
        Face::Serif => ("DejaVu Serif", "serif"),
    }
}
/// Em of the face per plotters text size: ab_glyph scales the DejaVu faces so that ascender −
/// descender (1901 + 483 font units, in all four faces) spans the size, and one em is 2048 units.
pub(super) const EM_PER_SIZE: f64 = 2048.0 / 2384.0;

/// Default curve width in CSS pixels (multiplied by `Style::width`).
pub(super) const BASE_LINE_PX: f64 = 1.5;
/// Dash and gap lengths of dashed curves, in multiples of the curve's width.
pub(super) const DASHED: (f64, f64) = (4.0, 2.5);
/// Dot and gap lengths of dotted curves, in multiples of the curve's width.
pub(super) const DOTTED: (f64, f64) = (1.0, 1.5);
/// Dash, gap, dot and gap lengths of dash-dot curves, in multiples of the curve's width.
pub(super) const DASH_DOT: [f64; 4] = [4.0, 1.5, 1.0, 1.5];
/// Radius of the dots of a scatter (`Mark::Points`), in CSS pixels.
const POINT_RADIUS_PX: f64 = 1.5;
/// Radius of the dots on a line (`Mark::LinePoints`) and of legend dots, in CSS pixels.
pub(super) const MARKER_RADIUS_PX: f64 = 3.0;

/// Opacity of surface meshes: lines and mesh cells behind them stay faintly visible.
pub(super) const SURFACE_OPACITY: f64 = 0.8;
/// Brightness of a surface's mesh lines relative to its colour.
pub(super) const MESH_DARKEN: f64 = 0.7;

/// Registers the embedded faces once per process — DejaVu Sans and its oblique, DejaVu Serif and
/// its italic (registered as the oblique style, which sets variables: see `mathtext`) — each also
/// under its generic family name; later calls return the first outcome.
pub(super) fn ensure_font() -> Result<(), PlotError> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        let faces = [
            (Face::Sans, dejavu::sans::regular(), dejavu::sans::oblique()),
            (
                Face::Serif,
                dejavu::serif::regular(),
                dejavu::serif::italic(),
            ),
        ];
        faces.into_iter().all(|(face, upright, slanted)| {
            let (name, generic) = family(face);
            [name, generic].into_iter().all(|n| {
                register_font(n, FontStyle::Normal, upright).is_ok()
                    && register_font(n, FontStyle::Oblique, slanted).is_ok()
            })
        })
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
    /// Page colours.
    pub(super) palette: &'static Palette,
    /// The registered family name of the figure's typeface ([`family`]).
    pub(super) family: &'static str,
    /// What the drawing places, recorded for the figure lint; `None` when not kept.
    pub(super) trace: super::lint::Recorder,
    /// Multiplier of curve widths and dot radii: the base text size over the default
    /// ([`Metrics::weight_of`]).
    pub(super) weight: f64,
}

impl Metrics {
    /// The weight of curves and dots next to text of `font_px` CSS pixels: 1 up to the default
    /// text size, in proportion above it, so that on a canvas whose text was enlarged to print
    /// at a legible size when the figure is placed smaller, its curves keep their weight too.
    pub(super) fn weight_of(font_px: f64) -> f64 {
        (font_px / crate::spec::look::DEFAULT_FONT_PX).max(1.0)
    }
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
        TextStyle::from((FontFamily::Name(self.family), units * self.unit).into_font())
            .color(&self.palette.ink)
    }
    /// Stroke of a curve drawn `multiplier` times the default width, at the figure's weight.
    pub(super) fn curve_style(&self, colour: Rgb, multiplier: f64) -> ShapeStyle {
        let width = (BASE_LINE_PX * multiplier.max(0.0) * self.weight * self.k)
            .round()
            .max(1.0);
        ShapeStyle {
            color: RGBColor(colour.0, colour.1, colour.2).to_rgba(),
            filled: false,
            stroke_width: width as u32,
        }
    }
    /// Radius in whole device pixels of the dots of a series drawn with `mark`: small for a
    /// scatter, larger on a line.
    pub(super) fn mark_dot(&self, mark: Mark) -> u32 {
        self.dot(if mark == Mark::Points {
            POINT_RADIUS_PX
        } else {
            MARKER_RADIUS_PX
        })
    }
    /// Radius in whole device pixels of a dot of `radius_px` CSS pixels at the figure's weight.
    pub(super) fn dot(&self, radius_px: f64) -> u32 {
        (radius_px * self.weight * self.k).round().max(1.0) as u32
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

/// On and off lengths in whole device pixels, starting with "on", for `pattern` drawn with
/// `style`; `None` when solid.
pub(super) fn dash_lengths(pattern: Pattern, style: &ShapeStyle) -> Option<Vec<f32>> {
    let width = f64::from(style.stroke_width);
    let lengths: &[f64] = match pattern {
        Pattern::Solid => return None,
        Pattern::Dashed => &[DASHED.0, DASHED.1],
        Pattern::Dotted => &[DOTTED.0, DOTTED.1],
        Pattern::DashDot => &DASH_DOT,
    };
    // Whole pixels, truncated as plotters sizes its own dashes.
    Some(lengths.iter().map(|l| (l * width) as i32 as f32).collect())
}

/// Strokes the polyline `path` (pixels of `area`) in `style` and `pattern`: one path when
/// solid, one per dash otherwise (see [`dashes`]).
pub(super) fn stroke<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    path: Vec<(i32, i32)>,
    style: ShapeStyle,
    pattern: Pattern,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let Some(lengths) = dash_lengths(pattern, &style) else {
        return area.draw(&PathElement::new(path, style)).map_err(draw_err);
    };
    // Walked in backend pixels, as plotters walks its dashes: the f32 steps round differently
    // at other offsets.
    let (x0, y0) = area.get_base_pixel();
    let backend: Vec<(i32, i32)> = path.iter().map(|&(x, y)| (x + x0, y + y0)).collect();
    dashes(&backend, &lengths).into_iter().try_for_each(|dash| {
        let dash: Vec<(i32, i32)> = dash.into_iter().map(|(x, y)| (x - x0, y - y0)).collect();
        area.draw(&PathElement::new(dash, style)).map_err(draw_err)
    })
}

/// The "on" stretches of the polyline `points` walked with the repeating on/off `lengths`
/// (device pixels, starting "on"): plotters' `DashedPathElement` walk, the same f32 steps and
/// rounding, so that two lengths give exactly its dashes, for any number of lengths.
pub(super) fn dashes(points: &[(i32, i32)], lengths: &[f32]) -> Vec<Vec<(i32, i32)>> {
    let to_f = |&(x, y): &(i32, i32)| (x as f32, y as f32);
    let to_i = |(x, y): (f32, f32)| (x.round() as i32, y.round() as i32);
    let mut out = Vec::new();
    let Some(first) = points.first() else {
        return out;
    };
    if lengths.first().is_none_or(|&l| l <= 0.0) {
        return out;
    }
    let mut start = to_f(first);
    let (mut phase, mut dist) = (0, 0.0f32);
    let mut queue = vec![to_i(start)];
    for point in &points[1..] {
        let end = to_f(point);
        while start != end {
            let (dx, dy) = (end.0 - start.0, end.1 - start.1);
            let d = dx.hypot(dy);
            let length = lengths[phase];
            let left = length - dist;
            if left < d {
                let t = left / d;
                start = (start.0 + dx * t, start.1 + dy * t);
                dist += left;
            } else {
                start = end;
                dist += d;
            }
            let on = phase % 2 == 0;
            if on {
                queue.push(to_i(start));
            }
            if length <= dist {
                if on {
                    out.push(std::mem::take(&mut queue));
                } else {
                    queue.push(to_i(start));
                }
                dist = 0.0;
                phase = (phase + 1) % lengths.len();
            }
        }
    }
    if queue.len() > 1 {
        out.push(queue);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use plotters::element::DashedPathElement;

    #[test]
    fn dashes_repeat_their_lengths_along_the_path() {
        let line = [(0, 0), (100, 0)];
        let two = dashes(&line, &[10.0, 5.0]);
        assert_eq!(two.len(), 7);
        assert_eq!(two[0], [(0, 0), (10, 0)]);
        assert_eq!(two[1], [(15, 0), (25, 0)]);
        let four = dashes(&line, &[10.0, 5.0, 2.0, 5.0]);
        assert_eq!(
            four[..3],
            [
                vec![(0, 0), (10, 0)],
                vec![(15, 0), (17, 0)],
                vec![(22, 0), (32, 0)]
            ]
        );
        // Corners are kept inside a dash.
        let bent = dashes(&[(0, 0), (4, 0), (4, 4)], &[6.0, 1.0]);
        assert_eq!(bent[0], [(0, 0), (4, 0), (4, 2)]);
        assert!(dashes(&line, &[0.0, 1.0]).is_empty());
    }

    #[test]
    fn two_lengths_draw_exactly_plotters_dashes() {
        // A wavy polyline with vertices a pixel or two apart, like a sampled curve, drawn on
        // an area offset from the backend's origin (the walk is not translation invariant in f32).
        let path: Vec<(i32, i32)> = (0..400)
            .map(|i| {
                let t = f64::from(i) * 0.37;
                let y = 100.0 + 60.0 * (t * 0.05).sin() + 3.0 * (t * 0.3).cos();
                ((t * 1.3) as i32, y as i32)
            })
            .collect();
        let style = ShapeStyle {
            color: BLACK.to_rgba(),
            filled: false,
            stroke_width: 3,
        };
        for (pattern, (on, off)) in [(Pattern::Dashed, DASHED), (Pattern::Dotted, DOTTED)] {
            let draw = |ours: bool| {
                let mut document = String::new();
                {
                    let root =
                        SVGBackend::with_string(&mut document, (700, 300)).into_drawing_area();
                    let area = root.margin(37, 0, 91, 0);
                    if ours {
                        stroke(&area, path.clone(), style, pattern).unwrap();
                    } else {
                        let (on, off) = (on * 3.0, off * 3.0);
                        let dashed = DashedPathElement::new(path.clone(), on, off, style);
                        area.draw(&dashed).unwrap();
                    }
                }
                document
            };
            assert!(draw(true) == draw(false), "{pattern:?}");
        }
    }
}
