//! Surface panels: the 3D axes box with its back panes and grid, depth-sorted translucent
//! meshes, 3D lines and dots, labelled edges and the legend, on the camera geometry of
//! [`crate::output::plot3d`].

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axis::{Axis, x_display};
use super::legend::{Covered, Legend, Sample};
use super::mathtext;
use super::style::{Metrics, SURFACE_OPACITY, mesh_colour, stroke};
use super::text::{anchor_towards, text_box, text_size};
use super::theme::Look;
use super::{PlotError, draw_err};
use crate::output::plot3d::{self, P3, Projector, View};
use crate::pipeline::figure::{Panel, Series};
use crate::spec::look::AXIS_LABEL_EM;
use crate::spec::look::{Mark, Rgb};

/// Free space between neighbouring tick labels along a 3D edge, in base text sizes.
pub(super) const TICK_CLEARANCE_EM: f64 = 0.8;

/// Draws a 3D panel: back panes with grid lines, surface meshes far to near, 3D lines and
/// dots over them, the labelled axis edges, and the legend.
///
/// A series with a grid of at least 2 × 2 points is a surface; any other series is a 3D line
/// (bars are drawn as lines), as is a grid of a single row or column. Mesh cells reaching
/// outside the displayed ranges are left out; lines are clipped to the box.
pub(super) fn draw_surface<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    looks: &[Look],
    (z_label, z_range): (&str, Option<(f64, f64)>),
    view: View,
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let z_values = z_columns(panel)?;
    let tick_font = m.font(1.0);
    let label_font = m.font(AXIS_LABEL_EM);
    let text = |s: &str, font: &TextStyle| text_size(area, s, font);
    let tick_len = f64::from(m.px(0.35));
    let gap = f64::from(m.px(0.4));
    let (_, tick_h) = text("0", &tick_font)?;
    let (_, label_h) = text("θ", &label_font)?;
    let (width, height) = area.dim_in_pixel();
    let (width, height) = (f64::from(width), f64::from(height));
    // The box fills the area less room for tick labels and axis labels on the sides and below.
    let fit = |tick_w: f64| {
        let side = tick_len + tick_w + label_h + 3.0 * gap;
        let below = tick_len + tick_h + label_h + 3.0 * gap;
        let right = (width - side).max(side + 1.0);
        let bottom = (height - below).max(2.0 * gap + 1.0);
        Projector::fit(view, [side, right, 2.0 * gap, bottom])
    };

    // Tick counts from a first layout with a typical label width; the final layout makes
    // room for the widest label.
    let edges = view.axis_edges();
    let typical_w = text("−0.00", &tick_font)?.0;
    let first = fit(typical_w);
    let max_ticks = |edge: &plot3d::Edge| {
        let (a, b) = (first.px(edge.from), first.px(edge.to));
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let length = dx.hypot(dy);
        // Neighbouring labels must clear each other across the screen or down it; labels
        // set off diagonally need less room along a slanted edge than on a 2D axis.
        let across = typical_w + TICK_CLEARANCE_EM * m.unit;
        let down = tick_h + TICK_CLEARANCE_EM * m.unit;
        let spacing = (across * length / dx.abs()).min(down * length / dy.abs());
        if spacing.is_finite() && spacing > 0.0 {
            length / spacing + 1.0
        } else {
            2.0
        }
    };
    let axes = [
        Axis::x(panel, max_ticks(&edges[0])),
        Axis::y(panel, max_ticks(&edges[1])),
        Axis::z(panel, z_range, max_ticks(&edges[2])),
    ];
    let mut tick_w = 0.0f64;
    for axis in &axes {
        for &tick in &axis.ticks {
            tick_w = tick_w.max(text(&axis.label(tick), &tick_font)?.0);
        }
    }
    let projector = fit(tick_w);
    let ranges = axes.each_ref().map(|a| (a.lo, a.hi));
    let px = |p: P3| {
        let (x, y) = projector.px(p);
        (x.round() as i32, y.round() as i32)
    };
    let ring = |points: &[P3]| -> Vec<(i32, i32)> {
        points
            .iter()
            .chain(points.first())
            .map(|&p| px(p))
            .collect()
    };
    // Everything drawn, in area pixels, for the legend to avoid.
    let mut covered = Covered::default();

    // Back panes and their grid lines.
    let far = view.far_sides();
    for (axis, &high) in far.iter().enumerate() {
        let corners = plot3d::face(axis, high);
        area.draw(&Polygon::new(ring(&corners), m.palette.pane.filled()))
            .map_err(draw_err)?;
        for other in [(axis + 1) % 3, (axis + 2) % 3] {
            let across = 3 - axis - other;
            for &tick in &axes[other].ticks {
                let mut a = corners[0];
                a[other] = plot3d::to_box(other, tick, ranges[other]);
                a[across] = -plot3d::BOX_ASPECT[across] / 2.0;
                let mut b = a;
                b[across] = -a[across];
                area.draw(&PathElement::new(
                    [px(a), px(b)],
                    m.line(m.palette.pane_grid),
                ))
                .map_err(draw_err)?;
            }
        }
        let outline = ring(&corners);
        area.draw(&PathElement::new(
            outline.clone(),
            m.line(m.palette.pane_edge),
        ))
        .map_err(draw_err)?;
        covered.add(&outline);
    }

    // Series in box coordinates (NaN where a point cannot be drawn).
    let placed: Vec<Vec<P3>> = panel
        .series
        .iter()
        .zip(&z_values)
        .map(|(series, zs)| {
            series
                .points
                .iter()
                .zip(zs.iter())
                .map(|(&(x, y), &z)| {
                    let shown = x_display(x, &panel.axes).zip(panel.axes.y_scale.display(y));
                    match shown {
                        Some((x, y)) if z.is_finite() => {
                            let v = [x, y, z];
                            [0, 1, 2].map(|i| plot3d::to_box(i, v[i], ranges[i]))
                        }
                        _ => [f64::NAN; 3],
                    }
                })
                .collect()
        })
        .collect();
    let is_surface = |s: &Series| matches!(s.grid, Some((rows, cols)) if rows >= 2 && cols >= 2);

    // Surface meshes, far to near.
    let mut quads = Vec::new();
    for (i, (series, points)) in panel.series.iter().zip(&placed).enumerate() {
        if let (true, Some(grid)) = (is_surface(series), series.grid) {
            plot3d::push_quads(&mut quads, &view, points, grid, i);
        }
    }
    plot3d::back_to_front(&mut quads);
    for quad in &quads {
        let colour = looks[quad.surface].colour;
        let shade = |c: u8| (f64::from(c) * quad.shade).round() as u8;
        let shaded = Rgb(shade(colour.0), shade(colour.1), shade(colour.2));
        let outline = ring(&quad.corners);
        area.draw(&Polygon::new(
            &outline[..4],
            m.fill(shaded, SURFACE_OPACITY),
        ))
        .map_err(draw_err)?;
        // Edge by edge: the raster backend mitres the joins of wide polylines, which spike
        // far out at the sharp corners of sliver cells.
        for edge in outline.windows(2) {
            area.draw(&PathElement::new(edge, m.line(mesh_colour(colour))))
                .map_err(draw_err)?;
        }
        covered.add(&outline);
    }

    // Lines and dots over the surfaces.
    for ((series, points), look) in panel.series.iter().zip(&placed).zip(looks) {
        if is_surface(series) {
            continue;
        }
        let (colour, mark) = (look.colour, series.style.mark);
        if mark != Mark::Points {
            let style = m.curve_style(colour, series.style.width);
            for piece in plot3d::visible_pieces(points) {
                let path: Vec<(i32, i32)> = piece.iter().map(|&p| px(p)).collect();
                covered.add(&path);
                stroke(area, path, style, look.pattern)?;
            }
        }
        if matches!(mark, Mark::Points | Mark::LinePoints) {
            let radius = m.mark_dot(mark);
            for &p in points.iter().filter(|&&p| plot3d::inside(p)) {
                area.draw(&Circle::new(px(p), radius, m.fill(colour, 1.0)))
                    .map_err(draw_err)?;
                let (x, y) = px(p);
                covered.add(&[(x - radius as i32, y), (x + radius as i32, y)]);
            }
        }
    }

    // Labelled edges: ticks and their labels point away from the box, the axis label beyond.
    let centre = projector.px([0.0; 3]);
    let titles = [
        panel.axes.x_label.as_str(),
        panel.axes.y_label.as_str(),
        z_label,
    ];
    for (i, edge) in edges.iter().enumerate() {
        area.draw(&PathElement::new(
            [px(edge.from), px(edge.to)],
            m.line(m.palette.frame),
        ))
        .map_err(draw_err)?;
        let mid = projector.px(edge.midpoint());
        let out = outward((mid.0 - centre.0, mid.1 - centre.1), i == 2);
        let (pos, corner) = anchor_towards(out);
        let style = tick_font.pos(pos);
        let mut reach = 0.0f64;
        for &tick in &axes[i].ticks {
            let (x, y) = projector.px(edge.at(plot3d::to_box(i, tick, ranges[i])));
            let end = (x + out.0 * tick_len, y + out.1 * tick_len);
            let tick_mark = [(x, y), end].map(|(x, y)| (x.round() as i32, y.round() as i32));
            area.draw(&PathElement::new(tick_mark, m.line(m.palette.frame)))
                .map_err(draw_err)?;
            let label = axes[i].label(tick);
            let size = text(&label, &tick_font)?;
            let at = (end.0 + out.0 * gap, end.1 + out.1 * gap);
            area.draw_text(&label, &style, (at.0.round() as i32, at.1.round() as i32))
                .map_err(draw_err)?;
            reach = reach.max(out.0.abs() * size.0 + out.1.abs() * size.1);
            covered.add(&text_box(at, size, corner));
        }
        if !titles[i].is_empty() {
            let (w, h) = text(titles[i], &label_font)?;
            // The z label reads upwards.
            let size = if i == 2 { (h, w) } else { (w, h) };
            let along =
                tick_len + 2.0 * gap + reach + (out.0.abs() * size.0 + out.1.abs() * size.1) / 2.0;
            let at = (mid.0 + out.0 * along, mid.1 + out.1 * along);
            let centred = label_font.pos(Pos::new(HPos::Center, VPos::Center));
            let style = if i == 2 {
                centred.transform(FontTransform::Rotate270)
            } else {
                centred
            };
            mathtext::draw(area, titles[i], &style, at, m)?;
            covered.add(&text_box(at, size, (0.5, 0.5)));
        }
    }

    let sample = |s: &Series| match s.style.mark {
        _ if is_surface(s) => Sample::Patch,
        Mark::Bars => Sample::Line,
        mark => Sample::of(mark),
    };
    if let Some(legend) = Legend::of_panel(area, panel, looks, sample, m)? {
        legend.draw_over(area, &covered.0, m)?;
    }
    Ok(())
}

/// The z values of each series of a surface panel, after checking that every point has one
/// and that each grid matches its number of points.
pub(super) fn z_columns(panel: &Panel) -> Result<Vec<&[f64]>, PlotError> {
    panel
        .series
        .iter()
        .map(|s| {
            let fail = |reason: String| PlotError::Series {
                label: s.label.clone(),
                reason,
            };
            let n = s.points.len();
            let z: &[f64] = match &s.z {
                Some(z) => z,
                None if n == 0 => &[],
                None => return Err(fail("a surface panel needs a z value per point".to_owned())),
            };
            if z.len() != n {
                return Err(fail(format!("{n} points but {} z values", z.len())));
            }
            if let Some((rows, cols)) = s.grid {
                if rows.checked_mul(cols) != Some(n) {
                    return Err(fail(format!(
                        "a {rows}×{cols} grid does not match {n} points"
                    )));
                }
            }
            Ok(z)
        })
        .collect()
}

/// Unit screen direction of `d`; horizontal only when `horizontal` (the upright z axis).
pub(super) fn outward((dx, dy): (f64, f64), horizontal: bool) -> (f64, f64) {
    let (dx, dy) = if horizontal { (dx, 0.0) } else { (dx, dy) };
    let length = dx.hypot(dy);
    if length > 0.0 {
        (dx / length, dy / length)
    } else {
        (0.0, 1.0)
    }
}
