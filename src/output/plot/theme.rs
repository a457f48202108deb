//! Themes: the page colours of a figure and the colour and line pattern each series is drawn
//! in. [`Theme::Notebook`] keeps every spec pattern and colour, darkening only colours too light
//! for 3:1 contrast on its white page; [`Theme::ColourBlind`] maps the
//! figure's distinct colours onto pairs of an Okabe–Ito colour and a line pattern, no two alike;
//! [`Theme::Dark`] lifts every colour above a luminance floor, keeping the order of a sweep's shades.

use plotters::style::RGBColor;

use crate::pipeline::figure::{Figure, Series};

use crate::spec::look::{Dash, MAX_LUMINANCE_ON_WHITE, Rgb, Theme};

/// The colours of everything that is not a series.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Palette {
    /// Page and plot background.
    pub(super) background: RGBColor,
    /// Text.
    pub(super) ink: RGBColor,
    /// Frame, axes and ticks.
    pub(super) frame: RGBColor,
    /// Major grid lines.
    pub(super) grid: RGBColor,
    /// Minor grid lines (log decades).
    pub(super) minor_grid: RGBColor,
    /// Legend box border.
    pub(super) legend_border: RGBColor,
    /// 3D back panes.
    pub(super) pane: RGBColor,
    /// Grid lines on the 3D panes.
    pub(super) pane_grid: RGBColor,
    /// Edges of the 3D panes.
    pub(super) pane_edge: RGBColor,
}

/// Dark ink and light grey rules on white.
const NOTEBOOK: Palette = Palette {
    background: RGBColor(0xFF, 0xFF, 0xFF),
    ink: RGBColor(0x22, 0x22, 0x22),
    frame: RGBColor(0x55, 0x55, 0x55),
    grid: RGBColor(0xE3, 0xE3, 0xE3),
    minor_grid: RGBColor(0xF1, 0xF1, 0xF1),
    legend_border: RGBColor(0xBB, 0xBB, 0xBB),
    pane: RGBColor(0xF4, 0xF4, 0xF4),
    pane_grid: RGBColor(0xDD, 0xDD, 0xDD),
    pane_edge: RGBColor(0xC4, 0xC4, 0xC4),
};

/// Light ink on a near-black blue-grey, rules a few steps above the background.
const DARK: Palette = Palette {
    background: RGBColor(0x16, 0x18, 0x1C),
    ink: RGBColor(0xE4, 0xE6, 0xEA),
    frame: RGBColor(0x9A, 0x9E, 0xA6),
    grid: RGBColor(0x34, 0x38, 0x40),
    minor_grid: RGBColor(0x23, 0x26, 0x2C),
    legend_border: RGBColor(0x55, 0x5A, 0x63),
    pane: RGBColor(0x1F, 0x22, 0x28),
    pane_grid: RGBColor(0x38, 0x3C, 0x45),
    pane_edge: RGBColor(0x4A, 0x4F, 0x58),
};

/// The Okabe–Ito colour-blind-safe palette (Okabe & Ito 2008, "Color Universal Design"),
/// most distinct first: blue, vermillion, bluish green, orange, reddish purple, sky blue,
/// black, and last yellow, the weakest on white.
const OKABE_ITO: [u32; 8] = [
    0x0072B2, 0xD55E00, 0x009E73, 0xE69F00, 0xCC79A7, 0x56B4E9, 0x000000, 0xF0E442,
];

/// Line patterns cycled with the colour-blind palette, so that curves differ without colour.
const PATTERN_CYCLE: [Pattern; 4] = [
    Pattern::Solid,
    Pattern::Dashed,
    Pattern::Dotted,
    Pattern::DashDot,
];

/// Least relative luminance of a series colour on the dark background: (0.35 + 0.05) /
/// (L(#16181C) + 0.05) ≈ 6.8, above WCAG's 4.5:1 for text, so thin curves stay clear.
const DARK_MIN_LUMINANCE: f64 = 0.35;
/// How a line is stroked.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Pattern {
    /// Continuous.
    Solid,
    /// Long dashes.
    Dashed,
    /// Short dots.
    Dotted,
    /// Alternating dashes and dots.
    DashDot,
}

impl From<Dash> for Pattern {
    fn from(dash: Dash) -> Pattern {
        match dash {
            Dash::Solid => Pattern::Solid,
            Dash::Dashed => Pattern::Dashed,
            Dash::Dotted => Pattern::Dotted,
        }
    }
}

/// The colour and pattern a series is drawn in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Look {
    /// Line, dot, bar or surface colour.
    pub(super) colour: Rgb,
    /// Line pattern.
    pub(super) pattern: Pattern,
}

/// The page colours of `theme` (the colour-blind theme is on the notebook's white page).
pub(super) fn palette(theme: Theme) -> &'static Palette {
    match theme {
        Theme::Notebook | Theme::ColourBlind => &NOTEBOOK,
        Theme::Dark => &DARK,
    }
}

/// The look of every series of `figure` under its theme, per panel and series.
///
/// Notebook: the spec's colour ([`on_white`]) and dash. Colour-blind: the k-th distinct spec colour in order
/// of first appearance across the figure becomes `OKABE_ITO[k mod 8]` and, unless the series
/// has a dash of its own, `PATTERN_CYCLE[(k + ⌊k/8⌋) mod 4]`: the patterns vary among the first
/// eight colours too, and colour k + 8j differs from colour k in pattern, so the first 32
/// distinct colours are 32 distinct looks; one spec colour looks the same in every panel.
/// Dark: each colour lifted to the luminance [`dark_luminance`] gives it (see [`lighten`]).
pub(super) fn looks(figure: &Figure) -> Vec<Vec<Look>> {
    let mut distinct: Vec<Rgb> = Vec::new();
    let mut rank = |colour: Rgb| match distinct.iter().position(|&c| c == colour) {
        Some(k) => k,
        None => {
            distinct.push(colour);
            distinct.len() - 1
        }
    };
    let mut look = |s: &Series| {
        let own = Look {
            colour: s.style.colour,
            pattern: s.style.dash.into(),
        };
        match figure.theme {
            Theme::Notebook => Look {
                colour: on_white(own.colour),
                ..own
            },
            Theme::ColourBlind => {
                let k = rank(s.style.colour);
                Look {
                    colour: on_white(Rgb::from_hex(OKABE_ITO[k % OKABE_ITO.len()])),
                    pattern: match s.style.dash {
                        Dash::Solid => {
                            PATTERN_CYCLE[(k + k / OKABE_ITO.len()) % PATTERN_CYCLE.len()]
                        }
                        dash => dash.into(),
                    },
                }
            }
            Theme::Dark => Look {
                colour: lighten(s.style.colour),
                ..own
            },
        }
    };
    figure
        .panels
        .iter()
        .map(|panel| panel.series.iter().map(&mut look).collect())
        .collect()
}

/// Luminance from which colours on the white page are compressed towards
/// [`MAX_LUMINANCE_ON_WHITE`] rather than kept.
const WHITE_PAGE_KNEE: f64 = 0.25;

/// The relative luminance a colour of luminance `l` is given on the white page: `l` up to
/// [`WHITE_PAGE_KNEE`], above it K + (M − K)(1 − e^{−(l − K)/(M − K)}) with M =
/// [`MAX_LUMINANCE_ON_WHITE`]: continuous, strictly increasing, below M, so every colour has 3:1
/// contrast on white and lighter colours stay lighter.
fn white_page_luminance(l: f64) -> f64 {
    let (knee, max) = (WHITE_PAGE_KNEE, MAX_LUMINANCE_ON_WHITE);
    if l <= knee {
        l
    } else {
        knee + (max - knee) * (1.0 - (-(l - knee) / (max - knee)).exp())
    }
}

/// `colour` darkened to [`white_page_luminance`] of its own where that is lower, keeping its hue.
pub(super) fn on_white(colour: Rgb) -> Rgb {
    let l = colour.luminance();
    let target = white_page_luminance(l);
    if target < l {
        colour.with_luminance(target)
    } else {
        colour
    }
}

/// The relative luminance a colour of luminance `l` is given on the dark background:
/// L_min + (1 − L_min) · l with L_min = [`DARK_MIN_LUMINANCE`]. Every colour clears the floor,
/// and the map is strictly increasing, so the dark-to-light shades of a sweep stay in order and
/// apart instead of all landing on the floor.
fn dark_luminance(l: f64) -> f64 {
    DARK_MIN_LUMINANCE + (1.0 - DARK_MIN_LUMINANCE) * l
}

/// `colour` lightened (mixed towards white) to [`dark_luminance`] of its own.
fn lighten(colour: Rgb) -> Rgb {
    colour.with_luminance(dark_luminance(colour.luminance()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::plot::fixtures::{BLACK, BLUE, RED, figure, panel, sample, series};
    use crate::spec::look::{Scale, XUnit};

    #[test]
    fn the_notebook_theme_keeps_spec_colours_and_dashes() {
        let figure = sample();
        for (panel, looks) in figure.panels.iter().zip(looks(&figure)) {
            for (s, look) in panel.series.iter().zip(looks) {
                assert_eq!(look.colour, on_white(s.style.colour));
                assert_eq!(look.pattern, Pattern::from(s.style.dash));
            }
        }
    }

    #[test]
    fn colour_blind_colours_follow_the_spec_colour_across_panels() {
        let line = |hex, dash| series("s", hex, 1.0, dash, vec![(0.0, 1.0), (1.0, 2.0)]);
        let first = panel(
            XUnit::Radians,
            Scale::Linear,
            vec![
                line(RED, Dash::Solid),
                line(BLUE, Dash::Solid),
                line(BLACK, Dash::Dotted),
            ],
        );
        let second = panel(
            XUnit::Radians,
            Scale::Linear,
            vec![line(BLUE, Dash::Solid), line(0x123456, Dash::Solid)],
        );
        let mut figure = figure(vec![first, second]);
        figure.theme = Theme::ColourBlind;
        let looks = looks(&figure);
        let okabe = |k: usize| on_white(Rgb::from_hex(OKABE_ITO[k]));
        assert_eq!(looks[0][0].colour, okabe(0));
        assert_eq!(looks[0][1].colour, okabe(1));
        assert_eq!(looks[1][0], looks[0][1], "blue is blue in both panels");
        assert_eq!(looks[0][0].pattern, Pattern::Solid);
        assert_eq!(looks[0][1].pattern, Pattern::Dashed);
        assert_eq!(looks[0][2].pattern, Pattern::Dotted, "its own dash");
        assert_eq!(looks[1][1].colour, okabe(3));
        assert_eq!(looks[1][1].pattern, Pattern::DashDot);
    }

    #[test]
    fn colour_blind_looks_are_distinct_for_the_first_32_colours() {
        let line = |hex| series("s", hex, 1.0, Dash::Solid, vec![(0.0, 1.0), (1.0, 2.0)]);
        let colours = (0..32u32).map(|k| line(0x010101 * (k + 1))).collect();
        let mut figure = figure(vec![panel(XUnit::Radians, Scale::Linear, colours)]);
        figure.theme = Theme::ColourBlind;
        let looks = &looks(&figure)[0];
        for (i, a) in looks.iter().enumerate() {
            for b in &looks[..i] {
                assert_ne!(a, b, "colour {i}");
            }
        }
    }

    #[test]
    fn white_page_colours_have_3_to_1_contrast_and_keep_their_order() {
        let colours = OKABE_ITO
            .into_iter()
            .chain([
                0xFF9900, 0xFFFF00, 0x88BEE6, 0xFFC773, 0xD6BE73, 0xFFFFFF, 0x222222,
            ])
            .map(Rgb::from_hex);
        for colour in colours {
            let drawn = on_white(colour);
            assert!(drawn.contrast(Rgb::WHITE) >= 3.0, "{colour:?} → {drawn:?}");
        }
        assert_eq!(on_white(Rgb::from_hex(0x222222)), Rgb::from_hex(0x222222));
        let ramp: Vec<f64> = (0..=20)
            .map(|i| {
                on_white(Rgb::from_hex(0x2689D1).mix(Rgb::WHITE, f64::from(i) / 20.0)).luminance()
            })
            .collect();
        // Lighter stays lighter, up to the rounding of a channel near the limit.
        for pair in ramp.windows(2) {
            assert!(pair[1] >= pair[0] - 0.003, "{ramp:?}");
        }
    }

    #[test]
    fn the_dark_theme_lifts_colours_above_the_floor_keeping_their_order() {
        let black = lighten(Rgb(0, 0, 0));
        assert!(black.luminance() >= DARK_MIN_LUMINANCE);
        assert!(
            black.luminance() < DARK_MIN_LUMINANCE + 0.01,
            "no lighter than needed"
        );
        assert_eq!(black.0, black.1);
        assert_eq!(lighten(Rgb(255, 255, 255)), Rgb(255, 255, 255));
        let blue = lighten(Rgb::from_hex(0x2689D1));
        assert!(blue.2 > blue.0, "stays blue");
        assert!((Rgb(255, 255, 255).luminance() - 1.0).abs() < 1e-12);
        // Five shades of one hue, dark to light, stay dark to light and apart.
        let shades = [0x0B2A40, 0x15507A, 0x2689D1, 0x6AB0E2, 0xA9D0EE].map(Rgb::from_hex);
        let lifted = shades.map(|c| lighten(c).luminance());
        for pair in lifted.windows(2) {
            assert!(pair[1] > pair[0] + 0.02, "{lifted:?}");
        }
    }
}
