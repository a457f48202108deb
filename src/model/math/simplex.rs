//! Nelder–Mead downhill simplex minimization of a function of a few variables within a box
//! (Nelder & Mead 1965, with the standard coefficients of Lagarias et al. 1998, SIAM J. Optim. 9(1)):
//! derivative-free, so it tolerates the quadrature noise of an objective such as `l2_projected`.
//!
//! Trial points outside the box are projected onto it. A run stops when every vertex lies within
//! `x_tol` (max norm) of the best one, or after `max_evaluations`; it then restarts from its best point
//! with the initial simplex size, as long as a restart improves the value — the usual remedy for a
//! simplex that collapsed before reaching the minimum. A NaN value counts as +∞. Sequential and
//! deterministic: the same inputs give the same bits on any thread. No I/O.

/// Reflection coefficient ρ.
const REFLECT: f64 = 1.0;
/// Expansion coefficient χ.
const EXPAND: f64 = 2.0;
/// Contraction coefficient γ.
const CONTRACT: f64 = 0.5;
/// Shrink coefficient σ.
const SHRINK: f64 = 0.5;
/// Most restarts after the first run: each restart costs a fresh simplex, and two are enough to escape a
/// collapsed simplex on the smooth objectives this serves.
const MAX_RESTARTS: usize = 2;

/// The box and the stopping rule of a minimization.
#[derive(Debug, Clone, Copy)]
pub struct Bounds<'a> {
    /// Lower bound of each coordinate.
    pub lower: &'a [f64],
    /// Upper bound of each coordinate.
    pub upper: &'a [f64],
    /// Initial simplex edge along each coordinate.
    pub step: &'a [f64],
    /// Largest max-norm distance of a vertex from the best one at convergence.
    pub x_tol: f64,
    /// Most function evaluations of one run (restarts get as many again).
    pub max_evaluations: usize,
}

/// The best point found and its value.
#[derive(Debug, Clone, PartialEq)]
pub struct Minimum {
    /// The point.
    pub x: Vec<f64>,
    /// f(x).
    pub value: f64,
}

/// Minimizes `f` over the box of `bounds`, starting from `start` (projected onto the box); an error
/// of `f` ends the search. All slices must have the length of `start`.
pub fn minimize<E>(
    mut f: impl FnMut(&[f64]) -> Result<f64, E>,
    start: &[f64],
    bounds: Bounds,
) -> Result<Minimum, E> {
    let mut best = run(&mut f, start, bounds)?;
    for _ in 0..MAX_RESTARTS {
        let again = run(&mut f, &best.x, bounds)?;
        if again.value >= best.value {
            break;
        }
        best = again;
    }
    Ok(best)
}

/// One Nelder–Mead run from `start`.
fn run<E>(
    f: &mut impl FnMut(&[f64]) -> Result<f64, E>,
    start: &[f64],
    bounds: Bounds,
) -> Result<Minimum, E> {
    let n = start.len();
    let project = |x: &mut Vec<f64>| {
        for (i, v) in x.iter_mut().enumerate() {
            *v = v.clamp(bounds.lower[i], bounds.upper[i]);
        }
    };
    let evaluations = std::cell::Cell::new(0);
    let mut value = |x: &[f64]| -> Result<f64, E> {
        evaluations.set(evaluations.get() + 1);
        f(x).map(|v| if v.is_nan() { f64::INFINITY } else { v })
    };
    // The initial simplex: the start and one step along each coordinate, stepping back where the box ends.
    let mut origin = start.to_vec();
    project(&mut origin);
    let mut simplex: Vec<(Vec<f64>, f64)> = Vec::with_capacity(n + 1);
    let v0 = value(&origin)?;
    simplex.push((origin.clone(), v0));
    for i in 0..n {
        let mut x = origin.clone();
        x[i] += bounds.step[i];
        if x[i] > bounds.upper[i] {
            x[i] = origin[i] - bounds.step[i];
        }
        project(&mut x);
        let v = value(&x)?;
        simplex.push((x, v));
    }
    loop {
        // Stable sort: among equal values the earlier vertex stays first, deterministically.
        simplex.sort_by(|a, b| a.1.total_cmp(&b.1));
        let size = simplex[1..]
            .iter()
            .flat_map(|(x, _)| x.iter().zip(&simplex[0].0).map(|(a, b)| (a - b).abs()))
            .fold(0.0, f64::max);
        if size <= bounds.x_tol || evaluations.get() >= bounds.max_evaluations {
            let (x, value) = simplex.swap_remove(0);
            return Ok(Minimum { x, value });
        }
        let centroid: Vec<f64> = (0..n)
            .map(|i| simplex[..n].iter().map(|(x, _)| x[i]).sum::<f64>() / n as f64)
            .collect();
        let worst = simplex[n].clone();
        // The point centroid + t (centroid − worst), projected onto the box.
        let along = |t: f64| {
            let mut x: Vec<f64> = (0..n)
                .map(|i| centroid[i] + t * (centroid[i] - worst.0[i]))
                .collect();
            project(&mut x);
            x
        };
        let reflected = along(REFLECT);
        let f_reflected = value(&reflected)?;
        if f_reflected < simplex[0].1 {
            let expanded = along(REFLECT * EXPAND);
            let f_expanded = value(&expanded)?;
            simplex[n] = if f_expanded < f_reflected {
                (expanded, f_expanded)
            } else {
                (reflected, f_reflected)
            };
            continue;
        }
        if f_reflected < simplex[n - 1].1 {
            simplex[n] = (reflected, f_reflected);
            continue;
        }
        // Contract outside (towards the reflected point), accepted if no worse than it, or inside
        // (towards the worst one), accepted only if better than the worst: on a flat stretch a
        // degenerate simplex whose centroid is its worst vertex would otherwise accept that same point
        // for ever instead of shrinking.
        let outside = f_reflected < worst.1;
        let t = if outside {
            REFLECT * CONTRACT
        } else {
            -CONTRACT
        };
        let contracted = along(t);
        let f_contracted = value(&contracted)?;
        if (outside && f_contracted <= f_reflected) || f_contracted < worst.1 {
            simplex[n] = (contracted, f_contracted);
            continue;
        }
        // Shrink every vertex towards the best one.
        let best = simplex[0].0.clone();
        for vertex in &mut simplex[1..] {
            let x: Vec<f64> = (0..n)
                .map(|i| best[i] + SHRINK * (vertex.0[i] - best[i]))
                .collect();
            let v = value(&x)?;
            *vertex = (x, v);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::convert::Infallible;

    fn bounds<'a>(lower: &'a [f64], upper: &'a [f64], step: &'a [f64]) -> Bounds<'a> {
        Bounds {
            lower,
            upper,
            step,
            x_tol: 1e-10,
            max_evaluations: 5000,
        }
    }

    #[test]
    fn finds_the_minimum_of_rosenbrocks_valley() {
        // f = (1 − x)² + 100 (y − x²)², minimum 0 at (1, 1): the classic curved valley.
        let rosenbrock = |x: &[f64]| {
            Ok::<_, Infallible>((1.0 - x[0]).powi(2) + 100.0 * (x[1] - x[0] * x[0]).powi(2))
        };
        let (lower, upper, step) = ([-5.0, -5.0], [5.0, 5.0], [0.5, 0.5]);
        let min = minimize(rosenbrock, &[-1.2, 1.0], bounds(&lower, &upper, &step)).unwrap();
        assert!(
            (min.x[0] - 1.0).abs() < 1e-8 && (min.x[1] - 1.0).abs() < 1e-8,
            "{min:?}"
        );
        assert!(min.value < 1e-16, "{min:?}");
    }

    #[test]
    fn stays_inside_the_box_and_stops_on_its_boundary() {
        // The unconstrained minimum (3, −2) lies outside [0, 1]²: the box's corner (1, 0) is the answer.
        let bowl = |x: &[f64]| {
            assert!(x.iter().all(|v| (0.0..=1.0).contains(v)), "{x:?}");
            Ok::<_, Infallible>((x[0] - 3.0).powi(2) + (x[1] + 2.0).powi(2))
        };
        let (lower, upper, step) = ([0.0, 0.0], [1.0, 1.0], [0.25, 0.25]);
        let min = minimize(bowl, &[0.5, 0.5], bounds(&lower, &upper, &step)).unwrap();
        assert_eq!(min.x, [1.0, 0.0]);
        assert_eq!(min.value, 8.0);
    }

    #[test]
    fn shrinks_on_a_flat_stretch_instead_of_stalling() {
        // A constant: every trial ties, so only shrinking converges. Accepting a tied inside
        // contraction moved one vertex for ever and ran each run to max_evaluations (10 002 calls here).
        let calls = std::cell::Cell::new(0);
        let flat = |_: &[f64]| {
            calls.set(calls.get() + 1);
            Ok::<_, Infallible>(1.0)
        };
        let (lower, upper, step) = ([-5.0, -5.0], [5.0, 5.0], [0.5, 0.5]);
        let min = minimize(flat, &[0.3, -0.2], bounds(&lower, &upper, &step)).unwrap();
        assert_eq!(min.x, [0.3, -0.2]);
        // Three runs (the first and two restarts), each ~33 halvings of 4 calls from 0.5 to x_tol.
        assert!(calls.get() <= 300, "{} evaluations", calls.get());
    }

    #[test]
    fn nan_counts_as_worse_and_errors_end_the_search() {
        let holey = |x: &[f64]| {
            Ok::<_, Infallible>(if x[0] < 0.0 {
                f64::NAN
            } else {
                (x[0] - 2.0).powi(2)
            })
        };
        let (lower, upper, step) = ([-10.0], [10.0], [1.0]);
        let min = minimize(holey, &[0.5], bounds(&lower, &upper, &step)).unwrap();
        assert!((min.x[0] - 2.0).abs() < 1e-9, "{min:?}");
        let failing = |x: &[f64]| {
            if x[0] > 1.0 {
                Err("too far")
            } else {
                Ok(-x[0])
            }
        };
        assert_eq!(
            minimize(failing, &[0.0], bounds(&lower, &upper, &step)),
            Err("too far")
        );
    }

    #[test]
    fn the_same_start_gives_the_same_bits() {
        let f = |x: &[f64]| {
            Ok::<_, Infallible>((x[0] - 0.3).powi(2) * (1.0 + x[1] * x[1]) + (x[1] - 0.7).abs())
        };
        let (lower, upper, step) = ([-1.0, -1.0], [1.0, 1.0], [0.1, 0.1]);
        let a = minimize(f, &[0.0, 0.0], bounds(&lower, &upper, &step)).unwrap();
        let b = minimize(f, &[0.0, 0.0], bounds(&lower, &upper, &step)).unwrap();
        assert_eq!(
            a.x.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
            b.x.iter().map(|v| v.to_bits()).collect::<Vec<_>>()
        );
    }
}
