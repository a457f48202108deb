//! Evaluation of a plan's jobs in parallel (rayon), results in job order so that output is
//! identical at any thread count.

use crate::error::{Error, Result};
use crate::grid::linspace;
use crate::plan::Job;
use crate::scene::Sampling;
use rayon::prelude::*;
use std::sync::Arc;

/// The evaluated points of one job.
#[derive(Debug, Clone)]
pub struct Evaluated {
    /// (x, y) per point; for curves (θ, value) with θ increasing.
    pub points: Arc<Vec<(f64, f64)>>,
    /// z per point (datasets with a z axis).
    pub z: Option<Arc<Vec<f64>>>,
    /// Grid shape when the points form a row-major grid.
    pub grid: Option<(usize, usize)>,
}

/// The θ values at which a curve job is sampled.
pub fn thetas(theta_range: (f64, f64), sampling: Sampling) -> Vec<f64> {
    match sampling {
        Sampling::Uniform(n) => linspace(theta_range.0, theta_range.1, n),
    }
}

/// Evaluates one job; a non-finite value is an error, never output.
pub fn evaluate(job: &Job) -> Result<Evaluated> {
    let (name, evaluated) = match job {
        Job::Curve { curve, theta_range, sampling } => {
            let points = thetas(*theta_range, *sampling).into_iter().map(|t| (t, curve.eval(t))).collect();
            (curve.canonical_json(), Evaluated { points: Arc::new(points), z: None, grid: None })
        }
        Job::Data(dataset) => {
            let data = dataset.evaluate();
            let evaluated = Evaluated { points: Arc::new(data.points), z: data.z.map(Arc::new), grid: data.grid };
            (dataset.canonical_json(), evaluated)
        }
    };
    let finite_z = evaluated.z.as_ref().is_none_or(|z| z.iter().all(|v| v.is_finite()));
    match evaluated.points.iter().find(|(x, y)| !(x.is_finite() && y.is_finite())) {
        Some(&(x, y)) => Err(Error::Numerics(format!("{name} gave a non-finite point ({x:?}, {y:?})"))),
        None if !finite_z => Err(Error::Numerics(format!("{name} gave a non-finite z value"))),
        None => Ok(evaluated),
    }
}

/// Evaluates every job in parallel; results are in job order.
pub fn evaluate_all(jobs: &[Job]) -> Result<Vec<Evaluated>> {
    jobs.par_iter().map(evaluate).collect()
}
