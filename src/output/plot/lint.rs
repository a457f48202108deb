//! The figure lint: what the drawing placed, recorded while it draws ([`Trace`]), and the rules a
//! publication figure keeps ([`lint`]): no literal markup, at least three labelled ticks per axis
//! of a 2D panel, plot areas that keep their share of the cell, equal plot areas along a row, no
//! text overlapping other text or leaving the canvas, every curve at 3:1 contrast with the page,
//! no two legend entries alike in a panel or told apart only by colours too close (in normal
//! vision or for a deuteranope), tick labels of at least 6 pt in print, and nothing the drawing
//! could not do as asked; and, not a rule of layout but said the same way, the points of each series
//! left out of the drawing because their value is not finite.

use std::cell::RefCell;

use super::theme::{self, Pattern};
use super::{PlotError, SVG_UNITS_PER_PX, draw_figure};
use crate::pipeline::figure::{Figure, Series};
use crate::spec::look::{self, MIN_PRINT_PT, PanelKind, Rgb, delta_e00};
use crate::spec::numbers::significant;
use plotters::prelude::*;

/// Significant digits of the θ range a left-out warning names: 1.571 for π/2.
const LEFT_OUT_DIGITS: usize = 4;
/// Least labelled ticks per axis of a 2D panel.
pub const MIN_LABELLED_TICKS: usize = 3;
/// Least share of its grid cell's width and of its height a 2D panel's plot area keeps (the cells
/// split what the figure title leaves).
pub const MIN_PLOT_SHARE: f64 = 0.35;
/// Least WCAG contrast of a curve with its page.
pub const MIN_CONTRAST: f64 = 3.0;
/// Least CIEDE2000 difference of two legend entries of a panel that differ only by colour: 8 is
/// about where two thin curves stop being confused at a glance.
pub const MIN_ENTRY_DELTA_E: f64 = 8.0;
/// The same under a deuteranope simulation (Machado 2009), where a little less is still
/// readable next to the legend.
pub const MIN_ENTRY_DELTA_E_DEUTAN: f64 = 5.0;
/// Plot areas of one row may differ by this much, in CSS pixels.
pub const ROW_TOLERANCE_PX: f64 = 1.0;
/// Text boxes may overlap by this much on each side before it counts, in CSS pixels, or by
/// [`OVERLAP_TOLERANCE_EM`] of the base text size when that is more: glyph boxes include the
/// line's full ascent and descent, so neighbouring lines of one block touch, and a digit's ink
/// stops short of its box's bottom by about that much.
pub const OVERLAP_TOLERANCE_PX: f64 = 1.0;
/// See [`OVERLAP_TOLERANCE_PX`]: a tenth of the base text size.
pub const OVERLAP_TOLERANCE_EM: f64 = 0.1;

/// A box in device pixels: left, top, right, bottom.
pub(super) type Rect = [f64; 4];

/// A piece of text as drawn.
#[derive(Debug, Clone)]
pub(super) struct DrawnText {
    /// The characters drawn (one run of a typeset label, or a whole plain label).
    pub(super) text: String,
    /// The label it belongs to, as given.
    pub(super) label: String,
    /// Its box.
    pub(super) rect: Rect,
    /// The panel being drawn when it was placed; `None` for the figure's title.
    pub(super) panel: Option<usize>,
}

/// What a 2D panel's drawing placed.
#[derive(Debug, Clone, Default)]
pub(super) struct PanelTrace {
    /// The plot area.
    pub(super) plot: Rect,
    /// Labelled ticks on x and y.
    pub(super) ticks: (usize, usize),
}

/// Everything one drawing placed, for the lint.
#[derive(Debug, Clone, Default)]
pub(super) struct Trace {
    /// Every text drawn.
    pub(super) texts: Vec<DrawnText>,
    /// Every 2D panel's plot area and tick count.
    pub(super) panels: Vec<PanelTrace>,
    /// What the drawing could not do as asked (a legend that fits no corner), in words, with the
    /// panel it was drawing.
    pub(super) warnings: Vec<(Option<usize>, String)>,
    /// What the drawing chose where the spec left it open (where each legend went, at what size),
    /// in words, with the panel it was drawing: `-v`'s decisions.
    pub(super) decisions: Vec<(Option<usize>, String)>,
    /// The panel being drawn (its index in the figure), once the panels are.
    pub(super) current: Option<usize>,
    /// The top of the panel grid, below the figure title's band, in device pixels.
    pub(super) grid_top: f64,
}

/// One broken rule: the panel it is about (`None`: the figure as a whole) and what was measured.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Finding {
    /// Index of the panel in the figure's `panels`.
    pub panel: Option<usize>,
    /// The rule and the measurement, in words.
    pub message: String,
}

impl Finding {
    /// The finding as a line after `source` (a spec file or figure id):
    /// `fig.json: panels[1]: plot area 12 % of its cell …`.
    pub fn line(&self, source: &str) -> String {
        match self.panel {
            Some(i) => format!("{source}: panels[{i}]: {}", self.message),
            None => format!("{source}: {}", self.message),
        }
    }
}

/// The record a drawing writes into, when one is kept.
pub(super) type Recorder = Option<RefCell<Trace>>;

/// Records `text` (of `label`) drawn in `rect`, when a trace is kept.
pub(super) fn record_text(recorder: &Recorder, text: &str, label: &str, rect: Rect) {
    if let Some(trace) = recorder {
        let mut trace = trace.borrow_mut();
        let panel = trace.current;
        trace.texts.push(DrawnText {
            text: text.to_owned(),
            label: label.to_owned(),
            rect,
            panel,
        });
    }
}

/// Records `warning`, when a trace is kept.
pub(super) fn record_warning(recorder: &Recorder, warning: String) {
    if let Some(trace) = recorder {
        let mut trace = trace.borrow_mut();
        let panel = trace.current;
        trace.warnings.push((panel, warning));
    }
}

/// Records `decision`, when a trace is kept.
pub(super) fn record_decision(recorder: &Recorder, decision: String) {
    if let Some(trace) = recorder {
        let mut trace = trace.borrow_mut();
        let panel = trace.current;
        trace.decisions.push((panel, decision));
    }
}

/// Notes that panel `index` is being drawn: what is recorded next belongs to it.
pub(super) fn record_current_panel(recorder: &Recorder, index: usize) {
    if let Some(trace) = recorder {
        trace.borrow_mut().current = Some(index);
    }
}

/// Records the top of the panel grid (device pixels), when a trace is kept.
pub(super) fn record_grid_top(recorder: &Recorder, top: f64) {
    if let Some(trace) = recorder {
        trace.borrow_mut().grid_top = top;
    }
}

/// Records a 2D panel's plot area and labelled tick counts, when a trace is kept.
pub(super) fn record_panel(recorder: &Recorder, plot: Rect, ticks: (usize, usize)) {
    if let Some(trace) = recorder {
        trace.borrow_mut().panels.push(PanelTrace { plot, ticks });
    }
}

/// Whether a panel of `kind` is drawn on 2D axes with ticks (cartesian and heat-map panels).
fn flat(kind: &PanelKind) -> bool {
    matches!(kind, PanelKind::Cartesian | PanelKind::Heatmap { .. })
}

/// The points of `series` whose value is not finite (a ratio where its divisor underflowed), which
/// the drawing and the table leave out: `"a / b": 12 points not finite, θ from 1.49 to 1.571, left
/// out`; `None` when every value is finite.
fn left_out(series: &Series) -> Option<String> {
    let bad: Vec<f64> = series
        .points
        .iter()
        .filter(|(_, y)| !y.is_finite())
        .map(|&(x, _)| x)
        .collect();
    let (lo, hi) = bad
        .iter()
        .fold(None, |acc: Option<(f64, f64)>, &x| match acc {
            None => Some((x, x)),
            Some((lo, hi)) => Some((lo.min(x), hi.max(x))),
        })?;
    let shown = |x: f64| significant(x, LEFT_OUT_DIGITS);
    let (count, plural) = (bad.len(), if bad.len() == 1 { "" } else { "s" });
    Some(format!(
        "{:?}: {count} point{plural} not finite, θ from {} to {}, left out",
        series.label,
        shown(lo),
        shown(hi)
    ))
}

fn overlap(a: &Rect, b: &Rect, tolerance: f64) -> bool {
    a[0] + tolerance < b[2]
        && b[0] + tolerance < a[2]
        && a[1] + tolerance < b[3]
        && b[1] + tolerance < a[3]
}

/// What drawing `figure` (as its SVG is drawn) places.
fn trace_of(figure: &Figure) -> Result<(Trace, (u32, u32)), PlotError> {
    let size = super::device_size(&figure.canvas, SVG_UNITS_PER_PX)?;
    let mut document = String::new();
    let root = SVGBackend::with_string(&mut document, size).into_drawing_area();
    let trace = draw_figure(&root, figure, SVG_UNITS_PER_PX, Some(RefCell::default()))?
        .map(RefCell::into_inner)
        .unwrap_or_default();
    Ok((trace, size))
}

/// The rules `figure` breaks, each as a sentence naming the figure, the panel or text and the
/// measurement (`fig: panels[1]: plot area …`); empty when it keeps them all. The figure is drawn
/// (as its SVG is) to find out.
pub fn lint(figure: &Figure) -> Result<Vec<String>, PlotError> {
    let (trace, size) = trace_of(figure)?;
    Ok(findings(figure, &trace, size)
        .iter()
        .map(|f| f.line(&figure.id))
        .collect())
}

/// The rules broken by `figure` drawn as `trace` on a canvas of `(width, height)` device pixels.
pub(super) fn findings(
    figure: &Figure,
    trace: &Trace,
    (width, height): (u32, u32),
) -> Vec<Finding> {
    let px = |device: f64| device / SVG_UNITS_PER_PX;
    let slack =
        OVERLAP_TOLERANCE_PX.max(OVERLAP_TOLERANCE_EM * figure.canvas.font_px) * SVG_UNITS_PER_PX;
    let mut findings: Vec<Finding> = Vec::new();
    let mut push = |panel: Option<usize>, message: String| {
        let finding = Finding { panel, message };
        // A text drawn twice (a label of two runs) is reported once.
        if !findings.contains(&finding) {
            findings.push(finding);
        }
    };
    for (panel, w) in &trace.warnings {
        push(*panel, w.clone());
    }
    for (p, panel) in figure.panels.iter().enumerate() {
        for series in &panel.series {
            if let Some(message) = left_out(series) {
                push(Some(p), message);
            }
        }
    }

    for t in &trace.texts {
        let escaped = t.label.contains("\\_") || t.label.contains("\\^");
        if t.text.contains(['_', '^']) && !escaped {
            push(t.panel, format!("literal markup drawn in {:?}", t.label));
        }
        let [l, top, r, b] = t.rect;
        if l < -slack
            || top < -slack
            || r > f64::from(width) + slack
            || b > f64::from(height) + slack
        {
            push(t.panel, format!("{:?} is clipped by the canvas", t.label));
        }
    }
    for (i, a) in trace.texts.iter().enumerate() {
        for b in &trace.texts[..i] {
            if a.label != b.label && overlap(&a.rect, &b.rect, slack) {
                push(
                    a.panel.or(b.panel),
                    format!("{:?} overlaps {:?}", a.label, b.label),
                );
            }
        }
    }

    let cartesian: Vec<usize> = figure
        .panels
        .iter()
        .enumerate()
        .filter(|(_, p)| flat(&p.axes.kind))
        .map(|(i, _)| i)
        .collect();
    let cols = figure.cols.max(1);
    for (traced, &panel) in trace.panels.iter().zip(&cartesian) {
        let (x, y) = traced.ticks;
        if x < MIN_LABELLED_TICKS || y < MIN_LABELLED_TICKS {
            push(
                Some(panel),
                format!(
                    "{x} labelled x ticks and {y} labelled y ticks (expected at least {MIN_LABELLED_TICKS} each)"
                ),
            );
        }
    }
    let printed = look::printed_pt(&figure.canvas, cols);
    if printed < MIN_PRINT_PT - 0.05 {
        let place = match figure.canvas.print {
            Some(_) => "at the figure's size".to_owned(),
            None => format!(
                "placed {} in wide",
                px(
                    look::placed_width_px(f64::from(figure.canvas.width_px), cols)
                        / look::CSS_PX_PER_INCH
                )
            ),
        };
        push(
            None,
            format!(
                "tick labels print at {printed:.1} pt {place} (expected at least {MIN_PRINT_PT} pt)"
            ),
        );
    }
    let rows = figure.rows.max(1);
    let cell = (
        f64::from(width) / cols as f64,
        (f64::from(height) - trace.grid_top) / rows as f64,
    );
    for (traced, &panel) in trace.panels.iter().zip(&cartesian) {
        let [l, t, r, b] = traced.plot;
        let share = ((r - l) / cell.0).min((b - t) / cell.1);
        if share < MIN_PLOT_SHARE {
            push(
                Some(panel),
                format!(
                    "plot area {:.0} % of its cell (expected at least {:.0} %) at {:.0} × {:.0} px",
                    100.0 * share,
                    100.0 * MIN_PLOT_SHARE,
                    px(f64::from(width)),
                    px(f64::from(height)),
                ),
            );
        }
    }
    for (a, &pa) in trace.panels.iter().zip(&cartesian) {
        for (b, &pb) in trace.panels.iter().zip(&cartesian) {
            let kind = |p: usize| std::mem::discriminant(&figure.panels[p].axes.kind);
            // Heat maps keep a colour bar beside their plot area: they line up with their own kind.
            if pb <= pa || pa / cols != pb / cols || kind(pa) != kind(pb) {
                continue;
            }
            let size = |r: &Rect| (r[2] - r[0], r[3] - r[1]);
            let ((wa, ha), (wb, hb)) = (size(&a.plot), size(&b.plot));
            let worst = [
                (wa - wb).abs(),
                (ha - hb).abs(),
                (a.plot[1] - b.plot[1]).abs(),
            ]
            .into_iter()
            .fold(0.0, f64::max);
            if px(worst) > ROW_TOLERANCE_PX {
                push(
                    Some(pb),
                    format!(
                        "plot area differs from panels[{pa}]'s in its row by {:.1} px",
                        px(worst)
                    ),
                );
            }
        }
    }

    let page = theme::palette(figure.theme).background;
    let page = Rgb(page.0, page.1, page.2);
    for (panel_index, (panel, looks)) in figure.panels.iter().zip(theme::looks(figure)).enumerate()
    {
        let mut seen: Vec<(Rgb, Pattern, u64, &str)> = Vec::new();
        for (series, look) in panel.series.iter().zip(looks) {
            let contrast = look.colour.contrast(page);
            if contrast < MIN_CONTRAST {
                push(
                    Some(panel_index),
                    format!(
                        "{:?} has contrast {contrast:.2}:1 with the page (expected at least {MIN_CONTRAST}:1)",
                        series.label
                    ),
                );
            }
            if series.label.is_empty() {
                continue;
            }
            let entry = (
                look.colour,
                look.pattern,
                series.style.width.to_bits(),
                series.label.as_str(),
            );
            if seen.contains(&entry) {
                push(
                    Some(panel_index),
                    format!("two legend entries {:?} look alike", series.label),
                );
            }
            seen.push(entry);
        }
        // Entries (not members of one sweep) told apart by colour alone must differ enough in
        // colour, for a deuteranope too.
        let mut firsts: Vec<(Rgb, Pattern, u64, &str)> = Vec::new();
        for (series, look) in panel
            .series
            .iter()
            .zip(theme::looks(figure)[panel_index].iter())
        {
            if series.label.is_empty() || series.style.sweep.is_some_and(|m| m.index > 0) {
                continue;
            }
            let this = (
                look.colour,
                look.pattern,
                series.style.width.to_bits(),
                series.label.as_str(),
            );
            for other in &firsts {
                if other.1 != this.1 || other.2 != this.2 || other.0 == this.0 {
                    continue;
                }
                let normal = delta_e00(other.0.lab(), this.0.lab());
                let deutan = delta_e00(other.0.deuteranopia().lab(), this.0.deuteranopia().lab());
                if normal < MIN_ENTRY_DELTA_E || deutan < MIN_ENTRY_DELTA_E_DEUTAN {
                    push(
                        Some(panel_index),
                        format!(
                            "{:?} and {:?} differ only by colour, and little: ΔE00 {normal:.1} (expected at least {MIN_ENTRY_DELTA_E}), {deutan:.1} for a deuteranope (expected at least {MIN_ENTRY_DELTA_E_DEUTAN})",
                            other.3, this.3
                        ),
                    );
                }
            }
            firsts.push(this);
        }
    }
    findings
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::output::plot::fixtures::{RED, figure, panel, sample, series};
    use crate::spec::look::{Dash, Scale, XUnit};

    #[test]
    fn the_trace_holds_every_label_plot_area_and_tick() {
        let figure = sample();
        let (trace, size) = trace_of(&figure).unwrap();
        let cartesian = figure.panels.iter().filter(|p| flat(&p.axes.kind)).count();
        assert_eq!(trace.panels.len(), cartesian);
        for label in ["NDF and Fresnel", "θ", "F₀ = 0.04"] {
            assert!(trace.texts.iter().any(|t| t.label == label), "{label}");
        }
        assert!(
            trace
                .panels
                .iter()
                .all(|p| p.ticks.0 >= 3 && p.ticks.1 >= 3),
            "{:?}",
            trace.panels
        );
        let found = findings(&figure, &trace, size);
        assert!(found.is_empty(), "{found:?}");
        assert!(
            trace.texts.iter().any(|t| t.panel.is_none()),
            "the figure title"
        );
        assert!(trace.texts.iter().any(|t| t.panel == Some(1)));
    }

    #[test]
    fn plots_keep_their_share_at_paper_size_and_asked_corners_are_kept_or_warned() {
        // Two panels of ten curves with labels that do not merge, at 7 × 2.6 in with 8 pt text
        // (672 × 250 CSS px, 10.67 px): their legends no longer fit beside or below the plots.
        let curves = |tag: &str| -> Vec<crate::pipeline::figure::Series> {
            (0..10)
                .map(|i| {
                    let slope = 1.0 + f64::from(i);
                    series(
                        &format!("{tag} curve {i}"),
                        RED,
                        1.0,
                        Dash::Solid,
                        vec![(0.0, 0.0), (1.0, slope)],
                    )
                })
                .collect()
        };
        let mut fig = figure(vec![
            panel(XUnit::Radians, Scale::Linear, curves("left")),
            panel(XUnit::Radians, Scale::Linear, curves("right")),
        ]);
        (fig.rows, fig.cols) = (1, 2);
        (fig.canvas.width_px, fig.canvas.height_px) = (672, 250);
        fig.canvas.font_px = 8.0 * 96.0 / 72.0;
        for p in &mut fig.panels {
            p.axes.title = "α = 0.4 … 1.0".to_owned();
        }
        let (trace, size) = trace_of(&fig).unwrap();
        let cell_h = f64::from(size.1);
        for p in &trace.panels {
            let share = (p.plot[3] - p.plot[1]) / cell_h;
            assert!(
                share >= MIN_PLOT_SHARE,
                "plot {:.0} % of the cell",
                100.0 * share
            );
        }
        let found = findings(&fig, &trace, size);
        assert!(
            !found.iter().any(|f| f.message.contains("plot area")),
            "{found:?}"
        );
        // A corner asked for keeps the legend there, shrunk; one too small for it is a warning.
        fig.panels[0].axes.legend =
            crate::spec::look::LegendPlace::Corner(crate::spec::look::Corner::UpperLeft);
        let (trace, _) = trace_of(&fig).unwrap();
        assert!(trace.warnings.is_empty(), "{:?}", trace.warnings);
        (fig.canvas.width_px, fig.canvas.height_px) = (240, 100);
        let (trace, size) = trace_of(&fig).unwrap();
        assert!(
            trace
                .warnings
                .iter()
                .any(|(_, w)| w.contains("does not fit its upper left corner")),
            "{:?}",
            trace.warnings
        );
        assert!(
            findings(&fig, &trace, size)
                .iter()
                .any(|f| f.panel == Some(0) && f.message.contains("upper left"))
        );
    }

    #[test]
    fn each_rule_is_reported() {
        let line = |label: &str| series(label, RED, 1.0, Dash::Solid, vec![(0.0, 1.0), (1.0, 2.0)]);
        let coloured = |label: &str, colour: u32| {
            series(
                label,
                colour,
                1.0,
                Dash::Solid,
                vec![(0.0, 1.0), (1.0, 2.0)],
            )
        };
        let mut twin = figure(vec![
            panel(XUnit::Radians, Scale::Linear, vec![line("a"), line("a")]),
            panel(XUnit::Radians, Scale::Linear, vec![line("b")]),
            // matplotlib's tab10 green and red: apart in normal vision, not for a deuteranope.
            panel(
                XUnit::Radians,
                Scale::Linear,
                vec![coloured("green", 0x2CA02C), coloured("red", 0xD62728)],
            ),
        ]);
        (twin.rows, twin.cols) = (2, 2);
        let text = |label: &str, rect: Rect| DrawnText {
            text: label.to_owned(),
            label: label.to_owned(),
            rect,
            panel: Some(0),
        };
        let trace = Trace {
            texts: vec![
                text("α_b", [10.0, 10.0, 50.0, 30.0]),
                text("first", [100.0, 100.0, 200.0, 130.0]),
                text("second", [150.0, 110.0, 260.0, 140.0]),
                text("clipped", [1590.0, 10.0, 1700.0, 30.0]),
            ],
            panels: vec![
                PanelTrace {
                    plot: [0.0, 100.0, 700.0, 500.0],
                    ticks: (2, 5),
                },
                PanelTrace {
                    plot: [800.0, 100.0 + 5.0 * SVG_UNITS_PER_PX, 1500.0, 500.0],
                    ticks: (5, 5),
                },
            ],
            warnings: vec![(
                Some(0),
                "the legend \"a\" does not fit its upper right corner".to_owned(),
            )],
            decisions: Vec::new(),
            current: None,
            grid_top: 0.0,
        };
        let found: Vec<String> = findings(&twin, &trace, (1600, 1000))
            .iter()
            .map(|f| f.line("fig.json"))
            .collect();
        let found = found.join("\n");
        for expected in [
            "fig.json: panels[0]: literal markup drawn in \"α_b\"",
            "fig.json: panels[0]: \"second\" overlaps \"first\"",
            "fig.json: panels[0]: \"clipped\" is clipped",
            "fig.json: panels[0]: 2 labelled x ticks",
            "fig.json: panels[1]: plot area differs from panels[0]'s in its row by 5.0 px",
            "fig.json: panels[0]: two legend entries \"a\" look alike",
            "fig.json: panels[0]: the legend \"a\" does not fit its upper right corner",
            "fig.json: panels[2]: \"green\" and \"red\" differ only by colour, and little: ΔE00 71.7 (expected at least 8), 4.6 for a deuteranope",
        ] {
            assert!(found.contains(expected), "{expected} not in:\n{found}");
        }
    }
}
