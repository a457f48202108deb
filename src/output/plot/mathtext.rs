//! Math text: `_` and `^` followed by one character or a `{…}` group write that character or group
//! as a real sub- or superscript (smaller, on a shifted baseline); groups nest (`cos^{α_p} θ`).
//! `\_`, `\^`, `\{`, `\}` and `\\` write the character itself, and so does a `_` or `^` with
//! nothing after it.
//!
//! Text is cut into runs of one size and baseline ([`parse`]); [`width`] measures them and
//! [`draw`] draws them one after the other with the face of the figure, so SVG, PNG and PDF (drawn
//! from the SVG) all show the same typeset label.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::lint::{Rect, record_text};
use super::style::Metrics;
use super::{PlotError, draw_err};

/// Size of a script relative to the text it is attached to.
pub(super) const SCRIPT_SCALE: f64 = 0.7;
/// How far a subscript's baseline drops, in units of the size of the text it is attached to.
pub(super) const SUB_DROP: f64 = 0.2;
/// How far a superscript's baseline rises, in units of the size of the text it is attached to.
pub(super) const SUP_RISE: f64 = 0.38;
/// Where the backends put the baseline below a `VPos::Top` anchor, in units of the text size
/// (plotters' SVG backend: 0.76 em of size/1.24, ≈ 0.61; its raster text: the ascent share of
/// DejaVu Sans, ≈ 0.80): the mean, so that a script sits within 0.03 sizes of its place in both.
const TOP_TO_BASELINE: f64 = 0.7;

/// A piece of text drawn at one size and baseline.
#[derive(Debug, Clone, PartialEq)]
pub(super) struct Run {
    /// The characters, markup removed.
    pub(super) text: String,
    /// Size relative to the label's.
    pub(super) scale: f64,
    /// Baseline above the label's, in units of the label's size (negative: below).
    pub(super) rise: f64,
}

/// Whether `text` holds markup that [`parse`] typesets or unescapes.
pub(super) fn has_markup(text: &str) -> bool {
    text.contains(['_', '^', '\\'])
}

/// The runs of `text`, in order; adjacent characters of one size and baseline share a run.
pub(super) fn parse(text: &str) -> Vec<Run> {
    let chars: Vec<char> = text.chars().collect();
    let mut runs = Vec::new();
    parse_into(&chars, 1.0, 0.0, &mut runs);
    runs
}

fn push(runs: &mut Vec<Run>, c: char, scale: f64, rise: f64) {
    match runs.last_mut() {
        Some(last) if last.scale == scale && last.rise == rise => last.text.push(c),
        _ => runs.push(Run {
            text: c.to_string(),
            scale,
            rise,
        }),
    }
}

/// The index just past the group that opens at `chars[open]` (`{`), and the group's contents'
/// range; an unclosed group runs to the end.
fn group(chars: &[char], open: usize) -> (usize, std::ops::Range<usize>) {
    let mut depth = 0;
    let mut i = open;
    while i < chars.len() {
        match chars[i] {
            '\\' => i += 1,
            '{' => depth += 1,
            '}' => {
                depth -= 1;
                if depth == 0 {
                    return (i + 1, open + 1..i);
                }
            }
            _ => {}
        }
        i += 1;
    }
    (chars.len(), open + 1..chars.len())
}

fn parse_into(chars: &[char], scale: f64, rise: f64, runs: &mut Vec<Run>) {
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        match c {
            '\\' if i + 1 < chars.len() => {
                push(runs, chars[i + 1], scale, rise);
                i += 2;
            }
            '_' | '^' if i + 1 < chars.len() && !chars[i + 1].is_whitespace() => {
                let shift = if c == '_' { -SUB_DROP } else { SUP_RISE };
                let (inner_scale, inner_rise) = (scale * SCRIPT_SCALE, rise + shift * scale);
                if chars[i + 1] == '{' {
                    let (next, inside) = group(chars, i + 1);
                    parse_into(&chars[inside], inner_scale, inner_rise, runs);
                    i = next;
                } else {
                    push(runs, chars[i + 1], inner_scale, inner_rise);
                    i += 2;
                }
            }
            _ => {
                push(runs, c, scale, rise);
                i += 1;
            }
        }
    }
}

/// The width in device pixels of `text` typeset in `font`.
pub(super) fn width<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    font: &TextStyle,
) -> Result<f64, PlotError>
where
    DB::ErrorType: 'static,
{
    let mut total = 0.0;
    for run in parse(text) {
        let (w, _) = area
            .estimate_text_size(&run.text, &scaled(font, run.scale))
            .map_err(draw_err)?;
        total += f64::from(w);
    }
    Ok(total)
}

/// `font` at `scale` times its size.
fn scaled<'a>(font: &TextStyle<'a>, scale: f64) -> TextStyle<'a> {
    if scale == 1.0 {
        return font.clone();
    }
    let size = font.font.get_size() * scale;
    TextStyle {
        font: font.font.clone().resize(size),
        ..font.clone()
    }
}

/// Draws `text` typeset in `style` at `at` (area pixels), placed by the style's anchor as plotters
/// places plain text (the anchor's horizontal part along the text, also when the style turns it
/// 270° to read upwards); a label without markup is one plotters text call.
pub(super) fn draw<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    style: &TextStyle,
    at: (f64, f64),
    m: &Metrics,
) -> Result<(), PlotError>
where
    DB::ErrorType: 'static,
{
    let point = |x: f64, y: f64| (x.round() as i32, y.round() as i32);
    let upwards = matches!(style.font.get_transform(), FontTransform::Rotate270);
    if m.trace.is_some() && !text.is_empty() {
        let (_, h) = area.estimate_text_size(text, style).map_err(draw_err)?;
        let shown: String = parse(text).into_iter().map(|r| r.text).collect();
        let base = area.get_base_pixel();
        let rect = placed(
            (f64::from(base.0) + at.0, f64::from(base.1) + at.1),
            (width(area, text, style)?, f64::from(h)),
            (style.pos.h_pos, style.pos.v_pos),
            upwards,
        );
        record_text(&m.trace, &shown, text, rect);
    }
    if !has_markup(text) {
        return area
            .draw_text(text, style, point(at.0, at.1))
            .map_err(draw_err);
    }
    let total = width(area, text, style)?;
    let start = match style.pos.h_pos {
        HPos::Left => 0.0,
        HPos::Center => -total / 2.0,
        HPos::Right => -total,
    };
    let size = style.font.get_size();
    let mut along = start;
    for run in parse(text) {
        let run_style = scaled(style, run.scale).pos(Pos::new(HPos::Left, style.pos.v_pos));
        let (w, _) = area
            .estimate_text_size(&run.text, &run_style)
            .map_err(draw_err)?;
        // Same anchor for every run: a smaller run's baseline sits TOP_TO_BASELINE × the size
        // difference higher, which the offset puts back, and `rise` then lifts it.
        let across = TOP_TO_BASELINE * size * (1.0 - run.scale) - run.rise * size;
        let (x, y) = if upwards {
            (at.0 + across, at.1 - along)
        } else {
            (at.0 + along, at.1 + across)
        };
        area.draw_text(&run.text, &run_style, point(x, y))
            .map_err(draw_err)?;
        along += f64::from(w);
    }
    Ok(())
}

/// The box of a label of `(along, across)` extent anchored at `at` as plotters anchors text
/// (`h` along the text, `v` across it), upright or reading upwards: left, top, right, bottom.
pub(super) fn placed(
    at: (f64, f64),
    (along, across): (f64, f64),
    (h, v): (HPos, VPos),
    upwards: bool,
) -> Rect {
    let start = match h {
        HPos::Left => 0.0,
        HPos::Center => -along / 2.0,
        HPos::Right => -along,
    };
    let near = match v {
        VPos::Top => 0.0,
        VPos::Center => -across / 2.0,
        VPos::Bottom => -across,
    };
    if upwards {
        // Along the text is up the page; its top faces left.
        [
            at.0 + near,
            at.1 - start - along,
            at.0 + near + across,
            at.1 - start,
        ]
    } else {
        [
            at.0 + start,
            at.1 + near,
            at.0 + start + along,
            at.1 + near + across,
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The characters `text` shows, markup resolved.
    fn plain(text: &str) -> String {
        parse(text).into_iter().map(|r| r.text).collect()
    }

    fn run(text: &str, scale: f64, rise: f64) -> Run {
        Run {
            text: text.to_owned(),
            scale,
            rise,
        }
    }

    #[test]
    fn scripts_take_one_character_or_a_group_and_nest() {
        assert_eq!(
            parse("α_b = 0.3"),
            [
                run("α", 1.0, 0.0),
                run("b", 0.7, -0.2),
                run(" = 0.3", 1.0, 0.0)
            ]
        );
        assert_eq!(
            parse("D_{ABC}(θ)"),
            [
                run("D", 1.0, 0.0),
                run("ABC", 0.7, -0.2),
                run("(θ)", 1.0, 0.0)
            ]
        );
        let nested = parse("cos^{α_p} θ");
        assert_eq!(nested[0], run("cos", 1.0, 0.0));
        assert_eq!(nested[1], run("α", 0.7, 0.38));
        assert!((nested[2].scale - 0.49).abs() < 1e-12);
        assert!((nested[2].rise - (0.38 - 0.2 * 0.7)).abs() < 1e-12);
        assert_eq!(nested[3], run(" θ", 1.0, 0.0));
    }

    #[test]
    fn escapes_and_dangling_marks_are_literal() {
        assert_eq!(plain(r"snake\_case"), "snake_case");
        assert_eq!(parse(r"a\^b"), [run("a^b", 1.0, 0.0)]);
        assert_eq!(plain("x_ y^"), "x_ y^");
        assert_eq!(plain("x_{unclosed"), "xunclosed");
        assert_eq!(plain("α_{tr} = 0.3"), "αtr = 0.3");
        assert!(!has_markup("a₁ = 10") && has_markup("α_b"));
    }
}
