//! Difference panels (`{"difference": …, "a": …, "b": …}`): a data series on either side, taken at
//! its own θ; non-finite points left out with one warning per series; the default value-axis label.

use crate::common::{ndfplot, scratch, text};
use std::f64::consts::{FRAC_PI_2, PI};
use std::path::{Path, PathBuf};

/// GGX (Trowbridge–Reitz) D(θ) = α²/(π (sin²θ + α² cos²θ)²), docs/maths.md, in f64.
fn ggx(theta: f64, alpha: f64) -> f64 {
    let (s, c) = theta.sin_cos();
    alpha * alpha / (PI * (s * s + alpha * alpha * c * c).powi(2))
}

/// The same formula as a shader computes it, in f32.
fn ggx_f32(theta: f32, alpha: f32) -> f32 {
    let (s, c) = theta.sin_cos();
    alpha * alpha / (std::f32::consts::PI * (s * s + alpha * alpha * c * c).powi(2))
}

/// Beckmann D(θ) = exp(−tan²θ/α²)/(π α² cos⁴θ), docs/maths.md, in f64.
fn beckmann(theta: f64, alpha: f64) -> f64 {
    let (t, c) = (theta.tan(), theta.cos());
    (-(t * t) / (alpha * alpha)).exp() / (PI * alpha * alpha * c.powi(4))
}

/// Writes `spec` as `<dir>/<id>.json` and renders it into `<dir>/out` with `extra` arguments.
fn render(dir: &Path, id: &str, spec: &str, extra: &[&str]) -> (std::process::Output, PathBuf) {
    let path = dir.join(format!("{id}.json"));
    std::fs::write(&path, spec).unwrap();
    let out = dir.join("out");
    let mut args = vec![
        "render",
        path.to_str().unwrap(),
        "-o",
        out.to_str().unwrap(),
    ];
    args.extend(extra);
    (ndfplot(&args), out)
}

/// (series, x, y) of every row of a figure CSV.
fn rows(csv: &Path) -> Vec<(usize, f64, f64)> {
    let mut reader = csv::Reader::from_path(csv).unwrap();
    reader
        .records()
        .map(|r| {
            let r = r.unwrap();
            (
                r[1].parse().unwrap(),
                r[3].parse().unwrap(),
                r[4].parse().unwrap(),
            )
        })
        .collect()
}

#[test]
fn a_shaders_float32_samples_against_the_exact_curve_as_a_relative_difference() {
    let dir = scratch("difference-data");
    let alpha = 0.3;
    // 91 samples every degree, θ and D rounded to f32 as a shader's output would be.
    let samples: Vec<(f64, f64)> = (0..=90)
        .map(|d| {
            let theta = (f64::from(d).to_radians() as f32).min(FRAC_PI_2 as f32);
            let theta = f64::from(theta).min(FRAC_PI_2);
            (theta, f64::from(ggx_f32(theta as f32, alpha as f32)))
        })
        .collect();
    let mut file = String::from("theta,value\n");
    for (t, v) in &samples {
        file += &format!("{t:?},{v:?}\n");
    }
    std::fs::write(dir.join("shader.csv"), file).unwrap();
    let spec = r#"{"id": "shader", "panels": [{"curves": [
        {"difference": "relative", "a": {"data": "csv", "path": "shader.csv", "label": "shader"},
         "b": {"ndf": "ggx", "alpha_tr": 0.3}}]}]}"#;
    let (out, dir_out) = render(&dir, "shader", spec, &["--format", "svg,csv"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let drawn = rows(&dir_out.join("shader.csv"));
    assert_eq!(drawn.len(), samples.len(), "one point per sample, at its θ");
    for ((_, x, y), (t, v)) in drawn.iter().zip(&samples) {
        let exact = ggx(*t, alpha);
        let expected = (v - exact) / exact.abs();
        assert_eq!(x, t);
        assert!(
            (y - expected).abs() <= 1e-12,
            "θ = {t}: {y} against {expected}"
        );
    }
    // Float32 rounding is visible: relative errors of order 1e-7, not 0.
    assert!(drawn.iter().any(|(_, _, y)| y.abs() > 1e-9));
    let svg = std::fs::read_to_string(dir_out.join("shader.svg")).unwrap();
    assert!(
        svg.contains("relative difference in"),
        "the default y label"
    );
}

#[test]
fn two_data_series_are_compared_at_the_first_ones_samples_inside_the_seconds_span() {
    let dir = scratch("difference-two-data");
    let spec = r#"{"id": "two", "panels": [{"curves": [
        {"difference": "minus",
         "a": {"data": "table", "x": [0.0, 0.25, 0.5, 1.0], "y": [1.0, 2.0, 3.0, 4.0]},
         "b": {"data": "table", "x": [0.1, 0.5, 0.9], "y": [10.0, 20.0, 30.0]}}]}]}"#;
    let (out, dir_out) = render(&dir, "two", spec, &["--format", "csv"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    // θ = 0 and 1.0 lie outside b's [0.1, 0.9]; at 0.25 b is 10 + (0.15/0.4)·10 = 13.75.
    let expected = [(0.25, 2.0 - 13.75), (0.5, 3.0 - 20.0)];
    let drawn: Vec<(f64, f64)> = rows(&dir_out.join("two.csv"))
        .into_iter()
        .map(|(_, x, y)| (x, y))
        .collect();
    assert_eq!(drawn, expected);
}

#[test]
fn a_swept_curve_against_one_data_series_gives_one_series_each() {
    let dir = scratch("difference-sweep");
    let spec = r#"{"id": "sweep", "panels": [{"curves": [
        {"difference": "ratio", "b": {"data": "table", "x": [0.0, 0.5], "y": [1.0, 2.0]},
         "a": {"ndf": "beckmann", "alpha_b": [0.2, 0.4]}}]}]}"#;
    let (out, dir_out) = render(&dir, "sweep", spec, &["--format", "csv"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let drawn = rows(&dir_out.join("sweep.csv"));
    let expected: Vec<(usize, f64, f64)> = [(0, 0.2), (1, 0.4)]
        .iter()
        .flat_map(|&(s, a)| [(s, 0.0, beckmann(0.0, a)), (s, 0.5, beckmann(0.5, a) / 2.0)])
        .collect();
    assert_eq!(drawn.len(), expected.len());
    for (got, want) in drawn.iter().zip(&expected) {
        assert_eq!((got.0, got.1), (want.0, want.1));
        assert!(
            (got.2 - want.2).abs() <= 1e-12 * want.2,
            "{got:?} against {want:?}"
        );
    }
}

#[test]
fn bad_data_sides_are_refused_with_their_path() {
    let dir = scratch("difference-bad");
    for (spec, needle) in [
        (
            r#"{"id": "bad", "panels": [{"curves": [{"difference": "minus",
              "a": {"data": "table", "x": [0.0, 2.0], "y": [1.0, 2.0]}, "b": {"ndf": "ggx", "alpha_tr": 0.3}}]}]}"#,
            "panels[0].curves[0].a.x: θ out of range (got 2.0",
        ),
        (
            r#"{"id": "bad", "panels": [{"curves": [{"difference": "minus",
              "a": {"data": "spectrum"}, "b": {"ndf": "ggx", "alpha_tr": 0.3}}]}]}"#,
            "panels[0].curves[0].a.data: not a series of θ",
        ),
        (
            r#"{"id": "bad", "panels": [{"curves": [{"difference": "minus",
              "a": {"data": "table", "x": [0.0, 0.1], "y": [1.0, 2.0]},
              "b": {"data": "table", "x": [0.5, 0.6], "y": [1.0, 2.0]}}]}]}"#,
            "panels[0].curves[0]: a and b have no θ in common",
        ),
    ] {
        let (out, _) = render(&dir, "bad", spec, &["--format", "csv"]);
        assert_eq!(out.status.code(), Some(2), "{spec}");
        assert!(text(&out.stderr).contains(needle), "{}", text(&out.stderr));
    }
}

/// GGX over Beckmann at α = 0.3: the ratio overflows to +∞ near grazing (Beckmann's exp(−tan²θ/α²)
/// underflows long before GGX does).
const RATIO: &str = r#"{"id": "ratio", "panels": [{"y": {"scale": "log"}, "curves": [
    {"difference": "ratio", "a": {"ndf": "ggx", "alpha_tr": 0.3}, "b": {"ndf": "beckmann", "alpha_b": 0.3},
     "label": "GGX / Beckmann"}]}]}"#;

#[test]
fn non_finite_points_are_left_out_with_one_warning_per_series() {
    let dir = scratch("difference-non-finite");
    let (out, dir_out) = render(&dir, "ratio", RATIO, &["--format", "png,csv"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let stderr = text(&out.stderr);
    let warnings: Vec<&str> = stderr
        .lines()
        .filter(|l| l.starts_with("warning:"))
        .collect();
    assert_eq!(warnings.len(), 1, "{stderr}");
    assert!(
        warnings[0].contains(r#"panels[0]: "GGX / Beckmann": "#)
            && warnings[0].contains("points not finite, θ from 1.4")
            && warnings[0].ends_with("to 1.571, left out"),
        "{stderr}"
    );
    // The CSV keeps every finite value as computed, and only those.
    let drawn = rows(&dir_out.join("ratio.csv"));
    assert!(
        drawn.len() < 1000 && drawn.len() > 900,
        "{} rows",
        drawn.len()
    );
    for (_, t, y) in &drawn {
        let expected = ggx(*t, 0.3) / beckmann(*t, 0.3);
        assert!(
            y.is_finite() && (y - expected).abs() <= 1e-9 * expected,
            "θ = {t}"
        );
    }
    // A warning makes --strict fail, as every lint warning does.
    let (strict, _) = render(&dir, "ratio", RATIO, &["--format", "svg", "--strict"]);
    assert_eq!(strict.status.code(), Some(1), "{}", text(&strict.stderr));
}

#[test]
fn difference_panels_say_what_they_show_on_the_value_axis() {
    let dir = scratch("difference-labels");
    for (op, quantity, label) in [
        ("minus", "d", " − "),
        ("log-ratio", "g1", "ln("),
        ("relative", "lambda", "relative difference in "),
    ] {
        let spec = format!(
            r#"{{"id": "labels", "panels": [{{"curves": [{{"difference": "{op}",
              "a": {{"ndf": "ggx", "alpha_tr": 0.3, "quantity": "{quantity}"}},
              "b": {{"ndf": "beckmann", "alpha_b": 0.3, "quantity": "{quantity}"}}}}]}}]}}"#
        );
        let (out, dir_out) = render(&dir, "labels", &spec, &["--format", "svg"]);
        assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
        let svg = std::fs::read_to_string(dir_out.join("labels.svg")).unwrap();
        assert!(svg.contains(label), "{op}: {label}");
    }
}
