//! The figure lint over the built-in catalogue: no literal markup, at least three labelled ticks
//! per axis, equal plot areas along a row, no overlapping or clipped text, 3:1 contrast for every
//! curve, and no two legend entries alike in a panel (`ndfplot::output::plot::lint`).

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
