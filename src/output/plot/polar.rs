//! Polar panels: the lobe in the plane of incidence. A point (θ, v) is drawn at angle θ from
//! the vertical normal and radius r(v), and again at −θ, so a curve over [0, π/2] becomes a
//! symmetric lobe over the upper half-disc. r is linear in the displayed value from the
//! radius axis' low end (the centre) to its high end (the rim): v on a linear scale, log₁₀ v
//! on a log scale, where values below the floor sit at the centre.
//!
//! Drawn: grid arcs at the radius ticks (and at 2…9 × 10ᵏ on a log scale), spokes at the
//! angle ticks, the rim and the sector's edges in the frame colour, angle labels outside the
//! rim, radius labels beside both edges (below the baseline of a half-disc) and the y label
//! under them, centred. The sector keeps a 1:1 aspect, centred in the panel. The x label is
//! not drawn: the angle labels carry their unit.

use std::f64::consts::FRAC_PI_2;

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::axis::Axis;
use super::clip::pieces;
use super::legend::{Covered, Legend, Outside, Sample, Setting, Side};
use super::mathtext;
use super::style::{Metrics, stroke};
use super::text::{anchor_towards, text_box, text_size};
use super::theme::Look;
use super::{PlotError, draw_err};
use crate::pipeline::figure::Panel;
use crate::spec::look::AXIS_LABEL_EM;
use crate::spec::look::{Mark, Scale, XUnit};

/// Angle steps tried for spokes and labels, in degrees, finest first.
const ANGLE_STEPS_DEG: [f64; 4] = [15.0, 30.0, 45.0, 90.0];
/// Free space between neighbouring angle labels along the rim, in base text sizes.
const ANGLE_CLEARANCE_EM: f64 = 0.8;
/// Minimum distance between radius labels along an edge, centre to centre, in base text sizes.
const RADIUS_SPACING_EM: f64 = 3.0;
/// Largest distance in CSS pixels between an arc's chords and its circle: a quarter of an
/// output pixel at the default PNG scale of 2, the tolerance curves are sampled to. Chords this
/// long (≈ 15 px on a 230 px rim) keep the arcs as smooth as the curves; chords of a pixel or
/// two, snapped to whole device units, would wobble.
const ARC_TOLERANCE_PX: f64 = 0.125;
/// Widest angle label, used to lay out the rim before the angle step is known.
const TYPICAL_ANGLE_LABEL: &str = "−5π/12";

/// Draws a polar panel: grid, each series as a mirrored lobe in its mark and look, frame,
/// labels and legend. Bars have no polar form and are an error.
pub(super) fn draw_polar<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    panel: &Panel,
    looks: &[Look],
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    if let Some(bars) = panel.series.iter().find(|s| s.style.mark == Mark::Bars) {
        return Err(PlotError::Series {
            label: bars.label.clone(),
            reason: "bars cannot be drawn in a polar panel (use line, points or line_points)"
                .to_owned(),
        });
    }
    let tick_font = m.font(1.0);
    let label_font = m.font(AXIS_LABEL_EM);
    let text = |s: &str, font: &TextStyle| text_size(area, s, font);
    let gap = f64::from(m.px(0.4));
    let (_, tick_h) = text("0", &tick_font)?;
    let label_h = if panel.axes.y_label.is_empty() {
        0.0
    } else {
        text(&panel.axes.y_label, &label_font)?.1 + gap
    };
    let (width, height) = area.dim_in_pixel();
    let (width, height) = (f64::from(width), f64::from(height));
    let (a, b) = theta_range(panel);

    let legend = Legend::of_panel(area, panel, looks, |s| Sample::of(s.style.mark), m)?;
    let inset = Legend::inset(m);
    // The sector, and where the legend goes: over the panel in a top corner clear of the rim
    // and its labels, else outside the sector, where the sector is largest.
    let layout = |side: f64| {
        let fit = |size| {
            Sector::fit(
                size,
                b,
                side,
                2.0 * gap + tick_h,
                tick_h + 2.0 * gap + label_h,
            )
        };
        let full = fit((width, height));
        let Some(legend) = &legend else {
            return (full, None);
        };
        let (w, h) = legend.size(Setting::FULL, m);
        let (w, h) = (w + 2.0 * inset, h + 2.0 * inset);
        let near = (
            full.centre.0.clamp(width - w, width),
            full.centre.1.clamp(0.0, h),
        );
        let (dx, dy) = (near.0 - full.centre.0, full.centre.1 - near.1);
        // Clear of the rim and its labels, or wholly beside the sector's edge and its labels.
        let beyond_rim = dx.hypot(dy) >= full.r + side;
        let beside_edge = (width - w - full.centre.0).atan2(full.centre.1) >= b + side / full.r;
        let clear = beyond_rim || beside_edge;
        if clear && w <= width && h <= height {
            return (full, None);
        }
        let outside = legend.outside((width, height), m, |w, h| Some(fit((w, h)).r));
        let (w, h) = outside.strip;
        let sector = match outside.side {
            Side::Right => fit((width - w, height)),
            Side::Below => fit((width, height - h)),
        };
        (sector, Some(outside))
    };

    // A first layout with the widest likely angle label fixes the angle step and the radius
    // ticks; the final one makes room for the labels actually drawn.
    let (first, _) = layout(2.0 * gap + text(TYPICAL_ANGLE_LABEL, &tick_font)?.0);
    let radius = Axis::radius(panel, first.r / (RADIUS_SPACING_EM * m.unit) + 1.0);
    let step = {
        let mut step = ANGLE_STEPS_DEG[ANGLE_STEPS_DEG.len() - 1];
        for candidate in ANGLE_STEPS_DEG {
            let mut widest = 0.0f64;
            for phi in angle_ticks(b, candidate) {
                widest = widest.max(text(&angle_label(phi, panel.axes.x_unit), &tick_font)?.0);
            }
            if first.r * candidate.to_radians() >= widest + ANGLE_CLEARANCE_EM * m.unit {
                step = candidate;
                break;
            }
        }
        step
    };
    let angles = angle_ticks(b, step);
    let mut side = 0.0f64;
    for &phi in &angles {
        side = side.max(text(&angle_label(phi, panel.axes.x_unit), &tick_font)?.0);
    }
    if let Some(&rim) = radius.ticks.last() {
        side = side.max(text(&radius.label(rim), &tick_font)?.0 / 2.0);
    }
    let (sector, place) = layout(side + 2.0 * gap);
    let to_r = |rho: f64| sector.r * (rho - radius.lo) / (radius.hi - radius.lo);
    let arc = |r: f64| -> Vec<(i32, i32)> {
        // A chord over angle δ strays r (1 − cos δ/2) ≈ r δ²/8 from the circle. An even count,
        // so that the top of the arc is a vertex.
        let delta = (8.0 * ARC_TOLERANCE_PX * m.k / r.max(1.0)).sqrt();
        let n = ((b / delta).ceil() as usize).max(4) * 2;
        (0..=n)
            .map(|i| sector.px(r, -b + 2.0 * b * i as f64 / n as f64))
            .collect()
    };
    // Everything drawn, in area pixels, for the legend to avoid.
    let mut covered = Covered::default();

    // Grid: arcs at the radius ticks, spokes at the angle ticks.
    for (values, colour) in [
        (&radius.minor, m.palette.minor_grid),
        (&radius.ticks, m.palette.grid),
    ] {
        for &rho in values {
            let r = to_r(rho);
            if r > 0.5 && r < sector.r - 0.5 {
                area.draw(&PathElement::new(arc(r), m.line(colour)))
                    .map_err(draw_err)?;
            }
        }
    }
    for &phi in angles.iter().filter(|phi| phi.abs() < b) {
        let spoke = [sector.px(0.0, phi), sector.px(sector.r, phi)];
        area.draw(&PathElement::new(spoke, m.line(m.palette.grid)))
            .map_err(draw_err)?;
    }

    // Series: each visible piece and its mirror image, one path when they meet at the normal.
    for (series, look) in panel.series.iter().zip(looks) {
        let mark = series.style.mark;
        let radial = |v: f64| radial_value(v, panel.axes.y_scale, radius.lo);
        if matches!(mark, Mark::Line | Mark::LinePoints) {
            let style = m.curve_style(look.colour, series.style.width);
            let points = series
                .points
                .iter()
                .map(|&(theta, v)| theta.is_finite().then_some(theta).zip(radial(v)));
            for piece in pieces(points, [a, b, radius.lo, radius.hi]) {
                let place = |&(theta, rho): &(f64, f64)| sector.px(to_r(rho), theta);
                let mirror = |&(theta, rho): &(f64, f64)| sector.px(to_r(rho), -theta);
                let right: Vec<(i32, i32)> = piece.iter().map(place).collect();
                let mut left: Vec<(i32, i32)> = piece.iter().rev().map(mirror).collect();
                let paths = if piece[0].0 == 0.0 {
                    left.extend(&right[1..]);
                    vec![left]
                } else {
                    vec![left, right]
                };
                for path in paths {
                    covered.add(&path);
                    stroke(area, path, style, look.pattern)?;
                }
            }
        }
        if matches!(mark, Mark::Points | Mark::LinePoints) {
            let dot = m.mark_dot(mark);
            let fill = m.fill(look.colour, 1.0);
            for &(theta, v) in series.points.iter() {
                let Some(rho) = radial(v).filter(|rho| *rho <= radius.hi) else {
                    continue;
                };
                if !(a..=b).contains(&theta) {
                    continue;
                }
                let sides: &[f64] = if theta == 0.0 { &[1.0] } else { &[1.0, -1.0] };
                for &sign in sides {
                    let (x, y) = sector.px(to_r(rho), sign * theta);
                    area.draw(&Circle::new((x, y), dot, fill))
                        .map_err(draw_err)?;
                    covered.add(&[(x - dot as i32, y), (x + dot as i32, y)]);
                }
            }
        }
    }

    // Frame: the rim and the sector's edges (the baseline of a half-disc).
    let frame = m.line(m.palette.frame);
    let rim = arc(sector.r);
    area.draw(&PathElement::new(rim.clone(), frame))
        .map_err(draw_err)?;
    covered.add(&rim);
    for phi in [-b, b] {
        let edge = [sector.px(0.0, phi), sector.px(sector.r, phi)];
        area.draw(&PathElement::new(edge, frame))
            .map_err(draw_err)?;
    }

    // Angle labels outside the rim; the ends of a half-disc's baseline carry theirs above it.
    for &phi in &angles {
        let out = (phi.sin(), -phi.cos());
        let (pos, corner) = if out.1.abs() < 1e-9 {
            let h = if out.0 > 0.0 { HPos::Left } else { HPos::Right };
            (
                Pos::new(h, VPos::Bottom),
                (f64::from(u8::from(out.0 < 0.0)), 1.0),
            )
        } else {
            anchor_towards(out)
        };
        let reach = sector.r + gap;
        let at = (
            sector.centre.0 + reach * out.0,
            sector.centre.1 + reach * out.1 - if out.1.abs() < 1e-9 { gap } else { 0.0 },
        );
        let label = angle_label(phi, panel.axes.x_unit);
        mathtext::draw(area, &label, &tick_font.pos(pos), at, m)?;
        covered.add(&text_box(at, text(&label, &tick_font)?, corner));
    }

    // Radius labels beside both edges, set off from the sector; the centre's once. A label that
    // would touch the one before it on its edge is left out (on a small sector, every other).
    let mut last: [Option<[(i32, i32); 5]>; 2] = [None, None];
    let clear = |a: &[(i32, i32); 5], b: &[(i32, i32); 5]| {
        let spacing = gap.round() as i32;
        a[1].0 + spacing <= b[0].0
            || b[1].0 + spacing <= a[0].0
            || a[2].1 + spacing <= b[0].1
            || b[2].1 + spacing <= a[0].1
    };
    for &rho in &radius.ticks {
        let r = to_r(rho);
        let label = radius.label(rho);
        let size = text(&label, &tick_font)?;
        let sides: &[f64] = if r < 0.5 { &[1.0] } else { &[1.0, -1.0] };
        let boxes: Vec<[(i32, i32); 5]> = sides
            .iter()
            .map(|&sign| {
                let phi = sign * b;
                let normal = if r < 0.5 {
                    (0.0, 1.0)
                } else {
                    (sign * b.cos(), b.sin())
                };
                let (x, y) = sector.px_f(r, phi);
                let at = (x + gap * normal.0, y + gap * normal.1);
                text_box(at, size, anchor_towards(normal).1)
            })
            .collect();
        let crowded = boxes.iter().zip(sides).any(|(bx, &sign)| {
            let edge = usize::from(sign < 0.0);
            last[edge].as_ref().is_some_and(|prev| !clear(prev, bx))
                || (r < 0.5 && last[1].as_ref().is_some_and(|prev| !clear(prev, bx)))
        });
        if crowded {
            continue;
        }
        for (bx, &sign) in boxes.iter().zip(sides) {
            last[usize::from(sign < 0.0)] = Some(*bx);
        }
        if r < 0.5 {
            last[1] = Some(boxes[0]);
        }
        for &sign in sides {
            let phi = sign * b;
            let normal = if r < 0.5 {
                (0.0, 1.0)
            } else {
                (sign * b.cos(), b.sin())
            };
            let (x, y) = sector.px_f(r, phi);
            let at = (x + gap * normal.0, y + gap * normal.1);
            let (pos, corner) = anchor_towards(normal);
            mathtext::draw(area, &label, &tick_font.pos(pos), at, m)?;
            covered.add(&text_box(at, size, corner));
        }
    }
    if !panel.axes.y_label.is_empty() {
        let at = (
            sector.centre.0,
            sector.centre.1 + 2.0 * gap + tick_h + label_h / 2.0,
        );
        let centred = label_font.pos(Pos::new(HPos::Center, VPos::Center));
        mathtext::draw(area, &panel.axes.y_label, &centred, at, m)?;
    }

    let Some(legend) = legend else {
        return Ok(());
    };
    match place {
        None => legend.draw_over(area, &covered.0, m),
        Some(Outside {
            side,
            setting,
            strip,
        }) => {
            let (box_w, box_h) = legend.size(setting, m);
            let at = match side {
                // Level with the middle of the sector's height, as far as the area allows.
                Side::Right => (
                    width - strip.0 + inset,
                    (sector.centre.1 - sector.r / 2.0 - box_h / 2.0)
                        .clamp(inset, (height - inset - box_h).max(inset)),
                ),
                Side::Below => ((width - box_w) / 2.0, height - strip.1 + inset),
            };
            legend.draw(area, at, setting, m, side.placed())
        }
    }
}

/// Where the sector sits in its area: the centre (on the normal, at the sector's bottom) and
/// the rim's radius, in area pixels.
#[derive(Debug, Clone, Copy)]
struct Sector {
    centre: (f64, f64),
    r: f64,
}

impl Sector {
    /// The largest sector over [−b, b] that fits an area of `(width, height)` with `side`
    /// pixels free left and right of it, `top` above and `bottom` below, centred in what is left.
    fn fit((width, height): (f64, f64), b: f64, side: f64, top: f64, bottom: f64) -> Sector {
        let half_width = b.sin().max(f64::MIN_POSITIVE);
        let r = ((width - 2.0 * side) / (2.0 * half_width))
            .min(height - top - bottom)
            .max(1.0);
        let spare = (height - top - bottom - r).max(0.0);
        Sector {
            centre: (width / 2.0, top + spare / 2.0 + r),
            r,
        }
    }

    /// The point at radius `r` pixels and angle `phi` from the upward normal, unrounded.
    fn px_f(&self, r: f64, phi: f64) -> (f64, f64) {
        let (sin, cos) = phi.sin_cos();
        (self.centre.0 + r * sin, self.centre.1 - r * cos)
    }

    /// The point at radius `r` pixels and angle `phi`, in whole pixels.
    fn px(&self, r: f64, phi: f64) -> (i32, i32) {
        let (x, y) = self.px_f(r, phi);
        (x.round() as i32, y.round() as i32)
    }
}

/// The θ range shown: `Panel::x_range` within [0, π/2], ends in either order; [0, π/2] when
/// not given or empty.
fn theta_range(panel: &Panel) -> (f64, f64) {
    match panel.axes.x_range {
        Some((p, q)) => {
            let (a, b) = (p.min(q).max(0.0), p.max(q).min(FRAC_PI_2));
            if b > a { (a, b) } else { (0.0, FRAC_PI_2) }
        }
        None => (0.0, FRAC_PI_2),
    }
}

/// The radius coordinate of value `v` on `scale`: its display value, or `floor` (the centre)
/// when it is below the floor or, on a log scale, ≤ 0; `None` when it is not finite.
fn radial_value(v: f64, scale: Scale, floor: f64) -> Option<f64> {
    if !v.is_finite() {
        return None;
    }
    Some(scale.display(v).map_or(floor, |rho| rho.max(floor)))
}

/// The angle ticks in [−b, b], multiples of `step_deg` degrees, in radians.
fn angle_ticks(b: f64, step_deg: f64) -> Vec<f64> {
    let last = (b.to_degrees() / step_deg + 1e-9).floor() as i32;
    (-last..=last)
        .map(|i| (f64::from(i) * step_deg).to_radians())
        .collect()
}

/// The label of angle `phi` (radians, a multiple of 15°): degrees (`−30°`) on a degree axis,
/// else a fraction of π (`π/6`, `5π/12`).
fn angle_label(phi: f64, unit: XUnit) -> String {
    let twelfths = (phi.to_degrees() / 15.0).round() as i64;
    let sign = if twelfths < 0 { "−" } else { "" };
    if unit == XUnit::Degrees {
        return format!("{sign}{}°", 15 * twelfths.abs());
    }
    let divisor = gcd(twelfths.abs(), 12);
    match (twelfths.abs() / divisor.max(1), 12 / divisor.max(1)) {
        (0, _) => "0".to_owned(),
        (1, 1) => format!("{sign}π"),
        (n, 1) => format!("{sign}{n}π"),
        (1, d) => format!("{sign}π/{d}"),
        (n, d) => format!("{sign}{n}π/{d}"),
    }
}

/// Greatest common divisor (Euclid).
fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 { a } else { gcd(b, a % b) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::plot::fixtures::draw_png;
    use crate::output::plot::fixtures::{
        BLUE, RED, figure, marked, panel, polar_sample, sampled, series,
    };
    use crate::output::plot::svg;
    use crate::pipeline::figure::{Figure, Series};
    use crate::spec::look::{Dash, PanelKind};

    #[test]
    fn angle_labels_read_in_degrees_or_fractions_of_pi() {
        let label = |deg: f64, unit| angle_label(deg.to_radians(), unit);
        assert_eq!(label(30.0, XUnit::Degrees), "30°");
        assert_eq!(label(-90.0, XUnit::Degrees), "−90°");
        assert_eq!(label(0.0, XUnit::Radians), "0");
        assert_eq!(label(30.0, XUnit::Radians), "π/6");
        assert_eq!(label(-75.0, XUnit::Radians), "−5π/12");
        assert_eq!(label(90.0, XUnit::Radians), "π/2");
        assert_eq!(label(180.0, XUnit::Radians), "π");
        assert_eq!(angle_ticks(FRAC_PI_2, 30.0).len(), 7);
    }

    /// The points of the SVG polylines stroked in `hex`, per polyline.
    fn polylines(svg: &str, hex: u32) -> Vec<Vec<(i32, i32)>> {
        let stroke = format!(r##"stroke="#{hex:06X}""##);
        svg.lines()
            .filter(|l| l.starts_with("<polyline") && l.contains(&stroke))
            .map(|l| {
                let points = l.split("points=\"").nth(1).unwrap_or_default();
                points
                    .split_whitespace()
                    .filter_map(|p| p.split_once(','))
                    .map(|(x, y)| (x.parse().unwrap(), y.parse().unwrap()))
                    .collect()
            })
            .collect()
    }

    /// A one-panel polar figure of `series`.
    fn polar(series: Vec<Series>, y_scale: Scale, y_range: Option<(f64, f64)>) -> Figure {
        let mut p = panel(XUnit::Degrees, y_scale, series);
        p.axes.kind = PanelKind::Polar;
        p.axes.y_range = y_range;
        p.axes.legend = crate::spec::look::LegendPlace::None;
        figure(vec![p])
    }

    #[test]
    fn a_lobe_peaks_on_the_normal_at_its_radius_and_is_mirrored() {
        // r = cos θ on a radius range [0, 1]: the peak touches the rim at the top.
        let lobe = series("cos", BLUE, 1.0, Dash::Solid, sampled(f64::cos));
        let text =
            String::from_utf8(svg(&polar(vec![lobe], Scale::Linear, Some((0.0, 1.0)))).unwrap())
                .unwrap();
        let curve = polylines(&text, BLUE);
        assert_eq!(curve.len(), 1, "one path through the normal");
        let curve = &curve[0];
        let rim = polylines(&text, 0x555555)
            .into_iter()
            .max_by_key(|p| p.len())
            .unwrap();
        let top = |p: &[(i32, i32)]| *p.iter().min_by_key(|q| q.1).unwrap();
        let middle = |p: &[(i32, i32)]| p[p.len() / 2];
        let (peak, rim_top) = (middle(curve), middle(&rim));
        assert_eq!(peak, rim_top, "the peak is the top of the rim");
        assert_eq!(top(curve).1, peak.1);
        let centre_x = rim_top.0;
        let (first, last) = (curve[0], curve[curve.len() - 1]);
        assert_eq!(first.1, last.1);
        assert!(
            (first.0 + last.0 - 2 * centre_x).abs() <= 1,
            "mirror images"
        );
        for (a, b) in curve.iter().zip(curve.iter().rev()) {
            assert!((a.0 + b.0 - 2 * centre_x).abs() <= 1 && a.1 == b.1);
        }
        // A half-radius value sits halfway from the centre (the ends of the baseline) to the rim.
        let baseline = first.1;
        let half = series("half", RED, 1.0, Dash::Solid, sampled(|_| 0.5));
        let half_text =
            String::from_utf8(svg(&polar(vec![half], Scale::Linear, Some((0.0, 1.0)))).unwrap())
                .unwrap();
        let arc = &polylines(&half_text, RED)[0];
        let radius = f64::from(baseline - top(arc).1);
        assert!((radius - f64::from(baseline - rim_top.1) / 2.0).abs() <= 1.0);
    }

    #[test]
    fn polar_panels_label_angles_and_radii_and_render_deterministically() {
        let figure = polar_sample();
        let svg0 = String::from_utf8(svg(&figure).unwrap()).unwrap();
        // D(θ) is typeset: an italic D and θ around upright brackets.
        for label in [
            "30°", "−30°", "90°", "π/6", "−π/3", "π/2", "10⁰", "D", "θ", ")",
        ] {
            assert!(svg0.contains(&format!(">{label}</text>")), "{label}");
        }
        assert!(svg0.contains(r#"font-style="oblique""#));
        assert!(svg(&figure).unwrap() == svg0.into_bytes());
        assert!(draw_png(&figure).unwrap() == draw_png(&figure).unwrap());
    }

    #[test]
    fn log_radii_start_at_most_four_decades_below_the_peak() {
        // Phong 100 peaks at 16: the centre is 10⁻³, the rim 10².
        let p = polar_sample().panels[1].clone();
        let axis = Axis::radius(&p, 8.0);
        assert_eq!((axis.lo, axis.hi), (-3.0, 2.0));
        assert_eq!(radial_value(0.0, Scale::Log, axis.lo), Some(-3.0));
        assert_eq!(radial_value(1e-9, Scale::Log, axis.lo), Some(-3.0));
        assert_eq!(radial_value(f64::NAN, Scale::Log, axis.lo), None);
    }

    #[test]
    fn bars_are_refused_and_odd_panels_render() {
        let bars = marked(
            series("bars", RED, 1.0, Dash::Solid, sampled(f64::cos)),
            Mark::Bars,
        );
        let refused = svg(&polar(vec![bars], Scale::Linear, None));
        assert!(matches!(refused, Err(PlotError::Series { label, .. }) if label == "bars"));
        let dots = marked(
            series("dots", RED, 1.0, Dash::Dotted, sampled(f64::cos)),
            Mark::LinePoints,
        );
        let zeros = series("zeros", BLUE, 1.0, Dash::Solid, sampled(|_| 0.0));
        let mut narrow = polar(vec![dots.clone()], Scale::Linear, None);
        narrow.panels[0].axes.x_range = Some((0.2, 0.6));
        for figure in [
            polar(vec![zeros.clone()], Scale::Log, None),
            polar(vec![zeros, dots], Scale::Linear, Some((2.0, 3.0))),
            polar(Vec::new(), Scale::Log, None),
            narrow,
        ] {
            svg(&figure).unwrap();
            draw_png(&figure).unwrap();
        }
    }
}
