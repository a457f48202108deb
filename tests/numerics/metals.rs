//! Measured metals (`{"fresnel": …, "metal": …, "wavelength_nm": …}`) against the embedded table
//! `data/published/pbrt-v4/metal_ior.csv`, read here row by row: a tabulated wavelength gives the
//! table's (η, κ) exactly, a wavelength between two gives the linear interpolation computed here from
//! the two rows, and the curve built from the JSON reflects at normal incidence what
//! F(0) = ((η − 1)² + κ²)/((η + 1)² + κ²) gives with the table's numbers.

use crate::common::root;
use ndfplot::model::curve::Curve;
use ndfplot::model::metal::Metal;
use ndfplot::spec::curve::{CurveSpec, parse};
use ndfplot::spec::json;

/// Reflectance through the exact complex-index form against the closed form at normal incidence:
/// a few ulps of rounding between two routes to the same number.
const NORMAL_INCIDENCE_TOL: f64 = 1e-14;

/// The table's rows of `metal` and `quantity` (`eta` or `k`): (wavelength in nm, value).
fn rows(metal: &str, quantity: &str) -> Vec<(f64, f64)> {
    let text =
        std::fs::read_to_string(root().join("data/published/pbrt-v4/metal_ior.csv")).unwrap();
    text.lines()
        .skip(1)
        .filter_map(|line| {
            let fields: Vec<&str> = line.split(',').collect();
            (fields[0] == metal && fields[1] == quantity)
                .then(|| (fields[2].parse().unwrap(), fields[3].parse().unwrap()))
        })
        .collect()
}

/// The curve the JSON `text` describes, built.
fn curve(text: &str) -> Curve {
    match parse(&json::parse(text).unwrap(), "") {
        Ok(CurveSpec::Ready(curve)) => curve,
        other => panic!("{text}: {other:?}"),
    }
}

#[test]
fn a_tabulated_wavelength_gives_the_tables_values_exactly() {
    for metal in Metal::ALL {
        let (eta, kappa) = (rows(metal.symbol(), "eta"), rows(metal.symbol(), "k"));
        assert_eq!(eta.len(), metal.samples());
        for (&(wavelength, eta), &(_, kappa)) in eta.iter().zip(&kappa) {
            assert_eq!(metal.index_at(wavelength), Some((eta, kappa)));
        }
    }
    // Gold's row at 551.040771 nm, as the file prints it.
    assert_eq!(Metal::Au.index_at(551.040771), Some((0.3455, 2.730625)));
}

#[test]
fn between_two_samples_the_index_is_their_linear_interpolation() {
    for metal in Metal::ALL {
        let (eta, kappa) = (rows(metal.symbol(), "eta"), rows(metal.symbol(), "k"));
        for i in 0..eta.len() - 1 {
            let (l0, l1) = (eta[i].0, eta[i + 1].0);
            for t in [0.5, 0.25] {
                let wavelength = l0 + t * (l1 - l0);
                let expected = |v: &[(f64, f64)]| {
                    v[i].1 + (v[i + 1].1 - v[i].1) * (wavelength - l0) / (l1 - l0)
                };
                let (e, k) = metal.index_at(wavelength).unwrap();
                let close = |a: f64, b: f64| (a - b).abs() <= 4.0 * f64::EPSILON * b.abs();
                assert!(
                    close(e, expected(&eta)) && close(k, expected(&kappa)),
                    "{} at {wavelength} nm: ({e}, {k}) against ({}, {})",
                    metal.symbol(),
                    expected(&eta),
                    expected(&kappa)
                );
            }
        }
    }
}

#[test]
fn gold_reflects_at_normal_incidence_what_its_tabulated_index_gives() {
    // Gold's rows at 551.040771 nm: η = 0.3455, κ = 2.730625.
    let (eta, kappa): (f64, f64) = (0.3455, 2.730625);
    let f0 = ((eta - 1.0).powi(2) + kappa * kappa) / ((eta + 1.0).powi(2) + kappa * kappa);
    for text in [
        r#"{"fresnel":"exact","metal":"Au","wavelength_nm":551.040771}"#,
        r#"{"fresnel":"schlick","metal":"gold","wavelength_nm":551.040771}"#,
    ] {
        let value = curve(text).eval(0.0);
        assert!(
            (value - f0).abs() <= NORMAL_INCIDENCE_TOL,
            "{text}: F(0) = {value}, closed form {f0}"
        );
    }
    // At 550 nm, between the rows at 539.06 and 551.04 nm: the same closed form of the interpolated
    // index, here ≈ 0.848.
    let (eta, kappa) = Metal::Au.index_at(550.0).unwrap();
    let f0 = ((eta - 1.0).powi(2) + kappa * kappa) / ((eta + 1.0).powi(2) + kappa * kappa);
    let value = curve(r#"{"fresnel":"exact","metal":"AU","wavelength_nm":550}"#).eval(0.0);
    assert!((value - f0).abs() <= NORMAL_INCIDENCE_TOL && (0.84..0.86).contains(&f0));
}
