//! Placing labels: the anchor of a label set off in a direction from its point, the box it
//! then covers (for the legend to avoid), and the size and lines at which a title fits its width.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::{PlotError, draw_err, mathtext};

/// Width and height in device pixels of `text` typeset in `font` on `area` ([`mathtext`]): the
/// height is that of the text at its own size.
pub(super) fn text_size<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    font: &TextStyle,
) -> Result<(f64, f64), PlotError>
where
    DB::ErrorType: 'static,
{
    let (w, h) = area.estimate_text_size(text, font).map_err(draw_err)?;
    let width = if mathtext::has_markup(text) {
        mathtext::width(area, text, font)?
    } else {
        f64::from(w)
    };
    Ok((width, f64::from(h)))
}

/// Smallest size a title is shrunk to before it is wrapped, relative to its own: a fifth
/// smaller still reads as a heading (a figure title, 1.4 base sizes, stays above the axis
/// labels' 1.1); smaller, it would not.
pub(super) const MIN_SHRINK: f64 = 0.8;
/// Space between the lines of a wrapped title, in multiples of its size: the measured text
/// height already spans ascenders to descenders, so a small gap reads as one heading.
pub(super) const LINE_GAP_EM: f64 = 0.15;

/// The size and lines at which `text`, wanted at `size`, fits `width` (device pixels, as
/// `measure(text, size)` gives them): one line at `size` if it fits; else one line shrunk in
/// proportion, if that is at least [`MIN_SHRINK`] × `size`; else wrapped at spaces into
/// the fewest greedy lines at `size`, each shrunk alike if one still does not fit (a single
/// word wider than `width`).
pub(super) fn fit_text(
    text: &str,
    size: f64,
    width: f64,
    measure: impl Fn(&str, f64) -> Result<f64, PlotError>,
) -> Result<(f64, Vec<String>), PlotError> {
    let full = measure(text, size)?;
    if full <= width {
        return Ok((size, vec![text.to_owned()]));
    }
    // Text width is proportional to the size, up to the rounding of glyph advances: aim low.
    let shrunk = size * width / full * (1.0 - SHRINK_MARGIN);
    if shrunk >= MIN_SHRINK * size && measure(text, shrunk)? <= width {
        return Ok((shrunk, vec![text.to_owned()]));
    }
    let mut lines: Vec<String> = Vec::new();
    for word in text.split(' ') {
        match lines.last_mut() {
            Some(line) if measure(&format!("{line} {word}"), size)? <= width => {
                line.push(' ');
                line.push_str(word);
            }
            _ => lines.push(word.to_owned()),
        }
    }
    let mut widest = 0.0f64;
    for line in &lines {
        widest = widest.max(measure(line, size)?);
    }
    let size = if widest > width {
        size * width / widest * (1.0 - SHRINK_MARGIN)
    } else {
        size
    };
    Ok((size, lines))
}

/// Relative amount by which a shrunk size undershoots the proportional one, so that rounded
/// glyph advances cannot push the text back over its width.
const SHRINK_MARGIN: f64 = 0.01;

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

#[cfg(test)]
mod tests {
    use super::*;

    /// A monospaced face: every character is `size` wide.
    fn mono(text: &str, size: f64) -> Result<f64, PlotError> {
        Ok(text.chars().count() as f64 * size)
    }

    #[test]
    fn titles_fit_as_they_are_shrunk_or_wrapped() {
        let fit = |text: &str, width: f64| fit_text(text, 10.0, width, mono).unwrap();
        assert_eq!(fit("abc def", 70.0), (10.0, vec!["abc def".to_owned()]));
        // 10 % too wide: shrunk on one line.
        let (size, lines) = fit("abc def", 63.0);
        assert!(
            lines == ["abc def"]
                && (8.0..9.0).contains(&size)
                && mono("abc def", size).unwrap() <= 63.0
        );
        // Twice too wide: wrapped at spaces at the full size.
        let (size, lines) = fit("abc def ghi jk", 75.0);
        assert_eq!(
            (size, lines),
            (10.0, vec!["abc def".to_owned(), "ghi jk".to_owned()])
        );
        // A single word wider than the width: its line is shrunk.
        let (size, lines) = fit("abcdefghijklmnop qr", 80.0);
        assert_eq!(lines, ["abcdefghijklmnop", "qr"]);
        assert!(mono("abcdefghijklmnop", size).unwrap() <= 80.0);
    }
}
