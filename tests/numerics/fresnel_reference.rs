//! Fresnel against the reference files of tests/data/reference (see its README.md): exact, Gulbrandsen
//! and Schlick curves from mpmath at 50 digits, and the Belcour–Bati–Barla basis, coefficients and
//! spectrum from numpy float64 following the notebook's procedure; against
//! tests/data/fresnel_near_one.csv: exact, Schlick and normalized curves near η̃ = 1 (mpmath); and
//! against tests/data/fresnel_normalized.csv: the normalized curve from θ = 1e-12 to π/2 (mpmath).

use std::collections::BTreeMap;
use std::time::Instant;

use crate::common::{csv_records, number};
use ndfplot::model::fresnel::{Fresnel, Incidence, Index, Ior, SchlickF0, basis, exact};
use ndfplot::model::math::tolerance::{REL_TOL_FRESNEL, floored_relative_difference};
/// The basis b₀…b₃, the coefficients c₀…c₃, `l2` and the normalized spectrum, absolute: a different
/// SVD routine moves them by ~2e-14 (reference/README.md), given training rows rounded like numpy's
/// (the row with 1 − F₀ = 2e-5 amplifies each ulp of F 5e4-fold). Measured: b₂ 9.0e-15, b₃ 1.1e-14.
const BELCOUR_ABS_TOL: f64 = 1e-12;
/// Singular values, absolute in units of s₀: values below ~1e-13 s₀ are noise (reference/README.md).
const SINGULAR_VALUE_TOL: f64 = 1e-12;
/// Node reproduction of the interpolated tabulated curves (docs/contracts.md `ndfplot eval`).
const NODE_TOL: f64 = 1e-13;

/// Maps a reference `curve_json` onto the Fresnel model.
fn curve(json: &str) -> Fresnel {
    let value: serde_json::Value = serde_json::from_str(json).expect("curve JSON");
    let param = |key: &str| value.get(key).and_then(serde_json::Value::as_f64);
    let ior = match (param("eta"), param("kappa"), param("r"), param("g")) {
        (Some(eta), Some(kappa), None, None) => Ior::eta_kappa(eta, kappa),
        (None, None, Some(r), Some(g)) => Ior::gulbrandsen(r, g, false),
        _ => panic!("unexpected parameters in {json}"),
    }
    .expect("a valid index");
    match value["fresnel"].as_str() {
        Some("exact") => Fresnel::Exact(ior),
        Some("schlick") => Fresnel::Schlick(SchlickF0::Ior(ior)),
        Some("normalized") => Fresnel::Normalized(ior),
        other => panic!("unexpected model {other:?} in {json}"),
    }
}

/// Checks every row of the curve reference file at `path` (`case_id,curve_json,theta,value`) at
/// [`REL_TOL_FRESNEL`], and returns the worst relative error with its case.
fn check_curves(path: &str, rows_expected: usize) -> (f64, String) {
    let rows = csv_records(path);
    assert_eq!(rows.len(), rows_expected);
    let mut worst = (0.0, String::new());
    for row in &rows {
        let (theta, expected) = (number(row, 2), number(row, 3));
        let value = curve(&row[1]).eval(theta);
        let err = floored_relative_difference(value, expected);
        assert!(
            err <= REL_TOL_FRESNEL,
            "{}: θ = {theta}: {value} vs {expected} (error {err:e})",
            &row[0]
        );
        if err >= worst.0 {
            worst = (err, row[0].to_string());
        }
    }
    worst
}

#[test]
fn visible_curves_match_mpmath() {
    let worst = check_curves("tests/data/reference/fresnel_visible.csv", 144);
    println!(
        "fresnel_visible: max relative error {:e} ({})",
        worst.0, worst.1
    );
}

#[test]
fn curves_near_index_one_match_mpmath() {
    let worst = check_curves("tests/data/fresnel_near_one.csv", 1224);
    println!(
        "fresnel_near_one: max relative error {:e} ({})",
        worst.0, worst.1
    );
}

/// The normalized curve of a `fresnel_normalized.csv` row at θ: through the curve model, or for
/// the basis training set's η < 0 row, which the model refuses, `exact::normalized_reflectance`.
fn normalized_value(json: &str, theta: f64) -> f64 {
    let value: serde_json::Value = serde_json::from_str(json).expect("curve JSON");
    let param = |key: &str| value.get(key).and_then(serde_json::Value::as_f64);
    match (param("eta"), param("kappa")) {
        (Some(eta), Some(kappa)) if eta < 0.0 => {
            exact::normalized_reflectance(Incidence::from_theta(theta), Index::new(eta, kappa))
        }
        _ => curve(json).eval(theta),
    }
}

#[test]
fn normalized_curve_matches_mpmath_down_to_tiny_angles() {
    let rows = csv_records("tests/data/fresnel_normalized.csv");
    assert_eq!(rows.len(), 1357);
    // Worst relative error and its case, per regime (the case id's second field).
    let mut worst: BTreeMap<String, (f64, String)> = BTreeMap::new();
    for row in &rows {
        let (theta, expected) = (number(row, 2), number(row, 3));
        let value = normalized_value(&row[1], theta);
        let err = floored_relative_difference(value, expected);
        assert!(
            err <= REL_TOL_FRESNEL,
            "{}: θ = {theta}: {value} vs {expected} (error {err:e})",
            &row[0]
        );
        let regime = row[0]
            .strip_prefix("nz-")
            .and_then(|id| id.rsplitn(3, '-').nth(2))
            .expect("case id nz-<regime>-<index>-<theta>");
        let entry = worst.entry(regime.to_string()).or_default();
        if err >= entry.0 {
            *entry = (err, row[0].to_string());
        }
    }
    for (regime, (err, case)) in &worst {
        println!("fresnel_normalized {regime}: max relative error {err:e} ({case})");
    }
}

#[test]
fn basis_matches_numpy_at_every_node() {
    let start = Instant::now();
    let basis = basis::basis();
    println!(
        "basis (two partial SVDs of 1000 × 1000): {:?}",
        start.elapsed()
    );
    let rows = csv_records("tests/data/reference/belcour_basis.csv");
    assert_eq!(rows.len(), basis::GRID_SIZE);
    let mut worst = [0.0_f64; 4];
    for (i, row) in rows.iter().enumerate() {
        assert_eq!(number(row, 0), i as f64);
        assert_eq!(basis.cos_theta()[i], number(row, 1), "c_{i}");
        for (k, worst_k) in worst.iter_mut().enumerate() {
            let err = (basis.function(k)[i] - number(row, 3 + k)).abs();
            assert!(
                err <= BELCOUR_ABS_TOL,
                "b{k}[{i}]: {} vs {} ({err:e})",
                basis.function(k)[i],
                &row[3 + k]
            );
            *worst_k = worst_k.max(err);
        }
    }
    assert_eq!(basis.critical_indices(), [128, 432]);
    println!("belcour_basis: max abs error b0..b3 {worst:?}");
}

#[test]
fn tabulated_curves_reproduce_their_nodes() {
    let basis = basis::basis();
    let gold = Fresnel::belcour(Ior::eta_kappa(0.29, 2.86).unwrap());
    let Fresnel::Belcour(_, coefficients) = gold else {
        unreachable!()
    };
    let nodes = coefficients.reconstruction();
    let mut worst = 0.0_f64;
    for row in csv_records("tests/data/reference/belcour_basis.csv") {
        let i = number(&row, 0) as usize;
        // The reference θ (numpy's arccos) and Rust's own acos of the node.
        for theta in [number(&row, 2), basis.cos_theta()[i].acos()] {
            for k in 0..4 {
                let err = (Fresnel::basis(k).unwrap().eval(theta) - basis.function(k)[i]).abs();
                assert!(err <= NODE_TOL, "b{k} at node {i}: {err:e}");
                worst = worst.max(err);
            }
            let err = (gold.eval(theta) - nodes[i]).abs();
            assert!(err <= NODE_TOL, "belcour(Au) at node {i}: {err:e}");
            worst = worst.max(err);
        }
        // Exactly at the node in c.
        for k in 0..4 {
            assert_eq!(
                basis.interpolate(k, basis.cos_theta()[i]),
                basis.function(k)[i]
            );
        }
        assert_eq!(coefficients.interpolate(basis.cos_theta()[i]), nodes[i]);
    }
    println!("node reproduction at θ = arccos c_i: max abs error {worst:e}");
}

#[test]
fn coefficients_and_l2_match_numpy() {
    let mut worst = [0.0_f64; 5];
    for row in csv_records("tests/data/reference/belcour_materials.csv") {
        let (eta, kappa) = (number(&row, 1), number(&row, 2));
        let index = Index::new(eta, kappa);
        let coefficients = basis::coeffs(index);
        let l2 = coefficients.l2_grid(index);
        let values = [
            coefficients.c0,
            coefficients.c1,
            coefficients.c2,
            coefficients.c3,
            l2,
        ];
        for (j, (value, worst_j)) in values.iter().zip(worst.iter_mut()).enumerate() {
            let err = (value - number(&row, 3 + j)).abs();
            assert!(
                err <= BELCOUR_ABS_TOL,
                "{}: column {j}: {value} vs {} ({err:e})",
                &row[0],
                &row[3 + j]
            );
            *worst_j = worst_j.max(err);
        }
    }
    println!("belcour_materials: max abs error c0, c1, c2, c3, l2 {worst:?}");
}

#[test]
fn spectrum_matches_numpy() {
    let start = Instant::now();
    let spectrum = basis::spectrum();
    println!("spectrum (one 100 × 1000 SVD): {:?}", start.elapsed());
    let rows = csv_records("tests/data/reference/fresnel_spectrum.csv");
    assert_eq!(rows.len(), spectrum.singular_values.len());
    let s0 = spectrum.singular_values[0];
    let mut worst = [0.0_f64; 3];
    for (k, row) in rows.iter().enumerate() {
        let errors = [
            (spectrum.singular_values[k] - number(row, 1)).abs() / s0,
            (spectrum.normalized[k] - number(row, 2)).abs(),
            (spectrum.cumulative[k] - number(row, 3)).abs(),
        ];
        let tolerances = [SINGULAR_VALUE_TOL, BELCOUR_ABS_TOL, BELCOUR_ABS_TOL];
        for (j, (err, tol)) in errors.iter().zip(tolerances).enumerate() {
            assert!(
                *err <= tol,
                "spectrum row {k}, column {}: error {err:e}",
                j + 1
            );
            worst[j] = worst[j].max(*err);
        }
    }
    // The notebook's first figure: 99% of Σs is reached with the third singular value.
    assert!(spectrum.cumulative[1] < 0.99 && spectrum.cumulative[2] > 0.99);
    println!("fresnel_spectrum: max error s/s0, normalized, cumulative {worst:?}");
}
