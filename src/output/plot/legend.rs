//! The legend: one entry per labelled series (a sample of its line, dot, bar or surface patch
//! and its label) in a translucent box, and where it goes.
//!
//! The placement rule: inside the plot area, where it hides the least of what is drawn, when
//! the box fits there and hides no more than [`HIDE_TOLERANCE_EM`] of curve (at its full size,
//! else in two columns or at a smaller text size, down to that of an outside legend); otherwise outside,
//! in a strip beside or below the plot area, which shrinks to make room ([`choose_outside`]),
//! in columns and at a smaller text size when one column does not fit. The box never reaches
//! past the area it is given.

use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::clip::{Clipped, clip};
use super::lint::record_warning;
use super::mathtext;
use super::style::{MARKER_RADIUS_PX, Metrics, SURFACE_OPACITY, mesh_colour, stroke};
use super::summary::summarize;
use super::text::MIN_SHRINK;
use super::theme::{Look, Pattern};
use super::{PlotError, draw_err, outline};
use crate::pipeline::figure::{Figure, Panel, Series};
use crate::spec::look::{Corner, LegendPlace, Mark, PanelKind, SweepMember};

/// Number of heights tried for the legend box, from the top to the bottom of the plot area.
pub(super) const LEGEND_HEIGHTS: i32 = 5;
/// Legend background opacity: curves under the box stay faintly visible.
pub(super) const LEGEND_OPACITY: f64 = 0.85;
/// Curve length a legend inside the plot area may hide, in base text sizes: about the width
/// of one glyph, so that a curve grazing a corner of the box does not push it out, while
/// any curve running under the box does.
pub(super) const HIDE_TOLERANCE_EM: f64 = 1.0;
/// Text sizes tried for a legend outside the plot area, relative to the tick labels, largest
/// first: down to the smallest size a fitted title is shrunk to ([`MIN_SHRINK`]).
const OUTSIDE_SCALES: [f64; 3] = [1.0, 0.9, MIN_SHRINK];
/// Largest share of the area's height a legend takes when it fits nowhere else (the last
/// resort of [`choose_outside`]): the plot keeps the other half.
const LAST_RESORT_SHARE: f64 = 0.5;
/// Space between legend columns, in base text sizes (scaled with the legend's text): twice
/// the gap between a sample and its label, so that columns read as separate.
const COLUMN_GAP_EM: f64 = 1.0;
/// Most columns a legend inside the plot area is set in: a wider box rarely finds a place that
/// hides no curve.
const MAX_INSIDE_COLUMNS: usize = 2;

/// What a legend entry shows next to its label.
#[derive(Clone, Copy, PartialEq, Eq)]
pub(super) enum Sample {
    /// A short stretch of the line in its dash pattern.
    Line,
    /// A dot.
    Dot,
    /// A line with a dot in its middle.
    LineDot,
    /// A small filled box (bars).
    Bar,
    /// A translucent box with a mesh-coloured border (surfaces).
    Patch,
}

impl Sample {
    /// The sample for a 2D series drawn with `mark`.
    pub(super) fn of(mark: Mark) -> Sample {
        match mark {
            Mark::Line => Sample::Line,
            Mark::Points => Sample::Dot,
            Mark::LinePoints => Sample::LineDot,
            Mark::Bars => Sample::Bar,
        }
    }
}

/// What a panel has drawn, as polylines in the legend's area pixels, for the legend to avoid.
#[derive(Default)]
pub(super) struct Covered(pub(super) Vec<Vec<(f64, f64)>>);

impl Covered {
    /// Records the polyline `path` (whole pixels).
    pub(super) fn add(&mut self, path: &[(i32, i32)]) {
        self.0.push(
            path.iter()
                .map(|&(x, y)| (f64::from(x), f64::from(y)))
                .collect(),
        );
    }
}

/// How a legend is set: its text size relative to the tick labels, and its number of columns
/// (filled top to bottom, then left to right).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Setting {
    /// Text size and spacings relative to the full-size legend.
    pub(super) scale: f64,
    /// Number of columns, at least 1.
    pub(super) columns: usize,
}

impl Setting {
    /// One column at the tick labels' size.
    pub(super) const FULL: Setting = Setting {
        scale: 1.0,
        columns: 1,
    };
}

/// Which side of the plot area an outside legend's strip is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Side {
    /// A strip along the right edge of the area, the full height available.
    Right,
    /// A strip along the bottom edge of the area, the full width available.
    Below,
}

impl Side {
    /// Where a legend on this side is, in words (`-v`).
    pub(super) fn placed(self) -> &'static str {
        match self {
            Side::Right => "right of the plot",
            Side::Below => "below the plot",
        }
    }
}

/// A legend outside the plot area: its side, its setting and the size of its strip (the box
/// and the inset around it), in device pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Outside {
    /// Where the strip is.
    pub(super) side: Side,
    /// How the legend is set in it.
    pub(super) setting: Setting,
    /// Width and height of the strip.
    pub(super) strip: (f64, f64),
}

/// One row of a legend: a series, or a whole sweep summarized.
struct Entry {
    /// The label drawn.
    label: String,
    /// The line width of its series, in multiples of the default.
    width: f64,
    /// The looks of its series, darkest shade first for a sweep (one look for a single series).
    looks: Vec<Look>,
    /// What is drawn next to the label.
    sample: Sample,
}

/// Most shades a sweep's legend sample shows side by side: the ends of the ramp and evenly
/// spaced members between them.
const MAX_SWATCH_SHADES: usize = 12;
/// Half the height of a sweep's bar sample, as a share of the legend's row height.
const SWEEP_BAR_HALF_HEIGHT: f64 = 0.2;

/// The legend rows of `series` drawn in `looks`, each shown by `sample(series)`: a run of the
/// members of one sweep (consecutive, index 0 to count − 1, drawn alike but for colour) is one
/// row when their labels merge ([`summarize`]); every other labelled series is its own row.
fn entries(series: &[Series], looks: &[Look], sample: impl Fn(&Series) -> Sample) -> Vec<Entry> {
    let mut out = Vec::new();
    let mut i = 0;
    while i < series.len().min(looks.len()) {
        let s = &series[i];
        let run = match s.style.sweep {
            Some(member) if member.index == 0 && i + member.count <= series.len() => {
                let members = &series[i..i + member.count];
                let alike = members.iter().enumerate().all(|(k, m)| {
                    m.style.sweep
                        == Some(SweepMember {
                            index: k,
                            count: member.count,
                        })
                        && m.style.width == s.style.width
                        && m.style.dash == s.style.dash
                        && m.style.mark == s.style.mark
                        && !m.label.is_empty()
                });
                let labels: Vec<&str> = members.iter().map(|m| m.label.as_str()).collect();
                alike
                    .then(|| summarize(&labels))
                    .flatten()
                    .map(|label| (member.count, label))
            }
            _ => None,
        };
        match run {
            Some((count, label)) => {
                let picks = count.min(MAX_SWATCH_SHADES);
                let looks = (0..picks)
                    .map(|j| looks[i + (j * (count - 1)).div_ceil((picks - 1).max(1))])
                    .collect();
                out.push(Entry {
                    label,
                    width: s.style.width,
                    looks,
                    sample: sample(s),
                });
                i += count;
            }
            None => {
                if !s.label.is_empty() {
                    out.push(Entry {
                        label: s.label.clone(),
                        width: s.style.width,
                        looks: vec![looks[i]],
                        sample: sample(s),
                    });
                }
                i += 1;
            }
        }
    }
    out
}

/// The legend each panel of `figure` (series drawn in `looks`) shares: for each panel whose 2D
/// legend is on, the index of the first panel with the same place and the same rows (label,
/// width, shades, sample) — its own index when it is the first; `None` for a panel with no
/// legend of its own to share (legend off, no rows, not cartesian). A legend that several panels
/// share is drawn once, as a figure legend would be.
pub(super) fn legend_groups(figure: &Figure, looks: &[Vec<Look>]) -> Vec<Option<usize>> {
    type Row = (String, u64, Vec<Look>, Sample);
    let rows = |panel: &Panel, looks: &[Look]| -> Vec<Row> {
        entries(&panel.series, looks, |s| Sample::of(s.style.mark))
            .into_iter()
            .map(|e| (e.label, e.width.to_bits(), e.looks, e.sample))
            .collect()
    };
    let mut firsts: Vec<(usize, LegendPlace, Vec<Row>)> = Vec::new();
    figure
        .panels
        .iter()
        .zip(looks)
        .enumerate()
        .map(|(i, (panel, looks))| {
            let place = panel.axes.legend;
            if place == LegendPlace::None || panel.axes.kind != PanelKind::Cartesian {
                return None;
            }
            let rows = rows(panel, looks);
            if rows.is_empty() {
                return None;
            }
            match firsts.iter().find(|(_, p, r)| *p == place && *r == rows) {
                Some((first, _, _)) => Some(*first),
                None => {
                    firsts.push((i, place, rows));
                    Some(i)
                }
            }
        })
        .collect()
}

/// A panel's legend: its rows and their label widths at the full size.
pub(super) struct Legend {
    entries: Vec<Entry>,
    widths: Vec<f64>,
}

/// Padding, sample length, gap before the label and row height of a full-size legend, in
/// base text sizes.
const SPACING_EM: (f64, f64, f64, f64) = (0.5, 2.2, 0.5, 1.35);
/// Distance between the legend box and the edge of its area, in base text sizes.
const INSET_EM: f64 = 0.6;

impl Legend {
    /// The legend of `panel`'s series in their `looks`, each shown by `sample(series)` and each
    /// sweep summarized in one row ([`entries`]), the labels measured in the tick font on `area`;
    /// `None` when the panel has its legend off or no series has a label (no legend is drawn).
    pub(super) fn of_panel<DB: DrawingBackend>(
        area: &DrawingArea<DB, Shift>,
        panel: &Panel,
        looks: &[Look],
        sample: impl Fn(&Series) -> Sample,
        m: &Metrics,
    ) -> Result<Option<Legend>, PlotError>
    where
        DB::ErrorType: 'static,
    {
        if panel.axes.legend == LegendPlace::None {
            return Ok(None);
        }
        let font = m.font(1.0);
        let entries = entries(&panel.series, looks, sample);
        if entries.is_empty() {
            return Ok(None);
        }
        let mut widths = Vec::with_capacity(entries.len());
        for entry in &entries {
            widths.push(mathtext::width(area, &entry.label, &font)?);
        }
        Ok(Some(Legend { entries, widths }))
    }

    /// Distance between the box and the edge of its area, in device pixels.
    pub(super) fn inset(m: &Metrics) -> f64 {
        f64::from(m.px(INSET_EM))
    }

    /// Width and height in device pixels of the box set as `setting`.
    pub(super) fn size(&self, setting: Setting, m: &Metrics) -> (f64, f64) {
        box_size(&self.widths, setting, m.unit)
    }

    /// The settings a legend inside a plot area is tried in, largest first: each of the
    /// outside scales in one to [`MAX_INSIDE_COLUMNS`] columns.
    fn inside_settings(&self) -> impl Iterator<Item = Setting> + use<> {
        let most = self.entries.len().clamp(1, MAX_INSIDE_COLUMNS);
        OUTSIDE_SCALES
            .into_iter()
            .flat_map(move |scale| (1..=most).map(move |columns| Setting { scale, columns }))
    }

    /// The setting of the box in a plot area of `plot` pixels and its top-left corner: the
    /// first of [`Legend::inside_settings`] whose box fits there and hides at most
    /// [`HIDE_TOLERANCE_EM`] of the `covered` curves (plot pixels); `None` when it belongs
    /// outside.
    pub(super) fn inside(
        &self,
        plot: (f64, f64),
        covered: &[Vec<(f64, f64)>],
        m: &Metrics,
    ) -> Option<(Setting, (i32, i32))> {
        let inset = Self::inset(m);
        self.inside_settings().find_map(|setting| {
            let size = self.size(setting, m);
            if size.0 + 2.0 * inset > plot.0 || size.1 + 2.0 * inset > plot.1 {
                return None;
            }
            let (at, hidden) = legend_position(plot, size, inset, covered);
            (hidden <= HIDE_TOLERANCE_EM * m.unit).then_some((setting, at))
        })
    }

    /// The setting of the box at `corner` of a plot area of `plot` pixels and its top-left corner:
    /// the full size when it fits there, else the largest of the outside scales in the fewest
    /// columns that fits; `None` when none does.
    pub(super) fn corner_setting(
        &self,
        plot: (f64, f64),
        corner: Corner,
        m: &Metrics,
    ) -> Option<(Setting, (f64, f64))> {
        OUTSIDE_SCALES
            .iter()
            .flat_map(|&scale| {
                (1..=self.entries.len().max(1)).map(move |columns| Setting { scale, columns })
            })
            .find_map(|setting| {
                self.at_corner_set(plot, corner, setting, m)
                    .map(|at| (setting, at))
            })
    }

    /// The top-left corner of the box set as `setting` at `corner` of a plot area of `plot`
    /// pixels, inset from its edges; `None` when it does not fit there.
    fn at_corner_set(
        &self,
        plot: (f64, f64),
        corner: Corner,
        setting: Setting,
        m: &Metrics,
    ) -> Option<(f64, f64)> {
        let (w, h) = self.size(setting, m);
        let inset = Self::inset(m);
        if w + 2.0 * inset > plot.0 || h + 2.0 * inset > plot.1 {
            return None;
        }
        let (left, right) = (inset, plot.0 - inset - w);
        let (top, bottom) = (inset, plot.1 - inset - h);
        Some(match corner {
            Corner::UpperRight => (right, top),
            Corner::UpperLeft => (left, top),
            Corner::LowerLeft => (left, bottom),
            Corner::LowerRight => (right, bottom),
        })
    }

    /// Whether the legend of a panel placed as `place` goes inside a plot area of `plot` pixels
    /// over the `covered` curves: at the best place when it hides none ([`Legend::inside`]), at
    /// its corner when it fits there; never when it is asked for outside.
    pub(super) fn goes_inside(
        &self,
        place: LegendPlace,
        plot: (f64, f64),
        covered: &[Vec<(f64, f64)>],
        m: &Metrics,
    ) -> bool {
        match place {
            LegendPlace::Best => self.inside(plot, covered, m).is_some(),
            // A corner asked for is kept (shrunk to fit, or with a warning).
            LegendPlace::Corner(_) => true,
            LegendPlace::Right | LegendPlace::Below | LegendPlace::None => false,
        }
    }

    /// Draws the legend inside `plot` as `place` asks (its corner, else where it hides the least
    /// of the `covered` curves).
    pub(super) fn draw_inside<DB: DrawingBackend>(
        &self,
        plot: &DrawingArea<DB, Shift>,
        place: LegendPlace,
        covered: &[Vec<(f64, f64)>],
        m: &Metrics,
    ) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        let (w, h) = plot.dim_in_pixel();
        let LegendPlace::Corner(corner) = place else {
            return self.draw_over(plot, covered, m);
        };
        match self.corner_setting((f64::from(w), f64::from(h)), corner, m) {
            Some((setting, at)) => {
                let placed = format!("in the {} corner asked for", corner.name());
                self.draw(plot, at, setting, m, &placed)
            }
            None => {
                record_warning(
                    &m.trace,
                    format!(
                        "the legend {:?} does not fit its {} corner ({:.0} × {:.0} px plot area): drawn where it hides the least",
                        self.entries.first().map_or("", |e| e.label.as_str()),
                        corner.name(),
                        f64::from(w) / m.k,
                        f64::from(h) / m.k
                    ),
                );
                self.draw_over(plot, covered, m)
            }
        }
    }

    /// Where the legend goes outside a plot that would fill an `area` of device pixels:
    /// [`choose_outside`] with `score`.
    pub(super) fn outside(
        &self,
        area: (f64, f64),
        m: &Metrics,
        score: impl Fn(f64, f64) -> Option<f64>,
    ) -> Outside {
        let n = self.entries.len();
        choose_outside(area, Self::inset(m), n, |s| self.size(s, m), score)
    }

    /// The legend below a plot in an `area` of device pixels, as a row of a grid reserves it: as many
    /// columns as fit the width, at the largest scale whose box fits the height ([`choose_outside`]
    /// restricted to its strip below).
    pub(super) fn below(&self, area: (f64, f64), m: &Metrics) -> Outside {
        self.outside(area, m, |w, h| (w >= area.0).then_some(h))
    }

    /// Whether the legend fits over a plot area of `plot` pixels at a readable size: at the full
    /// setting, or as [`Legend::draw_over`] would set it, at no less than the smallest of the
    /// outside scales.
    pub(super) fn fits_over(&self, plot: (f64, f64), m: &Metrics) -> bool {
        let smallest = OUTSIDE_SCALES[OUTSIDE_SCALES.len() - 1];
        self.outside(plot, m, |_, _| Some(0.0)).setting.scale >= smallest
    }

    /// Draws the legend over `area`: where [`Legend::inside`] puts it when it hides no curve
    /// there; else where it hides the least of the `covered` curves (area pixels), at the full
    /// setting when the box fits the area with its inset, else in the setting
    /// [`choose_outside`] finds for the whole area.
    pub(super) fn draw_over<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        covered: &[Vec<(f64, f64)>],
        m: &Metrics,
    ) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        let (w, h) = area.dim_in_pixel();
        let dims = (f64::from(w), f64::from(h));
        if let Some((setting, at)) = self.inside(dims, covered, m) {
            let placed = "inside the plot, clear of the curves";
            return self.draw(area, (f64::from(at.0), f64::from(at.1)), setting, m, placed);
        }
        let inset = Self::inset(m);
        let (box_w, box_h) = self.size(Setting::FULL, m);
        let setting = if box_w + 2.0 * inset <= dims.0 && box_h + 2.0 * inset <= dims.1 {
            Setting::FULL
        } else {
            self.outside(dims, m, |_, _| Some(0.0)).setting
        };
        let (at, _) = legend_position(dims, self.size(setting, m), inset, covered);
        let placed = "over the plot where it hides the least";
        self.draw(area, (f64::from(at.0), f64::from(at.1)), setting, m, placed)
    }

    /// Draws the legend set as `setting` with its box's top-left corner at `at` (pixels of
    /// `area`), recording where it was `placed` (in words) and how for `-v`.
    pub(super) fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        at: (f64, f64),
        setting: Setting,
        m: &Metrics,
        placed: &str,
    ) -> Result<(), PlotError>
    where
        DB::ErrorType: 'static,
    {
        let (box_w, box_h) = self.size(setting, m);
        super::lint::record_decision(
            &m.trace,
            format!(
                "legend of {} entr{} {placed}, {} column{} at {:.0} % size",
                self.entries.len(),
                if self.entries.len() == 1 { "y" } else { "ies" },
                setting.columns,
                if setting.columns == 1 { "" } else { "s" },
                setting.scale * 100.0
            ),
        );
        let (x0, y0) = (at.0.round() as i32, at.1.round() as i32);
        let background = m.palette.background.mix(LEGEND_OPACITY).filled();
        // Saturating: on a canvas far too small for its legend the box may reach past i32 (the
        // figure lint reports the clipped text).
        let bounds = [
            (x0, y0),
            (
                x0.saturating_add(box_w.round() as i32),
                y0.saturating_add(box_h.round() as i32),
            ),
        ];
        area.draw(&Rectangle::new(bounds, background))
            .map_err(draw_err)?;
        outline(area, bounds, m.line(m.palette.legend_border))?;
        let [pad, sample, gap, row] = spacing(setting.scale, m.unit);
        let column_gap = COLUMN_GAP_EM * setting.scale * m.unit;
        let label_style = m
            .font(setting.scale)
            .pos(Pos::new(HPos::Left, VPos::Center));
        let rows = rows(self.entries.len(), setting.columns);
        let mut left = at.0 + pad;
        for (column, chunk) in self.entries.chunks(rows).enumerate() {
            for (i, entry) in chunk.iter().enumerate() {
                let kind = &entry.sample;
                let cy = (at.1 + pad + row * (i as f64 + 0.5)).round() as i32;
                let sx = left.round() as i32;
                let sample_px = sample.round() as i32;
                let mid = sx + sample_px / 2;
                let (half_w, half_h) = (sample_px / 4, (row * 0.3).round() as i32);
                let patch = [(mid - half_w, cy - half_h), (mid + half_w, cy + half_h)];
                // A sweep's sample shows its shades side by side, darkest first; its mark takes
                // the middle shade. A sweep of solid lines shows them as a bar, a small colour
                // bar that its label's range reads along.
                let shades = entry.looks.len() as i32;
                let colour = entry.looks[entry.looks.len() / 2].colour;
                let bar = shades > 1
                    && *kind == Sample::Line
                    && entry.looks.iter().all(|l| l.pattern == Pattern::Solid);
                if bar {
                    let half = (row * SWEEP_BAR_HALF_HEIGHT).round().max(1.0) as i32;
                    for (j, look) in entry.looks.iter().enumerate() {
                        let j = j as i32;
                        let (from, to) = (
                            sx + sample_px * j / shades,
                            sx + sample_px * (j + 1) / shades,
                        );
                        let cell = [(from, cy - half), (to, cy + half)];
                        area.draw(&Rectangle::new(cell, m.fill(look.colour, 1.0)))
                            .map_err(draw_err)?;
                    }
                } else if matches!(kind, Sample::Line | Sample::LineDot) {
                    for (j, look) in entry.looks.iter().enumerate() {
                        let j = j as i32;
                        let style = m.curve_style(look.colour, entry.width);
                        let (from, to) = (
                            sx + sample_px * j / shades,
                            sx + sample_px * (j + 1) / shades,
                        );
                        stroke(area, vec![(from, cy), (to, cy)], style, look.pattern)?;
                    }
                }
                match kind {
                    Sample::Line => {}
                    Sample::Dot | Sample::LineDot => area
                        .draw(&Circle::new(
                            (mid, cy),
                            m.dot(MARKER_RADIUS_PX * setting.scale),
                            m.fill(colour, 1.0),
                        ))
                        .map_err(draw_err)?,
                    Sample::Bar => area
                        .draw(&Rectangle::new(patch, m.fill(colour, 1.0)))
                        .map_err(draw_err)?,
                    Sample::Patch => {
                        area.draw(&Rectangle::new(patch, m.fill(colour, SURFACE_OPACITY)))
                            .map_err(draw_err)?;
                        outline(area, patch, m.line(mesh_colour(colour)))?;
                    }
                }
                let text_x = (left + sample + gap).round() as i32;
                mathtext::draw(
                    area,
                    &entry.label,
                    &label_style,
                    (f64::from(text_x), f64::from(cy)),
                    m,
                )?;
            }
            left += column_width(&self.widths, rows, column, setting.scale, m.unit) + column_gap;
        }
        Ok(())
    }
}

/// Padding, sample length, gap before the label and row height of a legend at `scale`, in
/// device pixels for a base text size of `unit`.
fn spacing(scale: f64, unit: f64) -> [f64; 4] {
    let (pad, sample, gap, row) = SPACING_EM;
    [pad, sample, gap, row].map(|em| em * scale * unit)
}

/// Entries per column when `n` entries are set in `columns` columns.
fn rows(n: usize, columns: usize) -> usize {
    n.div_ceil(columns.max(1)).max(1)
}

/// Width of column `column` (sample, gap and widest label) of labels `widths` (full size) set
/// `rows` to a column at `scale`.
fn column_width(widths: &[f64], rows: usize, column: usize, scale: f64, unit: f64) -> f64 {
    let [_, sample, gap, _] = spacing(scale, unit);
    let widest = widths
        .iter()
        .skip(column * rows)
        .take(rows)
        .fold(0.0f64, |w, &l| w.max(l));
    sample + gap + widest * scale
}

/// Width and height of the box of labels `widths` (full size, device pixels) set as
/// `setting`, for a base text size of `unit`.
fn box_size(widths: &[f64], setting: Setting, unit: f64) -> (f64, f64) {
    let [pad, _, _, row] = spacing(setting.scale, unit);
    let rows = rows(widths.len(), setting.columns);
    let columns = widths.len().div_ceil(rows);
    let width: f64 = (0..columns)
        .map(|c| column_width(widths, rows, c, setting.scale, unit))
        .sum();
    let gaps = COLUMN_GAP_EM * setting.scale * unit * (columns.max(1) - 1) as f64;
    (2.0 * pad + width + gaps, 2.0 * pad + row * rows as f64)
}

/// Where a legend of `n` entries goes outside the plot area, in an `area` of device pixels
/// that the plot would otherwise fill; `size` gives the box of a setting and `score(w, h)`
/// how good a plot in the w × h pixels left beside or above the strip is (`None`: too small
/// to draw).
///
/// To the right: the fewest columns, at the largest of the [`OUTSIDE_SCALES`], whose box fits
/// the area's height (text is shrunk before a column is added). Below: the largest scale at
/// which a box in as many columns as fit the width (the fewest rows) fits the height. Of the
/// two, the one whose plot scores higher; ties go to the right. When neither leaves a plot,
/// the last resort is below, at the smallest scale in as many columns as fit the width, shrunk
/// further until the box takes at most [`LAST_RESORT_SHARE`] of the height. The strip (box
/// and `inset` around it) never exceeds the area.
pub(super) fn choose_outside(
    (width, height): (f64, f64),
    inset: f64,
    n: usize,
    size: impl Fn(Setting) -> (f64, f64),
    score: impl Fn(f64, f64) -> Option<f64>,
) -> Outside {
    let n = n.max(1);
    let strip = |setting: Setting| {
        let (w, h) = size(setting);
        (w + 2.0 * inset, h + 2.0 * inset)
    };
    let widest_fit = |scale: f64| {
        (1..=n)
            .rev()
            .map(|columns| Setting { scale, columns })
            .find(|&s| strip(s).0 <= width)
    };
    let candidate = |side: Side, setting: Setting| {
        let (w, h) = strip(setting);
        if w > width || h > height {
            return None;
        }
        let plot = match side {
            Side::Right => score(width - w, height),
            Side::Below => score(width, height - h),
        }?;
        Some((
            plot,
            Outside {
                side,
                setting,
                strip: (w, h),
            },
        ))
    };
    let right = (1..=n)
        .flat_map(|columns| OUTSIDE_SCALES.map(|scale| Setting { scale, columns }))
        .find(|&s| strip(s).1 <= height)
        .and_then(|s| candidate(Side::Right, s));
    let below = OUTSIDE_SCALES
        .iter()
        .filter_map(|&scale| widest_fit(scale))
        .find(|&s| strip(s).1 <= height)
        .and_then(|s| candidate(Side::Below, s));
    match (right, below) {
        (Some(r), Some(b)) => return if b.0 > r.0 { b.1 } else { r.1 },
        (Some((_, chosen)), None) | (None, Some((_, chosen))) => return chosen,
        (None, None) => {}
    }
    let smallest = OUTSIDE_SCALES[OUTSIDE_SCALES.len() - 1];
    let fitted = widest_fit(smallest).unwrap_or(Setting {
        scale: smallest,
        columns: 1,
    });
    let (w, h) = size(fitted);
    // The box, not the inset, shrinks with the text: scale it into what is left of each.
    let room_w = (width - 2.0 * inset).max(0.0);
    let room_h = (LAST_RESORT_SHARE * height - 2.0 * inset).max(0.0);
    let shrink = (room_w / w).min(room_h / h).min(1.0);
    let setting = Setting {
        scale: fitted.scale * shrink,
        ..fitted
    };
    Outside {
        side: Side::Below,
        setting,
        strip: strip(setting),
    }
}

/// Top-left corner for a legend box of `size` in a plot area of `plot` pixels, `inset` from
/// its edges, and the curve length it hides there: among [`LEGEND_HEIGHTS`] heights along the
/// right, left and centre, the position hiding the least curve length (`pieces`, in plot
/// pixels). A curve within half the inset of the box counts as hidden, so that none runs
/// along its border; curves along the plot's frame stay clear. Ties go to the higher, then
/// right, left, centre.
pub(super) fn legend_position(
    (plot_w, plot_h): (f64, f64),
    (box_w, box_h): (f64, f64),
    inset: f64,
    pieces: &[Vec<(f64, f64)>],
) -> ((i32, i32), f64) {
    let (plot_w, plot_h) = (plot_w.round() as i32, plot_h.round() as i32);
    let (box_w, box_h) = (box_w.round() as i32, box_h.round() as i32);
    let inset = inset.round() as i32;
    let bottom = (plot_h - inset - box_h).max(inset);
    let right = (plot_w - inset - box_w).max(inset);
    let columns = [right, inset, (right + inset) / 2];
    let rows: Vec<i32> = (0..LEGEND_HEIGHTS)
        .map(|i| inset + (bottom - inset) * i / (LEGEND_HEIGHTS - 1))
        .collect();
    let clearance = f64::from(inset) / 2.0;
    // Hidden curve length per position, row-major; rows and columns reject segments separately.
    let mut hidden = vec![0.0; rows.len() * columns.len()];
    for pair in pieces.iter().flat_map(|piece| piece.windows(2)) {
        let ((ax, ay), (bx, by)) = (pair[0], pair[1]);
        for (r, &y0) in rows.iter().enumerate() {
            let (y_top, y_bottom) = (f64::from(y0) - clearance, f64::from(y0 + box_h) + clearance);
            if ay.max(by) < y_top || ay.min(by) > y_bottom {
                continue;
            }
            for (c, &x0) in columns.iter().enumerate() {
                let (x_left, x_right) =
                    (f64::from(x0) - clearance, f64::from(x0 + box_w) + clearance);
                if ax.max(bx) < x_left || ax.min(bx) > x_right {
                    continue;
                }
                let bounds = [x_left, x_right, y_top, y_bottom];
                if let Some(Clipped { start, end, .. }) = clip(pair[0], pair[1], bounds) {
                    hidden[r * columns.len() + c] += (end.0 - start.0).hypot(end.1 - start.1);
                }
            }
        }
    }
    let mut best = 0;
    for (i, &length) in hidden.iter().enumerate() {
        if length < hidden[best] {
            best = i;
        }
    }
    (
        (columns[best % columns.len()], rows[best / columns.len()]),
        hidden[best],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Labels of `n` entries 100 px wide, at a base text size of 10 px: a column is 127 px
    /// wide (sample 22, gap 5), each row 13.5 px high, the padding 5 px, column gaps 10 px.
    fn sized(n: usize) -> impl Fn(Setting) -> (f64, f64) {
        move |setting| box_size(&vec![100.0; n], setting, 10.0)
    }

    /// The golden width of a plot filling `(w, h)`, if at least 100 px.
    fn golden(w: f64, h: f64) -> Option<f64> {
        let g = w.min(1.618 * h);
        (g >= 100.0).then_some(g)
    }

    #[test]
    fn the_legend_avoids_the_curves() {
        // A curve through the top corners: the legend goes below it, on the right.
        let top = vec![vec![(0.0, 30.0), (400.0, 30.0)]];
        let size = (100.0, 50.0);
        assert_eq!(
            legend_position((400.0, 300.0), size, 10.0, &top),
            ((290, 67), 0.0)
        );
        assert_eq!(
            legend_position((400.0, 300.0), size, 10.0, &[]),
            ((290, 10), 0.0)
        );
        // Curves everywhere, 10 px apart: six run through the box and the 5 px clearance
        // around it, 110 px each.
        let rows: Vec<Vec<(f64, f64)>> = (0..30)
            .map(|i| vec![(0.0, f64::from(i) * 10.0), (400.0, f64::from(i) * 10.0)])
            .collect();
        let ((_, _), hidden) = legend_position((400.0, 300.0), size, 10.0, &rows);
        assert!((hidden - 6.0 * 110.0).abs() < 1e-9, "{hidden}");
    }

    #[test]
    fn boxes_grow_by_rows_and_columns_and_shrink_with_the_text() {
        let size = sized(10);
        assert_eq!(size(Setting::FULL), (137.0, 145.0));
        // Two columns of five: two column widths and a gap; five rows.
        let two = size(Setting {
            scale: 1.0,
            columns: 2,
        });
        assert_eq!(two, (274.0, 77.5));
        // Three columns of 4, 4 and 2.
        let (w, h) = size(Setting {
            scale: 1.0,
            columns: 3,
        });
        assert_eq!((w, h), (411.0, 64.0));
        let (w, h) = size(Setting {
            scale: 0.5,
            columns: 1,
        });
        assert_eq!((w, h), (68.5, 72.5));
    }

    #[test]
    fn a_wide_area_takes_the_legend_to_the_right_in_one_column() {
        let chosen = choose_outside((600.0, 300.0), 5.0, 10, sized(10), golden);
        assert_eq!(chosen.side, Side::Right);
        assert_eq!(chosen.setting, Setting::FULL);
        assert_eq!(chosen.strip, (147.0, 155.0));
    }

    #[test]
    fn a_tall_area_takes_the_legend_below_in_as_many_columns_as_fit() {
        let chosen = choose_outside((300.0, 600.0), 5.0, 10, sized(10), golden);
        assert_eq!(chosen.side, Side::Below);
        assert_eq!(
            chosen.setting,
            Setting {
                scale: 1.0,
                columns: 2
            }
        );
        assert!(chosen.strip.0 <= 300.0);
    }

    #[test]
    fn text_shrinks_before_a_column_is_added_beside_the_plot() {
        // 145 + 10 px does not fit 150 px of height; at 0.9, 130.5 + 10 does.
        let chosen = choose_outside((600.0, 150.0), 5.0, 10, sized(10), golden);
        assert_eq!(chosen.side, Side::Right);
        assert_eq!(
            chosen.setting,
            Setting {
                scale: 0.9,
                columns: 1
            }
        );
    }

    #[test]
    fn a_legend_too_large_for_any_side_still_stays_inside_its_area() {
        for (area, n) in [((200.0, 120.0), 40), ((90.0, 60.0), 3), ((1.0, 1.0), 1)] {
            let chosen = choose_outside(area, 5.0, n, sized(n), golden);
            assert_eq!(chosen.side, Side::Below);
            assert!(chosen.strip.0 <= area.0.max(10.0) + 1e-9, "{area:?}");
            let (_, box_h) = sized(n)(chosen.setting);
            assert!(box_h <= LAST_RESORT_SHARE * area.1 + 1e-9, "{area:?}");
        }
    }
}
