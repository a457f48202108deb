//! Cartesian panels: plotters' 2D chart over two [`Axis`] coordinates, each series drawn as
//! a line, dots, a line with dots, or bars, and the legend placed where it hides least.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::annotate;
use super::axis::{Axis, median_spacing, x_display};
use super::clip::visible_pieces;
use super::legend::{Legend, Outside, Sample, Side};
use super::lint::{record_panel, record_text};
use super::mathtext;
use super::style::{Metrics, stroke};
use super::theme::Look;
use super::{PlotError, draw_err, outline};
use crate::pipeline::figure::{Panel, Series};
use crate::spec::look::AXIS_LABEL_EM;
use crate::spec::look::DEFAULT_ASPECT_RATIO;
use crate::spec::look::{LegendPlace, Mark, Scale};

/// Bar width as a fraction of the median spacing of a series' x values.
pub(super) const BAR_FRACTION: f64 = 0.6;
/// Bar width, as a fraction of the x span, of a series with a single x value.
pub(super) const LONE_BAR_FRACTION: f64 = 0.05;

/// Minimum distance between tick labels in base text sizes (x: centre to centre; y: line to line).
pub(super) const X_TICK_SPACING_EM: f64 = 4.0;
pub(super) const Y_TICK_SPACING_EM: f64 = 3.0;

/// A 2D panel laid out alone in its area: its legend, the area's size, the frame filling it, and
/// whether the legend belongs outside that frame's plot area (as its place and the curves decide).
struct Alone {
    legend: Option<Legend>,
    size: (u32, u32),
    full: Frame,
    legend_outside: bool,
}

impl Alone {
    fn of<DB: DrawingBackend>(
        area: &DrawingArea<DB, Shift>,
        panel: &Panel,
        looks: &[Look],
        m: &Metrics,
    ) -> Result<Alone, PlotError>
    where
        DB::ErrorType: 'static,
    {
        let legend = Legend::of_panel(area, panel, looks, |s| Sample::of(s.style.mark), m)?;
        let size = area.dim_in_pixel();
        let full = Frame::fit(area, size, panel, m, (0, 0))?;
        let legend_outside = legend.as_ref().is_some_and(|legend| {
            !legend.goes_inside(
                panel.axes.legend,
                full.plot_f(),
                &covered(panel, &full, m),
                m,
            )
        });
        Ok(Alone {
            legend,
            size,
            full,
            legend_outside,
        })
    }

    /// The area's size as numbers.
    fn dims(&self) -> (f64, f64) {
        (f64::from(self.size.0), f64::from(self.size.1))
    }
}

/// What a 2D panel of a grid asks of its row and column: the tick-label areas of its frame and
/// the height of the band below the plots its legend needs when it fits inside no plot area.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Needs {
    /// Height of the x tick-label area, device pixels.
    pub(super) x_area: u32,
    /// Width of the y tick-label area, device pixels.
    pub(super) y_area: u32,
    /// Height of the legend band below the plot, device pixels; 0 when the legend fits inside.
    pub(super) band: f64,
}

/// What the panels of a grid share, so that their plot areas line up: the band below every plot
/// of the row and the least tick-label areas (the row's tallest x area, the grid's widest y area).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Shared {
    /// The row's legend band height, device pixels (0 for none).
    pub(super) band: f64,
    /// Least x and y tick-label areas, device pixels.
    pub(super) areas: (u32, u32),
}

/// What `panel`, drawn alone in `area`, needs of a grid ([`Needs`]): its legend goes into the
/// row's band when it fits inside no plot area, and the frame is measured with that band taken.
pub(super) fn needs<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    looks: &[Look],
    m: &Metrics,
) -> Result<Needs, PlotError>
where
    DB::ErrorType: 'static,
{
    let alone = Alone::of(area, panel, looks, m)?;
    let (width, height) = alone.size;
    let band = match &alone.legend {
        Some(legend) if alone.legend_outside => legend.below(alone.dims(), m).strip.1,
        _ => 0.0,
    };
    let chart_h = height.saturating_sub(band.ceil() as u32).max(1);
    let frame = Frame::fit(area, (width, chart_h), panel, m, (0, 0))?;
    // A band that would leave the plot less than its share is not taken: the legend goes over
    // the plot instead, where it hides the least.
    let asked_outside = matches!(panel.axes.legend, LegendPlace::Right | LegendPlace::Below);
    let over = |legend: &Legend| legend.fits_over(alone.full.plot_f(), m);
    if band > 0.0
        && !asked_outside
        && !keeps_share(frame.plot, (width, height))
        && alone.legend.as_ref().is_some_and(over)
    {
        let full = &alone.full;
        return Ok(Needs {
            x_area: full.x_area,
            y_area: full.y_area,
            band: 0.0,
        });
    }
    Ok(Needs {
        x_area: frame.x_area,
        y_area: frame.y_area,
        band,
    })
}

/// Whether the legend of `panel` goes inside its plot area when the panel fills `area` alone:
/// it has one and fits where its place and the curves allow ([`Legend::goes_inside`]).
pub(super) fn legend_fits_inside<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    looks: &[Look],
    m: &Metrics,
) -> Result<bool, PlotError>
where
    DB::ErrorType: 'static,
{
    let alone = Alone::of(area, panel, looks, m)?;
    Ok(alone.legend.is_some() && !alone.legend_outside)
}

/// Draws a 2D panel of a grid: the chart above the row's band with the shared label areas, the
/// legend inside the plot area where it fits, else centred in the band under the plot.
pub(super) fn draw_cartesian_shared<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    looks: &[Look],
    shared: Shared,
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let legend = Legend::of_panel(area, panel, looks, |s| Sample::of(s.style.mark), m)?;
    let (width, height) = area.dim_in_pixel();
    let chart_h = height.saturating_sub(shared.band.ceil() as u32).max(1);
    let chart_area = if shared.band > 0.0 {
        area.split_vertically(chart_h).0
    } else {
        area.clone()
    };
    let frame = Frame::fit(&chart_area, (width, chart_h), panel, m, shared.areas)?;
    let plot = draw_chart(&chart_area, panel, looks, &frame, m)?;
    let Some(legend) = legend else {
        return Ok(());
    };
    let (pw, ph) = plot.dim_in_pixel();
    let covered = covered(
        panel,
        &Frame {
            plot: (pw, ph),
            ..frame.clone()
        },
        m,
    );
    let place = panel.axes.legend;
    if shared.band == 0.0 || legend.goes_inside(place, frame.plot_f(), &covered, m) {
        return legend.draw_inside(&plot, place, &covered, m);
    }
    let dims = (f64::from(width), f64::from(height));
    let setting = legend.below(dims, m).setting;
    let (box_w, _) = legend.size(setting, m);
    let inset = Legend::inset(m);
    let (left, _) = frame.origin(m);
    let (plot_w, _) = frame.plot_f();
    let at = (
        (left + (plot_w - box_w) / 2.0).clamp(inset, (dims.0 - inset - box_w).max(inset)),
        f64::from(chart_h) + inset,
    );
    legend.draw(area, at, setting, m, "in a band below the plots it serves")
}

/// Draws a 2D panel: axes, each series in its mark and look, legend (inside the plot area
/// or beside or below it, by the rule of [`super::legend`]).
pub(super) fn draw_cartesian<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    looks: &[Look],
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let Alone {
        legend,
        size: (width, height),
        full,
        legend_outside,
    } = Alone::of(area, panel, looks, m)?;
    let dims = (f64::from(width), f64::from(height));
    let outside = match &legend {
        Some(legend) if legend_outside => Some(match panel.axes.legend {
            LegendPlace::Right => legend.outside(dims, m, |w, h| {
                (h >= dims.1).then(|| full.score((w, h), m)).flatten()
            }),
            LegendPlace::Below => legend.below(dims, m),
            _ => legend.outside(dims, m, |w, h| full.score((w, h), m)),
        }),
        _ => None,
    };
    let (chart_area, frame, outside) = match outside {
        None => (area.clone(), full, None),
        Some(Outside { side, strip, .. }) => {
            let chart_area = match side {
                Side::Right => {
                    area.split_horizontally(width.saturating_sub(strip.0.ceil() as u32).max(1))
                        .0
                }
                Side::Below => {
                    area.split_vertically(height.saturating_sub(strip.1.ceil() as u32).max(1))
                        .0
                }
            };
            let frame = Frame::fit(&chart_area, chart_area.dim_in_pixel(), panel, m, (0, 0))?;
            let asked = matches!(panel.axes.legend, LegendPlace::Right | LegendPlace::Below);
            let over = legend
                .as_ref()
                .is_some_and(|l| l.fits_over(full.plot_f(), m));
            if asked || !over || keeps_share(frame.plot, (width, height)) {
                (chart_area, frame, outside)
            } else {
                // Beside or below, the plot would lose its share: the legend goes over it.
                (area.clone(), full, None)
            }
        }
    };
    let plot = draw_chart(&chart_area, panel, looks, &frame, m)?;

    let Some(legend) = legend else {
        return Ok(());
    };
    match outside {
        None => {
            let (pw, ph) = plot.dim_in_pixel();
            let covered = covered(
                panel,
                &Frame {
                    plot: (pw, ph),
                    ..frame
                },
                m,
            );
            legend.draw_inside(&plot, panel.axes.legend, &covered, m)
        }
        Some(Outside { side, setting, .. }) => {
            let (box_w, box_h) = legend.size(setting, m);
            let inset = Legend::inset(m);
            let (width, height) = (f64::from(width), f64::from(height));
            let (left, top) = frame.origin(m);
            let (pw, ph) = frame.plot_f();
            // Level with the middle of the plot area, or centred under it, inside the area.
            let at = match side {
                Side::Right => (
                    width - inset - box_w,
                    (top + (ph - box_h) / 2.0).clamp(inset, (height - inset - box_h).max(inset)),
                ),
                Side::Below => (
                    (left + (pw - box_w) / 2.0).clamp(inset, (width - inset - box_w).max(inset)),
                    height - inset - box_h,
                ),
            };
            legend.draw(area, at, setting, m, side.placed())
        }
    }
}

/// Margins around the chart: above the plot area, right of it (room for the last x tick
/// label), and left of the y label and below the x label, in base text sizes.
const MARGIN_EM: (f64, f64, f64) = (0.8, 1.4, 0.4);
/// Length of the tick marks and the gap between tick labels and axis labels, in base text
/// sizes.
const TICK_EM: f64 = 0.35;
const LABEL_GAP_EM: f64 = 0.5;
/// Smallest plot area an outside legend may leave, as the width of the largest rectangle of
/// the default panel aspect 1/φ inside it, in base text sizes: two x tick spacings.
const MIN_PLOT_EM: f64 = 2.0 * X_TICK_SPACING_EM;

/// Least share of its area's width and of its height (the panel's cell below its title) a plot
/// area keeps when a legend is placed: a legend that would leave less beside or below the plot
/// goes over it instead. With the title and tick labels this keeps the plot above about a third of
/// its cell, which the figure lint checks ([`super::lint::MIN_PLOT_SHARE`]).
pub(super) const MIN_PLOT_SHARE: f64 = 0.45;

/// Whether a plot area of `plot` pixels keeps [`MIN_PLOT_SHARE`] of an `area` each way.
fn keeps_share(plot: (u32, u32), area: (u32, u32)) -> bool {
    f64::from(plot.0) >= MIN_PLOT_SHARE * f64::from(area.0)
        && f64::from(plot.1) >= MIN_PLOT_SHARE * f64::from(area.1)
}

/// The layout of a chart in an area: its axes, the sizes of the tick-label areas and of the
/// plot area, in device pixels.
#[derive(Clone)]
struct Frame {
    x: Axis,
    y: Axis,
    x_area: u32,
    y_area: u32,
    plot: (u32, u32),
}

impl Frame {
    /// The chart of `panel` in an area of `(width, height)` pixels: y ticks first, as their
    /// widest label decides the width left for the x axis.
    fn fit<DB: DrawingBackend>(
        area: &DrawingArea<DB, Shift>,
        (width, height): (u32, u32),
        panel: &Panel,
        m: &Metrics,
        (min_x_area, min_y_area): (u32, u32),
    ) -> Result<Frame, PlotError>
    where
        DB::ErrorType: 'static,
    {
        let tick_font = m.font(1.0);
        let (_, tick_h) = area.estimate_text_size("0", &tick_font).map_err(draw_err)?;
        let (_, label_h) = area
            .estimate_text_size("θ", &m.font(AXIS_LABEL_EM))
            .map_err(draw_err)?;
        let (tick_len, label_gap) = (m.px(TICK_EM), m.px(LABEL_GAP_EM));
        let (top, right, side) = margins(m);
        let x_area = (2 * tick_len + tick_h + label_gap + label_h).max(min_x_area);
        let plot_h = height.saturating_sub(top + side + x_area).max(1);
        let y = Axis::y(panel, f64::from(plot_h) / (Y_TICK_SPACING_EM * m.unit));
        let mut widest = 0;
        for &tick in &y.ticks {
            let (w, _) = area
                .estimate_text_size(&y.label(tick), &tick_font)
                .map_err(draw_err)?;
            widest = widest.max(w);
        }
        let y_area = (2 * tick_len + widest + label_gap + label_h).max(min_y_area);
        let plot_w = width.saturating_sub(side + right + y_area).max(1);
        let x = Axis::x(panel, f64::from(plot_w) / (X_TICK_SPACING_EM * m.unit));
        Ok(Frame {
            x,
            y,
            x_area,
            y_area,
            plot: (plot_w, plot_h),
        })
    }

    /// The plot area's size in pixels.
    fn plot_f(&self) -> (f64, f64) {
        (f64::from(self.plot.0), f64::from(self.plot.1))
    }

    /// The plot area's top-left corner in its chart area.
    fn origin(&self, m: &Metrics) -> (f64, f64) {
        let (top, _, side) = margins(m);
        (f64::from(side + self.y_area), f64::from(top))
    }

    /// How good a plot area the chart would have in `(w, h)` pixels with these tick-label
    /// areas: the width of the largest 1/φ rectangle inside it; `None` below [`MIN_PLOT_EM`].
    fn score(&self, (w, h): (f64, f64), m: &Metrics) -> Option<f64> {
        let (top, right, side) = margins(m);
        let plot_w = w - f64::from(side + right + self.y_area);
        let plot_h = h - f64::from(top + side + self.x_area);
        let golden = plot_w.min(plot_h / DEFAULT_ASPECT_RATIO);
        (golden >= MIN_PLOT_EM * m.unit).then_some(golden)
    }
}

/// [`MARGIN_EM`] in device pixels: top, right, and the other two sides.
fn margins(m: &Metrics) -> (u32, u32, u32) {
    let (top, right, side) = MARGIN_EM;
    (m.px(top), m.px(right), m.px(side))
}

/// Draws the axes of `panel` alone filling `area` (its series are not drawn), `fill` inside its
/// plot area (given that area and the x and y axes), then the frame round it; returns the plot
/// area. For panels whose content is not series of points, such as heat maps.
pub(super) fn draw_framed<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    m: &Metrics,
    fill: impl FnOnce(&DrawingArea<DB, Shift>, &Axis, &Axis) -> Result<(), PlotError>,
) -> Result<DrawingArea<DB, Shift>, PlotError>
where
    DB::ErrorType: 'static,
{
    let frame = Frame::fit(area, area.dim_in_pixel(), panel, m, (0, 0))?;
    let (_, plot) = draw_axes(area, panel, &frame, m)?;
    fill(&plot, &frame.x, &frame.y)?;
    let (pw, ph) = plot.dim_in_pixel();
    outline(
        &plot,
        [(0, 0), (pw as i32 - 1, ph as i32 - 1)],
        m.line(m.palette.frame),
    )?;
    Ok(plot)
}

/// Draws the axes of `panel` in `area`, laid out as `frame`: grid, ticks, tick labels and axis
/// labels; returns the chart and its plot area.
#[allow(clippy::type_complexity)]
fn draw_axes<'a, DB: DrawingBackend>(
    area: &'a DrawingArea<DB, Shift>,
    panel: &Panel,
    frame: &Frame,
    m: &Metrics,
) -> Result<
    (
        ChartContext<'a, DB, Cartesian2d<Axis, Axis>>,
        DrawingArea<DB, Shift>,
    ),
    PlotError,
>
where
    DB::ErrorType: 'static,
{
    let (x, y) = (&frame.x, &frame.y);
    let (top, right, side) = margins(m);
    let mut chart = ChartBuilder::on(area)
        .margin_top(top)
        .margin_right(right)
        .margin_left(side)
        .margin_bottom(side)
        .x_label_area_size(frame.x_area)
        .y_label_area_size(frame.y_area)
        .build_cartesian_2d(x.clone(), y.clone())
        .map_err(draw_err)?;
    let x_fmt = |v: &f64| x.label(*v);
    let y_fmt = |v: &f64| y.label(*v);
    let mut mesh = chart.configure_mesh();
    if !panel.axes.grid {
        mesh.disable_mesh();
    }
    mesh.x_label_formatter(&x_fmt)
        .y_label_formatter(&y_fmt)
        .label_style(m.font(1.0))
        .bold_line_style(m.line(m.palette.grid))
        .light_line_style(m.line(m.palette.minor_grid))
        .axis_style(m.line(m.palette.frame))
        .set_all_tick_mark_size(m.px(TICK_EM))
        .draw()
        .map_err(draw_err)?;

    // The axis labels where plotters puts its own, typeset: the x label centred under the plot area
    // at the foot of its label area, the y label reading upwards at the outer edge of its own.
    let (x_px, y_px) = chart.plotting_area().get_pixel_range();
    let (base_x, base_y) = area.get_base_pixel();
    if m.trace.is_some() {
        record_frame(area, frame, (&x_px, &y_px), m)?;
    }
    let (left, right) = (f64::from(x_px.start - base_x), f64::from(x_px.end - base_x));
    let (upper, lower) = (f64::from(y_px.start - base_y), f64::from(y_px.end - base_y));
    let desc = m.font(AXIS_LABEL_EM);
    let x_style = desc.pos(Pos::new(HPos::Center, VPos::Bottom));
    // In an area too small for the frame, plotters shortens the label areas; so do the labels.
    let (_, area_h) = area.dim_in_pixel();
    let (_, _, side) = margins(m);
    let foot = (lower + f64::from(frame.x_area)).min(f64::from(area_h.saturating_sub(side)));
    let x_at = ((left + right) / 2.0, foot);
    mathtext::draw(area, &panel.axes.x_label, &x_style, x_at, m)?;
    let y_style = desc
        .transform(FontTransform::Rotate270)
        .pos(Pos::new(HPos::Center, VPos::Top));
    let y_at = (
        (left - f64::from(frame.y_area)).max(f64::from(side)),
        (upper + lower) / 2.0,
    );
    mathtext::draw(area, &panel.axes.y_label, &y_style, y_at, m)?;

    let plot = chart.plotting_area().strip_coord_spec();
    Ok((chart, plot))
}

/// Draws the axes and the series of `panel` in `area`, laid out as `frame`, and returns the
/// plot area.
fn draw_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    looks: &[Look],
    frame: &Frame,
    m: &Metrics,
) -> Result<DrawingArea<DB, Shift>, PlotError>
where
    DB::ErrorType: 'static,
{
    let (x, y) = (&frame.x, &frame.y);
    let (mut chart, plot) = draw_axes(area, panel, frame, m)?;
    let (pw, ph) = plot.dim_in_pixel();
    let placement = annotate::Placement {
        x,
        y,
        scales: (panel.axes.x_scale, panel.axes.y_scale),
        size: (pw, ph),
    };
    annotate::draw(
        &plot,
        &panel.axes.annotations,
        &placement,
        annotate::Layer::Under,
        m,
    )?;
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
            for piece in visible_pieces(series, panel, x, y) {
                stroke(
                    &plot,
                    piece.iter().map(vertex).collect(),
                    style,
                    look.pattern,
                )?;
            }
        }
        if matches!(mark, Mark::Points | Mark::LinePoints) {
            let radius = m.mark_dot(mark);
            let fill = m.fill(colour, 1.0);
            let dots = visible_points(series, panel, x, y);
            chart
                .draw_series(dots.into_iter().map(|p| Circle::new(p, radius, fill)))
                .map_err(draw_err)?;
        }
        if mark == Mark::Bars {
            let fill = m.fill(colour, 1.0);
            let bars = visible_bars(series, panel, x, y);
            chart
                .draw_series(
                    bars.into_iter()
                        .map(|corners| Rectangle::new(corners, fill)),
                )
                .map_err(draw_err)?;
        }
    }
    annotate::draw(
        &plot,
        &panel.axes.annotations,
        &placement,
        annotate::Layer::Over,
        m,
    )?;
    outline(
        &plot,
        [(0, 0), (pw as i32 - 1, ph as i32 - 1)],
        m.line(m.palette.frame),
    )?;
    Ok(plot)
}

/// Records the plot area and the boxes of the tick labels plotters drew for the figure lint: x
/// labels centred under their ticks below the tick marks, y labels right-aligned left of them.
fn record_frame<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    frame: &Frame,
    (x_px, y_px): (&std::ops::Range<i32>, &std::ops::Range<i32>),
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let plot = [x_px.start, y_px.start, x_px.end, y_px.end].map(f64::from);
    let (x, y) = (&frame.x, &frame.y);
    let font = m.font(1.0);
    let tick = f64::from(m.px(TICK_EM));
    let labelled = |axis: &Axis| axis.labels.iter().filter(|l| !l.is_empty()).count();
    record_panel(&m.trace, plot, (labelled(x), labelled(y)));
    let along = |axis: &Axis, v: f64, (lo, hi): (f64, f64)| {
        lo + (v - axis.lo) / (axis.hi - axis.lo) * (hi - lo)
    };
    for (&v, label) in x.ticks.iter().zip(&x.labels) {
        let (w, h) = area.estimate_text_size(label, &font).map_err(draw_err)?;
        let cx = along(x, v, (plot[0], plot[2]));
        let rect = mathtext::placed(
            (cx, plot[3] + tick),
            (f64::from(w), f64::from(h)),
            (HPos::Center, VPos::Top),
            false,
        );
        record_text(&m.trace, label, label, rect);
    }
    for (&v, label) in y.ticks.iter().zip(&y.labels) {
        let (w, h) = area.estimate_text_size(label, &font).map_err(draw_err)?;
        let cy = along(y, v, (plot[3], plot[1]));
        let rect = mathtext::placed(
            (plot[0] - tick, cy),
            (f64::from(w), f64::from(h)),
            (HPos::Right, VPos::Center),
            false,
        );
        record_text(&m.trace, label, label, rect);
    }
    Ok(())
}

/// What the series of `panel` cover in the plot area of `frame`, in plot pixels, for the
/// legend to avoid: the visible pieces of lines, a dot's width across each dot, and each
/// bar's centre line.
fn covered(panel: &Panel, frame: &Frame, m: &Metrics) -> Vec<Vec<(f64, f64)>> {
    let (x, y) = (&frame.x, &frame.y);
    let (pw, ph) = frame.plot_f();
    let to_plot_px = |(vx, vy): (f64, f64)| {
        (
            (vx - x.lo) / (x.hi - x.lo) * pw,
            (y.hi - vy) / (y.hi - y.lo) * ph,
        )
    };
    let mut covered: Vec<Vec<(f64, f64)>> = Vec::new();
    for series in &panel.series {
        let mark = series.style.mark;
        if matches!(mark, Mark::Line | Mark::LinePoints) {
            covered.extend(
                visible_pieces(series, panel, x, y)
                    .into_iter()
                    .map(|piece| piece.into_iter().map(to_plot_px).collect()),
            );
        }
        if matches!(mark, Mark::Points | Mark::LinePoints) {
            let r = f64::from(m.mark_dot(mark));
            covered.extend(visible_points(series, panel, x, y).into_iter().map(|p| {
                let (px, py) = to_plot_px(p);
                vec![(px - r, py), (px + r, py)]
            }));
        }
        if mark == Mark::Bars {
            covered.extend(visible_bars(series, panel, x, y).into_iter().map(
                |[(x0, y0), (x1, y1)]| {
                    let centre = (x0 + x1) / 2.0;
                    vec![to_plot_px((centre, y0)), to_plot_px((centre, y1))]
                },
            ));
        }
    }
    covered
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
        .filter_map(|&(theta, v)| x_display(theta, &panel.axes).zip(panel.axes.y_scale.display(v)))
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
    let width = median_spacing(series, &panel.axes)
        .map_or(LONE_BAR_FRACTION * (x.hi - x.lo), |gap| BAR_FRACTION * gap);
    let base = match panel.axes.y_scale {
        Scale::Linear => 0.0f64.clamp(y.lo, y.hi),
        Scale::Log => y.lo,
    };
    series
        .points
        .iter()
        .filter_map(|&(theta, v)| x_display(theta, &panel.axes).zip(panel.axes.y_scale.display(v)))
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
    use crate::spec::look::{Dash, XUnit};

    #[test]
    fn plain_axes_pad_the_data_and_tick_whole_indices() {
        let points = (0..20).map(|i| (f64::from(i), 1.0)).collect();
        let bars = vec![marked(
            series("s", RED, 1.0, Dash::Solid, points),
            Mark::Bars,
        )];
        let axis = Axis::x(&panel(XUnit::Plain, Scale::Linear, bars), 12.0);
        assert!((axis.lo + 0.95).abs() < 1e-12 && (axis.hi - 19.95).abs() < 1e-12);
        assert_eq!(axis.ticks, [0.0, 5.0, 10.0, 15.0]);
        assert_eq!(axis.label(5.0), "5");
        let two = vec![marked(
            series("s", RED, 1.0, Dash::Solid, vec![(1.0, 1.0), (2.0, -1.0)]),
            Mark::Bars,
        )];
        let p = panel(XUnit::Plain, Scale::Linear, two);
        let (x, y) = (Axis::x(&p, 8.0), Axis::y(&p, 8.0));
        assert_eq!((x.lo, x.hi), (0.5, 2.5));
        assert!(y.lo < -1.0 && y.hi > 0.0);
        let bars = visible_bars(&p.series[0], &p, &x, &y);
        assert_eq!(bars.len(), 2);
        assert!((bars[0][1].0 - bars[0][0].0 - BAR_FRACTION).abs() < 1e-12);
    }
}
