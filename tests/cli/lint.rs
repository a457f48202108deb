//! The figure lint over the built-in catalogue: no literal markup, at least three labelled ticks
//! per axis, equal plot areas along a row, no overlapping or clipped text, 3:1 contrast for every
//! curve, and no two legend entries alike in a panel (`ndfplot::output::plot::lint`).

use crate::common::{ndfplot, scratch, text};
use ndfplot::output::plot::lint;
use ndfplot::render::drawn_figures;
use ndfplot::spec::source::CanvasOverride;

#[test]
fn every_catalogue_figure_passes_the_figure_lint() {
    let figures = drawn_figures(&[], &[], CanvasOverride::default()).unwrap();
    assert!(figures.len() >= 36);
    let findings: Vec<String> = figures
        .iter()
        .flat_map(|figure| lint(figure).unwrap())
        .collect();
    assert!(findings.is_empty(), "{}", findings.join("\n"));
}

/// A figure far too small for its text: 160 × 90 px with 14 px text and a long title.
const CRAMPED: &str = r#"{
  "id": "cramped",
  "title": "A title far wider than the canvas it is drawn on",
  "width": 160,
  "height": 90,
  "panels": [{"curves": [{"ndf": "beckmann", "alpha_b": 0.3}]}]
}"#;

#[test]
fn render_prints_the_lint_and_strict_fails_on_it() {
    let dir = scratch("lint-warnings");
    let spec = dir.join("cramped.json");
    std::fs::write(&spec, CRAMPED).unwrap();
    let out = dir.join("out");
    let (spec, out) = (spec.to_str().unwrap(), out.to_str().unwrap());
    let run = |extra: &[&str]| {
        let mut args = vec!["render", spec, "-o", out, "--format", "svg"];
        args.extend_from_slice(extra);
        ndfplot(&args)
    };
    let plain = run(&[]);
    let err = text(&plain.stderr);
    assert_eq!(plain.status.code(), Some(0), "{err}");
    let warnings: Vec<&str> = err.lines().filter(|l| l.starts_with("warning: ")).collect();
    assert!(!warnings.is_empty(), "{err}");
    assert!(
        warnings
            .iter()
            .all(|w| w.starts_with(&format!("warning: {spec}: "))),
        "{err}"
    );
    assert!(
        warnings
            .iter()
            .any(|w| w.starts_with(&format!("warning: {spec}: panels[0]: "))),
        "{err}"
    );
    // -q keeps the warnings; --strict turns them into exit 1, the files still written.
    let quiet = run(&["-q"]);
    assert_eq!(quiet.status.code(), Some(0));
    let quiet_err = text(&quiet.stderr);
    assert_eq!(
        quiet_err
            .lines()
            .filter(|l| l.starts_with("warning: "))
            .count(),
        warnings.len(),
        "{quiet_err}"
    );
    let strict = run(&["--strict", "-q"]);
    let strict_err = text(&strict.stderr);
    assert_eq!(strict.status.code(), Some(1), "{strict_err}");
    assert!(
        strict_err.contains("error: render --strict"),
        "{strict_err}"
    );
    assert!(std::path::Path::new(out).join("cramped.svg").exists());
    // A figure with no finding: nothing printed, --strict exits 0.
    let clean = ndfplot(&[
        "render",
        "gtr-gamma",
        "-o",
        out,
        "--format",
        "svg",
        "--strict",
        "-q",
    ]);
    assert_eq!(clean.status.code(), Some(0), "{}", text(&clean.stderr));
    assert!(!text(&clean.stderr).contains("warning:"));
}
