//! The figure lint over the built-in catalogue: no literal markup, at least three labelled ticks
//! per axis, equal plot areas along a row, no overlapping or clipped text, 3:1 contrast for every
//! curve, and no two legend entries alike in a panel (`ndfplot::output::plot::lint`).

use crate::common::{ndfplot, scratch, text};
use ndfplot::output::plot::lint;
use ndfplot::render::drawn_figures;
use ndfplot::spec::look::Preset;
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

/// The lint's findings over the catalogue under `canvas`.
fn catalogue_findings(canvas: CanvasOverride) -> Vec<String> {
    let figures = drawn_figures(&[], &[], canvas).unwrap();
    figures
        .iter()
        .flat_map(|figure| lint(figure).unwrap())
        .collect()
}

#[test]
fn every_catalogue_figure_passes_the_figure_lint_at_page_width() {
    let findings = catalogue_findings(CanvasOverride {
        preset: Some(Preset::PaperPage),
        ..CanvasOverride::default()
    });
    assert!(findings.is_empty(), "{}", findings.join("\n"));
}

#[test]
fn every_catalogue_figure_passes_the_figure_lint_at_column_width() {
    let findings = catalogue_findings(CanvasOverride {
        preset: Some(Preset::PaperColumn),
        ..CanvasOverride::default()
    });
    assert!(findings.is_empty(), "{}", findings.join("\n"));
}

#[test]
fn a_spec_names_a_preset_and_its_own_keys_win() {
    let dir = scratch("lint-preset");
    let write = |name: &str, extra: &str| {
        let path = dir.join(format!("{name}.json"));
        std::fs::write(
            &path,
            format!(
                r#"{{"id": "{name}", {extra} "panels": [{{"curves": [{{"ndf": "beckmann", "alpha_b": 0.3}}]}}]}}"#
            ),
        )
        .unwrap();
        path
    };
    let column = write("column", r#""preset": "paper-column","#);
    let wider = write("wider", r#""preset": "paper-column", "width": 400,"#);
    let figures = drawn_figures(&[column, wider.clone()], &[], CanvasOverride::default()).unwrap();
    let (c, w) = (&figures[0].canvas, &figures[1].canvas);
    assert_eq!((c.width_px, c.height_px), (317, 211));
    assert!((c.png_scale - 300.0 / 96.0).abs() < 1e-12 && (c.font_px - 32.0 / 3.0).abs() < 1e-12);
    assert_eq!(w.width_px, 400);
    assert_eq!(w.font_px, c.font_px);
    let bad = write("bad", r#""preset": "paper-a4","#);
    let out = ndfplot(&["render", bad.to_str().unwrap(), "-o", dir.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("preset"),
        "{}",
        text(&out.stderr)
    );
    // render --preset overrides the spec's own size.
    let cli = ndfplot(&[
        "render",
        wider.to_str().unwrap(),
        "--preset",
        "paper-page",
        "-o",
        dir.to_str().unwrap(),
        "--format",
        "svg",
    ]);
    assert_eq!(cli.status.code(), Some(0), "{}", text(&cli.stderr));
    let svg = std::fs::read_to_string(dir.join("wider.svg")).unwrap();
    assert!(svg.contains(r#"width="7in""#), "{}", &svg[..300]);
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
