//! Cartesian panels: plotters' 2D chart over two [`Axis`] coordinates, each series drawn as
//! a line, dots, a line with dots, or bars, and the legend placed where it hides least.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::axis::{Axis, median_spacing, x_display};
use super::clip::visible_pieces;
use super::legend::{Sample, draw_legend};
use super::style::{AXIS_LABEL_EM, Metrics, stroke};
use super::theme::Look;
use super::{PlotError, draw_err, outline};
use crate::series::{Mark, Panel, Series, YScale};

/// Bar width as a fraction of the median spacing of a series' x values.
pub(super) const BAR_FRACTION: f64 = 0.6;
/// Bar width, as a fraction of the x span, of a series with a single x value.
pub(super) const LONE_BAR_FRACTION: f64 = 0.05;

/// Minimum distance between tick labels in base text sizes (x: centre to centre; y: line to line).
pub(super) const X_TICK_SPACING_EM: f64 = 4.0;
pub(super) const Y_TICK_SPACING_EM: f64 = 3.0;

/// Draws a 2D panel: axes, each series in its mark and look, legend.
pub(super) fn draw_cartesian<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    looks: &[Look],
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let tick_font = m.font(1.0);
    let label_font = m.font(AXIS_LABEL_EM);
    let tick_len = m.px(0.35);
    let (margin_top, margin_right, margin_side) = (m.px(0.8), m.px(1.4), m.px(0.4));
    let (_, tick_h) = area.estimate_text_size("0", &tick_font).map_err(draw_err)?;
    let (_, label_h) = area
        .estimate_text_size("θ", &label_font)
        .map_err(draw_err)?;
    let label_gap = m.px(0.5);
    let x_area = 2 * tick_len + tick_h + label_gap + label_h;

    // y ticks first: their widest label decides the width left for the x axis.
    let (width, height) = area.dim_in_pixel();
    let plot_h = height
        .saturating_sub(margin_top + margin_side + x_area)
        .max(1);
    let y = Axis::y(panel, f64::from(plot_h) / (Y_TICK_SPACING_EM * m.unit));
    let mut widest = 0;
    for &tick in &y.ticks {
        let (w, _) = area
            .estimate_text_size(&y.label(tick), &tick_font)
            .map_err(draw_err)?;
        widest = widest.max(w);
    }
    let y_area = 2 * tick_len + widest + label_gap + label_h;
    let plot_w = width
        .saturating_sub(margin_side + margin_right + y_area)
        .max(1);
    let x = Axis::x(panel, f64::from(plot_w) / (X_TICK_SPACING_EM * m.unit));

    let mut chart = ChartBuilder::on(area)
        .margin_top(margin_top)
        .margin_right(margin_right)
        .margin_left(margin_side)
        .margin_bottom(margin_side)
        .x_label_area_size(x_area)
        .y_label_area_size(y_area)
        .build_cartesian_2d(x.clone(), y.clone())
        .map_err(draw_err)?;
    let x_fmt = |v: &f64| x.label(*v);
    let y_fmt = |v: &f64| y.label(*v);
    chart
        .configure_mesh()
        .x_desc(panel.x_label.as_str())
        .y_desc(panel.y_label.as_str())
        .x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style(tick_font.clone())
        .axis_desc_style(label_font)
        .bold_line_style(m.line(m.palette.grid))
        .light_line_style(m.line(m.palette.minor_grid))
        .axis_style(m.line(m.palette.frame))
        .set_all_tick_mark_size(tick_len)
        .draw()
        .map_err(draw_err)?;

    let plot = chart.plotting_area().strip_coord_spec();
    let (pw, ph) = plot.dim_in_pixel();
    let to_plot_px = |(vx, vy): (f64, f64)| {
        (
            (vx - x.lo) / (x.hi - x.lo) * f64::from(pw),
            (y.hi - vy) / (y.hi - y.lo) * f64::from(ph),
        )
    };
    // What each series covers, in plot pixels, for the legend to avoid.
    let mut covered: Vec<Vec<(f64, f64)>> = Vec::new();
    // Curve vertices in plot pixels, clamped to the plot area as plotters clamps the points
    // of the elements it draws (the dashes are walked along the clamped polyline).
    let (x_px, y_px) = plot.get_pixel_range();
    let coordinates = chart.plotting_area().clone();
    let vertex = |p: &(f64, f64)| {
        let (px, py) = coordinates.map_coordinate(p);
        (
            px.clamp(x_px.start, x_px.end) - x_px.start,
            py.clamp(y_px.start, y_px.end) - y_px.start,
        )
    };
    for (series, look) in panel.series.iter().zip(looks) {
        let colour = look.colour;
        let mark = series.style.mark;
        if matches!(mark, Mark::Line | Mark::LinePoints) {
            let style = m.curve_style(colour, series.style.width);
            for piece in visible_pieces(series, panel, &x, &y) {
                stroke(
                    &plot,
                    piece.iter().map(vertex).collect(),
                    style,
                    look.pattern,
                )?;
                covered.push(piece.into_iter().map(to_plot_px).collect());
            }
        }
        if matches!(mark, Mark::Points | Mark::LinePoints) {
            let radius = m.mark_dot(mark);
            let dots = visible_points(series, panel, &x, &y);
            let fill = m.fill(colour, 1.0);
            chart
                .draw_series(dots.iter().map(|&p| Circle::new(p, radius, fill)))
                .map_err(draw_err)?;
            let r = f64::from(radius);
            covered.extend(dots.into_iter().map(|p| {
                let (px, py) = to_plot_px(p);
                vec![(px - r, py), (px + r, py)]
            }));
        }
        if mark == Mark::Bars {
            let bars = visible_bars(series, panel, &x, &y);
            let fill = m.fill(colour, 1.0);
            chart
                .draw_series(bars.iter().map(|&corners| Rectangle::new(corners, fill)))
                .map_err(draw_err)?;
            covered.extend(bars.into_iter().map(|[(x0, y0), (x1, y1)]| {
                let centre = (x0 + x1) / 2.0;
                vec![to_plot_px((centre, y0)), to_plot_px((centre, y1))]
            }));
        }
    }

    outline(
        &plot,
        [(0, 0), (pw as i32 - 1, ph as i32 - 1)],
        m.line(m.palette.frame),
    )?;
    if panel.legend {
        let entries: Vec<(&Series, Look, Sample)> = panel
            .series
            .iter()
            .zip(looks)
            .map(|(s, &look)| (s, look, Sample::of(s.style.mark)))
            .collect();
        draw_legend(&plot, &entries, &covered, &tick_font, m)?;
    }
    Ok(())
}

/// The points of `series` inside the axes box, in display coordinates.
pub(super) fn visible_points(
    series: &Series,
    panel: &Panel,
    x: &Axis,
    y: &Axis,
) -> Vec<(f64, f64)> {
    series
        .points
        .iter()
        .filter_map(|&(theta, v)| x_display(theta, panel.x_unit).zip(panel.y_scale.display(v)))
        .filter(|&(vx, vy)| (x.lo..=x.hi).contains(&vx) && (y.lo..=y.hi).contains(&vy))
        .collect()
}

/// The bars of `series` as display-coordinate rectangles clipped to the axes box: from 0
/// (the bottom of a log axis) to each value, [`BAR_FRACTION`] of the median x spacing wide.
pub(super) fn visible_bars(
    series: &Series,
    panel: &Panel,
    x: &Axis,
    y: &Axis,
) -> Vec<[(f64, f64); 2]> {
    let width = median_spacing(series, panel.x_unit)
        .map_or(LONE_BAR_FRACTION * (x.hi - x.lo), |gap| BAR_FRACTION * gap);
    let base = match panel.y_scale {
        YScale::Linear => 0.0f64.clamp(y.lo, y.hi),
        YScale::Log => y.lo,
    };
    series
        .points
        .iter()
        .filter_map(|&(theta, v)| x_display(theta, panel.x_unit).zip(panel.y_scale.display(v)))
        .filter_map(|(centre, top)| {
            let (x0, x1) = (
                (centre - width / 2.0).max(x.lo),
                (centre + width / 2.0).min(x.hi),
            );
            let top = top.clamp(y.lo, y.hi);
            (x0 < x1 && top != base).then_some([(x0, base), (x1, top)])
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::plot::fixtures::{RED, marked, panel, series};
    use crate::series::{Dash, XUnit};

    #[test]
    fn plain_axes_pad_the_data_and_tick_whole_indices() {
        let points = (0..20).map(|i| (f64::from(i), 1.0)).collect();
        let bars = vec![marked(
            series("s", RED, 1.0, Dash::Solid, points),
            Mark::Bars,
        )];
        let axis = Axis::x(&panel(XUnit::Plain, YScale::Linear, bars), 12.0);
        assert!((axis.lo + 0.95).abs() < 1e-12 && (axis.hi - 19.95).abs() < 1e-12);
        assert_eq!(
            axis.ticks,
            [0.0, 2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 14.0, 16.0, 18.0]
        );
        assert_eq!(axis.label(4.0), "4");
        let two = vec![marked(
            series("s", RED, 1.0, Dash::Solid, vec![(1.0, 1.0), (2.0, -1.0)]),
            Mark::Bars,
        )];
        let p = panel(XUnit::Plain, YScale::Linear, two);
        let (x, y) = (Axis::x(&p, 8.0), Axis::y(&p, 8.0));
        assert_eq!((x.lo, x.hi), (0.5, 2.5));
        assert!(y.lo < -1.0 && y.hi > 0.0);
        let bars = visible_bars(&p.series[0], &p, &x, &y);
        assert_eq!(bars.len(), 2);
        assert!((bars[0][1].0 - bars[0][0].0 - BAR_FRACTION).abs() < 1e-12);
    }
}
