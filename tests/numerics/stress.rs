//! Stress tests: every NDF family over its whole accepted domain on log grids of at least 10⁵
//! parameter points: D finite and ≥ 0 on [0, π/2], normalized, monotone in θ where the maths says so
//! (Phong; Trowbridge–Reitz with α ≤ 1; Beckmann with α_b ≤ 1/√2), and continuous across the removable
//! singularities (ABC at a₂ = 1 and 2, SGD at s = 1 − a₂ = 0). Normalization, by piecewise adaptive
//! quadrature, is checked at every point of the full run.
//!
//! The full runs are `#[ignore]`d (`cargo test --release --test numerics stress -- --ignored`, about 2.5
//! minutes on two busy cores); the default run takes every [`SLICE_STRIDE`]th point of the same
//! grids and normalizes a regular subset of those (see [`SLICE_NORMALIZED_EVERY`]).

use crate::common::log_grid;
use ndfplot::model::domain::Param;
use ndfplot::model::math::quad::{QuadError, integrate};
use ndfplot::model::ndf::{Family, Ndf};
use rayon::prelude::*;
use std::f64::consts::{FRAC_1_SQRT_2, FRAC_PI_2, PI};

/// Parameter points per family in the full run (a 317 × 317 grid for two-parameter families).
const POINTS: usize = 100_000;
/// The default run checks every this-many-th point: 2000 per family, a few seconds.
const SLICE_STRIDE: usize = 50;
/// The normalization quadrature costs ~10⁴ evaluations and up to 50 ms per point (narrow lobes,
/// pieces of negligible mass), most of the full run: the default run applies it to every
/// this-many-th point of the grid (10² per family).
const SLICE_NORMALIZED_EVERY: usize = 1000;
/// θ per parameter point for the finite, sign and monotonicity checks: a uniform grid plus decades
/// towards 0 and towards π/2.
const UNIFORM_THETAS: usize = 129;
/// |2π ∫ D sin cos dθ − 1| accepted: the reference and property tests hold the families to 1e-12; a
/// stress run over 10⁵ points per family holds them to what the piecewise quadrature resolves.
const NORMALIZATION_TOL: f64 = 1e-9;
/// Relative tolerance of each quadrature piece.
const QUAD_TOL: f64 = 1e-11;
/// Absolute error of a piece that does not matter against the unit mass and [`NORMALIZATION_TOL`].
const NEGLIGIBLE_PIECE_ERROR: f64 = 1e-13;
/// Relative decrease allowed between neighbouring θ where D is monotone: rounding only.
const MONOTONE_SLACK: f64 = 1e-13;
/// Relative step across a removable singularity, and the relative change of D(0) it may cause
/// (D(0) is smooth in a₂ with a derivative of order ln(1 + a₁) ≤ 231 relative).
const SINGULAR_STEP: f64 = 1e-9;
const SINGULAR_CHANGE: f64 = 1e-6;

/// Lowest value of a log grid over a domain bounded below by 0: far below every lobe scale.
const LOG_FLOOR: f64 = 1e-300;

/// `n` values over the stated domain of `param`, bounds included: linear when it reaches below 0,
/// else log-spaced from its lower bound (from [`LOG_FLOOR`] when that is 0, plus 0 itself if accepted).
fn axis(param: &Param, n: usize) -> Vec<f64> {
    let (lo, hi) = (param.min.value, param.max.value);
    if lo < 0.0 {
        return (0..n)
            .map(|i| lo + (hi - lo) * i as f64 / (n - 1) as f64)
            .collect();
    }
    let zero = if param.contains(0.0) {
        vec![0.0]
    } else {
        vec![]
    };
    let lo = if param.min.inclusive || lo == 0.0 {
        lo
    } else {
        lo.next_up()
    };
    [zero, log_grid(lo.max(LOG_FLOOR), hi, n)].concat()
}

/// The parameter grid of a family over its stated domain, bounds included: [`POINTS`] values for one
/// parameter, a square grid for two.
fn grid(family: Family) -> Vec<Vec<f64>> {
    match family.params() {
        [a] => axis(a, POINTS).into_iter().map(|v| vec![v]).collect(),
        [a, b] => {
            let side = (POINTS as f64).sqrt().ceil() as usize;
            let b = axis(b, side);
            axis(a, side)
                .into_iter()
                .flat_map(|x| b.iter().map(move |&y| vec![x, y]))
                .collect()
        }
        params => panic!("{family:?}: no grid for {} parameters", params.len()),
    }
}

fn thetas() -> Vec<f64> {
    let mut thetas: Vec<f64> = (0..UNIFORM_THETAS)
        .map(|i| FRAC_PI_2 * i as f64 / (UNIFORM_THETAS - 1) as f64)
        .collect();
    thetas.extend(log_grid(1e-300, 1e-2, 30));
    thetas.extend(log_grid(1e-15, 1e-2, 14).into_iter().map(|d| FRAC_PI_2 - d));
    thetas.sort_by(f64::total_cmp);
    thetas
}

/// Whether the maths makes D non-increasing in θ.
fn monotone(ndf: &Ndf) -> bool {
    match ndf {
        Ndf::Phong(_) => true,
        Ndf::TrowbridgeReitz(d) => d.alpha_tr() <= 1.0,
        Ndf::Beckmann(d) => d.alpha_b() <= FRAC_1_SQRT_2,
        Ndf::Gtr(d) => d.alpha_gtr() <= 1.0,
        // ln D's slope in tan²θ is 2 − γ/(α²(γ − 1)) at θ = 0 and rises with θ for γ ≥ 2.
        Ndf::StudentT(d) => {
            d.gamma_std() >= 2.0
                && 2.0 * d.alpha_std().powi(2) * (d.gamma_std() - 1.0) <= d.gamma_std()
        }
        _ => false,
    }
}

/// 2π ∫₀^{π/2} D sin θ cos θ dθ over pieces broken geometrically (factor 4) from the lobe scale
/// 1/√(π D(0)) up to π/2 and from π/2 − 1e-15 down, so that a lobe of any width meets a piece of
/// comparable width.
fn normalization(ndf: &Ndf) -> f64 {
    let width = (1.0 / (PI * ndf.eval(0.0)).sqrt()).clamp(1e-300, 1.0);
    let mut breaks = vec![0.0, FRAC_PI_2];
    breaks.extend(
        std::iter::successors(Some(width / 16.0), |b| Some(b * 4.0)).take_while(|&b| b < FRAC_PI_2),
    );
    breaks.extend(
        std::iter::successors(Some(1e-15), |d| Some(d * 4.0))
            .take_while(|&d| d < 1.0)
            .map(|d| FRAC_PI_2 - d),
    );
    breaks.sort_by(f64::total_cmp);
    breaks.dedup();
    let f = |t: f64| ndf.eval(t) * t.sin() * t.cos();
    // A piece holding a negligible part of the unit mass may stop short of its relative tolerance.
    let piece = |a: f64, b: f64| match integrate(f, a, b, QUAD_TOL) {
        Ok(v) => v,
        Err(QuadError::NotConverged { estimate, error }) if error <= NEGLIGIBLE_PIECE_ERROR => {
            estimate
        }
        Err(e) => panic!("{ndf:?}: quadrature over [{a}, {b}] fails: {e:?}"),
    };
    let pieces: f64 = breaks.windows(2).map(|w| piece(w[0], w[1])).sum();
    2.0 * PI * pieces
}

/// Every check of one parameter point; `Err` names what failed.
fn check_point(
    family: Family,
    params: &[f64],
    thetas: &[f64],
    normalized: bool,
) -> Result<(), String> {
    let ndf = family
        .build(params)
        .map_err(|e| format!("{params:?} rejected: {e}"))?;
    let values: Vec<f64> = thetas.iter().map(|&t| ndf.eval(t)).collect();
    if let Some(i) = values.iter().position(|v| !(v.is_finite() && *v >= 0.0)) {
        return Err(format!("{ndf:?}: D({}) = {}", thetas[i], values[i]));
    }
    if monotone(&ndf)
        && let Some(i) =
            (1..values.len()).find(|&i| values[i] > values[i - 1] * (1.0 + MONOTONE_SLACK))
    {
        return Err(format!(
            "{ndf:?}: rises from θ = {} to {}",
            thetas[i - 1],
            thetas[i]
        ));
    }
    let n = if normalized { normalization(&ndf) } else { 1.0 };
    if (n - 1.0).abs() > NORMALIZATION_TOL {
        return Err(format!("{ndf:?}: normalization {n}"));
    }
    Ok(())
}

fn run(family: Family, stride: usize, normalized_every: usize) {
    let thetas = thetas();
    let points: Vec<(usize, Vec<f64>)> = grid(family)
        .into_iter()
        .enumerate()
        .step_by(stride)
        .collect();
    let failures: Vec<String> = points
        .par_iter()
        .filter_map(|(i, p)| check_point(family, p, &thetas, i % normalized_every == 0).err())
        .collect();
    assert!(
        failures.is_empty(),
        "{} of {} points fail, e.g.:\n{}",
        failures.len(),
        points.len(),
        failures[..failures.len().min(5)].join("\n")
    );
}

/// D(0) on both sides of a removable singularity a₂ = `at`, against the value at it, for a₁ over `a1s`.
fn continuous_across(family: Family, a1s: &[f64], at: f64) {
    for &a1 in a1s {
        let d0 = |a2: f64| family.build(&[a1, a2]).unwrap().eval(0.0);
        let centre = d0(at);
        for a2 in [at * (1.0 - SINGULAR_STEP), at * (1.0 + SINGULAR_STEP)] {
            let change = (d0(a2) - centre).abs() / centre;
            assert!(
                change <= SINGULAR_CHANGE,
                "{family:?} a1 = {a1}: D(0) jumps by {change} from a2 = {at} to {a2}"
            );
        }
    }
}

#[test]
fn abc_sgd_and_gtr_are_continuous_across_their_removable_singularities() {
    let a1s = |family: Family| axis(&family.params()[0], 2001);
    continuous_across(Family::Abc, &a1s(Family::Abc), 1.0);
    continuous_across(Family::Abc, &a1s(Family::Abc), 2.0);
    continuous_across(Family::Sgd, &a1s(Family::Sgd), 1.0);
    continuous_across(Family::Gtr, &a1s(Family::Gtr), 1.0);
}

macro_rules! family_tests {
    ($($slice:ident, $full:ident, $family:expr;)*) => {
        $(
            #[test]
            fn $slice() {
                run($family, SLICE_STRIDE, SLICE_NORMALIZED_EVERY);
            }

            #[test]
            #[ignore = "full domain, 10⁵ points: cargo test --release --test numerics stress -- --ignored"]
            fn $full() {
                run($family, 1, 1);
            }
        )*

        /// The list above names every registered family, in the registry's order.
        #[test]
        fn every_family_is_stressed() {
            assert_eq!([$($family),*], Family::ALL);
        }
    };
}

family_tests! {
    phong_slice, phong_full, Family::Phong;
    beckmann_slice, beckmann_full, Family::Beckmann;
    torrance_sparrow_slice, torrance_sparrow_full, Family::TorranceSparrow;
    trowbridge_reitz_slice, trowbridge_reitz_full, Family::TrowbridgeReitz;
    abc_slice, abc_full, Family::Abc;
    sgd_slice, sgd_full, Family::Sgd;
    gtr_slice, gtr_full, Family::Gtr;
    student_t_slice, student_t_full, Family::StudentT;
}
