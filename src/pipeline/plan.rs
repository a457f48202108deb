//! The sampling plan: what a set of scenes actually needs evaluated.
//!
//! Between validated scenes and evaluation sits this one place that decides the work: each
//! distinct (curve, θ range, sampling) or dataset is evaluated once however many panels or scenes
//! show it, curves only over the θ range their panel makes visible, only for the outputs
//! requested (drawn figures, tables), and nothing that no series shows (the Fresnel basis is built
//! only by a job that needs it). It decides, never evaluates.

use crate::model::curve::Curve;
use crate::model::dataset::Dataset;
use crate::pipeline::adaptive::{Frame, Geometry};
use crate::spec::look::PanelKind;
use crate::spec::scene::{Sampling, Scene, ScenePanel};
use std::collections::HashMap;

/// One evaluation job.
#[derive(Debug, Clone)]
pub enum Job {
    /// A curve sampled on `samples` evenly spaced θ over an interval, ends included.
    Uniform {
        /// The curve.
        curve: Curve,
        /// θ interval in radians.
        theta_range: (f64, f64),
        /// Number of samples.
        samples: usize,
    },
    /// A curve sampled adaptively for the panel `frames[frame]` (its pixel size and y axis).
    Adaptive {
        /// The curve.
        curve: Curve,
        /// Index into [`Plan::frames`].
        frame: usize,
    },
    /// A dataset computed once.
    Data(Dataset),
}

/// `feeds[scene][panel][series]` = index into [`Plan::jobs`]; a panel's series are its curves,
/// then its data series.
pub type Feeds = Vec<Vec<Vec<usize>>>;

/// Which kinds of output a run produces.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Outputs {
    /// Drawn figures (SVG, PNG or PDF).
    pub drawn: bool,
    /// Tables (CSV).
    pub table: bool,
}

/// The jobs, plus for each requested output kind the job feeding each scene, panel and series.
#[derive(Debug, Clone)]
pub struct Plan {
    /// Distinct jobs in first-use order.
    pub jobs: Vec<Job>,
    /// Pixel frames of the panels that adaptive jobs are judged in.
    pub frames: Vec<Frame>,
    /// Feeds of the drawn figures, `None` when no figure is drawn.
    pub drawn: Option<Feeds>,
    /// Feeds of the tables, `None` when no table is written.
    pub table: Option<Feeds>,
}

impl Plan {
    /// Where job `job` is first used: its scene, and the panel and series it draws or tabulates.
    pub fn first_use(&self, job: usize) -> Option<(usize, usize, usize)> {
        let in_feeds = |feeds: &Feeds| {
            feeds.iter().enumerate().find_map(|(scene, panels)| {
                panels.iter().enumerate().find_map(|(panel, series)| {
                    let s = series.iter().position(|&j| j == job)?;
                    Some((scene, panel, s))
                })
            })
        };
        self.drawn
            .as_ref()
            .and_then(in_feeds)
            .or_else(|| self.table.as_ref().and_then(in_feeds))
    }
}

/// Plans the evaluation of `scenes` for `outputs`, sharing identical jobs. Adaptive tolerances
/// are judged at the finer of the SVG's and the PNG's pixel sizes whichever formats are asked
/// for, so the requested formats never change a value written.
pub fn plan(scenes: &[Scene], outputs: Outputs) -> Plan {
    let mut planner = Planner::default();
    let mut feeds_for = |pick: fn(Sampling) -> Sampling| -> Feeds {
        scenes
            .iter()
            .map(|scene| {
                let sampling = pick(scene.sampling);
                (0..scene.panels.len())
                    .map(|p| planner.panel(scene, p, sampling))
                    .collect()
            })
            .collect()
    };
    let drawn = outputs.drawn.then(|| feeds_for(Sampling::for_drawing));
    let table = outputs.table.then(|| feeds_for(Sampling::for_table));
    Plan {
        jobs: planner.jobs,
        frames: planner.frames,
        drawn,
        table,
    }
}

/// Interns jobs and frames by a key naming everything their result depends on.
#[derive(Default)]
struct Planner {
    jobs: Vec<Job>,
    frames: Vec<Frame>,
    index: HashMap<String, usize>,
    /// Distinct adaptive contexts (a frame and every curve of its panel), numbered, so that a
    /// job's key names its context by number: a panel of n curves costs O(n) keys, not O(n²).
    contexts: HashMap<String, usize>,
}

impl Planner {
    fn intern(&mut self, key: String, job: impl FnOnce(&mut Vec<Frame>) -> Job) -> usize {
        if let Some(&i) = self.index.get(&key) {
            return i;
        }
        let job = job(&mut self.frames);
        self.jobs.push(job);
        self.index.insert(key, self.jobs.len() - 1);
        self.jobs.len() - 1
    }

    /// The jobs feeding panel `p` of `scene` under `sampling`.
    fn panel(&mut self, scene: &Scene, p: usize, sampling: Sampling) -> Vec<usize> {
        let panel = &scene.panels[p];
        let (a, b) = panel.axes.theta_range();
        let mut feed = Vec::with_capacity(panel.curves.len() + panel.data.len());
        match sampling {
            // Cartesian and polar panels place (θ, v) in a 2D pixel frame; surface and heat-map
            // panels do not.
            Sampling::Adaptive { tolerance_px }
                if !matches!(
                    panel.axes.kind,
                    PanelKind::Surface { .. } | PanelKind::Heatmap { .. }
                ) =>
            {
                let frame = frame(scene, panel, tolerance_px);
                // An adaptive curve depends on its panel's frame and, through the automatic y range,
                // on every other curve of the panel.
                let neighbours: Vec<String> = panel
                    .curves
                    .iter()
                    .map(|c| c.curve.canonical_json())
                    .collect();
                let next = self.contexts.len();
                let context = *self
                    .contexts
                    .entry(format!("{frame:?} {neighbours:?}"))
                    .or_insert(next);
                let mut frame_index = None;
                for shown in &panel.curves {
                    let key = format!("adaptive {} in #{context}", shown.curve.canonical_json());
                    feed.push(self.intern(key, |frames| {
                        let index = *frame_index.get_or_insert_with(|| {
                            frames.push(frame.clone());
                            frames.len() - 1
                        });
                        Job::Adaptive {
                            curve: shown.curve.clone(),
                            frame: index,
                        }
                    }));
                }
            }
            // Surface panels draw curves as 3D lines (heat maps none): no 2D pixel frame, so the
            // table's grid.
            Sampling::Adaptive { .. } | Sampling::Default => {
                return self.panel(
                    scene,
                    p,
                    Sampling::Uniform(crate::spec::scene::DEFAULT_SAMPLES),
                );
            }
            Sampling::Uniform(samples) => {
                for shown in &panel.curves {
                    let key = format!(
                        "uniform {} {a:?} {b:?} {samples}",
                        shown.curve.canonical_json()
                    );
                    feed.push(self.intern(key, |_| Job::Uniform {
                        curve: shown.curve.clone(),
                        theta_range: (a, b),
                        samples,
                    }));
                }
            }
        }
        for shown in &panel.data {
            feed.push(self.intern(shown.dataset.canonical_json(), |_| {
                Job::Data(shown.dataset.clone())
            }));
        }
        feed
    }
}

/// The pixel frame of `panel` in `scene` (see [`Frame::of_cell`]), at the PNG's pixel size or
/// the SVG's, whichever is finer.
fn frame(scene: &Scene, panel: &ScenePanel, tolerance_px: f64) -> Frame {
    let canvas = &scene.canvas;
    let scale = canvas.png_scale.max(1.0);
    Frame::of_cell(
        (f64::from(canvas.width_px), f64::from(canvas.height_px)),
        (scene.rows, scene.cols),
        canvas.font_px,
        !scene.title.is_empty(),
        scale,
        (
            panel.axes.theta_range(),
            Geometry::of(&panel.axes.kind, panel.axes.x_unit),
            panel.axes.x_scale,
        ),
        (panel.axes.y_scale, panel.axes.y_range),
        tolerance_px,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec::source::{CanvasOverride, load_scenes};

    /// A panel of n adaptive curves costs keys of O(n) bytes in all: each names its panel's
    /// context by number (it held the JSON of every curve of the panel, O(n²) bytes: 4 GB at the
    /// 10 000-curve cap).
    #[test]
    fn job_keys_grow_linearly_with_the_curves_of_a_panel() {
        let spec = r#"{"id": "many", "panels": [{"curves": [
            {"ndf": "beckmann", "alpha_b": {"linspace": [0.05, 1.0, 2000]}}]}]}"#;
        let sources = [("many.json".to_owned(), spec.to_owned(), None)];
        let scenes =
            crate::pipeline::resolve::scenes(load_scenes(&sources, CanvasOverride::default()))
                .unwrap();
        let mut planner = Planner::default();
        let feed = planner.panel(&scenes[0], 0, Sampling::Adaptive { tolerance_px: 0.25 });
        assert_eq!(feed.len(), 2000);
        let key_bytes: usize = planner.index.keys().map(String::len).sum();
        assert!(key_bytes < 2000 * 200, "{key_bytes} bytes of keys");
        assert_eq!(planner.contexts.len(), 1);
    }
}
