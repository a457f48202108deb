//! A 2D panel's annotations ([`Annotation`]): bands and reference lines drawn under the curves,
//! their labels and the notes at data points over them. Values are in the units the axes show;
//! what lies outside the displayed ranges is clipped to the plot area (a note outside it is not
//! drawn).

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axis::Axis;
use super::style::{Metrics, stroke};
use super::theme::Pattern;
use super::{PlotError, draw_err, mathtext};
use crate::spec::look::{Annotation, Dimension, Scale};

/// Opacity of a band's fill of the page's ink colour: light enough that curves read through it.
const BAND_OPACITY: f64 = 0.08;
/// Text size of labels and notes, relative to the tick labels.
const TEXT_EM: f64 = 0.9;
/// Gap between a line, band edge or point and its text, in base text sizes.
const GAP_EM: f64 = 0.3;
/// Radius of a note's dot, in CSS pixels.
const DOT_PX: f64 = 2.5;

/// How display coordinates map to pixels of the plot area: the axes and scales of the panel and
/// the plot area's size in device pixels.
pub(super) struct Placement<'a> {
    /// The x axis (display units).
    pub(super) x: &'a Axis,
    /// The y axis (display units).
    pub(super) y: &'a Axis,
    /// The scales of x and y (log axes show log₁₀ of the value).
    pub(super) scales: (Scale, Scale),
    /// Width and height of the plot area in device pixels.
    pub(super) size: (u32, u32),
}

impl Placement<'_> {
    /// The plot-area pixel of value `v` along `dimension`; `None` when it cannot be shown (≤ 0
    /// on a log axis).
    fn pixel(&self, dimension: Dimension, v: f64) -> Option<f64> {
        let (axis, scale, length) = match dimension {
            Dimension::X => (self.x, self.scales.0, f64::from(self.size.0)),
            Dimension::Y => (self.y, self.scales.1, f64::from(self.size.1)),
        };
        let t = (scale.display(v)? - axis.lo) / (axis.hi - axis.lo);
        Some(match dimension {
            Dimension::X => t * length,
            Dimension::Y => (1.0 - t) * length,
        })
    }

    /// The plot-area pixel of a line at `v` along `dimension`, when it falls inside the plot.
    fn line(&self, dimension: Dimension, v: f64) -> Option<f64> {
        let length = f64::from(match dimension {
            Dimension::X => self.size.0,
            Dimension::Y => self.size.1,
        });
        self.pixel(dimension, v)
            .filter(|p| (0.0..=length).contains(p))
    }

    /// The pixel span `[a, b]` along `dimension` covers, clamped to the plot area; `None` when
    /// it lies wholly outside.
    fn span(&self, dimension: Dimension, a: f64, b: f64) -> Option<(f64, f64)> {
        let length = f64::from(match dimension {
            Dimension::X => self.size.0,
            Dimension::Y => self.size.1,
        });
        let (p, q) = (self.pixel(dimension, a)?, self.pixel(dimension, b)?);
        let (lo, hi) = (p.min(q).max(0.0), p.max(q).min(length));
        (lo <= hi).then_some((lo, hi))
    }
}

/// Which part of the annotations a call draws: what goes under the curves or over them.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Layer {
    /// Bands and reference lines.
    Under,
    /// Labels and notes.
    Over,
}

/// Draws the `layer` of `annotations` on `plot`: under the curves, the bands and the dashed
/// reference lines; over them, a vertical line's label right of its top end, a horizontal line's
/// above its right end, a band's inside its top left corner, and each note up and right of a dot
/// at its point.
pub(super) fn draw<DB: DrawingBackend>(
    plot: &DrawingArea<DB, Shift>,
    annotations: &[Annotation],
    place: &Placement,
    layer: Layer,
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let (w, h) = (f64::from(place.size.0), f64::from(place.size.1));
    let whole = |x: f64, y: f64| (x.round() as i32, y.round() as i32);
    let gap = GAP_EM * m.unit;
    let text = |anchor: (HPos, VPos)| m.font(TEXT_EM).pos(Pos::new(anchor.0, anchor.1));
    for annotation in annotations {
        match (layer, annotation) {
            (Layer::Under, &Annotation::Band { axis, from, to, .. }) => {
                let Some((lo, hi)) = place.span(axis, from, to) else {
                    continue;
                };
                let [a, b] = match axis {
                    Dimension::X => [whole(lo, 0.0), whole(hi, h)],
                    Dimension::Y => [whole(0.0, lo), whole(w, hi)],
                };
                let fill = m.palette.ink.mix(BAND_OPACITY).filled();
                plot.draw(&Rectangle::new([a, b], fill)).map_err(draw_err)?;
            }
            (Layer::Under, &Annotation::Line { axis, at, .. }) => {
                let Some(p) = place.line(axis, at) else {
                    continue;
                };
                let path = match axis {
                    Dimension::X => vec![whole(p, 0.0), whole(p, h)],
                    Dimension::Y => vec![whole(0.0, p), whole(w, p)],
                };
                stroke(plot, path, m.line(m.palette.frame), Pattern::Dashed)?;
            }
            (Layer::Over, Annotation::Line { axis, at, label }) if !label.is_empty() => {
                let Some(p) = place.line(*axis, *at) else {
                    continue;
                };
                let (at, anchor) = match axis {
                    Dimension::X => ((p + gap, gap), (HPos::Left, VPos::Top)),
                    Dimension::Y => ((w - gap, p - gap), (HPos::Right, VPos::Bottom)),
                };
                mathtext::draw(plot, label, &text(anchor), at, m)?;
            }
            (
                Layer::Over,
                Annotation::Band {
                    axis,
                    from,
                    to,
                    label,
                },
            ) if !label.is_empty() => {
                let Some((lo, _)) = place.span(*axis, *from, *to) else {
                    continue;
                };
                let at = match axis {
                    Dimension::X => (lo + gap, gap),
                    Dimension::Y => (gap, lo + gap),
                };
                mathtext::draw(plot, label, &text((HPos::Left, VPos::Top)), at, m)?;
            }
            (
                Layer::Over,
                Annotation::Note {
                    at: (x, y),
                    text: note,
                },
            ) => {
                let (Some(px), Some(py)) =
                    (place.pixel(Dimension::X, *x), place.pixel(Dimension::Y, *y))
                else {
                    continue;
                };
                if !(0.0..=w).contains(&px) || !(0.0..=h).contains(&py) {
                    continue;
                }
                let dot = Circle::new(whole(px, py), m.dot(DOT_PX), m.palette.ink.filled());
                plot.draw(&dot).map_err(draw_err)?;
                let anchor = text((HPos::Left, VPos::Bottom));
                mathtext::draw(plot, note, &anchor, (px + gap, py - gap), m)?;
            }
            _ => {}
        }
    }
    Ok(())
}
