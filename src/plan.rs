//! The sampling plan: what a set of scenes actually needs evaluated.
//!
//! Between validated scenes and evaluation sits this one place that decides the work: each
//! distinct (curve, θ range, sampling) or dataset is evaluated once however many panels or scenes
//! show it, curves only over the θ range their panel makes visible, and nothing that no series
//! shows (the Fresnel basis is built only by a job that needs it).

use crate::curve::Curve;
use crate::dataset::Dataset;
use crate::scene::{Sampling, Scene};
use std::collections::HashMap;

/// One evaluation job.
#[derive(Debug, Clone)]
pub enum Job {
    /// A curve sampled over a θ interval.
    Curve {
        /// The curve.
        curve: Curve,
        /// θ interval in radians.
        theta_range: (f64, f64),
        /// How to sample it.
        sampling: Sampling,
    },
    /// A dataset computed once.
    Data(Dataset),
}

/// The jobs, plus for each scene, panel and series the index of the job that feeds it.
#[derive(Debug, Clone)]
pub struct Plan {
    /// Distinct jobs in first-use order.
    pub jobs: Vec<Job>,
    /// `feeds[scene][panel][series]` = index into `jobs`; a panel's series are its curves, then
    /// its data series.
    pub feeds: Vec<Vec<Vec<usize>>>,
}

/// Plans the evaluation of `scenes`, sharing identical jobs.
pub fn plan(scenes: &[Scene]) -> Plan {
    let mut jobs: Vec<Job> = Vec::new();
    let mut index: HashMap<String, usize> = HashMap::new();
    let mut intern = |key: String, job: &dyn Fn() -> Job| {
        *index.entry(key).or_insert_with(|| {
            jobs.push(job());
            jobs.len() - 1
        })
    };
    let feeds = scenes
        .iter()
        .map(|scene| {
            scene
                .panels
                .iter()
                .map(|panel| {
                    let (a, b) = panel.theta_range();
                    let curves = panel.curves.iter().map(|shown| {
                        let key = format!("{} {:?} {:?} {:?}", shown.curve.canonical_json(), a, b, scene.sampling);
                        intern(key, &|| Job::Curve {
                            curve: shown.curve.clone(),
                            theta_range: (a, b),
                            sampling: scene.sampling,
                        })
                    });
                    let mut feed: Vec<usize> = curves.collect();
                    for shown in &panel.data {
                        feed.push(intern(shown.dataset.canonical_json(), &|| Job::Data(shown.dataset.clone())));
                    }
                    feed
                })
                .collect()
        })
        .collect();
    Plan { jobs, feeds }
}
