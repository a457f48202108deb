//! Quantities of an NDF through the command line (docs/contracts.md "Quantities of an NDF"): `eval` of Λ, G1,
//! G2, albedo and furnace curves against closed forms and published values computed here independently,
//! their canonical JSON, the key rules with their messages, `compare` and differences pairing only one
//! quantity, scenes' default axis labels and `check`'s Smith-consistency rows.

use crate::common::{ndfplot, scratch, text};
use std::f64::consts::{FRAC_PI_2, LN_2};
use std::process::Output;

/// The values `eval` prints for `curve` at `thetas` (radians), in order.
fn eval(curve: &str, thetas: &[f64]) -> Vec<f64> {
    let list: Vec<String> = thetas.iter().map(|t| format!("{t:?}")).collect();
    let output = ndfplot(&["eval", "--curve", curve, "--theta", &list.join(",")]);
    assert_eq!(output.status.code(), Some(0), "{}", text(&output.stderr));
    text(&output.stdout)
        .lines()
        .skip(1)
        .map(|line| line.split(',').nth(1).unwrap().parse().unwrap())
        .collect()
}

/// Asserts exit 2, nothing on stdout, and `needle` in the one-line error.
fn refused(output: &Output, needle: &str) {
    let err = text(&output.stderr);
    assert_eq!(output.status.code(), Some(2), "{err}");
    assert!(output.stdout.is_empty());
    assert!(
        err.starts_with("error: ") && err.contains(needle),
        "{needle:?} in {err}"
    );
}

fn close(got: f64, expected: f64, tol: f64) {
    assert!(
        (got - expected).abs() <= tol * expected.abs().max(1e-300),
        "got {got:e}, expected {expected:e} (relative tolerance {tol:e})"
    );
}

const THETAS: [f64; 6] = [0.0, 0.1, 0.5, 1.0, 1.4, 1.55];

/// GGX's Smith Λ from its textbook closed form (Heitz 2014 eq. 72), written here apart from the library.
fn ggx_lambda(alpha: f64, theta: f64) -> f64 {
    ((1.0 + (alpha * theta.tan()).powi(2)).sqrt() - 1.0) / 2.0
}

#[test]
fn lambda_g1_and_g2_follow_smith_from_lambda() {
    let alpha = 0.5;
    let lambda = eval(
        r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"lambda"}"#,
        &THETAS,
    );
    for (&theta, &l) in THETAS.iter().zip(&lambda) {
        // The textbook form cancels near θ = 0; 1e-9 covers it where Λ is ~1e-3.
        close(l, ggx_lambda(alpha, theta), 1e-9);
    }
    let g1 = eval(r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"g1"}"#, &THETAS);
    for (&g, &l) in g1.iter().zip(&lambda) {
        close(g, 1.0 / (1.0 + l), 1e-15);
    }
    // θi fixed at 0.3: height-correlated 1/(1 + Λo + Λi), separable G1(θo) G1(θi).
    let lambda_i = eval(
        r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"lambda"}"#,
        &[0.3],
    )[0];
    let correlated = eval(
        r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"g2","theta_i":0.3}"#,
        &THETAS,
    );
    let separable = eval(
        r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"g2","g2":"separable","theta_i":0.3}"#,
        &THETAS,
    );
    for i in 0..THETAS.len() {
        close(correlated[i], 1.0 / (1.0 + lambda[i] + lambda_i), 1e-15);
        close(separable[i], g1[i] / (1.0 + lambda_i), 1e-15);
    }
    // θi = "same" (the default): 1/(1 + 2Λ).
    let same = eval(r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"g2"}"#, &THETAS);
    for (&g, &l) in same.iter().zip(&lambda) {
        close(g, 1.0 / (1.0 + 2.0 * l), 1e-15);
    }
}

#[test]
fn every_family_has_masking_in_range() {
    for curve in [
        r#"{"ndf":"phong","alpha_p":20}"#,
        r#"{"ndf":"beckmann","alpha_b":0.3}"#,
        r#"{"ndf":"torrance_sparrow","alpha_ts":0.3}"#,
        r#"{"ndf":"ggx","alpha_tr":0.3}"#,
        r#"{"ndf":"abc","alpha_abc1":23.5,"alpha_abc2":1.75}"#,
        r#"{"ndf":"sgd","alpha_sgd1":0.122506,"alpha_sgd2":0.795078}"#,
        r#"{"ndf":"gtr","alpha_gtr":0.3,"gamma_gtr":1}"#,
    ] {
        let g1 = curve.replace('}', r#","quantity":"g1"}"#);
        let values = eval(&g1, &[0.0, 0.5, 1.0, 1.3, 1.5, FRAC_PI_2]);
        assert_eq!(values[0], 1.0, "{curve}: G1(0)");
        for pair in values.windows(2) {
            assert!(
                (0.0..=1.0).contains(&pair[1]) && pair[1] <= pair[0],
                "{curve}: G1 in [0, 1], non-increasing: {values:?}"
            );
        }
    }
}

#[test]
fn albedo_matches_exact_and_published_values() {
    // α = 1 makes D = 1/π and G2 = 2μi/(1 + μi): E(1) = ∫₀¹ μ/(1 + μ) dμ = 1 − ln 2.
    let e = eval(r#"{"ndf":"ggx","alpha_tr":1,"quantity":"albedo"}"#, &[0.0]);
    close(e[0], 1.0 - LN_2, 1e-12);
    // Test values of the research note (height-correlated, F = 1): E(μ = 0.5, α = 0.25), E(0.2, 0.5).
    let e = eval(
        r#"{"ndf":"ggx","alpha_tr":0.25,"quantity":"albedo"}"#,
        &[0.5f64.acos()],
    );
    assert!((e[0] - 0.857263436).abs() < 1e-9, "{}", e[0]);
    let e = eval(
        r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"albedo"}"#,
        &[0.2f64.acos()],
    );
    assert!((e[0] - 0.789929187).abs() < 1e-9, "{}", e[0]);
    // Schlick with F₀ = 1 is 1 at every angle: the same albedo as F = 1.
    let plain = eval(
        r#"{"ndf":"ggx","alpha_tr":0.3,"quantity":"albedo","g2":"separable"}"#,
        &[0.2, 1.0],
    );
    let schlick = eval(
        r#"{"ndf":"ggx","alpha_tr":0.3,"quantity":"albedo","g2":"separable","fresnel":{"fresnel":"schlick","f0":1}}"#,
        &[0.2, 1.0],
    );
    for (a, b) in plain.iter().zip(&schlick) {
        close(*b, *a, 1e-12);
    }
    // A dielectric reflects less than F = 1.
    let glass = eval(
        r#"{"ndf":"ggx","alpha_tr":0.3,"quantity":"albedo","fresnel":{"fresnel":"exact","eta":1.5}}"#,
        &[0.2],
    );
    assert!(glass[0] > 0.0 && glass[0] < 0.1, "{}", glass[0]);
}

#[test]
fn furnace_is_one_for_smith_and_shows_the_engines_g1() {
    let smith = eval(
        r#"{"ndf":"abc","alpha_abc1":10,"alpha_abc2":0.5,"quantity":"furnace"}"#,
        &[0.3, 1.2, 1.5],
    );
    assert_eq!(smith, [1.0, 1.0, 1.0]);
    // Phong n = 20 through Walter's rational G1 at its Beckmann-equivalent roughness (research values, 4 digits).
    let walter = eval(
        r#"{"ndf":"phong","alpha_p":20,"quantity":"furnace","g1":"walter-rational"}"#,
        &[75f64.to_radians(), 85f64.to_radians(), 89f64.to_radians()],
    );
    for (got, expected) in walter.iter().zip([1.0076, 1.0221, 1.0340]) {
        assert!((got - expected).abs() < 5e-5, "{got} vs {expected}");
    }
}

#[test]
fn canonical_json_writes_every_option_of_the_quantity() {
    let output = ndfplot(&[
        "eval",
        "--curve",
        r#"{"quantity":"g2","ndf":"ggx","alpha_tr":0.5}"#,
        "--curve",
        r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"albedo","fresnel":{"fresnel":"exact","eta":1.5}}"#,
        "--curve",
        r#"{"ndf":"phong","alpha_p":20,"quantity":"furnace"}"#,
        "--curve",
        r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"d"}"#,
        "--theta",
        "0.5",
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", text(&output.stderr));
    let header = text(&output.stdout).lines().next().unwrap().to_string();
    let header = header.replace("\"\"", "\"");
    for expected in [
        r#"{"ndf":"trowbridge_reitz","alpha_tr":0.5,"quantity":"g2","g2":"height-correlated","theta_i":"same"}"#,
        r#"{"ndf":"trowbridge_reitz","alpha_tr":0.5,"quantity":"albedo","g2":"height-correlated","fresnel":{"fresnel":"exact","eta":1.5,"kappa":0.0}}"#,
        r#"{"ndf":"phong","alpha_p":20.0,"quantity":"furnace","g1":"smith"}"#,
        // D, the default, is written as every NDF curve always was.
        r#","{"ndf":"trowbridge_reitz","alpha_tr":0.5}""#,
    ] {
        assert!(header.contains(expected), "{expected} in {header}");
    }
}

#[test]
fn key_rules_are_reported_at_their_path() {
    let cases = [
        (
            r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"g3"}"#,
            r#"quantity: unknown quantity (got "g3", expected one of: d, lambda, g1, g2, albedo, furnace); did you mean "g1"?"#,
        ),
        (
            r#"{"ndf":"ggx","alpha_tr":0.5,"g2":"separable"}"#,
            r#"g2: only a quantity "g2" or "albedo" curve takes this key (got "separable" on quantity "d")"#,
        ),
        (
            r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"g1","theta_i":0.2}"#,
            r#"theta_i: only a quantity "g2" curve takes this key"#,
        ),
        (
            r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"g2","theta_i":2}"#,
            "theta_i: expected the light's angle (got 2, expected radians in [0, 1.5707963267948966] or \"same\")",
        ),
        (
            r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"g2","g2":"correlated"}"#,
            "g2: unknown G2 model (got \"correlated\", expected one of: height-correlated, separable)",
        ),
        (
            r#"{"ndf":"abc","alpha_abc1":10,"alpha_abc2":0.5,"quantity":"furnace","g1":"walter-rational"}"#,
            "g1: ABC has no Beckmann-equivalent roughness",
        ),
        (
            r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"albedo","fresnel":{"ndf":"ggx","alpha_tr":0.5}}"#,
            "fresnel: an albedo's Fresnel factor is a Fresnel curve",
        ),
        (
            r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"albedo","fresnel":{"fresnel":"exact","eta":-1}}"#,
            "fresnel.eta: out of domain",
        ),
        (
            r#"{"fresnel":"exact","eta":1.5,"quantity":"g1"}"#,
            "quantity: unknown key for fresnel \"exact\"",
        ),
        (
            r#"{"transform":"slope","curve":{"ndf":"ggx","alpha_tr":0.5,"quantity":"g1"}}"#,
            "the slope view applies to NDF curves showing D",
        ),
        (
            r#"{"difference":"ratio","a":{"ndf":"ggx","alpha_tr":0.5,"quantity":"g1"},"b":{"ndf":"ggx","alpha_tr":0.5,"quantity":"lambda"}}"#,
            r#"a difference needs two curves of the same kind (got ndf quantity "g1" against ndf quantity "lambda""#,
        ),
    ];
    for (curve, needle) in cases {
        refused(
            &ndfplot(&["eval", "--curve", curve, "--theta", "0.5"]),
            needle,
        );
    }
}

#[test]
fn compare_pairs_curves_of_one_quantity_only() {
    let output = ndfplot(&[
        "compare",
        "--a",
        r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"g1"}"#,
        "--b",
        r#"{"ndf":"beckmann","alpha_b":0.5,"quantity":"g1"}"#,
        "--metric",
        "max_abs",
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", text(&output.stderr));
    let max_abs: f64 = text(&output.stdout).trim().parse().unwrap();
    assert!(max_abs > 0.1 && max_abs < 0.3, "{max_abs}");
    refused(
        &ndfplot(&[
            "compare",
            "--a",
            r#"{"ndf":"ggx","alpha_tr":0.5,"quantity":"g1"}"#,
            "--b",
            r#"{"ndf":"ggx","alpha_tr":0.5}"#,
        ]),
        r#"compare needs two curves showing the same quantity (got ndf against ndf quantity "g1")"#,
    );
}

#[test]
fn scenes_label_quantity_axes_and_check_audits_smith() {
    let dir = scratch("quantity-scene");
    let spec = dir.join("masking.json");
    std::fs::write(
        &spec,
        r#"{"id": "masking", "panels": [{"curves": [
            {"ndf": "beckmann", "alpha_b": 0.3, "quantity": "g1"},
            {"ndf": "abc", "alpha_abc1": {"fit": {"target": {"ndf": "beckmann", "alpha_b": 0.3}}}, "alpha_abc2": 1.75, "quantity": "g1"}
        ]}]}"#,
    )
    .unwrap();
    let out = dir.join("out");
    let output = ndfplot(&[
        "render",
        spec.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
        "--format",
        "svg,csv",
    ]);
    assert_eq!(output.status.code(), Some(0), "{}", text(&output.stderr));
    let svg = std::fs::read_to_string(out.join("masking.svg")).unwrap();
    assert!(
        svg.contains(r#"xml:space="preserve">G</text>"#)
            && svg.contains(r#"xml:space="preserve">θ</text>"#),
        "the G_1(θ_o) axis label"
    );
    let csv = std::fs::read_to_string(out.join("masking.csv")).unwrap();
    // Every row, the fitted ABC's included, is a G1 curve.
    assert_eq!(
        csv.matches(r#""quantity"":""g1"""#).count(),
        csv.lines().count() - 1
    );
    let output = ndfplot(&["check", spec.to_str().unwrap(), "--format", "csv"]);
    assert_eq!(output.status.code(), Some(0), "{}", text(&output.stderr));
    let report = text(&output.stdout);
    let smith: Vec<&str> = report
        .lines()
        .filter(|l| l.contains("smith_consistency"))
        .collect();
    assert_eq!(smith.len(), 2, "{report}");
    for line in smith {
        let deviation: f64 = line.split(',').nth(4).unwrap().parse().unwrap();
        assert!(deviation < 1e-12, "{line}");
    }
}
