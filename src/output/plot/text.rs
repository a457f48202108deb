//! Placing labels: the anchor of a label set off in a direction from its point, and the box
//! it then covers (for the legend to avoid).

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::{PlotError, draw_err};

/// Width and height in device pixels of `text` in `font` on `area`.
pub(super) fn text_size<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    font: &TextStyle,
) -> Result<(f64, f64), PlotError>
where
    DB::ErrorType: 'static,
{
    area.estimate_text_size(text, font)
        .map(|(w, h)| (f64::from(w), f64::from(h)))
        .map_err(draw_err)
}

/// Sine of 22.5°: a label direction leaning less than this toward an axis counts as along it.
pub(super) const LEAN: f64 = 0.382_683_432_365_089_8;

/// The text anchor for a label set off in direction `out` from its point, and that anchor's
/// place in the label's box as fractions of its width and height (0 = left or top).
pub(super) fn anchor_towards((dx, dy): (f64, f64)) -> (Pos, (f64, f64)) {
    let (h, fx) = if dx > LEAN {
        (HPos::Left, 0.0)
    } else if dx < -LEAN {
        (HPos::Right, 1.0)
    } else {
        (HPos::Center, 0.5)
    };
    let (v, fy) = if dy > LEAN {
        (VPos::Top, 0.0)
    } else if dy < -LEAN {
        (VPos::Bottom, 1.0)
    } else {
        (VPos::Center, 0.5)
    };
    (Pos::new(h, v), (fx, fy))
}

/// The outline of a text box of `(w, h)` whose anchor at `at` sits at `(fx, fy)` in it.
pub(super) fn text_box(
    at: (f64, f64),
    (w, h): (f64, f64),
    (fx, fy): (f64, f64),
) -> [(i32, i32); 5] {
    let (x0, y0) = (at.0 - fx * w, at.1 - fy * h);
    let [x0, y0, x1, y1] = [x0, y0, x0 + w, y0 + h].map(|v| v.round() as i32);
    [(x0, y0), (x1, y0), (x1, y1), (x0, y1), (x0, y0)]
}
