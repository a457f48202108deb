//! Evaluation of a plan's jobs in parallel (rayon), results in job order so that output is
//! identical at any thread count.

use crate::error::{Error, Result};
use crate::grid::linspace;
use crate::plan::Job;
use crate::scene::Sampling;
use rayon::prelude::*;
use std::sync::Arc;

/// Sampled points of one job: (θ, value) with θ increasing.
pub type Points = Arc<Vec<(f64, f64)>>;

/// The θ values at which a job is evaluated.
pub fn thetas(job: &Job) -> Vec<f64> {
    let (a, b) = job.theta_range;
    match job.sampling {
        Sampling::Uniform(n) => linspace(a, b, n),
    }
}

/// Evaluates one job; a non-finite value is an error, never output.
pub fn evaluate(job: &Job) -> Result<Points> {
    let points: Vec<(f64, f64)> = thetas(job).into_iter().map(|t| (t, job.curve.eval(t))).collect();
    if let Some(&(theta, value)) = points.iter().find(|(_, v)| !v.is_finite()) {
        return Err(Error::Numerics(format!(
            "{} gave {value} at theta = {theta:?}",
            job.curve.canonical_json()
        )));
    }
    Ok(Arc::new(points))
}

/// Evaluates every job in parallel; results are in job order.
pub fn evaluate_all(jobs: &[Job]) -> Result<Vec<Points>> {
    jobs.par_iter().map(evaluate).collect()
}
