//! Interactive pages: the catalogue's pages are self-contained, small and deterministic, bad
//! slider declarations exit 2 naming their path, and, in a real browser, `render` writes a page,
//! Debian's Chromium (driven by playwright-core, tests/browser/check.mjs) opens it from disk with
//! the network off, a slider is moved, and the values the page then draws must equal `ndfplot
//! eval` at the new slider position to the stated precision. The browser part is skipped, saying
//! so, only when /usr/bin/chromium, node or the node project's playwright-core is missing; `.ci/run`
//! installs all three.

use crate::common::{files_in, ndfplot, render_into, root, scratch};
use ndfplot::output::html::PRECISION;
use ndfplot::scene::sweep::phong_from_beckmann;
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::Command;

const CHROMIUM: &str = "/usr/bin/chromium";

/// The node project that drives the browser.
fn project() -> PathBuf {
    root().join("tests/browser")
}

/// Why the browser cannot run here, if it cannot.
fn missing_browser() -> Option<String> {
    if !Path::new(CHROMIUM).exists() {
        return Some(format!(
            "{CHROMIUM} is not installed (apt-get install chromium)"
        ));
    }
    if !matches!(Command::new("node").arg("--version").output(), Ok(out) if out.status.success()) {
        return Some("node is not installed".to_string());
    }
    if !project().join("node_modules/playwright-core").exists() {
        return Some(
            "playwright-core is not installed (PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --prefix tests/browser)"
                .to_string(),
        );
    }
    None
}

/// Renders the catalogue page `id` into a scratch folder, opens it in Chromium, moves its first
/// slider, and returns what check.mjs reported; the screenshot is left at `<tmp>/ndfplot-<id>.png`.
fn drive(id: &str) -> Value {
    let dir = scratch(&format!("browser-{id}"));
    let spec = root().join(format!("configs/{id}.json"));
    render_into(&[&spec], &dir, "html");
    let page = dir.join(format!("{id}.html"));
    let screenshot: PathBuf = std::env::temp_dir().join(format!("ndfplot-{id}.png"));
    let out = Command::new("node")
        .arg(project().join("check.mjs"))
        .arg(&page)
        .arg(&screenshot)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "check.mjs failed: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    println!("{id}: screenshot {}", screenshot.display());
    let report: Value = serde_json::from_slice(&out.stdout).expect("check.mjs prints JSON");
    assert_eq!(
        report["external_requests"],
        Value::Array(vec![]),
        "the page asked for something besides itself"
    );
    assert_eq!(report["errors"], Value::Array(vec![]), "script errors");
    assert_ne!(
        report["before"]["params"], report["after"]["params"],
        "the slider did not move"
    );
    assert_eq!(report["canvas_changed"], true, "the plot was not redrawn");
    assert_eq!(
        (&report["log_scale"], &report["log_redrawn"]),
        (&Value::from("log"), &Value::from(true))
    );
    report
}

/// Asserts that every drawn series equals `ndfplot eval` at its θ to [`PRECISION`], relative.
fn assert_drawn_values_equal_eval(series: &[Value]) {
    for s in series {
        let curve = s["curve"].as_str().unwrap();
        let theta: Vec<f64> = s["theta"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        let drawn: Vec<f64> = s["y"]
            .as_array()
            .unwrap()
            .iter()
            .map(|v| v.as_f64().unwrap())
            .collect();
        assert!(
            theta.len() > 10 && theta.len() == drawn.len(),
            "{curve}: {} points",
            theta.len()
        );
        let list: Vec<String> = theta.iter().map(|t| format!("{t:?}")).collect();
        let out = ndfplot(&["eval", "--curve", curve, "--theta", &list.join(",")]);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let text = String::from_utf8(out.stdout).unwrap();
        let rows: Vec<(f64, f64)> = text
            .lines()
            .skip(1)
            .map(|line| {
                let (t, v) = line.split_once(',').unwrap();
                (t.parse().unwrap(), v.parse().unwrap())
            })
            .collect();
        assert_eq!(rows.len(), drawn.len());
        for ((&(t, exact), &y), &t_page) in rows.iter().zip(&drawn).zip(&theta) {
            assert_eq!(t, t_page, "{curve}: θ changed on the way");
            assert!(
                (y - exact).abs() <= PRECISION * exact.abs(),
                "{curve} at θ = {t}: drawn {y}, eval {exact}"
            );
        }
    }
}

fn curves(report: &Value) -> Vec<String> {
    report["after"]["series"]
        .as_array()
        .unwrap()
        .iter()
        .map(|s| s["curve"].as_str().unwrap().to_string())
        .collect()
}

#[test]
fn moving_a_slider_redraws_values_equal_to_eval_at_the_new_position() {
    if let Some(reason) = missing_browser() {
        // Straight to stderr, past the test harness's capture, so that a skip is always seen.
        use std::io::Write;
        let _ = writeln!(std::io::stderr(), "SKIPPED: browser test not run: {reason}");
        return;
    }
    // One slider through a mapping: Beckmann α_b and Phong at α_p = 2/α_b² − 2.
    let report = drive("beckmann-vs-phong-interactive");
    let alpha_b = report["after"]["params"]["alpha_b"].as_f64().unwrap();
    // The readout is typeset: `α_b` shows as α with a subscript b, whose text is "αb".
    assert_eq!(report["printed"], format!("αb = {alpha_b}"));
    let alpha_p = phong_from_beckmann(alpha_b).unwrap();
    assert_eq!(
        curves(&report),
        [
            format!(r#"{{"ndf":"beckmann","alpha_b":{alpha_b:?}}}"#),
            format!(r#"{{"ndf":"phong","alpha_p":{alpha_p:?}}}"#)
        ]
    );
    assert_drawn_values_equal_eval(report["after"]["series"].as_array().unwrap());

    // Two sliders, three Fresnel curves, the printed coefficients.
    let report = drive("gulbrandsen-interactive");
    let (r, g) = (
        &report["after"]["params"]["r"],
        &report["after"]["params"]["g"],
    );
    let (r, g) = (r.as_f64().unwrap(), g.as_f64().unwrap());
    assert_eq!(
        curves(&report),
        [
            format!(r#"{{"fresnel":"belcour","r":{r:?},"g":{g:?},"g_remap":false}}"#),
            format!(r#"{{"fresnel":"exact","r":{r:?},"g":{g:?},"g_remap":false}}"#),
            format!(r#"{{"fresnel":"schlick","f0":{r:?}}}"#),
        ]
    );
    let readout = report["after"]["readouts"][0].as_str().unwrap();
    let coeffs = ndfplot(&["coeffs", "--curve", &curves(&report)[0]]);
    let row = String::from_utf8(coeffs.stdout).unwrap();
    let c0: f64 = row
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .next()
        .unwrap()
        .parse()
        .unwrap();
    assert!(
        readout.contains(&format!("c₀ = {c0:.4}")),
        "{readout} vs {row}"
    );
    assert_drawn_values_equal_eval(report["after"]["series"].as_array().unwrap());
}

/// Largest page the catalogue may have (README).
const MAX_PAGE_BYTES: usize = 1_000_000;

#[test]
fn catalogue_pages_are_self_contained_small_and_deterministic() {
    let dir = scratch("interactive-catalogue");
    let mut runs = Vec::new();
    for run in ["a", "b"] {
        let out_dir = dir.join(run);
        render_into(&[], &out_dir, "html");
        let mut pages: Vec<(String, Vec<u8>)> = std::fs::read_dir(&out_dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .map(|p| {
                (
                    p.file_name().unwrap().to_string_lossy().into_owned(),
                    std::fs::read(&p).unwrap(),
                )
            })
            .collect();
        pages.sort();
        runs.push(pages);
    }
    let names: Vec<&str> = runs[0].iter().map(|(n, _)| n.as_str()).collect();
    let interactive: Vec<String> = files_in(&root().join("configs"))
        .into_iter()
        .filter(|n| n.contains("interactive"))
        .map(|n| n.replace(".json", ".html"))
        .collect();
    assert!(
        interactive.len() >= 10 && interactive.iter().all(|n| names.contains(&n.as_str())),
        "{names:?}"
    );
    assert_eq!(runs[0], runs[1], "pages differ between runs");
    for (name, bytes) in &runs[0] {
        let text = std::str::from_utf8(bytes).unwrap();
        assert!(
            bytes.len() <= MAX_PAGE_BYTES,
            "{name}: {} bytes",
            bytes.len()
        );
        // Nothing to fetch: no external URL besides the SVG namespace name, no src attributes.
        let urls = text.matches("http").count();
        let namespaces = text.matches("http://www.w3.org/2000/svg").count();
        assert_eq!(urls, namespaces, "{name} names a URL");
        assert!(
            !text.contains(" src=") && !text.contains("@import") && !text.contains("url("),
            "{name} loads a resource"
        );
    }
}

#[test]
fn bad_interactive_declarations_exit_2_naming_the_path() {
    let dir = scratch("interactive-bad");
    let slider = r#"{"params": [{"name": "a", "range": [0.2, 1.0, 0.1]}]}"#;
    let beckmann = r#"{"ndf": "beckmann", "alpha_b": {"slider": "a"}}"#;
    for (interactive, curve, needle) in [
        (
            slider,
            r#"{"ndf": "beckmann", "alpha_b": {"slider": "b"}}"#,
            r#"panels[0].curves[0].alpha_b.slider: unknown slider (got "b", expected one of: a)"#,
        ),
        (
            r#"{"params": [{"name": "a", "range": [1.0, 0.2, 0.1]}]}"#,
            beckmann,
            "interactive.params[0].range: step points away from stop",
        ),
        (
            r#"{"params": [{"name": "a", "range": [0, 1, 0.0001]}]}"#,
            beckmann,
            "interactive.params[0].range: 10001 values exceed the cap of 1001",
        ),
        (
            r#"{"params": [{"name": "a", "range": [0.01, 1, 0.01]}, {"name": "b", "range": [0, 1.5, 0.05]}]}"#,
            r#"{"ndf": "sgd", "alpha_sgd1": {"slider": "a"}, "alpha_sgd2": {"slider": "b"}}"#,
            "interactive.params: the page would precompute up to 3100 curves",
        ),
    ] {
        let spec = dir.join("bad.json");
        let text = format!(
            r#"{{"id": "bad", "interactive": {interactive}, "panels": [{{"curves": [{curve}]}}]}}"#
        );
        std::fs::write(&spec, text).unwrap();
        let out_dir = dir.join("out");
        let out = ndfplot(&[
            "render",
            spec.to_str().unwrap(),
            "-o",
            out_dir.to_str().unwrap(),
        ]);
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{err}");
        assert!(
            err.contains(&format!("error: {}: {needle}", spec.display())),
            "expected {needle:?} in {err}"
        );
        assert!(!out_dir.exists(), "a bad spec wrote files");
    }
}
