//! Invariants of the seven NDFs over log grids of their whole accepted domains, bounds included:
//! every value finite and ≥ 0 on [0, π/2], and 2π ∫₀^{π/2} D sin θ cos θ dθ = 1 within NORMALIZATION_TOL by
//! adaptive quadrature; constructors accept exactly the domain their family states.

use crate::common::log_grid;
use ndfplot::model::math::quad::{QuadError, integrate};
use ndfplot::model::math::tolerance::{NORMALIZATION_TOL, QUAD_REL_TOL};
use ndfplot::model::ndf::{
    Abc, Beckmann, Family, Gtr, Ndf, Phong, Sgd, StudentT, TorranceSparrow, TrowbridgeReitz,
};
use rayon::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};

/// Geometric ratio between successive quadrature breakpoints: pieces span a factor 4 in θ (or in π/2 − θ),
/// so that a lobe of any width meets a piece of comparable width.
const BREAK_RATIO: f64 = 4.0;

/// Closest approach of the grazing breakpoints to π/2, 4⁻²⁴ ≈ 3.6e-15 rad: ~16 doubles from π/2, below the
/// narrowest grazing lobe accepted (~1e-4 rad) by eleven orders of magnitude.
const GRAZING_BREAK_MIN: f64 = 3.552713678800501e-15;

/// The stated bounds (min, max) of parameter `index` of `family`.
fn bounds(family: Family, index: usize) -> (f64, f64) {
    let param = &family.params()[index];
    (param.min.value, param.max.value)
}

/// θ values probing [0, π/2]: 0, decades from 1e-300, a uniform grid, grazing approaches and π/2 itself.
fn theta_grid() -> Vec<f64> {
    let mut thetas = vec![0.0, FRAC_PI_2];
    thetas.extend(log_grid(1e-300, 1.0, 301));
    thetas.extend((1..200).map(|i| FRAC_PI_2 * i as f64 / 200.0));
    thetas.extend(log_grid(1e-15, 1.0, 31).into_iter().map(|d| FRAC_PI_2 - d));
    thetas
}

/// 2π ∫₀^{π/2} D sin θ cos θ dθ, summed over pieces broken geometrically around the lobe scale
/// w = 1/√(π D(0)) (the width of a lobe of peak D(0) holding unit mass) and towards grazing.
fn projected_integral(ndf: &Ndf) -> f64 {
    let width = (1.0 / (PI * ndf.eval(0.0)).sqrt()).min(FRAC_PI_2);
    let mut breaks = vec![0.0, FRAC_PI_2];
    let mut t = width / BREAK_RATIO.powi(3);
    while t < FRAC_PI_2 {
        breaks.push(t);
        t *= BREAK_RATIO;
    }
    let mut d = 0.5;
    while d >= GRAZING_BREAK_MIN {
        breaks.push(FRAC_PI_2 - d);
        d /= BREAK_RATIO;
    }
    breaks.sort_by(f64::total_cmp);
    breaks.dedup();
    let integrand = |theta: f64| ndf.eval(theta) * theta.sin() * theta.cos();
    // The pieces next to π/2 can hold ~1e-30 of the mass, sampled by θ values only a few ulps apart: relative
    // convergence is out of reach there, so a piece is also accepted once its absolute error estimate is
    // within the budget of the whole integral (≈ 1/(2π)).
    let piece = |a: f64, b: f64| match integrate(integrand, a, b, QUAD_REL_TOL) {
        Ok(v) => v,
        Err(QuadError::NotConverged { estimate, error }) if error <= QUAD_REL_TOL / (2.0 * PI) => {
            estimate
        }
        Err(e) => panic!("{ndf:?} on [{a:e}, {b:e}]: {e}"),
    };
    2.0 * PI * breaks.windows(2).map(|w| piece(w[0], w[1])).sum::<f64>()
}

/// Checks finiteness, sign and normalization; returns |mass − 1|.
fn assert_invariants(ndf: &Ndf, thetas: &[f64]) -> f64 {
    for &theta in thetas {
        let d = ndf.eval(theta);
        assert!(d.is_finite() && d >= 0.0, "{ndf:?} at θ = {theta:e}: {d}");
    }
    let mass = projected_integral(ndf);
    assert!(
        (mass - 1.0).abs() <= NORMALIZATION_TOL,
        "{ndf:?}: projected integral {mass}"
    );
    (mass - 1.0).abs()
}

/// Checks every NDF of `ndfs` (in parallel) and prints the worst normalization error (visible with `--nocapture`).
fn assert_all(family: &str, ndfs: impl IntoIterator<Item = Ndf>) {
    let thetas = theta_grid();
    let ndfs: Vec<Ndf> = ndfs.into_iter().collect();
    let worst = ndfs
        .par_iter()
        .map(|ndf| assert_invariants(ndf, &thetas))
        .reduce(|| 0.0, f64::max);
    println!("{family}: max |2π∫D sinθ cosθ dθ − 1| = {worst:.2e}");
}

#[test]
fn phong_over_its_domain() {
    let (min, max) = bounds(Family::Phong, 0);
    let mut grid = vec![min, 1.0, 2.0, max];
    grid.extend(log_grid(1e-6, max, 63));
    assert_all(
        "phong",
        grid.into_iter().map(|a| Ndf::Phong(Phong::new(a).unwrap())),
    );
}

#[test]
fn beckmann_over_its_domain() {
    let (min, max) = bounds(Family::Beckmann, 0);
    let mut grid = log_grid(min, max, 78);
    grid.extend([0.001, 0.01, std::f64::consts::FRAC_1_SQRT_2, 1.0, 7.0]);
    assert_all(
        "beckmann",
        grid.into_iter()
            .map(|a| Ndf::Beckmann(Beckmann::new(a).unwrap())),
    );
}

#[test]
fn torrance_sparrow_over_its_domain() {
    let (min, max) = bounds(Family::TorranceSparrow, 0);
    let mut grid = log_grid(min, max, 101);
    grid.extend([1e-3, 0.2027, 26.6, 30.0, 1e3]);
    assert_all(
        "torrance_sparrow",
        grid.into_iter()
            .map(|a| Ndf::TorranceSparrow(TorranceSparrow::new(a).unwrap())),
    );
}

#[test]
fn trowbridge_reitz_over_its_domain() {
    let (min, max) = bounds(Family::TrowbridgeReitz, 0);
    let mut grid = log_grid(min, max, 78);
    grid.extend([0.01, 1.0, 7.0]);
    assert_all(
        "trowbridge_reitz",
        grid.into_iter()
            .map(|a| Ndf::TrowbridgeReitz(TrowbridgeReitz::new(a).unwrap())),
    );
}

#[test]
fn abc_over_its_domain() {
    // Both lower bounds are an excluded 0: the grids start at 1e-300.
    let mut a1_grid = log_grid(1e-300, bounds(Family::Abc, 0).1, 41);
    a1_grid.extend([f64::MIN_POSITIVE, 1e-6, 1.718281828459045, 1e6]);
    let mut a2_grid = log_grid(1e-300, bounds(Family::Abc, 1).1, 21);
    a2_grid.extend([
        1e-3,
        0.5,
        1.0 - 1e-9,
        1.0,
        1.0 + 1e-9,
        1.75,
        2.0 - 1e-9,
        2.0,
        2.0 + 1e-9,
        1e3,
        1e4,
    ]);
    let pairs = a1_grid
        .iter()
        .flat_map(|&a1| a2_grid.iter().map(move |&a2| (a1, a2)));
    assert_all(
        "abc",
        pairs.map(|(a1, a2)| Ndf::Abc(Abc::new(a1, a2).unwrap())),
    );
}

#[test]
fn sgd_over_its_domain() {
    let (a1_min, a1_max) = bounds(Family::Sgd, 0);
    let a1_grid = log_grid(a1_min, a1_max, 25);
    let (a2_min, a2_max) = bounds(Family::Sgd, 1);
    let mut a2_grid: Vec<f64> = (0..=40)
        .map(|i| a2_min + (a2_max - a2_min) * i as f64 / 40.0)
        .collect();
    a2_grid.extend([1.0 - 1e-9, 1.0 + 1e-9, 2.0 - 1e-9, 2.0 + 1e-9]);
    let pairs = a1_grid
        .iter()
        .flat_map(|&a1| a2_grid.iter().map(move |&a2| (a1, a2)));
    assert_all(
        "sgd",
        pairs.map(|(a1, a2)| Ndf::Sgd(Sgd::new(a1, a2).unwrap())),
    );
}

#[test]
fn gtr_over_its_domain() {
    let (alpha_min, alpha_max) = bounds(Family::Gtr, 0);
    let mut alpha_grid = log_grid(alpha_min, alpha_max, 52);
    alpha_grid.extend([0.3, 1.0 - 1e-9, 1.0, 1.0 + 1e-9]);
    // γ's lower bound is an excluded 0: the grid starts at the smallest positive double.
    let mut gamma_grid = log_grid(1e-6, bounds(Family::Gtr, 1).1, 17);
    gamma_grid.extend([f64::from_bits(1), 1.0 - 1e-9, 1.0, 1.0 + 1e-9, 1.5, 2.0]);
    let pairs = alpha_grid
        .iter()
        .flat_map(|&a| gamma_grid.iter().map(move |&g| (a, g)));
    assert_all("gtr", pairs.map(|(a, g)| Ndf::Gtr(Gtr::new(a, g).unwrap())));
}

#[test]
fn student_t_over_its_domain() {
    // α and γ over their domains in log steps plus the notable values: 18 × 18 lobes, each integrated to 1e-12
    // (the lobes with γ < 2, unbounded at grazing, cost the most).
    let (alpha_min, alpha_max) = bounds(Family::StudentT, 0);
    let mut alpha_grid = log_grid(alpha_min, alpha_max, 16);
    alpha_grid.extend([0.3, 1.0]);
    // γ's lower bound is an excluded 1.5: the grid starts at the next double, and runs to the largest.
    let (gamma_min, gamma_max) = bounds(Family::StudentT, 1);
    let mut gamma_grid = log_grid(gamma_min.next_up(), gamma_max, 10);
    gamma_grid.extend([1.5 + 1e-12, 1.6, 1.9, 2.0, 2.1, 2.5, 3.0, 1e8]);
    let pairs = alpha_grid
        .iter()
        .flat_map(|&a| gamma_grid.iter().map(move |&g| (a, g)));
    assert_all(
        "student_t",
        pairs.map(|(a, g)| Ndf::StudentT(StudentT::new(a, g).unwrap())),
    );
}

/// The next double after `v` towards +∞ (`outward` = 1) or −∞ (−1); `v` finite.
fn step(v: f64, outward: f64) -> f64 {
    if v == 0.0 {
        return outward * f64::from_bits(1);
    }
    let away_from_zero = (v > 0.0) == (outward > 0.0);
    f64::from_bits(if away_from_zero {
        v.to_bits() + 1
    } else {
        v.to_bits() - 1
    })
}

/// Every family accepts each closed bound it includes and the next double inside one it
/// excludes, and rejects the next double beyond (or the excluded bound), NaN and ±∞ with the
/// stated expectation; the other parameters sit at their example values.
#[test]
fn constructors_accept_exactly_the_stated_domains() {
    for family in Family::ALL {
        for (i, param) in family.params().iter().enumerate() {
            let with = |v: f64| {
                let mut params = family.example().to_vec();
                params[i] = v;
                family.build(&params)
            };
            for (bound, outward) in [(param.min, -1.0), (param.max, 1.0)] {
                if bound.is_open() {
                    assert!(with(bound.value).is_ok(), "{family:?} {}", param.name);
                    continue;
                }
                let (inside, outside) = if bound.inclusive {
                    (bound.value, step(bound.value, outward))
                } else {
                    (step(bound.value, -outward), bound.value)
                };
                assert!(
                    with(inside).is_ok(),
                    "{family:?} {} = {inside:e}",
                    param.name
                );
                let err = with(outside).unwrap_err();
                assert_eq!(err.param, param.name);
                assert_eq!(err.expected, param.expected());
            }
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                assert_eq!(with(bad).unwrap_err().param, param.name);
            }
        }
    }
}
