//! Math text: `_` and `^` followed by one character or a `{…}` group write that character or group
//! as a real sub- or superscript (smaller, on a shifted baseline); groups nest (`cos^{α_p} θ`).
//! `\_`, `\^`, `\{`, `\}` and `\\` write the character itself, and so does a `_` or `^` with
//! nothing after it.
//!
//! Unicode subscripts (`a₁`, `F₀`, `log₁₀`) are set as `_` subscripts are, so that a label has one
//! kind of subscript whichever way it was written.
//!
//! Variables are italic, as TeX and matplotlib's mathtext set them: a letter (Latin or Greek) that
//! stands alone — not part of a word of two or more letters, nor the end of an elided word
//! (`notebook's`), nor a version hyphenated to a word (`pbrt-v4`) — is drawn in the oblique face (`D(θ)`, `α_p`, `G_1`, `Λ`); words (`cos`, `ln`, `radians`, `ABC`, `tr`) and digits stay upright, and so
//! does a lone `a`, `A` or `I` followed by a word (an article or pronoun in prose), a panel letter
//! opening a label (`(a)`), and π, Σ and Π (a constant and operators).
//!
//! Text is cut into runs of one size, baseline and slant ([`parse`]); [`width`] measures them and
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
    /// Set in the oblique face (a variable).
    pub(super) italic: bool,
}

/// Whether `text` holds markup that [`parse`] typesets or unescapes, or a variable it slants: text
/// without either is one plain run.
pub(super) fn has_markup(text: &str) -> bool {
    parse(text).len() > 1 || parse(text).first().is_some_and(|r| r.italic)
}

/// The plain character a Unicode subscript character stands for.
fn unsubscript(c: char) -> Option<char> {
    const SUBSCRIPTS: [(char, char); 25] = [
        ('₀', '0'),
        ('₁', '1'),
        ('₂', '2'),
        ('₃', '3'),
        ('₄', '4'),
        ('₅', '5'),
        ('₆', '6'),
        ('₇', '7'),
        ('₈', '8'),
        ('₉', '9'),
        ('₊', '+'),
        ('₋', '−'),
        ('₌', '='),
        ('₍', '('),
        ('₎', ')'),
        ('ₐ', 'a'),
        ('ₑ', 'e'),
        ('ₒ', 'o'),
        ('ₓ', 'x'),
        ('ₕ', 'h'),
        ('ₖ', 'k'),
        ('ₘ', 'm'),
        ('ₙ', 'n'),
        ('ₚ', 'p'),
        ('ₜ', 't'),
    ];
    SUBSCRIPTS.iter().find(|(s, _)| *s == c).map(|(_, p)| *p)
}

/// `text` with each run of Unicode subscript characters written as a `_{…}` group.
fn with_subscripts_marked(text: &str) -> std::borrow::Cow<'_, str> {
    if !text.chars().any(|c| unsubscript(c).is_some()) {
        return std::borrow::Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    let mut open = false;
    for c in text.chars() {
        match (unsubscript(c), open) {
            (Some(p), false) => {
                out.push_str("_{");
                out.push(p);
                open = true;
            }
            (Some(p), true) => out.push(p),
            (None, true) => {
                out.push('}');
                out.push(c);
                open = false;
            }
            (None, false) => out.push(c),
        }
    }
    if open {
        out.push('}');
    }
    std::borrow::Cow::Owned(out)
}

/// The runs of `text`, in order; adjacent characters of one size, baseline and slant share a run.
pub(super) fn parse(text: &str) -> Vec<Run> {
    let marked = with_subscripts_marked(text);
    let chars: Vec<char> = marked.chars().collect();
    let mut runs = Vec::new();
    parse_into(&chars, 1.0, 0.0, &mut runs);
    slant_variables(&mut runs);
    runs
}

fn push(runs: &mut Vec<Run>, c: char, scale: f64, rise: f64) {
    match runs.last_mut() {
        Some(last) if last.scale == scale && last.rise == rise => last.text.push(c),
        _ => runs.push(Run {
            text: c.to_string(),
            scale,
            rise,
            italic: false,
        }),
    }
}

/// The letters of `text` that are set in italics, in order: what a label's variables are.
#[cfg(test)]
pub(crate) fn slanted_letters(text: &str) -> String {
    parse(text)
        .into_iter()
        .filter(|r| r.italic)
        .map(|r| r.text)
        .collect()
}

/// Splits `runs` so that every letter standing alone (see the module's rule) is a run of its own,
/// marked italic. Letters are read across runs of one size and baseline only: `α_p` is two lone
/// letters, `D_{ABC}` a lone `D` and the word `ABC`.
fn slant_variables(runs: &mut Vec<Run>) {
    let mut out: Vec<Run> = Vec::with_capacity(runs.len());
    for (index, run) in runs.drain(..).enumerate() {
        let chars: Vec<char> = run.text.chars().collect();
        // A panel letter, `(a)` or `(ab)` opening the label, is a name: upright.
        let panel_letter = index == 0
            && chars.first() == Some(&'(')
            && (2..=3).contains(&chars.iter().position(|&c| c == ')').unwrap_or(0))
            && chars[1..]
                .iter()
                .take_while(|&&c| c != ')')
                .all(char::is_ascii_lowercase);
        let letter = |i: usize| chars.get(i).is_some_and(|c| c.is_alphabetic());
        let mut piece = String::new();
        let flush = |piece: &mut String, italic: bool, out: &mut Vec<Run>| {
            if piece.is_empty() {
                return;
            }
            match out.last_mut() {
                Some(last)
                    if last.scale == run.scale
                        && last.rise == run.rise
                        && last.italic == italic =>
                {
                    last.text.push_str(piece)
                }
                _ => out.push(Run {
                    text: std::mem::take(piece),
                    scale: run.scale,
                    rise: run.rise,
                    italic,
                }),
            }
            piece.clear();
        };
        for (i, &c) in chars.iter().enumerate() {
            // The s of "notebook's" ends a word: an apostrophe between letters joins them.
            let elided = i > 1 && matches!(chars[i - 1], '\'' | '’') && letter(i - 2);
            // A letter and digits hyphenated to a word are a version's name: the v of "pbrt-v4"
            // (the t of "Student-t" stays a variable).
            let versioned = i > 1
                && chars[i - 1] == '-'
                && letter(i - 2)
                && chars.get(i + 1).is_some_and(char::is_ascii_digit);
            let alone = c.is_alphabetic()
                && !(i > 0 && letter(i - 1))
                && !letter(i + 1)
                && !elided
                && !versioned;
            // "a reference", "A sweep", "I": an article or pronoun before a word stays upright.
            let prose = matches!(c, 'a' | 'A' | 'I')
                && chars.get(i + 1) == Some(&' ')
                && chars.get(i + 2).is_some_and(|n| n.is_alphabetic())
                && chars.get(i + 3).is_some_and(|n| n.is_alphabetic());
            // π is a constant and Σ, Π operators: upright, as ISO 80000-2 sets them.
            let constant = matches!(c, 'π' | 'Σ' | 'Π');
            let named = panel_letter && i < 4;
            if alone && !prose && !constant && !named {
                flush(&mut piece, false, &mut out);
                piece.push(c);
                flush(&mut piece, true, &mut out);
            } else {
                piece.push(c);
            }
        }
        flush(&mut piece, false, &mut out);
    }
    *runs = out;
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
            .estimate_text_size(&run.text, &scaled(font, run.scale, run.italic))
            .map_err(draw_err)?;
        total += f64::from(w);
    }
    Ok(total)
}

/// `font` at `scale` times its size, in the oblique face when `italic`.
fn scaled<'a>(font: &TextStyle<'a>, scale: f64, italic: bool) -> TextStyle<'a> {
    if scale == 1.0 && !italic {
        return font.clone();
    }
    let size = font.font.get_size() * scale;
    let mut desc = font.font.clone().resize(size);
    if italic {
        desc = desc.style(FontStyle::Oblique);
    }
    TextStyle {
        font: desc,
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
        let run_style =
            scaled(style, run.scale, run.italic).pos(Pos::new(HPos::Left, style.pos.v_pos));
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
            italic: false,
        }
    }

    fn var(text: &str, scale: f64, rise: f64) -> Run {
        Run {
            italic: true,
            ..run(text, scale, rise)
        }
    }

    #[test]
    fn scripts_take_one_character_or_a_group_and_nest() {
        assert_eq!(
            parse("α_b = 0.3"),
            [
                var("α", 1.0, 0.0),
                var("b", 0.7, -0.2),
                run(" = 0.3", 1.0, 0.0)
            ]
        );
        assert_eq!(
            parse("D_{ABC}(θ)"),
            [
                var("D", 1.0, 0.0),
                run("ABC", 0.7, -0.2),
                run("(", 1.0, 0.0),
                var("θ", 1.0, 0.0),
                run(")", 1.0, 0.0)
            ]
        );
        let nested = parse("cos^{α_p} θ");
        assert_eq!(nested[0], run("cos", 1.0, 0.0));
        assert_eq!(nested[1], var("α", 0.7, 0.38));
        assert!((nested[2].scale - 0.49).abs() < 1e-12 && nested[2].italic);
        assert!((nested[2].rise - (0.38 - 0.2 * 0.7)).abs() < 1e-12);
        assert_eq!(nested[3], run(" ", 1.0, 0.0));
        assert_eq!(nested[4], var("θ", 1.0, 0.0));
    }

    #[test]
    fn unicode_subscripts_are_set_as_markup_subscripts_are() {
        assert_eq!(parse("a₁ = 10"), parse("a_1 = 10"));
        assert_eq!(parse("F₀"), parse("F_0"));
        assert_eq!(parse("log₁₀ D"), parse("log_{10} D"));
        assert_eq!(parse("F₀")[1], run("0", 0.7, -0.2));
        assert!(has_markup("a₁ = 10") && has_markup("α_b") && !has_markup("0.25"));
    }

    #[test]
    fn variables_are_italic_and_words_digits_and_articles_upright() {
        let slanted = slanted_letters;
        assert_eq!(slanted("θ (radians)"), "θ");
        assert_eq!(slanted("G_1(θ_o) (1 + Λ(θ_o))"), "GθoΛθo");
        assert_eq!(slanted("ln D(θ) and cos θ"), "Dθθ");
        assert_eq!(slanted("E_{avg} = 0.41"), "E");
        assert_eq!(slanted("a reference for a₁"), "a");
        assert_eq!(slanted("α_{tr} = 0.4 … 0.9"), "α");
        assert_eq!(slanted("ABC 2048"), "");
        assert_eq!(slanted("π/6 and Σ x"), "x");
        assert_eq!(slanted("the notebook's α and θ'"), "αθ");
        assert_eq!(slanted("pbrt-v4 α = √r"), "αr");
        assert_eq!(slanted("Student-t"), "t");
        assert_eq!(
            slanted("(b) D(θ) of (a)"),
            "Dθa",
            "a panel letter opening a label"
        );
    }

    #[test]
    fn escapes_and_dangling_marks_are_literal() {
        assert_eq!(plain(r"snake\_case"), "snake_case");
        assert_eq!(parse(r"x\^yz")[1], run("^yz", 1.0, 0.0));
        assert_eq!(plain("x_ y^"), "x_ y^");
        assert_eq!(plain("x_{unclosed"), "xunclosed");
        assert_eq!(plain("α_{tr} = 0.3"), "αtr = 0.3");
    }
}
