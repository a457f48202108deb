//! The Fresnel basis (two 1000 × 1000 SVDs) is computed only when a figure needs it. The check runs
//! in a process of its own (this binary started again for this one test), so that no other test
//! computes the basis first.

use crate::common::scratch;
use ndfplot::fresnel::basis::basis_is_computed;
use ndfplot::output::Format;
use ndfplot::render::{self, RenderOptions};
use ndfplot::source::CanvasOverride;
use std::process::Command;

/// Set in the process that runs the check alone.
const ALONE: &str = "NDFPLOT_TEST_ALONE";

fn render(dir: &std::path::Path, spec: &str) {
    let path = dir.join("s.json");
    std::fs::write(&path, spec).unwrap();
    render::run(&RenderOptions {
        paths: vec![path],
        out: dir.join("out"),
        formats: vec![Format::Svg, Format::Png, Format::Csv],
        canvas: CanvasOverride::default(),
    })
    .unwrap();
}

#[test]
fn the_basis_is_computed_only_for_a_figure_that_uses_it() {
    if std::env::var_os(ALONE).is_none() {
        let (_, module) = module_path!().split_once("::").unwrap();
        let name = format!("{module}::the_basis_is_computed_only_for_a_figure_that_uses_it");
        let out = Command::new(std::env::current_exe().unwrap())
            .args([&name, "--exact", "--test-threads=1"])
            .env(ALONE, "1")
            .output()
            .unwrap();
        let report = format!(
            "{}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        assert!(
            out.status.success() && report.contains("1 passed"),
            "{report}"
        );
        return;
    }
    let dir = scratch("lazy-basis");
    render(
        &dir,
        r#"{"id": "ndf-and-exact-fresnel", "panels": [
            {"curves": [{"ndf": "ggx", "alpha_tr": 0.3}, {"ndf": "beckmann", "alpha_b": 0.3}]},
            {"curves": [{"fresnel": "exact", "eta": 1.5, "kappa": 0.0}]}]}"#,
    );
    assert!(!basis_is_computed(), "NDFs and exact Fresnel need no basis");
    render(
        &dir,
        r#"{"id": "belcour", "panels": [{"curves": [{"fresnel": "belcour", "eta": 1.5, "kappa": 0.0}]}]}"#,
    );
    assert!(basis_is_computed(), "the decomposition needs the basis");
}
