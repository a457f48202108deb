//! Curves cut to what is visible: broken at points that cannot be drawn and clipped to the
//! axes box (Liang–Barsky), in display coordinates.

use super::axis::{Axis, x_display};
use crate::pipeline::figure::{Panel, Series};

/// The drawable parts of `series` in display coordinates: broken at undrawable points
/// (non-finite, or ≤ 0 on a log axis) and clipped to the axes box.
pub(super) fn visible_pieces(
    series: &Series,
    panel: &Panel,
    x: &Axis,
    y: &Axis,
) -> Vec<Vec<(f64, f64)>> {
    let points = series
        .points
        .iter()
        .map(|&(theta, v)| x_display(theta, &panel.axes).zip(panel.axes.y_scale.display(v)));
    pieces(points, [x.lo, x.hi, y.lo, y.hi])
}

/// The unbroken parts of a polyline inside `bounds` = `[x0, x1, y0, y1]`: a `None` point
/// breaks it, a segment leaving the box ends a part and one entering it starts the next.
pub(super) fn pieces(
    points: impl Iterator<Item = Option<(f64, f64)>>,
    bounds: [f64; 4],
) -> Vec<Vec<(f64, f64)>> {
    let mut pieces = Vec::new();
    let mut current: Vec<(f64, f64)> = Vec::new();
    let mut flush = |current: &mut Vec<(f64, f64)>| {
        if current.len() >= 2 {
            pieces.push(std::mem::take(current));
        } else {
            current.clear();
        }
    };
    let mut previous: Option<(f64, f64)> = None;
    for point in points {
        match (previous, point) {
            (_, None) => flush(&mut current),
            (None, Some(p)) => {
                if clip(p, p, bounds).is_some() {
                    current.push(p);
                }
            }
            (Some(a), Some(b)) => match clip(a, b, bounds) {
                None => flush(&mut current),
                Some(Clipped {
                    start,
                    end,
                    entered,
                    left,
                }) => {
                    if entered {
                        flush(&mut current);
                    }
                    if current.is_empty() {
                        current.push(start);
                    }
                    current.push(end);
                    if left {
                        flush(&mut current);
                    }
                }
            },
        }
        previous = point;
    }
    flush(&mut current);
    pieces
}

/// The part of a segment inside a box.
pub(super) struct Clipped {
    pub(super) start: (f64, f64),
    pub(super) end: (f64, f64),
    /// The segment starts outside the box.
    pub(super) entered: bool,
    /// The segment ends outside the box.
    pub(super) left: bool,
}

/// Liang–Barsky: the part of segment a→b inside `[x0, x1] × [y0, y1]`.
pub(super) fn clip(a: (f64, f64), b: (f64, f64), [x0, x1, y0, y1]: [f64; 4]) -> Option<Clipped> {
    let (dx, dy) = (b.0 - a.0, b.1 - a.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (p, q) in [
        (-dx, a.0 - x0),
        (dx, x1 - a.0),
        (-dy, a.1 - y0),
        (dy, y1 - a.1),
    ] {
        if p == 0.0 {
            if q < 0.0 {
                return None;
            }
        } else {
            let t = q / p;
            if p < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    if t0 > t1 {
        return None;
    }
    let at = |t: f64| (a.0 + t * dx, a.1 + t * dy);
    Some(Clipped {
        start: at(t0),
        end: at(t1),
        entered: t0 > 0.0,
        left: t1 < 1.0,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::plot::fixtures::{RED, panel, series};
    use crate::spec::look::{Dash, Scale, XUnit};

    #[test]
    fn curves_break_at_undrawable_points_and_clip_to_the_axes() {
        let points = vec![
            (0.0, 1.0),
            (0.1, 2.0),
            (0.2, 0.0),
            (0.3, 2.0),
            (0.4, 20.0),
            (0.5, 2.0),
        ];
        let s = series("s", RED, 1.0, Dash::Solid, points);
        let mut p = panel(XUnit::Radians, Scale::Log, vec![s.clone()]);
        p.axes.y_range = Some((0.5, 10.0));
        let (x, y) = (Axis::x(&p, 8.0), Axis::y(&p, 8.0));
        let pieces = visible_pieces(&s, &p, &x, &y);
        assert_eq!(pieces.len(), 3);
        assert_eq!(pieces[0].len(), 2);
        let top = 1.0;
        assert!(
            pieces[1]
                .last()
                .is_some_and(|&(_, v)| (v - top).abs() < 1e-12)
        );
        assert!(
            pieces[2]
                .first()
                .is_some_and(|&(_, v)| (v - top).abs() < 1e-12)
        );
    }
}
