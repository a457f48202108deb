//! The legend: one entry per labelled series (a sample of its line, dot, bar or surface patch
//! and its label) in a translucent box placed where it hides the least of what is drawn.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::clip::{Clipped, clip};
use super::style::{MARKER_RADIUS_PX, Metrics, SURFACE_OPACITY, mesh_colour, stroke};
use super::theme::Look;
use super::{PlotError, draw_err, outline};
use crate::series::{Mark, Series};

/// Number of heights tried for the legend box, from the top to the bottom of the plot area.
pub(super) const LEGEND_HEIGHTS: i32 = 5;
/// Legend background opacity: curves under the box stay faintly visible.
pub(super) const LEGEND_OPACITY: f64 = 0.85;

/// What a legend entry shows next to its label.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Sample {
    /// A short stretch of the line in its dash pattern.
    Line,
    /// A dot.
    Dot,
    /// A line with a dot in its middle.
    LineDot,
    /// A small filled box (bars).
    Bar,
    /// A translucent box with a mesh-coloured border (surfaces).
    Patch,
}

impl Sample {
    /// The sample for a 2D series drawn with `mark`.
    pub(super) fn of(mark: Mark) -> Sample {
        match mark {
            Mark::Line => Sample::Line,
            Mark::Points => Sample::Dot,
            Mark::LinePoints => Sample::LineDot,
            Mark::Bars => Sample::Bar,
        }
    }
}

/// What a panel has drawn, as polylines in the legend's area pixels, for the legend to avoid.
#[derive(Default)]
pub(super) struct Covered(pub(super) Vec<Vec<(f64, f64)>>);

impl Covered {
    /// Records the polyline `path` (whole pixels).
    pub(super) fn add(&mut self, path: &[(i32, i32)]) {
        self.0.push(
            path.iter()
                .map(|&(x, y)| (f64::from(x), f64::from(y)))
                .collect(),
        );
    }
}

/// Padding, sample length, gap before the label and row height of the legend box, in device
/// pixels.
fn legend_spacing(m: &Metrics) -> (u32, u32, u32, u32) {
    (m.px(0.5), m.px(2.2), m.px(0.5), m.px(1.35))
}

/// Distance between the legend box and the edge of its area, in device pixels.
pub(super) fn legend_inset(m: &Metrics) -> i32 {
    m.px(0.6) as i32
}

/// Width and height in device pixels of the legend box of `entries`; `None` when no entry has
/// a label (no legend is drawn).
pub(super) fn legend_size<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    entries: &[(&Series, Look, Sample)],
    font: &TextStyle,
    m: &Metrics,
) -> Result<Option<(i32, i32)>, PlotError>
where
    DB::ErrorType: 'static,
{
    let (pad, sample, gap, row) = legend_spacing(m);
    let mut rows = 0;
    let mut text_w = 0;
    for (s, _, _) in entries.iter().filter(|(s, _, _)| !s.label.is_empty()) {
        text_w = text_w.max(area.estimate_text_size(&s.label, font).map_err(draw_err)?.0);
        rows += 1;
    }
    if rows == 0 {
        return Ok(None);
    }
    let box_w = (2 * pad + sample + gap + text_w) as i32;
    let box_h = (2 * pad + row * rows) as i32;
    Ok(Some((box_w, box_h)))
}

/// Draws the legend inside `plot` where it hides the least of what is drawn.
///
/// `covered` are the drawn curves, dots and bars in plot-area pixels. Series with an empty
/// label get no entry.
pub(super) fn draw_legend<DB: DrawingBackend>(
    plot: &DrawingArea<DB, Shift>,
    entries: &[(&Series, Look, Sample)],
    covered: &[Vec<(f64, f64)>],
    font: &TextStyle,
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let Some((box_w, box_h)) = legend_size(plot, entries, font, m)? else {
        return Ok(());
    };
    let entries: Vec<&(&Series, Look, Sample)> = entries
        .iter()
        .filter(|(s, _, _)| !s.label.is_empty())
        .collect();
    let (pad, sample, gap, row) = legend_spacing(m);
    let (pw, ph) = plot.dim_in_pixel();
    let (x0, y0) = legend_position(
        (pw as i32, ph as i32),
        (box_w, box_h),
        legend_inset(m),
        covered,
    );

    let background = m.palette.background.mix(LEGEND_OPACITY).filled();
    let bounds = [(x0, y0), (x0 + box_w, y0 + box_h)];
    plot.draw(&Rectangle::new(bounds, background))
        .map_err(draw_err)?;
    outline(plot, bounds, m.line(m.palette.legend_border))?;
    let label_style = font.pos(Pos::new(HPos::Left, VPos::Center));
    for (i, (s, look, kind)) in entries.iter().enumerate() {
        let cy = y0 + (pad + row * i as u32 + row / 2) as i32;
        let sx = x0 + pad as i32;
        let colour = look.colour;
        let mid = sx + sample as i32 / 2;
        let (half_w, half_h) = (sample as i32 / 4, row as i32 * 3 / 10);
        let patch = [(mid - half_w, cy - half_h), (mid + half_w, cy + half_h)];
        if matches!(kind, Sample::Line | Sample::LineDot) {
            let style = m.curve_style(colour, s.style.width);
            let line = vec![(sx, cy), (sx + sample as i32, cy)];
            stroke(plot, line, style, look.pattern)?;
        }
        match kind {
            Sample::Line => {}
            Sample::Dot | Sample::LineDot => plot
                .draw(&Circle::new(
                    (mid, cy),
                    m.dot(MARKER_RADIUS_PX),
                    m.fill(colour, 1.0),
                ))
                .map_err(draw_err)?,
            Sample::Bar => plot
                .draw(&Rectangle::new(patch, m.fill(colour, 1.0)))
                .map_err(draw_err)?,
            Sample::Patch => {
                plot.draw(&Rectangle::new(patch, m.fill(colour, SURFACE_OPACITY)))
                    .map_err(draw_err)?;
                outline(plot, patch, m.line(mesh_colour(colour)))?;
            }
        }
        let text_x = sx + (sample + gap) as i32;
        plot.draw_text(&s.label, &label_style, (text_x, cy))
            .map_err(draw_err)?;
    }
    Ok(())
}

/// Top-left corner for a legend box of `size` in a plot area of `plot` pixels: among
/// [`LEGEND_HEIGHTS`] heights along the right, left and centre, the position hiding the least
/// curve length (`pieces`, in plot pixels). Ties go to the higher, then right, left, centre.
pub(super) fn legend_position(
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_legend_avoids_the_curves() {
        // A curve through the top corners: the legend goes below it, on the right.
        let top = vec![vec![(0.0, 30.0), (400.0, 30.0)]];
        assert_eq!(legend_position((400, 300), (100, 50), 10, &top), (290, 67));
        assert_eq!(legend_position((400, 300), (100, 50), 10, &[]), (290, 10));
    }
}
