//! Invariants of the six NDFs over log grids of their whole accepted domains, bounds included:
//! every value finite and ≥ 0 on [0, π/2], and 2π ∫₀^{π/2} D sin θ cos θ dθ = 1 within NORMALIZATION_TOL by
//! adaptive quadrature; constructors accept exactly their documented domain.

use crate::common::log_grid;
use ndfplot::math::quad::{QuadError, integrate};
use ndfplot::math::tolerance::{NORMALIZATION_TOL, QUAD_REL_TOL};
use ndfplot::ndf::{Abc, Beckmann, Family, Ndf, Phong, Sgd, TorranceSparrow, TrowbridgeReitz};
use std::f64::consts::{FRAC_PI_2, PI};

/// Geometric ratio between successive quadrature breakpoints: pieces span a factor 4 in θ (or in π/2 − θ),
/// so that a lobe of any width meets a piece of comparable width.
const BREAK_RATIO: f64 = 4.0;

/// Closest approach of the grazing breakpoints to π/2, 4⁻²⁴ ≈ 3.6e-15 rad: ~16 doubles from π/2, below the
/// narrowest grazing lobe accepted (~1e-4 rad) by eleven orders of magnitude.
const GRAZING_BREAK_MIN: f64 = 3.552713678800501e-15;

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

/// Checks every NDF of `ndfs` and prints the worst normalization error (visible with `--nocapture`).
fn assert_all(family: &str, ndfs: impl IntoIterator<Item = Ndf>) {
    let thetas = theta_grid();
    let worst = ndfs
        .into_iter()
        .map(|ndf| assert_invariants(&ndf, &thetas))
        .fold(0.0, f64::max);
    println!("{family}: max |2π∫D sinθ cosθ dθ − 1| = {worst:.2e}");
}

#[test]
fn phong_over_its_domain() {
    let mut grid = vec![0.0, 1.0, 2.0, f64::MAX];
    grid.extend(log_grid(1e-6, 1e308, 63));
    assert_all(
        "phong",
        grid.into_iter().map(|a| Ndf::Phong(Phong::new(a).unwrap())),
    );
}

#[test]
fn beckmann_over_its_domain() {
    let mut grid = log_grid(1e-150, 1e4, 78);
    grid.extend([0.001, 0.01, std::f64::consts::FRAC_1_SQRT_2, 1.0, 7.0]);
    assert_all(
        "beckmann",
        grid.into_iter()
            .map(|a| Ndf::Beckmann(Beckmann::new(a).unwrap())),
    );
}

#[test]
fn torrance_sparrow_over_its_domain() {
    let mut grid = log_grid(1e-150, 1e150, 101);
    grid.extend([1e-3, 0.2027, 26.6, 30.0, 1e3]);
    assert_all(
        "torrance_sparrow",
        grid.into_iter()
            .map(|a| Ndf::TorranceSparrow(TorranceSparrow::new(a).unwrap())),
    );
}

#[test]
fn trowbridge_reitz_over_its_domain() {
    let mut grid = log_grid(1e-150, 1e4, 78);
    grid.extend([0.01, 1.0, 7.0]);
    assert_all(
        "trowbridge_reitz",
        grid.into_iter()
            .map(|a| Ndf::TrowbridgeReitz(TrowbridgeReitz::new(a).unwrap())),
    );
}

#[test]
fn abc_over_its_domain() {
    let mut a1_grid = log_grid(1e-300, 1e100, 41);
    a1_grid.extend([f64::MIN_POSITIVE, 1e-6, 1.718281828459045, 1e6]);
    let mut a2_grid = log_grid(1e-300, 1e100, 21);
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
    let a1_grid = log_grid(1e-6, 1e6, 25);
    let mut a2_grid: Vec<f64> = (0..=40).map(|i| -10.0 + 0.5 * i as f64).collect();
    a2_grid.extend([1.0 - 1e-9, 1.0 + 1e-9, 2.0 - 1e-9, 2.0 + 1e-9]);
    let pairs = a1_grid
        .iter()
        .flat_map(|&a1| a2_grid.iter().map(move |&a2| (a1, a2)));
    assert_all(
        "sgd",
        pairs.map(|(a1, a2)| Ndf::Sgd(Sgd::new(a1, a2).unwrap())),
    );
}

/// Parameter lists a constructor must accept.
type Accepted = Vec<Vec<f64>>;
/// Parameter lists a constructor must reject.
type Rejected = Vec<Vec<f64>>;

#[test]
fn constructors_accept_their_bounds_and_reject_beyond() {
    let next_up = |v: f64| f64::from_bits(v.to_bits() + 1);
    let next_down = |v: f64| f64::from_bits(v.to_bits() - 1);
    let cases: [(Family, Accepted, Rejected); 6] = [
        (
            Family::Phong,
            vec![vec![0.0], vec![f64::MAX]],
            vec![vec![-f64::MIN_POSITIVE], vec![f64::INFINITY]],
        ),
        (
            Family::Beckmann,
            vec![vec![1e-150], vec![1e4]],
            vec![
                vec![next_down(1e-150)],
                vec![next_up(1e4)],
                vec![0.0],
                vec![-0.3],
            ],
        ),
        (
            Family::TorranceSparrow,
            vec![vec![1e-150], vec![1e150]],
            vec![vec![next_down(1e-150)], vec![next_up(1e150)], vec![0.0]],
        ),
        (
            Family::TrowbridgeReitz,
            vec![vec![1e-150], vec![1e4]],
            vec![vec![next_down(1e-150)], vec![next_up(1e4)], vec![0.0]],
        ),
        (
            Family::Abc,
            vec![vec![5e-324, 5e-324], vec![1e100, 1e100]],
            vec![
                vec![0.0, 1.0],
                vec![1.0, 0.0],
                vec![next_up(1e100), 1.0],
                vec![1.0, next_up(1e100)],
            ],
        ),
        (
            Family::Sgd,
            vec![vec![1e-6, -10.0], vec![1e6, 10.0], vec![0.5, 0.0]],
            vec![
                vec![next_down(1e-6), 0.0],
                vec![next_up(1e6), 0.0],
                vec![1.0, -10.5],
                vec![1.0, 10.5],
            ],
        ),
    ];
    for (family, accepted, rejected) in cases {
        for params in accepted {
            assert!(
                family.build(&params).is_ok(),
                "{family:?} {params:?} should be accepted"
            );
        }
        let mut rejected = rejected;
        for i in 0..family.param_names().len() {
            for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
                let mut params = vec![1.0; family.param_names().len()];
                params[i] = bad;
                rejected.push(params);
            }
        }
        for params in rejected {
            let err = family
                .build(&params)
                .expect_err(&format!("{family:?} {params:?} should be rejected"));
            assert!(family.param_names().contains(&err.param), "{err}");
            assert!(
                family.domain().contains(err.param),
                "{} does not name {}",
                family.domain(),
                err.param
            );
        }
    }
}
