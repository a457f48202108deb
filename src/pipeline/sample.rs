//! Evaluation of a plan's jobs in parallel (rayon), results in job order so that output is
//! identical at any thread count.
//!
//! Uniform and data jobs are evaluated in one pass. Adaptive jobs take three: their initial points,
//! then (once every curve of a panel has its initial points, which fixes the panel's automatic y
//! range and so its pixel scale) the refinement, then a second refinement only for panels whose
//! y range grew because the first one found a taller peak. Every curve value is `Curve::eval` at its
//! θ (uniform grids take them a block at a time, `Curve::eval_many`, the same bits), so tables equal
//! `ndfplot eval`.

use crate::error::{Error, Result};
use crate::model::curve::Curve;
use crate::model::grid::linspace;
use crate::pipeline::adaptive::{self, Frame, PixelMap, Refined};
use crate::pipeline::plan::{Job, Plan};
use rayon::prelude::*;
use std::sync::Arc;

/// The evaluated points of one job.
#[derive(Debug, Clone)]
pub struct Evaluated {
    /// (x, y) per point; for curves (θ, value) with θ increasing, the value possibly non-finite
    /// (see [`evaluate_all`]).
    pub points: Arc<Vec<(f64, f64)>>,
    /// z per point (datasets with a z axis).
    pub z: Option<Arc<Vec<f64>>>,
    /// Grid shape when the points form a row-major grid.
    pub grid: Option<(usize, usize)>,
    /// Curve evaluations spent (the points, plus the midpoints adaptive sampling rejected); 0 for
    /// datasets.
    pub evaluations: usize,
}

/// θ where a curve has a peak that an even grid could miss: its NDF's off-normal maximum
/// ([`Ndf::interior_peak`]). Peaks at θ = 0 or π/2 are grid points already.
pub fn peak_hints(curve: &Curve) -> Vec<f64> {
    match curve {
        Curve::Ndf(ndf) => ndf.interior_peak().into_iter().collect(),
        _ => Vec::new(),
    }
}

/// `samples` evenly spaced θ over `theta_range` (ends included) and the curve there, in one block
/// ([`Curve::eval_many`]).
fn uniform(curve: &Curve, theta_range: (f64, f64), samples: usize) -> Evaluated {
    let thetas = linspace(theta_range.0, theta_range.1, samples);
    let mut values = vec![0.0; thetas.len()];
    curve.eval_many(&thetas, &mut values);
    let points: Vec<(f64, f64)> = thetas.into_iter().zip(values).collect();
    Evaluated {
        evaluations: points.len(),
        points: Arc::new(points),
        z: None,
        grid: None,
    }
}

fn initial(curve: &Curve, theta_range: &(f64, f64)) -> Refined {
    adaptive::initial(&|t| curve.eval(t), *theta_range, &peak_hints(curve))
}

/// A job's evaluation in progress: done, or an adaptive polyline still to refine.
enum Stage {
    Done(Evaluated),
    Refining {
        curve: Curve,
        frame: usize,
        refined: Refined,
    },
}

/// Evaluates every job of `plan` in parallel; results are in job order. A dataset that is not a
/// function of θ and gives a non-finite value fails, reported with its index so that the caller can
/// name its spec; a series of θ keeps its non-finite values, for outputs to leave out.
pub fn evaluate_all(plan: &Plan) -> std::result::Result<Vec<Evaluated>, JobError> {
    evaluate_all_counted(plan, &|_| {})
}

/// Steps [`evaluate_all_counted`] counts per job: its first sampling and its refinement (a job that
/// needs none counts both at once).
pub const STEPS_PER_JOB: u64 = 2;

/// [`evaluate_all`], calling `done(n)` from the worker threads as jobs reach their stages, so that
/// a progress bar moves during evaluation: [`STEPS_PER_JOB`] steps per job in all.
pub fn evaluate_all_counted(
    plan: &Plan,
    done: &(dyn Fn(u64) + Sync),
) -> std::result::Result<Vec<Evaluated>, JobError> {
    let mut stages: Vec<Stage> = plan
        .jobs
        .par_iter()
        .map(|job| {
            let stage = first_stage(job, plan);
            done(match stage {
                Stage::Done(_) => STEPS_PER_JOB,
                Stage::Refining { .. } => 1,
            });
            stage
        })
        .collect();
    let mut maps = pixel_maps(&plan.frames, &stages);
    let mut pending: Vec<bool> = vec![true; plan.frames.len()];
    // At most two refinements: the second only where the first changed the pixel scale.
    for pass in 0..2 {
        stages.par_iter_mut().for_each(|stage| {
            if let Stage::Refining {
                curve,
                frame,
                refined,
            } = stage
                && pending[*frame]
            {
                let start = std::mem::replace(
                    refined,
                    Refined {
                        points: Vec::new(),
                        evaluations: 0,
                    },
                );
                let tolerance = plan.frames[*frame].tolerance_px;
                *refined = adaptive::refine(
                    &|t| curve.eval(t),
                    &maps[*frame],
                    tolerance,
                    adaptive::budget(curve),
                    start,
                );
                if pass == 0 {
                    done(STEPS_PER_JOB - 1);
                }
            }
        });
        let after = pixel_maps(&plan.frames, &stages);
        pending = maps
            .iter()
            .zip(&after)
            .map(|(before, after)| adaptive::needs_rescale(before, after))
            .collect();
        maps = after;
        if !pending.contains(&true) {
            break;
        }
    }
    stages
        .into_iter()
        .zip(&plan.jobs)
        .enumerate()
        .map(|(index, (stage, job))| {
            let failed = |error| JobError { job: index, error };
            let evaluated = match stage {
                Stage::Done(evaluated) => evaluated,
                Stage::Refining { refined, .. } => Evaluated {
                    points: Arc::new(refined.points),
                    z: None,
                    grid: None,
                    evaluations: refined.evaluations,
                },
            };
            check_finite(job, evaluated).map_err(failed)
        })
        .collect()
}

/// The first stage of `job`: a uniform or data job done, an adaptive one sampled once.
fn first_stage(job: &Job, plan: &Plan) -> Stage {
    match job {
        Job::Uniform {
            curve,
            theta_range,
            samples,
        } => Stage::Done(uniform(curve, *theta_range, *samples)),
        Job::Data(dataset) => {
            let data = dataset.evaluate();
            Stage::Done(Evaluated {
                points: Arc::new(data.points),
                z: data.z.map(Arc::new),
                grid: data.grid,
                evaluations: 0,
            })
        }
        Job::Adaptive { curve, frame } => {
            let refined = initial(curve, &plan.frames[*frame].theta_range);
            Stage::Refining {
                curve: curve.clone(),
                frame: *frame,
                refined,
            }
        }
    }
}

/// Why the job at index `job` of a plan could not be evaluated.
#[derive(Debug)]
pub struct JobError {
    /// The job's index in [`Plan::jobs`].
    pub job: usize,
    /// What went wrong.
    pub error: Error,
}

/// The pixel map of every frame from the current points of its adaptive jobs.
fn pixel_maps(frames: &[Frame], stages: &[Stage]) -> Vec<PixelMap> {
    (0..frames.len())
        .map(|f| {
            let polylines = stages.iter().filter_map(|s| match s {
                Stage::Refining { frame, refined, .. } if *frame == f => {
                    Some(refined.points.as_slice())
                }
                _ => None,
            });
            frames[f].map(adaptive::extent(polylines))
        })
        .collect()
}

/// A curve's non-finite values (a ratio where its divisor underflowed) stay in its points: drawings
/// break the line there, tables leave those rows out, and the figure lint names them. A non-finite
/// point of any other series is an error, never output.
fn check_finite(job: &Job, evaluated: Evaluated) -> Result<Evaluated> {
    let name = match job {
        Job::Uniform { .. } | Job::Adaptive { .. } => return Ok(evaluated),
        Job::Data(dataset) if dataset.is_theta() => return Ok(evaluated),
        Job::Data(dataset) => dataset.canonical_json(),
    };
    let finite_z = evaluated
        .z
        .as_ref()
        .is_none_or(|z| z.iter().all(|v| v.is_finite()));
    match evaluated
        .points
        .iter()
        .find(|(x, y)| !(x.is_finite() && y.is_finite()))
    {
        Some(&(x, y)) => Err(Error::Numerics(format!(
            "{name} gave a non-finite point ({x:?}, {y:?})"
        ))),
        None if !finite_z => Err(Error::Numerics(format!("{name} gave a non-finite z value"))),
        None => Ok(evaluated),
    }
}
