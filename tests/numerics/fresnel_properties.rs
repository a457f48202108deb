//! Fresnel invariants over whole parameter domains: F ∈ [0, 1], F(0) in closed form, η̃ = 1 gives 0,
//! total internal reflection gives 1, the Gulbrandsen round trip, the Lazanyi `a` bounds and the
//! domain checks of the constructors.

use std::f64::consts::FRAC_PI_2;

use crate::common::log_grid;
use ndfplot::model::fresnel::{Coefficients, Fresnel, Ior, SchlickF0, approx, gulbrandsen};

/// F(0) against ((η − 1)² + κ²)/((η + 1)² + κ²), relative: the exact form at c = 1 takes a complex
/// square root and a few products, each within an ulp or two.
const NORMAL_INCIDENCE_REL_TOL: f64 = 1e-14;
/// Gulbrandsen round trip, absolute on r and g over r ∈ [1e-3, 0.99]: g = (n_max − η)/(n_max − n_min)
/// divides η's rounding by n_max − n_min ≥ 2√r ≈ 0.06, and κ² cancels as g → 0.
const ROUND_TRIP_TOL: f64 = 1e-10;

/// θ over [0, π/2] with both ends exact, dense near each end.
fn theta_grid() -> Vec<f64> {
    let mut thetas: Vec<f64> = (0..=64).map(|i| FRAC_PI_2 * i as f64 / 64.0).collect();
    thetas.extend([
        1e-300,
        1e-12,
        1e-8,
        1e-4,
        FRAC_PI_2 - 1e-4,
        FRAC_PI_2 - 1e-8,
        FRAC_PI_2 - 1e-12,
    ]);
    thetas.push(FRAC_PI_2);
    thetas
}

/// η ∈ [1e-3, 1e3] (log), κ ∈ {0} ∪ [1e-3, 1e3] (log), plus η = 1 and the notebook's values.
fn indices() -> Vec<(f64, f64)> {
    let etas: Vec<f64> = log_grid(1e-3, 1e3, 61)
        .into_iter()
        .chain([1.0, 1.01, 1.1, 1.5, 2.0])
        .collect();
    let kappas: Vec<f64> = std::iter::once(0.0)
        .chain(log_grid(1e-3, 1e3, 31))
        .collect();
    etas.iter()
        .flat_map(|&eta| kappas.iter().map(move |&kappa| (eta, kappa)))
        .collect()
}

#[test]
fn exact_stays_within_zero_and_one() {
    for (eta, kappa) in indices() {
        let curve = Fresnel::Exact(Ior::eta_kappa(eta, kappa).unwrap());
        for theta in theta_grid() {
            let f = curve.eval(theta);
            assert!(
                (0.0..=1.0).contains(&f),
                "η̃ = {eta} + {kappa}i, θ = {theta}: F = {f}"
            );
        }
    }
}

#[test]
fn exact_at_normal_incidence_is_the_closed_form() {
    for (eta, kappa) in indices() {
        let f0 = Fresnel::Exact(Ior::eta_kappa(eta, kappa).unwrap()).eval(0.0);
        let kappa2 = kappa * kappa;
        let expected = ((eta - 1.0).powi(2) + kappa2) / ((eta + 1.0).powi(2) + kappa2);
        let err = if expected > 0.0 {
            (f0 - expected).abs() / expected
        } else {
            f0
        };
        assert!(
            err <= NORMAL_INCIDENCE_REL_TOL,
            "η̃ = {eta} + {kappa}i: {f0} vs {expected}"
        );
    }
}

#[test]
fn index_one_reflects_nothing() {
    let curve = Fresnel::Exact(Ior::eta_kappa(1.0, 0.0).unwrap());
    for theta in theta_grid() {
        assert_eq!(curve.eval(theta), 0.0, "θ = {theta}");
    }
    // r = 0 is η̃ = 1 for every edge tint.
    for g in [0.0, 0.3, 1.0] {
        assert_eq!(
            Fresnel::Exact(Ior::gulbrandsen(0.0, g, false).unwrap()).eval(1.0),
            0.0
        );
    }
}

#[test]
fn total_internal_reflection_past_the_critical_angle() {
    for eta in [0.1, 0.5, 0.9, 0.999] {
        let curve = Fresnel::Exact(Ior::eta_kappa(eta, 0.0).unwrap());
        let critical = f64::asin(eta);
        for theta in theta_grid().into_iter().filter(|&t| t > critical) {
            assert_eq!(curve.eval(theta), 1.0, "η = {eta}, θ = {theta}");
        }
        assert!(curve.eval(0.0) < 1.0);
    }
}

#[test]
fn extreme_indices_stay_finite() {
    for (eta, kappa) in [
        (1e-150, 0.0),
        (1e-150, 1e-150),
        (1e150, 0.0),
        (1e150, 1e150),
        (1e-150, 1e150),
    ] {
        let curve = Fresnel::Exact(Ior::eta_kappa(eta, kappa).unwrap());
        for theta in theta_grid() {
            let f = curve.eval(theta);
            assert!(
                (0.0..=1.0).contains(&f),
                "η̃ = {eta} + {kappa}i, θ = {theta}: F = {f}"
            );
        }
    }
}

#[test]
fn gulbrandsen_round_trip() {
    for r in log_grid(1e-3, 0.99, 40) {
        for g in (0..=20).map(|j| j as f64 / 20.0) {
            let (eta, kappa) = gulbrandsen::to_eta_kappa(r, g);
            let (r_back, g_back) = gulbrandsen::from_eta_kappa(eta, kappa);
            assert!(
                (r_back - r).abs() <= ROUND_TRIP_TOL && (g_back - g).abs() <= ROUND_TRIP_TOL,
                "(r, g) = ({r}, {g}) → ({eta}, {kappa}) → ({r_back}, {g_back})"
            );
            // The reflectivity is the normal-incidence reflectance of the index.
            let f0 = Fresnel::Exact(Ior::gulbrandsen(r, g, false).unwrap()).eval(0.0);
            assert!(
                (f0 - r).abs() <= ROUND_TRIP_TOL,
                "(r, g) = ({r}, {g}): F(0) = {f0}"
            );
        }
    }
}

/// Reflectivities far below the round trip's grid, where n − 1 ≈ −2r/(1 + r) would lose its digits if
/// formed after the conversion: the exact Fresnel of Gulbrandsen's index still reflects r at normal
/// incidence to a few ulps of r (relative), for every edge tint.
#[test]
fn gulbrandsen_reflectivity_holds_to_ulps_down_to_tiny_r() {
    for r in [1e-12, 1e-9, 1e-6, 1e-4] {
        for g in [0.0, 0.3, 0.7, 1.0] {
            let f0 = Fresnel::Exact(Ior::gulbrandsen(r, g, false).unwrap()).eval(0.0);
            assert!(
                (f0 / r - 1.0).abs() <= 8.0 * f64::EPSILON,
                "(r, g) = ({r}, {g}): F(0) = {f0}"
            );
        }
    }
}

#[test]
fn remapped_edge_tint_is_one_minus_the_cube() {
    for g in (0..=20).map(|j| j as f64 / 20.0) {
        let expected = 1.0 - (1.0 - g).powi(3);
        assert!(
            (gulbrandsen::remap_edge_tint(g) - expected).abs() < 4.0 * f64::EPSILON,
            "g = {g}"
        );
        let remapped = Ior::gulbrandsen(0.5, g, true).unwrap().index();
        assert_eq!(
            remapped,
            gulbrandsen::index(0.5, gulbrandsen::remap_edge_tint(g))
        );
    }
}

#[test]
fn schlick_and_lazanyi_stay_within_zero_and_one_over_their_domain() {
    for f0 in (0..=20).map(|j| j as f64 / 20.0) {
        let (a_min, a_max) = approx::lazanyi_a_range(f0);
        for a in [a_min, 0.5 * a_min, 0.0, 0.5 * a_max, a_max] {
            let curve = Fresnel::lazanyi(f0, a).unwrap();
            for theta in theta_grid() {
                let f = curve.eval(theta);
                assert!(
                    (0.0..=1.0).contains(&f),
                    "f0 = {f0}, a = {a}, θ = {theta}: F = {f}"
                );
            }
        }
        // Just outside the range F leaves [0, 1] somewhere, so the constructor refuses it.
        assert!(Fresnel::lazanyi(f0, a_max * (1.0 + 1e-9)).is_err());
        assert!(Fresnel::lazanyi(f0, a_min - 1e-9).is_err());
        let schlick = Fresnel::schlick(f0).unwrap();
        assert_eq!(schlick.eval(0.0), f0);
        // At θ = fl(π/2), 1 − cos θ = 1 − 6e-17: F is 1 to a few ulps.
        assert!((schlick.eval(FRAC_PI_2) - 1.0).abs() <= 4.0 * f64::EPSILON);
    }
    // a = 0 is Schlick; small θ keeps the θ² behaviour that 1 − cos θ would round away.
    let (lazanyi, schlick) = (
        Fresnel::lazanyi(0.04, 0.0).unwrap(),
        Fresnel::schlick(0.04).unwrap(),
    );
    assert_eq!(lazanyi.eval(0.7), schlick.eval(0.7));
    let small = Fresnel::schlick(0.0).unwrap().eval(1e-3);
    let expected = (1e-3_f64 * 1e-3 / 2.0).powi(5);
    assert!(
        (small - expected).abs() <= 1e-6 * expected,
        "{small} vs {expected}"
    );
}

#[test]
fn schlick_from_an_index_uses_its_normal_reflectance() {
    let gold = Ior::eta_kappa(0.29, 2.86).unwrap();
    let f0 = Fresnel::Exact(gold).eval(0.0);
    assert_eq!(
        Fresnel::Schlick(SchlickF0::Ior(gold)).eval(0.9),
        Fresnel::schlick(f0).unwrap().eval(0.9)
    );
}

#[test]
fn constructors_check_both_sides_of_each_bound() {
    assert!(Ior::eta_kappa(1e-150, 0.0).is_ok() && Ior::eta_kappa(1e150, 1e150).is_ok());
    for (eta, kappa) in [
        (0.0, 0.0),
        (9e-151, 0.0),
        (1.1e150, 0.0),
        (1.5, -1e-300),
        (1.5, 1.1e150),
        (f64::NAN, 0.0),
    ] {
        assert!(Ior::eta_kappa(eta, kappa).is_err(), "η̃ = {eta} + {kappa}i");
    }
    assert!(
        Ior::gulbrandsen(0.0, 0.0, false).is_ok() && Ior::gulbrandsen(0.999, 1.0, true).is_ok()
    );
    for (r, g) in [
        (1.0, 0.5),
        (-1e-300, 0.5),
        (0.5, -1e-300),
        (0.5, 1.0 + f64::EPSILON),
        (0.5, f64::INFINITY),
    ] {
        assert!(
            Ior::gulbrandsen(r, g, false).is_err(),
            "(r, g) = ({r}, {g})"
        );
    }
    assert!(Fresnel::schlick(0.0).is_ok() && Fresnel::schlick(1.0).is_ok());
    assert!(Fresnel::schlick(-1e-300).is_err() && Fresnel::schlick(1.0 + f64::EPSILON).is_err());
    assert!(Fresnel::basis(3).is_ok() && Fresnel::basis(4).is_err());
    let error = Fresnel::lazanyi(0.0, 4.1).unwrap_err();
    assert_eq!((error.param, error.value), ("a", 4.1));
}

#[test]
fn names_are_canonical() {
    let gold = Ior::eta_kappa(0.29, 2.86).unwrap();
    let curves = [
        (Fresnel::Exact(gold), "exact"),
        (Fresnel::schlick(0.5).unwrap(), "schlick"),
        (Fresnel::lazanyi(0.5, 1.0).unwrap(), "lazanyi"),
        (Fresnel::LazanyiTerm, "lazanyi_term"),
        // Built directly: `Fresnel::belcour` would compute the basis, which fresnel_reference tests.
        (
            Fresnel::Belcour(
                gold,
                Coefficients {
                    c0: 0.9,
                    c1: 0.1,
                    c2: 0.0,
                    c3: 0.0,
                },
            ),
            "belcour",
        ),
        (Fresnel::basis(2).unwrap(), "basis"),
    ];
    for (curve, name) in curves {
        assert_eq!(curve.name(), name);
    }
}
