//! The sampling plan: what a set of scenes actually needs evaluated.
//!
//! Between validated scenes and evaluation sits this one place that decides the work: each
//! distinct (curve, θ range, sampling) is evaluated once however many panels or scenes show it,
//! and only over the θ range a panel makes visible.

use crate::curve::Curve;
use crate::scene::{Sampling, Scene};
use std::collections::HashMap;

/// One evaluation job: a curve sampled over a θ interval.
#[derive(Debug, Clone)]
pub struct Job {
    /// The curve.
    pub curve: Curve,
    /// θ interval in radians.
    pub theta_range: (f64, f64),
    /// How to sample it.
    pub sampling: Sampling,
}

/// The jobs, plus for each scene, panel and series the index of the job that feeds it.
#[derive(Debug, Clone)]
pub struct Plan {
    /// Distinct jobs in first-use order.
    pub jobs: Vec<Job>,
    /// `feeds[scene][panel][series]` = index into `jobs`.
    pub feeds: Vec<Vec<Vec<usize>>>,
}

/// Plans the evaluation of `scenes`, sharing identical jobs.
pub fn plan(scenes: &[Scene]) -> Plan {
    let mut jobs: Vec<Job> = Vec::new();
    let mut index: HashMap<(String, u64, u64, Sampling), usize> = HashMap::new();
    let feeds = scenes
        .iter()
        .map(|scene| {
            scene
                .panels
                .iter()
                .map(|panel| {
                    panel
                        .curves
                        .iter()
                        .map(|shown| {
                            let (a, b) = panel.x_range;
                            let key = (shown.curve.canonical_json(), a.to_bits(), b.to_bits(), scene.sampling);
                            *index.entry(key).or_insert_with(|| {
                                jobs.push(Job { curve: shown.curve.clone(), theta_range: (a, b), sampling: scene.sampling });
                                jobs.len() - 1
                            })
                        })
                        .collect()
                })
                .collect()
        })
        .collect();
    Plan { jobs, feeds }
}
