//! Heat-map panels: a series' z over its rectilinear (x, y) grid as cells coloured by
//! [`viridis`], on the 2D axes of [`super::cartesian`], with a colour bar and its ticks beside the
//! plot area.
//!
//! Each grid node owns the cell between the midpoints to its neighbours (the outer cells end at
//! the outer nodes, so the axes span the grid exactly). Runs of equal colour along x are one
//! rectangle, and each rectangle reaches one CSS pixel into its right and upper neighbours, which
//! are drawn after it: anti-aliased edges then never let the page show between cells.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axis::Axis;
use super::cartesian::{Y_TICK_SPACING_EM, draw_framed};
use super::mathtext;
use super::style::Metrics;
use super::{PlotError, draw_err, outline};
use crate::pipeline::figure::{Panel, Series};
use crate::spec::look::AXIS_LABEL_EM;
use crate::spec::look::{Rgb, viridis};

/// Gap between the plot area and the colour bar, and the bar's width, in base text sizes.
const BAR_GAP_EM: f64 = 1.0;
const BAR_WIDTH_EM: f64 = 1.1;
/// Tick marks, the gap before their labels and before the bar's label, the right margin, in
/// base text sizes (as a 2D axis has them).
const TICK_EM: f64 = 0.35;
const LABEL_GAP_EM: f64 = 0.5;
const MARGIN_EM: f64 = 0.4;
/// Most bands the colour bar is drawn in: finer than the eye separates.
const MAX_BAR_BANDS: usize = 128;

/// A series' grid: node coordinates along x and y and z at node (i, j) as `z[i * ys.len() + j]`.
struct Grid<'a> {
    xs: Vec<f64>,
    ys: Vec<f64>,
    z: &'a [f64],
}

impl<'a> Grid<'a> {
    /// The grid of `series`: its points must be (x_i, y_j) in row-major order over its `grid`
    /// shape, with a z per point.
    fn of(series: &'a Series) -> Result<Grid<'a>, PlotError> {
        let fail = |reason: &str| PlotError::Series {
            label: series.label.clone(),
            reason: reason.to_owned(),
        };
        let (rows, cols) = series
            .grid
            .ok_or_else(|| fail("a heat map needs a grid of at least 2 × 2 points"))?;
        let z = series
            .z
            .as_deref()
            .filter(|z| z.len() == rows * cols && series.points.len() == rows * cols)
            .ok_or_else(|| fail("a heat map needs a z value per grid point"))?;
        let xs: Vec<f64> = (0..rows).map(|i| series.points[i * cols].0).collect();
        let ys: Vec<f64> = (0..cols).map(|j| series.points[j].1).collect();
        let rectilinear = series
            .points
            .iter()
            .enumerate()
            .all(|(k, &p)| p == (xs[k / cols], ys[k % cols]));
        if !rectilinear {
            return Err(fail(
                "a heat map needs x constant along rows and y along columns",
            ));
        }
        Ok(Grid { xs, ys, z })
    }
}

/// The cell boundaries of nodes `v`: the first node, the midpoints between neighbours, the last.
fn edges(v: &[f64]) -> Vec<f64> {
    let mut edges = Vec::with_capacity(v.len() + 1);
    edges.push(v[0]);
    edges.extend(v.windows(2).map(|w| (w[0] + w[1]) / 2.0));
    edges.push(v[v.len() - 1]);
    edges
}

/// Draws a heat-map panel: the 2D axes spanning its one series' grid (or the ranges given), the
/// cells, and the colour bar labelled `z_label` over `z_range` (the data's extent by default).
pub(super) fn draw_heatmap<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    (z_label, z_range): (&str, Option<(f64, f64)>),
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let Some(series) = panel.series.first() else {
        return Ok(());
    };
    let grid = Grid::of(series)?;
    let (width, height) = area.dim_in_pixel();
    let z_axis = Axis::colour(
        panel,
        z_range,
        0.8 * f64::from(height) / (Y_TICK_SPACING_EM * m.unit),
    );
    let tick_font = m.font(1.0);
    let mut widest = 0.0f64;
    for label in &z_axis.labels {
        widest = widest.max(mathtext::width(area, label, &tick_font)?);
    }
    let (_, label_h) = area
        .estimate_text_size("θ", &m.font(AXIS_LABEL_EM))
        .map_err(draw_err)?;
    let (gap, bar_w, tick) = (
        f64::from(m.px(BAR_GAP_EM)),
        f64::from(m.px(BAR_WIDTH_EM)),
        f64::from(m.px(TICK_EM)),
    );
    let label_gap = f64::from(m.px(LABEL_GAP_EM));
    let strip = gap + bar_w + 2.0 * tick + widest + label_gap + f64::from(label_h);
    let strip = strip + f64::from(m.px(MARGIN_EM));
    let chart_w = (f64::from(width) - strip).max(1.0) as u32;
    let chart_area = area.split_horizontally(chart_w).0;

    // The axes span the grid unless the spec gives ranges; the cells hide any grid lines.
    let span = |v: &[f64]| {
        let lo = v.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = v.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Some((lo, hi))
    };
    let mut framed = panel.clone();
    framed.axes.x_range = panel.axes.x_range.or(span(&grid.xs));
    framed.axes.y_range = panel.axes.y_range.or(span(&grid.ys));
    framed.axes.grid = false;
    let colour_of = |v: f64| viridis((v - z_axis.lo) / (z_axis.hi - z_axis.lo));
    let overlap = m.hairline() as i32;
    let plot = draw_framed(&chart_area, &framed, m, |plot, x, y| {
        draw_cells(plot, &grid, (x, y), &colour_of, overlap)
    })?;

    // The colour bar, level with the plot area.
    let (plot_x, plot_y) = plot.get_base_pixel();
    let (base_x, base_y) = area.get_base_pixel();
    let (pw, ph) = plot.dim_in_pixel();
    let left = f64::from(plot_x - base_x) + f64::from(pw) + gap;
    let (top, bottom) = (
        f64::from(plot_y - base_y),
        f64::from(plot_y - base_y) + f64::from(ph),
    );
    let right = left + bar_w;
    let bands = (f64::from(ph) / m.k).clamp(2.0, MAX_BAR_BANDS as f64) as usize;
    let y_at = |t: f64| bottom - t * (bottom - top);
    for band in 0..bands {
        let (t0, t1) = (band as f64 / bands as f64, (band + 1) as f64 / bands as f64);
        let reach = if band + 1 < bands { overlap } else { 0 };
        let colour = viridis((t0 + t1) / 2.0);
        let corners = [
            (left.round() as i32, y_at(t1).round() as i32 - reach),
            (right.round() as i32, y_at(t0).round() as i32),
        ];
        area.draw(&Rectangle::new(corners, fill(colour)))
            .map_err(draw_err)?;
    }
    outline(
        area,
        [
            (left.round() as i32, top.round() as i32),
            (right.round() as i32, bottom.round() as i32),
        ],
        m.line(m.palette.frame),
    )?;
    let label_style = tick_font.pos(Pos::new(HPos::Left, VPos::Center));
    for (&v, label) in z_axis.ticks.iter().zip(&z_axis.labels) {
        let t = (v - z_axis.lo) / (z_axis.hi - z_axis.lo);
        let at = y_at(t).round() as i32;
        let from = right.round() as i32;
        area.draw(&PathElement::new(
            [(from, at), (from + tick as i32, at)],
            m.line(m.palette.frame),
        ))
        .map_err(draw_err)?;
        let label_at = (right + 2.0 * tick, f64::from(at));
        mathtext::draw(area, label, &label_style, label_at, m)?;
    }
    let z_style = m
        .font(AXIS_LABEL_EM)
        .transform(FontTransform::Rotate270)
        .pos(Pos::new(HPos::Center, VPos::Top));
    let z_at = (
        right + 2.0 * tick + widest + label_gap,
        (top + bottom) / 2.0,
    );
    mathtext::draw(area, z_label, &z_style, z_at, m)
}

/// A solid fill of `colour`.
fn fill(colour: Rgb) -> ShapeStyle {
    RGBColor(colour.0, colour.1, colour.2).filled()
}

/// Draws the cells of `grid` in the plot area `plot` over the axes `(x, y)`, each run of equal
/// colour along x one rectangle reaching `overlap` pixels into the cells drawn after it (right
/// and above); cells outside the axes are clipped to them.
fn draw_cells<DB: DrawingBackend>(
    plot: &DrawingArea<DB, Shift>,
    grid: &Grid,
    (x, y): (&Axis, &Axis),
    colour_of: &dyn Fn(f64) -> Rgb,
    overlap: i32,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let (pw, ph) = plot.dim_in_pixel();
    let (pw, ph) = (f64::from(pw), f64::from(ph));
    let px = |v: f64| ((v - x.lo) / (x.hi - x.lo) * pw).clamp(0.0, pw).round() as i32;
    let py = |v: f64| ((y.hi - v) / (y.hi - y.lo) * ph).clamp(0.0, ph).round() as i32;
    let (x_edges, y_edges) = (edges(&grid.xs), edges(&grid.ys));
    let (nx, ny) = (grid.xs.len(), grid.ys.len());
    let mut rects = Vec::new();
    for j in 0..ny {
        let up = if j + 1 < ny { overlap } else { 0 };
        let (lower, upper) = (py(y_edges[j]), py(y_edges[j + 1]) - up);
        let mut i = 0;
        while i < nx {
            let colour = colour_of(grid.z[i * ny + j]);
            let mut end = i + 1;
            while end < nx && colour_of(grid.z[end * ny + j]) == colour {
                end += 1;
            }
            let reach = if end < nx { overlap } else { 0 };
            let corners = [(px(x_edges[i]), upper), (px(x_edges[end]) + reach, lower)];
            if corners[0].0 < corners[1].0 && corners[0].1 < corners[1].1 {
                rects.push(Rectangle::new(corners, fill(colour)));
            }
            i = end;
        }
    }
    for rect in &rects {
        plot.draw(rect).map_err(draw_err)?;
    }
    Ok(())
}
