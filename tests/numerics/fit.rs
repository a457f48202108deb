//! Fits and metrics at library level: peak fits against 30-digit mpmath fits
//! (`tests/data/reference/peak_fits.csv`) and the exact matches of docs/maths.md's table; the max and L2 fits
//! checked independently (the matched quantity equal, the L2 distance locally minimal); every kind of bad
//! fit input; difference series.

use crate::common::{csv_records, number};
use ndfplot::model::curve::{Curve, DiffOp};
use ndfplot::model::fit::{By, FitError, Subject, fit};
use ndfplot::model::metrics::{self, lobe_width, maximum};
use ndfplot::model::ndf::Family;
use ndfplot::spec::curve::{self};

/// Relative agreement required with the mpmath peak fits: the brief's bound; the solver reaches ~1e-15.
const PEAK_FIT_REL_TOL: f64 = 1e-7;

fn parse(text: &str) -> Curve {
    ndfplot::pipeline::resolve::curve(
        &curve::parse(&ndfplot::spec::json::parse(text).unwrap(), "").unwrap(),
    )
    .unwrap()
}

fn ndf(family: Family, params: &[f64]) -> Curve {
    Curve::Ndf(family.build(params).unwrap())
}

fn fixed(pairs: &[(&str, f64)]) -> Vec<(String, f64)> {
    pairs.iter().map(|&(k, v)| (k.to_string(), v)).collect()
}

fn phong_of_beckmann(alpha_b: f64) -> Curve {
    ndf(Family::Phong, &[2.0 / (alpha_b * alpha_b) - 2.0])
}

#[test]
fn peak_fits_match_the_mpmath_reference() {
    let mut worst: f64 = 0.0;
    let mut rows = 0;
    for record in csv_records("tests/data/reference/peak_fits.csv") {
        let target = parse(&record[0]);
        let family = Family::from_name(&record[1]).unwrap();
        let fixed: Vec<(String, f64)> = record[2]
            .split(',')
            .filter(|s| !s.is_empty())
            .map(|kv| {
                let (k, v) = kv.split_once('=').unwrap();
                (k.to_string(), v.parse().unwrap())
            })
            .collect();
        let expected = number(&record, 4);
        let got = fit(&target, family, &fixed, By::Peak).unwrap();
        assert_eq!(got.free[0].0, &record[3]);
        let rel = (got.free[0].1 / expected - 1.0).abs();
        assert!(
            rel <= PEAK_FIT_REL_TOL,
            "{}: got {:?}, expected {expected:?}",
            &record[0],
            got.free[0].1
        );
        worst = worst.max(rel);
        rows += 1;
    }
    assert!(rows >= 5);
    println!("peak fits: max relative error {worst:e} over {rows} rows");
}

#[test]
fn peak_fits_reproduce_the_exact_matches_of_math_md() {
    let abc_tr = [
        (0.3, 23.4442),
        (0.4, 11.5819),
        (0.5, 6.3102),
        (0.6, 3.5736),
        (0.7, 2.0040),
    ];
    for (alpha_tr, expected) in abc_tr {
        let target = ndf(Family::TrowbridgeReitz, &[alpha_tr]);
        let got = fit(
            &target,
            Family::Abc,
            &fixed(&[("alpha_abc2", 1.75)]),
            By::Peak,
        )
        .unwrap();
        assert!(
            (got.free[0].1 - expected).abs() <= 5e-5,
            "α_tr = {alpha_tr}: {}",
            got.free[0].1
        );
        assert!(metrics::relative_difference(got.curve.eval(0.0), target.eval(0.0)) <= 1e-14);
    }
    // To half a unit of the last digit docs/maths.md prints.
    for (alpha_b, expected, half_unit) in [(0.3, 0.0211927, 5e-8), (0.5, 0.00683542, 5e-9)] {
        let got = fit(
            &phong_of_beckmann(alpha_b),
            Family::Abc,
            &fixed(&[("alpha_abc2", 1000.0)]),
            By::Peak,
        )
        .unwrap();
        assert!(
            (got.free[0].1 - expected).abs() <= half_unit,
            "α_b = {alpha_b}: {}",
            got.free[0].1
        );
    }
    for (alpha_b, manual) in [(0.2, 0.2027), (0.3, 0.3097), (0.4, 0.425), (0.5, 0.552)] {
        let got = fit(
            &phong_of_beckmann(alpha_b),
            Family::TorranceSparrow,
            &[],
            By::Peak,
        )
        .unwrap();
        assert!(
            (got.free[0].1 / manual - 1.0).abs() <= 0.01,
            "α_b = {alpha_b}: {}",
            got.free[0].1
        );
    }
}

#[test]
fn a_family_fitted_to_itself_returns_the_parameter() {
    let target = ndf(Family::TrowbridgeReitz, &[0.37]);
    for by in By::ALL {
        let got = fit(&target, Family::TrowbridgeReitz, &[], by).unwrap();
        // L2 minima are located to ~1e-8 (the distance is flat there); roots to rounding.
        let tol = if by == By::L2 { 1e-6 } else { 1e-14 };
        assert!(
            (got.free[0].1 / 0.37 - 1.0).abs() <= tol,
            "{by:?}: {}",
            got.free[0].1
        );
    }
    // A linear parameter (SGD's a₂, which may be negative) and Phong's lower bound α_p = 0.
    let sgd = ndf(Family::Sgd, &[0.5, -0.3]);
    let got = fit(&sgd, Family::Sgd, &fixed(&[("alpha_sgd1", 0.5)]), By::Peak).unwrap();
    assert!((got.free[0].1 + 0.3).abs() <= 1e-13, "{}", got.free[0].1);
    let uniform = ndf(Family::Phong, &[0.0]);
    assert_eq!(
        fit(&uniform, Family::Phong, &[], By::Peak).unwrap().free[0].1,
        0.0
    );
}

#[test]
fn gtr_fits_either_parameter_and_meets_trowbridge_reitz_at_gamma_2() {
    // GTR with γ fixed at 2 is Trowbridge–Reitz: its α fitted to α_tr = 0.37 is 0.37.
    let target = ndf(Family::TrowbridgeReitz, &[0.37]);
    for by in By::ALL {
        let got = fit(&target, Family::Gtr, &fixed(&[("gamma_gtr", 2.0)]), by).unwrap();
        let tol = if by == By::L2 { 1e-6 } else { 1e-13 };
        assert!(
            (got.free[0].1 / 0.37 - 1.0).abs() <= tol,
            "{by:?}: {}",
            got.free[0].1
        );
    }
    // γ fitted with α fixed recovers the γ of a GTR target, on both sides of Berry's γ = 1.
    for gamma in [0.5, 1.0, 3.0] {
        let target = ndf(Family::Gtr, &[0.3, gamma]);
        let got = fit(
            &target,
            Family::Gtr,
            &fixed(&[("alpha_gtr", 0.3)]),
            By::Peak,
        )
        .unwrap();
        assert!(
            (got.free[0].1 / gamma - 1.0).abs() <= 1e-12,
            "γ = {gamma}: {}",
            got.free[0].1
        );
    }
}

#[test]
fn max_fits_equate_the_maxima_where_peak_fits_do_not() {
    // SGD a₁ = 1, a₂ = 0.5 peaks away from the normal (docs/contracts.md).
    let target = ndf(Family::Sgd, &[1.0, 0.5]);
    let target_max = maximum(|t| target.eval(t), lobe_width(target.eval(0.0))).unwrap();
    assert!(
        target_max.theta > 0.0 && target_max.value > target.eval(0.0),
        "{target_max:?}"
    );
    let by_max = fit(
        &target,
        Family::Abc,
        &fixed(&[("alpha_abc2", 1.75)]),
        By::Max,
    )
    .unwrap();
    let by_peak = fit(
        &target,
        Family::Abc,
        &fixed(&[("alpha_abc2", 1.75)]),
        By::Peak,
    )
    .unwrap();
    let fitted_max = maximum(|t| by_max.curve.eval(t), lobe_width(by_max.curve.eval(0.0))).unwrap();
    assert!(
        metrics::relative_difference(fitted_max.value, target_max.value) <= 1e-12,
        "{fitted_max:?}"
    );
    assert!(
        (by_max.free[0].1 / by_peak.free[0].1 - 1.0).abs() > 0.01,
        "{} vs {}",
        by_max.free[0].1,
        by_peak.free[0].1
    );
}

#[test]
fn l2_fits_are_local_minima_and_differ_from_peak_fits() {
    let target = phong_of_beckmann(0.3);
    let l2 = fit(&target, Family::TorranceSparrow, &[], By::L2).unwrap();
    let peak = fit(&target, Family::TorranceSparrow, &[], By::Peak).unwrap();
    let at = |x: f64| metrics::l2_projected(&ndf(Family::TorranceSparrow, &[x]), &target).unwrap();
    assert_eq!(l2.residual, at(l2.free[0].1));
    for factor in [1.0 - 1e-4, 1.0 + 1e-4] {
        assert!(at(l2.free[0].1 * factor) >= l2.residual, "{factor}");
    }
    assert!(
        at(peak.free[0].1) > l2.residual * 1.01,
        "peak {} vs l2 {}",
        at(peak.free[0].1),
        l2.residual
    );
    assert!((l2.free[0].1 / peak.free[0].1 - 1.0).abs() > 1e-3);
}

#[test]
fn unreachable_targets_and_bad_fixed_keys_are_errors_naming_the_problem() {
    let uniform = ndf(Family::Phong, &[0.0]);
    for by in [By::Peak, By::L2] {
        let e = fit(&uniform, Family::TorranceSparrow, &[], by).unwrap_err();
        assert_eq!(
            (e.subject, e.key.as_str()),
            (Subject::Target, "alpha_ts"),
            "{e}"
        );
        assert!(e.message.contains("cannot reach"), "{e}");
    }
    // Below 1/π no Phong lobe has its D(0).
    let super_rough = ndf(Family::TrowbridgeReitz, &[2.0]);
    let e = fit(&super_rough, Family::Phong, &[], By::Peak).unwrap_err();
    assert!(
        e.message.contains("cannot reach") && e.message.contains("got 0.0795"),
        "{e}"
    );
    let target = ndf(Family::TrowbridgeReitz, &[0.3]);
    let check = |fixed: &[(&str, f64)], needle: &str| {
        let e: FitError = fit(&target, Family::Abc, &self::fixed(fixed), By::Peak).unwrap_err();
        assert_eq!(e.subject, Subject::Fixed, "{e}");
        assert!(e.to_string().contains(needle), "{needle}: {e}");
    };
    check(&[("alpha_abc3", 1.0)], "did you mean \"alpha_abc1\"");
    check(
        &[("alpha_abc1", 1.0), ("alpha_abc2", 1.0)],
        "no free parameter left",
    );
    check(&[], "abc has 2 free parameters");
    check(
        &[("alpha_abc2", -1.0)],
        "alpha_abc2: out of domain (got -1.0",
    );
    check(&[("alpha_abc2", 1.0), ("alpha_abc2", 2.0)], "fixed twice");
    let fresnel = parse(r#"{"fresnel":"exact","eta":1.5}"#);
    let e = fit(
        &fresnel,
        Family::Abc,
        &fixed(&[("alpha_abc2", 1.75)]),
        By::Peak,
    )
    .unwrap_err();
    assert!(
        e.to_string()
            .starts_with("fresnel: a fit needs an NDF target"),
        "{e}"
    );
}

#[test]
fn difference_series_parse_evaluate_and_print_canonically() {
    let minus = parse(
        r#"{"b":{"ndf":"ggx","alpha_tr":0.5},"difference":"minus","a":{"ndf":"beckmann","alpha_b":0.5}}"#,
    );
    assert_eq!(
        minus.canonical_json(),
        r#"{"difference":"minus","a":{"ndf":"beckmann","alpha_b":0.5},"b":{"ndf":"trowbridge_reitz","alpha_tr":0.5}}"#
    );
    let (a, b) = (
        ndf(Family::Beckmann, &[0.5]),
        ndf(Family::TrowbridgeReitz, &[0.5]),
    );
    assert_eq!(minus.eval(0.3), a.eval(0.3) - b.eval(0.3));
    assert_eq!(parse(&minus.canonical_json()), minus);
    // 0/0 is 1 (both vanish: they agree); x/0 is infinite, which every consumer reports as an error.
    assert_eq!(DiffOp::Ratio.apply(0.0, 0.0), 1.0);
    assert_eq!(DiffOp::Ratio.apply(1.0, 0.0), f64::INFINITY);
    let ratio = parse(
        r#"{"difference":"ratio","a":{"ndf":"phong","alpha_p":2},"b":{"ndf":"phong","alpha_p":4}}"#,
    );
    assert_eq!(
        ratio.eval(0.0),
        (4.0 / (2.0 * std::f64::consts::PI)) / (6.0 / (2.0 * std::f64::consts::PI))
    );
    let problems = |text: &str| {
        let list = curve::parse(&ndfplot::spec::json::parse(text).unwrap(), "").unwrap_err();
        list.iter()
            .map(|p| format!("{}: {}", p.at, p.message))
            .collect::<Vec<_>>()
            .join("\n")
    };
    let p = problems(
        r#"{"difference":"minsu","a":{"ndf":"phong","alpha_p":2},"b":{"fresnel":"exact","eta":1.5}}"#,
    );
    assert!(
        p.contains("difference: unknown difference (got \"minsu\"")
            && p.contains("did you mean \"minus\""),
        "{p}"
    );
    let p = problems(
        r#"{"difference":"minus","a":{"ndf":"phong","alpha_p":2},"b":{"fresnel":"exact","eta":1.5}}"#,
    );
    assert!(
        p.contains("b: a difference needs two curves of the same kind (got ndf against fresnel"),
        "{p}"
    );
    let p = problems(r#"{"difference":"ratio","a":{"ndf":"phong","alpha_p":-2},"c":1}"#);
    assert!(
        p.contains("c: unknown key") && p.contains("b: missing operand"),
        "{p}"
    );
}
