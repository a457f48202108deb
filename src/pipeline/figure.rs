//! The evaluated figure: the one result type between the sampler and every exporter.
//!
//! Exporters (SVG, PNG, PDF, CSV, the interactive page) turn a [`Figure`] into bytes and never
//! decide what to compute; [`Figure::assemble`] is the one place that joins a scene's description
//! with its evaluated jobs.

use crate::model::curve::Curve;
use crate::pipeline::provenance::Provenance;
use crate::pipeline::sample::Evaluated;
use crate::spec::look::{Axes, Canvas, Style, Theme, XUnit};
use crate::spec::scene::Scene;
use crate::spec::scene::interactive::Interactive;
use std::sync::Arc;

/// One drawn series: a polyline of (θ, value) points with its style and legend label.
#[derive(Debug, Clone)]
pub struct Series {
    /// Legend label, e.g. `α_b = 0.4`.
    pub label: String,
    /// Canonical curve JSON, used as the `curve` column of the CSV.
    pub curve: String,
    /// Drawing style.
    pub style: Style,
    /// Points (x, y): for curves (θ in radians, value) with θ increasing. Shared when several
    /// panels show one curve.
    pub points: Arc<Vec<(f64, f64)>>,
    /// z per point, for series in surface panels; `None` elsewhere.
    pub z: Option<Arc<Vec<f64>>>,
    /// `Some((rows, cols))` when the points form a row-major grid to draw as a surface mesh.
    pub grid: Option<(usize, usize)>,
}

/// One panel (sub-plot) of a figure: its axes as the spec gave them (the θ axis range made
/// explicit) and its evaluated series.
#[derive(Debug, Clone)]
pub struct Panel {
    /// Titles, axes, scales, ranges and legend.
    pub axes: Axes,
    /// Series in drawing order.
    pub series: Vec<Series>,
}

/// A figure ready for export: panels laid out on a `rows × cols` grid, filled row by row.
#[derive(Debug, Clone)]
pub struct Figure {
    /// Scene id; output files are `<id>.<ext>`.
    pub id: String,
    /// Figure title drawn above the panels; empty for none.
    pub title: String,
    /// Grid rows.
    pub rows: usize,
    /// Grid columns.
    pub cols: usize,
    /// Size and typography.
    pub canvas: Canvas,
    /// Colours and line distinctions.
    pub theme: Theme,
    /// Panels, row-major; `panels.len() <= rows * cols`.
    pub panels: Vec<Panel>,
    /// Which ndfplot drew it from which spec; every drawn format embeds it, tables do not.
    pub provenance: Provenance,
    /// What its interactive page computes live, for a scene with sliders; `None` otherwise.
    pub page: Option<Page>,
}

/// What the interactive page of a figure needs besides the figure: its sliders, and the curves of
/// its one panel at the sliders' start values with the parameters each slider drives.
#[derive(Debug, Clone)]
pub struct Page {
    /// The scene's own title (the figure's also states the sliders' start values).
    pub title: String,
    /// The sliders and, per curve, its label template and slider bindings.
    pub interactive: Interactive,
    /// The panel's curves at the start values with their styles, in panel order.
    pub curves: Vec<(Curve, Style)>,
}

impl Figure {
    /// The points of every series of every panel, counted.
    pub fn point_count(&self) -> usize {
        self.panels
            .iter()
            .flat_map(|p| &p.series)
            .map(|s| s.points.len())
            .sum()
    }

    /// Builds the figure of `scene`, drawn from the spec `provenance` records, from its evaluated jobs
    /// (`feeds[panel][series]` → job index).
    pub fn assemble(
        scene: &Scene,
        provenance: &Provenance,
        feeds: &[Vec<usize>],
        evaluated: &[Evaluated],
    ) -> Figure {
        let panels = scene
            .panels
            .iter()
            .zip(feeds)
            .map(|(panel, feed)| {
                let named = panel
                    .curves
                    .iter()
                    .map(|c| (c.label.clone(), c.curve.canonical_json(), c.style))
                    .chain(
                        panel
                            .data
                            .iter()
                            .map(|d| (d.label.clone(), d.dataset.canonical_json(), d.style)),
                    );
                let axes = Axes {
                    x_range: match panel.axes.x_unit {
                        XUnit::Plain => panel.axes.x_range,
                        _ => Some(panel.axes.theta_range()),
                    },
                    ..panel.axes.clone()
                };
                Panel {
                    axes,
                    series: named
                        .zip(feed)
                        .map(|((label, curve, style), &job)| Series {
                            label,
                            curve,
                            style,
                            points: evaluated[job].points.clone(),
                            z: evaluated[job].z.clone(),
                            grid: evaluated[job].grid,
                        })
                        .collect(),
                }
            })
            .collect();
        Figure {
            id: scene.id.clone(),
            title: static_title(scene),
            rows: scene.rows,
            cols: scene.cols,
            canvas: scene.canvas,
            theme: scene.theme,
            panels,
            provenance: provenance.clone(),
            page: scene.interactive.as_ref().map(|interactive| Page {
                title: scene.title.clone(),
                interactive: interactive.clone(),
                curves: scene.panels[0]
                    .curves
                    .iter()
                    .map(|c| (c.curve.clone(), c.style))
                    .collect(),
            }),
        }
    }
}

/// The title of a scene's static figure: an interactive scene's figure shows the sliders' start
/// positions, so it also says which (`Fresnel … — at η = 1.1`; just the positions when untitled).
fn static_title(scene: &Scene) -> String {
    let Some(interactive) = &scene.interactive else {
        return scene.title.clone();
    };
    let at = interactive
        .sliders
        .iter()
        .map(|s| format!("{} = {}", s.label, crate::spec::numbers::pretty(s.start)))
        .collect::<Vec<_>>()
        .join(", ");
    if scene.title.is_empty() {
        format!("at {at}")
    } else {
        format!("{} — at {at}", scene.title)
    }
}
